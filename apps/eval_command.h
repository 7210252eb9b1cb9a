#pragma once
// cbbg eval: measures a learnt policy. Loads a weights file (docs/weights-format.md), runs
// the actor alone with frozen weights from each initial pitch, `repeats` times with seeds
// seed, seed + 1, ... (they differ only with sensor noise), optionally pushed, and prints how
// many runs balanced for the whole trial.duration. It runs on the plant the weights were
// learnt on (the file's plant.kind) unless --config or --set names one; weights of another
// robot or layout than the evaluation's are refused (store::check_weights).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cbbg::app {

struct EvalOptions {
  std::filesystem::path weights_file;  // --load-weights (required)
  std::filesystem::path config_file;   // --config; empty: defaults only
  std::vector<std::string> sets;       // --set key.path=value overrides, in order
  std::string angles;                  // --angles as typed: rad, comma-separated; empty: the
                                       // config's evaluation.angles
  int repeats = 1;                     // --repeats: runs per angle, >= 1
  // --push-time (s, >= 0) and --push-duration (s, > 0) with at least one of --push-torque
  // (N m through the motors, added to both wheels), --push-force (N at the body's centre of
  // mass) and --push-pitch-torque (N m on the body), the last two from outside; or none.
  std::optional<double> push_time;
  std::optional<double> push_torque;
  std::optional<double> push_duration;
  std::optional<double> push_force;
  std::optional<double> push_pitch_torque;
  // --linearise: also print the actor's slopes at rest and the modes of the robot it closes
  // (experiments/actor_linearisation.h).
  bool linearise = false;
  // --out: a directory that receives evaluation.csv (theta0, seed, balanced, steps,
  // final_theta, status: one row per run); empty: no file. An evaluation.csv there is
  // replaced only when cbbg wrote it (the directory's .cbbg-written lists it).
  std::filesystem::path out;
};

// Returns 0 when the evaluation ran (whatever the policy did), 2 for bad input (options,
// config, weights file, a plant or a layout the config does not share), 1 when it failed
// otherwise (writing --out). Errors go to stderr as one line "cbbg: error: ...".
int eval_command(const EvalOptions& options);

}  // namespace cbbg::app
