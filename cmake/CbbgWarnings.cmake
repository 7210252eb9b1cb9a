# Warnings on, and errors, for the project's own code only (dependencies are SYSTEM includes).
function(cbbg_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                         -Wnon-virtual-dtor -Wold-style-cast -Werror)
endfunction()

# Debian builds Simbody without NDEBUG and its State layout differs with it: every
# translation unit that includes Simbody must see NDEBUG undefined.
function(cbbg_simbody_sources)
  set_source_files_properties(${ARGN} DIRECTORY ${CMAKE_SOURCE_DIR}
                              PROPERTIES COMPILE_OPTIONS "-UNDEBUG")
endfunction()
