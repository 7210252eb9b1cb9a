#pragma once
// The name messages give the program a user runs: "cbbg", or a user's own program built on
// the command line (apps/cli.h's run_cli sets it from argv[0]). Advice such as "continue it
// with cbbg run --resume DIR" then names the command the user can type.

#include <string>

namespace cbbg::config {

const std::string& program_name();
void set_program_name(std::string name);

}  // namespace cbbg::config
