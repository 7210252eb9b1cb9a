# Warnings on, and errors, for the project's own code only (dependencies are SYSTEM includes).
function(cbbg_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                         -Wnon-virtual-dtor -Wold-style-cast -Werror)
endfunction()
