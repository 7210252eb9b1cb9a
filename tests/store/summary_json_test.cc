// summary.json's reference to the paper: its Fig. 11 figures for the arms that ran, under a
// protocol that declares them, on the paper's robot; nothing for anything else.

#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/config/config.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/experiments/seed_run.h"
#include "cbbg/parameters/parameters.h"
#include "cbbg/store/results_writer.h"

namespace cbbg::store {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// One seed of each arm, as a protocol named `experiment` would return it on `plant_kind`.
experiments::ExperimentResults results_of(const std::string& experiment,
                                          const std::vector<std::string>& arms,
                                          const std::string& plant_kind) {
  config::Config config;
  config.set("plant.kind=" + plant_kind);
  config.set("experiment=" + experiment);
  experiments::ExperimentResults results;
  results.experiment = experiment;
  results.schema = experiments::results_schema(parameters::read_parameters(config));
  results.arms = arms;
  results.seeds = {1};
  for (const std::string& arm : arms) {
    experiments::SeedRun run;
    run.arm = arm;
    run.seed = 1;
    results.runs.push_back(run);
  }
  return results;
}

RunFacts on(const std::string& plant_kind) { return {.plant = plant_kind, .max_trials = 100}; }

TEST(SummaryJson, ThePapersFiguresAreThoseOfTheArmsThatRanUnderExp1OnItsRobot) {
  const auto both = results_of("exp1", {"cbbg", "bg_only"}, "simbody");
  EXPECT_THAT(summary_json(both, on("simbody")),
              HasSubstr("\n  \"paper\": {\"cbbg\": 0, \"bg_only\": 8},\n  \"note\""));
  EXPECT_THAT(summary_json(results_of("exp1", {"cbbg", "bg_only"}, "analytic"), on("analytic")),
              HasSubstr("\"paper\": {\"cbbg\": 0, \"bg_only\": 8}"));
  // An arm alone is exp1's protocol: its own figure only.
  EXPECT_THAT(summary_json(results_of("bg_only", {"bg_only"}, "analytic"), on("analytic")),
              HasSubstr("\"paper\": {\"bg_only\": 8}"));
  // Arms the paper did not run, protocols it has no such figure for: none.
  EXPECT_THAT(summary_json(results_of("exp1", {"pd_only"}, "simbody"), on("simbody")),
              Not(HasSubstr("\"paper\"")));
  EXPECT_THAT(summary_json(results_of("exp3", {"cbbg", "bg_only"}, "simbody"), on("simbody")),
              Not(HasSubstr("\"paper\"")));
}

}  // namespace
}  // namespace cbbg::store
