#pragma once
// The `cbbg` command line as a function, so a user's own program is `cbbg` with its
// registrations added (plant kinds, arms, config sections): every subcommand (run, eval,
// graph, plot, replay, merge, status, list) then knows them.
//
//   int main(int argc, char** argv) {
//     cbbg::config::register_section<CartPoleParams>("cartpole");
//     cbbg::diagrams::register_plant_kind({...});
//     cbbg::diagrams::register_arm("tiles", "...", options);
//     return cbbg::app::run_cli(argc, argv);
//   }

#include <filesystem>

namespace cbbg::app {

// Runs the command line `argv`; returns the exit code (0 done, 1 failed while running, 2 bad
// input). `share` is where cbbg's plotting script and replay page are when they are not in
// share/cbbg/ beside the program's bin/ (a user's program: the package's share/cbbg).
int run_cli(int argc, char** argv, const std::filesystem::path& share);

// The same, with the share/cbbg/ of the cbbg package the program was built against (set by
// find_package(cbbg) for cbbg::cli, and by the build tree).
inline int run_cli(int argc, char** argv) {
#ifdef CBBG_SHARE_DIR
  return run_cli(argc, argv, CBBG_SHARE_DIR);
#else
  return run_cli(argc, argv, {});
#endif
}

}  // namespace cbbg::app
