#include "diagrams/experiments.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "diagrams/controller_diagram.h"
#include "diagrams/results_writer.h"
#include "plant/plant_ports.h"

namespace cbbg::diagrams {
namespace {

using ::testing::HasSubstr;

// The analytic plant keeps these tests quick.
config::Config quick_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("seeds=2");
  return config;
}

bool has_block(const Diagram& diagram, const std::string& name) {
  for (const auto& block : diagram.blocks()) {
    if (block->name() == name) return true;
  }
  return false;
}

TEST(ControllerDiagram, EachArmHasTheBlocksItsNameSays) {
  const config::Config config = quick_config();
  const auto cbbg = build_controller_diagram("cbbg", config);
  EXPECT_TRUE(has_block(*cbbg.diagram, "supervisor"));
  EXPECT_TRUE(has_block(*cbbg.diagram, "critic"));
  EXPECT_TRUE(has_block(*cbbg.diagram, "sampler"));
  const auto bg_only = build_controller_diagram("bg_only", config);
  EXPECT_FALSE(has_block(*bg_only.diagram, "supervisor"));
  EXPECT_TRUE(has_block(*bg_only.diagram, "actor"));
  const auto pd_only = build_controller_diagram("pd_only", config);
  EXPECT_TRUE(has_block(*pd_only.diagram, "supervisor"));
  EXPECT_FALSE(has_block(*pd_only.diagram, "actor"));
  EXPECT_FALSE(pd_only.learns());
  const auto policy = build_controller_diagram(kLearntActorDiagram, config);
  EXPECT_TRUE(has_block(*policy.diagram, "actor"));
  EXPECT_FALSE(has_block(*policy.diagram, "critic"));
  EXPECT_FALSE(has_block(*policy.diagram, "supervisor"));
  EXPECT_EQ(cbbg.telemetry->size(), kTelemetrySize);
  EXPECT_THROW(build_controller_diagram("cbbg_fast", config), std::invalid_argument);
}

TEST(ControllerDiagram, OmegaFollowsTheArm) {
  const config::Config config = quick_config();
  for (const auto& [arm, omega] : {std::pair<const char*, double>{"bg_only", 1.0},
                                   {"cb_only", 0.0},
                                   {"cbbg", 0.0},  // the schedule starts at 0 (n2 = 500)
                                   {"pd_only", 0.0}}) {
    const auto controller = build_controller_diagram(arm, config);
    auto context = controller.diagram->create_context(1);
    EXPECT_EQ(controller.diagram->eval_output(*context, *controller.telemetry)[kTelemetryOmega],
              omega)
        << arm;
  }
}

TEST(ControllerDiagram, ThePlantKindAndSupervisorKindSwapBlocks) {
  config::Config config = quick_config();
  config.set("supervisor.kind=lqr");
  const auto lqr = build_controller_diagram("cbbg", config);
  auto context = lqr.diagram->create_context(1);
  // Leaning forward, both supervisors push the wheels forward (a_S > 0).
  EXPECT_GT(lqr.diagram->eval_output(*context, *lqr.telemetry)[kTelemetrySupervisorAction], 0.0);
  config.set("plant.kind=simbody");
  const auto simbody = build_controller_diagram("cbbg", config);
  auto simbody_context = simbody.diagram->create_context(1);
  EXPECT_EQ(simbody.diagram->eval_output(*simbody_context, *simbody.telemetry)[kTelemetryThetaB],
            config.number("trial.theta0"));
}

TEST(TrialRunner, WeightsCarryOverAndTheRobotRestarts) {
  const config::Config config = quick_config();
  const auto controller = build_controller_diagram("bg_only", config);
  TrialRunner runner(controller, 1, config.number("trial.period"));
  const TrialOutcome first = runner.run_trial(0.1744, 20.0);
  EXPECT_EQ(first.status, TrialStatus::kFailed);  // a blank actor cannot balance
  EXPECT_GT(std::abs(first.final_theta), config.number("trial.failure_angle"));
  EXPECT_EQ(first.steps, runner.telemetry().num_samples());
  const Vector learnt = controller.actor->weights(runner.context());
  EXPECT_GT(learnt.norm(), 0.0);
  controller.start_trial(runner.context(), 0.1);
  EXPECT_EQ(controller.actor->weights(runner.context()), learnt);
  EXPECT_EQ(runner.context().time(), 0.0);
  EXPECT_EQ(
      controller.diagram->eval_output(runner.context(), *controller.telemetry)[kTelemetryThetaB],
      0.1);
}

TEST(TrialRunner, ATrialReachingItsDurationSucceeds) {
  const config::Config config = quick_config();
  const auto controller = build_controller_diagram("pd_only", config);
  TrialRunner runner(controller, 1, config.number("trial.period"));
  const TrialOutcome outcome = runner.run_trial(0.1744, 2.0);
  EXPECT_EQ(outcome.status, TrialStatus::kSuccess);
  EXPECT_EQ(outcome.steps, 200);  // ticks at 0, 0.01, ..., 1.99
}

TEST(Experiments, Exp1CountsFailuresBeforeTheFirstSuccess) {
  config::Config config = quick_config();
  config.set("arms=[cbbg, bg_only]");
  ExperimentOptions two_threads;
  two_threads.jobs = 2;
  const ExperimentResults results = run_experiment(config, two_threads);
  ASSERT_EQ(results.runs.size(), 4u);
  EXPECT_EQ(results.seeds, (std::vector<long long>{1, 2}));
  for (const SeedRun& run : results.runs) {
    ASSERT_FALSE(run.trials.empty());
    EXPECT_TRUE(run.succeeded);
    EXPECT_EQ(run.trials.back().outcome.status, TrialStatus::kSuccess);
    EXPECT_EQ(run.failures_before_success, static_cast<int>(run.trials.size()) - 1);
    EXPECT_EQ(run.evaluation.size(), config.numbers("evaluation.angles").size());
  }
  EXPECT_EQ(results.run(0, 0).arm, "cbbg");
  EXPECT_EQ(results.run(1, 1).arm, "bg_only");
  EXPECT_EQ(results.run(1, 1).seed, 2);
}

TEST(Experiments, ASeedThatNeverSucceedsCountsAllItsTrials) {
  config::Config config = quick_config();
  config.set("experiment=bg_only");
  config.set("seeds=1");
  config.set("max_trials=3");
  config.set("trial.failure_angle=0.1");  // below theta0: every trial fails at once
  const ExperimentResults results = run_experiment(config);
  ASSERT_EQ(results.runs.size(), 1u);
  EXPECT_FALSE(results.runs[0].succeeded);
  EXPECT_EQ(results.runs[0].failures_before_success, 3);
  EXPECT_EQ(results.runs[0].trials.size(), 3u);
  EXPECT_THAT(summary_json(results, config), HasSubstr("\"succeeded\": [false]"));
}

TEST(Experiments, ADivergingTrialIsRecordedAndTheRunGoesOn) {
  config::Config config = quick_config();
  config.set("experiment=bg_only");
  config.set("seeds=1");
  config.set("max_trials=3");
  config.set("critic.beta=1e300");  // the critic's weights overflow within a few ticks
  const ExperimentResults results = run_experiment(config);
  const auto& trials = results.runs.at(0).trials;
  ASSERT_EQ(trials.size(), 3u);
  for (const TrialRecord& record : trials) {
    EXPECT_EQ(record.outcome.status, TrialStatus::kDiverged) << "trial " << record.trial;
    EXPECT_THAT(record.outcome.message,
                HasSubstr("'bg_only/critic': discrete state became non-finite"));
  }
  EXPECT_FALSE(results.runs[0].succeeded);
  EXPECT_THAT(trials_csv(results), HasSubstr("bg_only,1,3,1,1,"));
  EXPECT_THAT(trials_csv(results), HasSubstr(",nan,diverged\n"));
}

TEST(Experiments, Exp2AnnealsK1TrialByTrial) {
  config::Config config = quick_config();
  config.set("experiment=exp2");
  config.set("seeds=1");
  config.set("exp2.trials=12");
  config.set("trial.duration=1");
  const ExperimentResults results = run_experiment(config);
  ASSERT_EQ(results.runs.size(), 1u);
  const auto& trials = results.runs[0].trials;
  ASSERT_EQ(trials.size(), 12u);
  EXPECT_EQ(trials[0].k1, 10.0);
  EXPECT_EQ(trials[9].k1, 10.0);  // trial 10
  EXPECT_EQ(trials[10].k1, 5.0);  // trial 11
  // T = k1 / (1 + exp(k2 V)) <= k1: the schedule shows in the mean temperature.
  EXPECT_LE(trials[10].outcome.mean_temperature, 5.0);
  EXPECT_GT(trials[9].outcome.mean_temperature, 5.0 * 0.5);
}

TEST(ResultsWriter, TrialsCsvHasOneRowPerTrial) {
  ExperimentResults results;
  results.experiment = "exp1";
  results.arms = {"cbbg"};
  results.seeds = {7};
  SeedRun run;
  run.arm = "cbbg";
  run.seed = 7;
  TrialOutcome failed{TrialStatus::kFailed, 53, 5.5, 2.75, 0.53, ""};
  TrialOutcome diverged{TrialStatus::kDiverged, 10, 1.0, 0.0, std::nan(""), "boom"};
  run.trials = {{1, 10.0, failed}, {2, 10.0, diverged}};
  results.runs = {run};
  EXPECT_EQ(trials_csv(results),
            "arm,seed,trial,failed,steps,mean_temperature,mean_entropy,final_theta,status\n"
            "cbbg,7,1,1,53,5.5,2.75,0.53,failed\n"
            "cbbg,7,2,1,10,1,0,nan,diverged\n");
}

}  // namespace
}  // namespace cbbg::diagrams
