// The diagram wiring test: every preset, run by the TrialRunner, must give the same
// doubles, tick by tick, as docs/model.md §2 written as one plain loop (plain_loop.h) for the
// same root seed. Any wiring slip (a wrong port, a signal a tick late, an update reading a
// post-update value, a sampler on another stream) shows as a first differing signal.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/trial_runner.h"
#include "tests/diagrams/plain_loop.h"

namespace cbbg::tests {
namespace {

using diagrams::TelemetryIndex;

// Each telemetry signal, with its field in the plain loop's tick.
struct Signal {
  const char* name;
  TelemetryIndex index;
  double PlainLoopTick::*field;
};

constexpr std::array<Signal, diagrams::kTelemetrySize> kSignals = {{
    {"theta_b", diagrams::kTelemetryThetaB, &PlainLoopTick::theta_b},
    {"theta_b_dot", diagrams::kTelemetryThetaBDot, &PlainLoopTick::theta_b_dot},
    {"phi_left", diagrams::kTelemetryPhiLeft, &PlainLoopTick::phi_left},
    {"phi_right", diagrams::kTelemetryPhiRight, &PlainLoopTick::phi_right},
    {"phi_left_dot", diagrams::kTelemetryPhiLeftDot, &PlainLoopTick::phi_left_dot},
    {"phi_right_dot", diagrams::kTelemetryPhiRightDot, &PlainLoopTick::phi_right_dot},
    {"supervisor_action", diagrams::kTelemetrySupervisorAction, &PlainLoopTick::supervisor_action},
    {"actor_action", diagrams::kTelemetryActorAction, &PlainLoopTick::actor_action},
    {"exploration_action", diagrams::kTelemetryExplorationAction,
     &PlainLoopTick::exploration_action},
    {"action", diagrams::kTelemetryAction, &PlainLoopTick::action},
    {"omega", diagrams::kTelemetryOmega, &PlainLoopTick::omega},
    {"value", diagrams::kTelemetryValue, &PlainLoopTick::value},
    {"td_error", diagrams::kTelemetryTdError, &PlainLoopTick::td_error},
    {"temperature", diagrams::kTelemetryTemperature, &PlainLoopTick::temperature},
    {"reward", diagrams::kTelemetryReward, &PlainLoopTick::reward},
    {"entropy", diagrams::kTelemetryEntropy, &PlainLoopTick::entropy},
    {"x", diagrams::kTelemetryX, &PlainLoopTick::x},
    {"y", diagrams::kTelemetryY, &PlainLoopTick::y},
    {"yaw", diagrams::kTelemetryYaw, &PlainLoopTick::yaw},
}};

std::string exact(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

const char* to_string(PlainLoopStatus status) {
  switch (status) {
    case PlainLoopStatus::kSuccess:
      return "success";
    case PlainLoopStatus::kFailed:
      return "failed";
    case PlainLoopStatus::kDiverged:
      return "diverged";
  }
  return "unknown";
}

// Success when the diagram's trial and the loop's have the same outcome, the same number
// of ticks and equal doubles (operator==, as EXPECT_EQ compares, or both NaN: a signal the
// preset does not have) in every signal at every tick; otherwise names the first differing signal
// and tick with both values.
testing::AssertionResult SameTrial(const experiments::TrialOutcome& diagram_outcome,
                                   const SignalLog& telemetry, const PlainLoopOutcome& loop_outcome,
                                   const std::vector<PlainLoopTick>& loop_ticks) {
  const int ticks = telemetry.num_samples();
  for (int k = 0; k < ticks && static_cast<size_t>(k) < loop_ticks.size(); ++k) {
    const auto sample = telemetry.sample(k);
    for (const Signal& signal : kSignals) {
      const double from_diagram = sample[signal.index];
      const double from_loop = loop_ticks[static_cast<size_t>(k)].*signal.field;
      if (!(from_diagram == from_loop) && !(std::isnan(from_diagram) && std::isnan(from_loop))) {
        return testing::AssertionFailure()
               << signal.name << " differs at tick " << k << ": diagram " << exact(from_diagram)
               << ", plain loop " << exact(from_loop);
      }
    }
  }
  if (static_cast<size_t>(ticks) != loop_ticks.size() ||
      diagram_outcome.steps != loop_outcome.steps) {
    return testing::AssertionFailure()
           << "the diagram ran " << ticks << " ticks (outcome: " << diagram_outcome.steps
           << "), the plain loop " << loop_ticks.size() << " (outcome: " << loop_outcome.steps
           << ")";
  }
  if (std::string(experiments::to_string(diagram_outcome.status)) !=
      to_string(loop_outcome.status)) {
    return testing::AssertionFailure()
           << "the diagram's trial ended " << experiments::to_string(diagram_outcome.status)
           << ", the plain loop's " << to_string(loop_outcome.status);
  }
  if (!(diagram_outcome.final_theta == loop_outcome.final_theta)) {
    return testing::AssertionFailure()
           << "final theta_b differs: diagram " << exact(diagram_outcome.final_theta)
           << ", plain loop " << exact(loop_outcome.final_theta);
  }
  return testing::AssertionSuccess();
}

testing::AssertionResult SameWeights(const char* name, ConstVectorView diagram,
                                     const Eigen::VectorXd& loop) {
  for (Eigen::Index i = 0; i < loop.size(); ++i) {
    if (!(diagram[i] == loop[i])) {
      return testing::AssertionFailure() << name << "[" << i << "] differs: diagram "
                                         << exact(diagram[i]) << ", plain loop " << exact(loop[i]);
    }
  }
  return testing::AssertionSuccess();
}

config::Config analytic_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  return config;
}

// The diagram's trial outcomes, and whether every trial matched the plain loop's.
struct BothRuns {
  std::vector<experiments::TrialOutcome> outcomes;
  testing::AssertionResult all_match = testing::AssertionSuccess();
};

// Learnt weights to start from: the critic's and the actor's.
struct StartWeights {
  Eigen::VectorXd critic;
  Eigen::VectorXd actor;
};

// Runs one trial from each of `theta0s` in turn with preset `arm` under `config` and root
// seed `seed`, and with the plain loop under `loop_config` and `loop_seed`, both from
// `start` where given, the diagram on the simulator's `schedule`; stops at the first trial
// whose ticks, outcome or learnt weights differ and says where.
BothRuns run_both(const std::string& arm, const config::Config& config,
                  const config::Config& loop_config, std::uint64_t seed, std::uint64_t loop_seed,
                  const std::vector<double>& theta0s,
                  const std::optional<StartWeights>& start = std::nullopt,
                  Schedule schedule = Schedule::kCompiled) {
  diagrams::ClosedLoop controller =
      diagrams::build_preset(arm, parameters::read_parameters(config));
  controller.schedule = schedule;
  experiments::TrialRunner runner(controller, seed, config.number("trial.period"));
  PlainLoop loop(loop_config, loop_seed, arm);
  if (start) {
    controller.learner.critic->mutable_learnt(runner.context(), "weights") = start->critic;
    controller.learner.actor->mutable_learnt(runner.context(), "weights") = start->actor;
    loop.set_weights(start->critic, start->actor);
  }
  const double duration = config.number("trial.duration");
  BothRuns run;
  for (size_t trial = 0; trial < theta0s.size(); ++trial) {
    run.outcomes.push_back(runner.run_trial(theta0s[trial], duration));
    const PlainLoopOutcome loop_outcome = loop.run_trial(theta0s[trial], duration);
    testing::AssertionResult same =
        SameTrial(run.outcomes.back(), runner.telemetry(), loop_outcome, loop.ticks());
    if (same && controller.learner.learns()) {
      same = SameWeights("w", controller.learner.critic->learnt(runner.context(), "weights"),
                         loop.critic_weights());
    }
    if (same && controller.learner.learns()) {
      same = SameWeights("theta", controller.learner.actor->learnt(runner.context(), "weights"),
                         loop.actor_weights());
    }
    if (!same) {
      run.all_match = testing::AssertionFailure() << arm << ", seed " << seed << ", trial "
                                                  << trial + 1 << ": " << same.message();
      return run;
    }
  }
  return run;
}

TEST(PlainLoopEquivalence, CbbgTrialMatchesTheDiagramBitForBitForThreeSeeds) {
  const config::Config config = analytic_config();
  const double theta0 = config.number("trial.theta0");
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const BothRuns run = run_both("cbbg", config, config, seed, seed, {theta0});
    EXPECT_TRUE(run.all_match);
    ASSERT_EQ(run.outcomes.size(), 1u);
    // A whole trial: the 20 s of a success (2000 ticks at 10 ms) or up to a failure.
    const auto& outcome = run.outcomes.front();
    if (outcome.status == experiments::TrialStatus::kSuccess) {
      EXPECT_EQ(outcome.steps, 2000) << "seed " << seed;
    } else {
      EXPECT_EQ(outcome.status, experiments::TrialStatus::kFailed) << "seed " << seed;
      EXPECT_GT(std::abs(outcome.final_theta), config.number("trial.failure_angle"));
    }
  }
}

TEST(PlainLoopEquivalence, ConsecutiveCbbgTrialsMatchAsWeightsAndOmegaCarryOver) {
  // Weights, the omega counter and the sampler's stream carry over; the trace, the previous
  // tick, the plant and the integrator's step size reset. With this seed trial 1 succeeds under
  // the supervisor and the next ones, with omega near 1 after 2000 ticks, fail: both
  // endings, and a reset after each, are exercised.
  const config::Config config = analytic_config();
  const double theta0 = config.number("trial.theta0");
  const BothRuns run = run_both("cbbg", config, config, 7, 7, {theta0, theta0, theta0, theta0});
  EXPECT_TRUE(run.all_match);
  ASSERT_EQ(run.outcomes.size(), 4u);
  EXPECT_EQ(run.outcomes[0].status, experiments::TrialStatus::kSuccess);
  EXPECT_EQ(run.outcomes[1].status, experiments::TrialStatus::kFailed);
}

TEST(PlainLoopEquivalence, TheInterpretedScheduleMatchesTooThroughSuccessAndFailures) {
  // The schedule the compiled one replaced, kept selectable: the same doubles, tick by tick.
  const config::Config config = analytic_config();
  const double theta0 = config.number("trial.theta0");
  const BothRuns run = run_both("cbbg", config, config, 7, 7, {theta0, theta0, theta0},
                                std::nullopt, Schedule::kInterpreted);
  EXPECT_TRUE(run.all_match);
  ASSERT_EQ(run.outcomes.size(), 3u);
  EXPECT_EQ(run.outcomes[0].status, experiments::TrialStatus::kSuccess);
  EXPECT_EQ(run.outcomes[1].status, experiments::TrialStatus::kFailed);
}

TEST(PlainLoopEquivalence, BgOnlyTrialsMatchTheDiagramThroughFailures) {
  // The basal ganglia alone (omega = 1, no supervisor) fails its first trials.
  const config::Config config = analytic_config();
  const double theta0 = config.number("trial.theta0");
  const BothRuns run = run_both("bg_only", config, config, 3, 3, {theta0, theta0, theta0});
  EXPECT_TRUE(run.all_match);
  ASSERT_EQ(run.outcomes.size(), 3u);
  EXPECT_EQ(run.outcomes[0].status, experiments::TrialStatus::kFailed);
}

TEST(PlainLoopEquivalence, WeightedRuleAndCbOnlyMatchTheDiagram) {
  const config::Config config = analytic_config();
  const double theta0 = config.number("trial.theta0");
  for (const char* arm : {"cbbg_weighted", "cb_only"}) {
    const BothRuns run = run_both(arm, config, config, 5, 5, {theta0, theta0});
    EXPECT_TRUE(run.all_match);
    EXPECT_EQ(run.outcomes.size(), 2u);
  }
}

TEST(PlainLoopEquivalence, PdOnlyMatchesTheDiagram) {
  const config::Config config = analytic_config();
  const BothRuns run = run_both("pd_only", config, config, 1, 1, {0.1744, 0.3});
  EXPECT_TRUE(run.all_match);
  ASSERT_EQ(run.outcomes.size(), 2u);
  EXPECT_EQ(run.outcomes[0].status, experiments::TrialStatus::kSuccess);
}

TEST(PlainLoopEquivalence, TheLearntActorMatchesTheDiagramAndKeepsItsWeights) {
  // Weights learnt by bg_only over a few trials, then the learnt actor alone from them.
  const config::Config config = analytic_config();
  PlainLoop learner(config, 3, "bg_only");
  for (int trial = 0; trial < 6; ++trial) learner.run_trial(0.1744, 20.0);
  const StartWeights learnt{learner.critic_weights(), learner.actor_weights()};
  ASSERT_GT(learnt.actor.norm(), 0.0);
  const BothRuns run = run_both("learnt_actor", config, config, 1, 1, {0.05, 0.1744}, learnt);
  EXPECT_TRUE(run.all_match);
  EXPECT_EQ(run.outcomes.size(), 2u);
  PlainLoop alone(config, 1, "learnt_actor");
  alone.set_weights(learnt.critic, learnt.actor);
  alone.run_trial(0.1, 20.0);
  EXPECT_EQ(alone.actor_weights(), learnt.actor);  // frozen
  EXPECT_EQ(alone.critic_weights(), learnt.critic);
}

TEST(PlainLoopEquivalence, DetectsAnotherSamplerStream) {
  // Another root seed gives the sampler another normal draw at the first tick: the first
  // signal to differ is a_E at tick 0 (the features, values, a_S and a_A agree there).
  const config::Config config = analytic_config();
  const BothRuns run = run_both("cbbg", config, config, 1, 2, {config.number("trial.theta0")});
  EXPECT_FALSE(run.all_match);
  EXPECT_THAT(run.all_match.message(), testing::HasSubstr("exploration_action differs at tick 0"));
}

TEST(PlainLoopEquivalence, DetectsAOneUlpChangeOfTheCriticRate) {
  // The critic learns from tick 1 on; one ulp more beta changes w, so V differs first.
  const config::Config config = analytic_config();
  config::Config perturbed = config;
  perturbed.set("critic.beta=" + exact(std::nextafter(config.number("critic.beta"), 1.0)));
  ASSERT_NE(perturbed.number("critic.beta"), config.number("critic.beta"));
  const BothRuns run = run_both("cbbg", config, perturbed, 1, 1, {config.number("trial.theta0")});
  EXPECT_FALSE(run.all_match);
  EXPECT_THAT(run.all_match.message(), testing::HasSubstr("value differs at tick"));
}

TEST(PlainLoop, RejectsWhatItDoesNotWriteOut) {
  const config::Config config = analytic_config();
  EXPECT_THAT([&] { PlainLoop loop(config, 1, "cbbg_fast"); },
              testing::ThrowsMessage<std::invalid_argument>(testing::HasSubstr(
                  "the arm must be cbbg, cbbg_weighted, bg_only, cb_only, pd_only or "
                  "learnt_actor; got 'cbbg_fast'")));
  config::Config noisy = config;
  noisy.set("sensors.noise_std=[0, 0.01, 0, 0, 0, 0]");
  EXPECT_THAT([&] { PlainLoop loop(noisy, 1); },
              testing::ThrowsMessage<std::invalid_argument>(
                  testing::HasSubstr("sensors.noise_std must be all 0")));
  config::Config lqr = config;
  lqr.set("supervisor.kind=lqr");
  EXPECT_THAT([&] { PlainLoop loop(lqr, 1); },
              testing::ThrowsMessage<std::invalid_argument>(
                  testing::HasSubstr("supervisor.kind must be pd; got 'lqr'")));
}

}  // namespace
}  // namespace cbbg::tests
