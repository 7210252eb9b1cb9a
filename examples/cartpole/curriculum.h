#pragma once
// A protocol of the user's own: a curriculum. Each arm and seed trains from a small angle
// until a trial succeeds, then from trial.theta0 until one succeeds there (or max_trials);
// then its learnt actor is evaluated as exp1's is. Its own key: curriculum.first_angle.

#include <string>
#include <vector>

#include <cbbg/config/declared_keys.h>
#include <cbbg/experiments/protocol_kit.h>
#include <cbbg/experiments/protocols.h>

namespace cartpole {

struct CurriculumParams {
  double first_angle = 0.05;  // rad

  template <class Archive>
  void describe(Archive& a) {
    a.number("first_angle", first_angle, "the curriculum's first starting angle, rad",
             cbbg::interval(0.0, 0.5, cbbg::kOpen, cbbg::kOpen));
  }
};

// One seed of one arm: `run` records every trial; failures_before_success counts the
// failures on the way to the first success from trial.theta0, and the seed's own figure
// warm_up_trials the trials from the first angle, which its schema declares (figures.csv,
// summed in summary.json, compared between arms, drawn by cbbg plot).
inline void curriculum_seed(const cbbg::parameters::Parameters& p, const cbbg::diagrams::Arm& arm,
                            const cbbg::experiments::TelemetryOptions& telemetry,
                            const cbbg::experiments::LearntWeights* initial_weights,
                            cbbg::experiments::SeedRun& run) {
  using namespace cbbg::experiments;
  const double first =
      cbbg::config::read_section<CurriculumParams>(p.own, "curriculum").first_angle;
  SeedLoop seed(p, arm, telemetry, initial_weights, run.seed);
  bool warmed_up = false;
  int warm_up_trials = 0;
  for (int trial = 1; trial <= p.run.max_trials; ++trial) {
    if (!warmed_up) ++warm_up_trials;
    const TrialRecord record = next_trial(p, seed, trial, warmed_up ? p.trial.theta0 : first);
    run.trials.push_back(record);
    const bool success = record.outcome.status == TrialStatus::kSuccess;
    if (success && warmed_up) {
      run.succeeded = true;
      break;
    }
    if (success) {
      warmed_up = true;
    } else {
      ++run.failures_before_success;
    }
  }
  run.figures.push_back({"warm_up_trials", static_cast<double>(warm_up_trials)});
  finish_run(p, arm, seed.loop, seed.runner.context(), run);
}

inline void register_curriculum() {
  cbbg::config::register_section<CurriculumParams>("curriculum");
  // [docs curriculum-protocol]
  cbbg::experiments::register_protocol(
      {.name = "curriculum",
       .meaning = "per arm and seed: trials from curriculum.first_angle until a success, then "
                  "from trial.theta0 until one",
       .run =
           [](const cbbg::parameters::Parameters& p, const std::vector<cbbg::diagrams::Arm>& arms,
              const cbbg::experiments::ExperimentOptions& options) {
             return cbbg::experiments::run_per_arm("curriculum", curriculum_seed, p, arms, options);
           },
       .schema =
           [](const cbbg::parameters::Parameters&) {
             using namespace cbbg::experiments;
             return ResultsSchema{
                 .figures = {{.name = "warm_up_trials",
                              .type = ValueType::kInteger,
                              .meaning = "trials from curriculum.first_angle until "
                                         "one succeeded",
                              .paired = true}},
                 .plots = {"pitch", "failures", "figures"}};
           }});
  // [docs curriculum-protocol end]
}

}  // namespace cartpole
