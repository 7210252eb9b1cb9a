#pragma once
// cbbg export: a weights file's learnt policy as dependency-free C99, DIR/NAME.h and
// DIR/NAME.c (experiments/policy_export.h): the normaliser, the features and the actor of the
// arm that learnt them, with the weights as constants (with --omega, also the supervisor and
// the mixer at that omega; with --learner, the whole online learner, which goes on learning);
// `double` or `float`.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cbbg::app {

struct ExportOptions {
  std::filesystem::path weights_file;  // --load-weights (required)
  std::filesystem::path config_file;   // --config; empty: defaults only
  std::vector<std::string> sets;       // --set key.path=value overrides, in order
  std::filesystem::path out;           // --out DIR (required), made with its parents if missing
  // --name: the files' and identifiers' prefix; none: cbbg_policy, or cbbg_learner.
  std::optional<std::string> name;
  std::string scalar = "double";  // --scalar double | float
  // --omega: the arm's whole controller at this omega, from 0 to 1, without exploration
  // (a = omega a_A + (1 - omega) a_S); none: the actor alone.
  std::optional<double> omega;
  // --learner: the arm's whole online learner (codegen/c_learner_export.h), its generators
  // as run.seed's; excludes --omega.
  bool learner = false;

  std::string name_or_default() const {
    return name.value_or(learner ? "cbbg_learner" : "cbbg_policy");
  }
};

// Returns 0 when the files were written, 2 for bad input (options, config, weights file, a
// block that cannot be written as C, a file there that cbbg export did not write), 1 when the
// machine refused (writing). Errors go to stderr as one line "cbbg: error: ...".
int export_command(const ExportOptions& options);

}  // namespace cbbg::app
