// cbbg: run the paper's experiments, draw the diagrams, plot results, list what exists.

#include "cbbg/apps/cli.h"

// The command finds its plotting script and replay page in share/cbbg/ beside its bin/, in
// the build tree and wherever it is installed: no directory is compiled in.
int main(int argc, char** argv) { return cbbg::app::run_cli(argc, argv, {}); }
