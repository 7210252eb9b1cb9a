// The Gymnasium-shaped environment: a rollout that plays the supervisor's action is the
// pd_only preset's trial tick for tick; a seed decides an episode; an episode ends
// terminated when the robot falls and truncated at trial.duration, and says so when stepped
// after; a user's own plant runs through it.

#include "cbbg/environment/balance_environment.h"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/telemetry.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/block_context.h"
#include "tests/support/pendulum_robot.h"

namespace cbbg::environment {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// The run's parameters with `settings` ("key=value"), checked as a run's are.
parameters::Parameters parameters_with(const std::vector<std::string>& settings) {
  config::Config config;
  for (const std::string& setting : settings) config.set(setting);
  return diagrams::validated_parameters(config);
}

// The analytic plant keeps these tests quick.
parameters::Parameters analytic(std::vector<std::string> settings = {}) {
  settings.insert(settings.begin(), "plant.kind=analytic");
  return parameters_with(settings);
}

// Some noise on every signal the PD law reads, so the seed decides the episode.
constexpr const char* kNoisySensors = "sensors.noise_std=[0.002, 0.01, 0.001, 0.001, 0.01, 0.01]";

struct Rollout {
  std::vector<Vector> observations;  // y_0 (reset's), y_1, ...
  std::vector<double> rewards;       // r_0, r_1, ... (step k's)
  bool terminated = false;
  bool truncated = false;
  double end_time = 0.0;
};

// One episode in which every action is the supervisor's on the observation.
Rollout supervisor_rollout(BalanceEnvironment& env, std::optional<std::uint64_t> seed,
                           std::optional<double> initial_pitch = std::nullopt) {
  Rollout rollout;
  ResetResult start = env.reset(seed, initial_pitch);
  rollout.observations.push_back(start.observation);
  // Unsaturated, as the pd_only controller gives it: a user's plant may saturate elsewhere.
  double action = start.info.unsaturated_supervisor_action;
  for (;;) {
    const StepResult step = env.step(action);
    rollout.observations.push_back(step.observation);
    rollout.rewards.push_back(step.reward);
    action = step.info.unsaturated_supervisor_action;
    if (step.terminated || step.truncated) {
      rollout.terminated = step.terminated;
      rollout.truncated = step.truncated;
      rollout.end_time = step.info.time;
      return rollout;
    }
  }
}

// The observations of a rollout, back to back, to compare bytes.
std::vector<double> flattened(const Rollout& rollout) {
  std::vector<double> values;
  for (const Vector& y : rollout.observations) values.insert(values.end(), y.begin(), y.end());
  return values;
}

// The telemetry of one trial of the pd_only preset, one row per tick.
std::vector<Vector> pd_only_trial(const parameters::Parameters& p, std::uint64_t seed,
                                  const diagrams::ClosedLoopOptions& options = {}) {
  const diagrams::ClosedLoop loop = diagrams::build_preset("pd_only", p, options);
  experiments::TrialRunner runner(loop, seed, p.trial.period);
  runner.run_trial(p.trial.theta0, p.trial.duration);
  std::vector<Vector> ticks;
  for (int k = 0; k < runner.telemetry().num_samples(); ++k) {
    ticks.emplace_back(runner.telemetry().sample(k));
  }
  return ticks;
}

// The rollout's observations and rewards are the trial's at every tick it has: y_k at tick k,
// and step k's reward is what the learner receives at tick k + 1.
void expect_same_as_trial(const Rollout& rollout, const std::vector<Vector>& trial) {
  ASSERT_TRUE(rollout.truncated);
  // The trial has ticks t_0 .. t_{N-1}; the episode's last observation is at trial.duration.
  ASSERT_EQ(rollout.observations.size(), trial.size() + 1);
  for (std::size_t k = 0; k < trial.size(); ++k) {
    EXPECT_NEAR(rollout.observations[k][blocks::kMeasuredThetaB],
                trial[k][diagrams::kTelemetryThetaB], 1e-12)
        << "tick " << k;
    if (k > 0) {
      EXPECT_EQ(rollout.rewards[k - 1], trial[k][diagrams::kTelemetryReward]) << "tick " << k;
    }
  }
}

TEST(BalanceEnvironment, PlayingTheSupervisorIsThePdOnlyPresetsTrial) {
  for (const char* kind : {"pd", "lqr"}) {
    const parameters::Parameters p = analytic({std::string("supervisor.kind=") + kind});
    BalanceEnvironment env(p);
    const Rollout rollout = supervisor_rollout(env, 3);
    expect_same_as_trial(rollout, pd_only_trial(p, 3));
    EXPECT_DOUBLE_EQ(rollout.end_time, p.trial.duration) << kind;
  }
}

TEST(BalanceEnvironment, TheObservationIsWhatTheSensorsMeasureNoiseIncluded) {
  const parameters::Parameters p = analytic({kNoisySensors});
  BalanceEnvironment env(p);
  const Rollout rollout = supervisor_rollout(env, 11);
  expect_same_as_trial(rollout, pd_only_trial(p, 11));
  // Not the true pitch: the noise is in the observation, not in info.state.
  const ResetResult start = env.reset(11);
  EXPECT_NE(start.observation[blocks::kMeasuredThetaB], p.trial.theta0);
  EXPECT_EQ(start.info.state[0], p.trial.theta0);
}

TEST(BalanceEnvironment, PlayingTheSupervisorOnTheSimbodyPlantIsThePresetsTrialToo) {
  const parameters::Parameters p = parameters_with({"plant.kind=simbody", "trial.duration=5"});
  BalanceEnvironment env(p);
  expect_same_as_trial(supervisor_rollout(env, 1), pd_only_trial(p, 1));
}

TEST(BalanceEnvironment, TheSameSeedGivesTheSameEpisode) {
  const parameters::Parameters p = analytic({kNoisySensors, "trial.duration=1"});
  BalanceEnvironment env(p);
  const std::vector<double> first = flattened(supervisor_rollout(env, 5));
  const std::vector<double> other = flattened(supervisor_rollout(env, 6));
  EXPECT_NE(first, other);
  EXPECT_EQ(flattened(supervisor_rollout(env, 5)), first);  // after another episode
  BalanceEnvironment fresh(p);
  EXPECT_EQ(flattened(supervisor_rollout(fresh, 5)), first);
  // Without a seed the streams carry on: not seed 5's episode again.
  EXPECT_NE(flattened(supervisor_rollout(fresh, std::nullopt)), first);
  // The first episode without a seed is the run's root seed's (the key `seed`).
  BalanceEnvironment unseeded(p);
  EXPECT_EQ(flattened(supervisor_rollout(unseeded, std::nullopt)),
            flattened(supervisor_rollout(fresh, static_cast<std::uint64_t>(p.run.seed))));
}

TEST(BalanceEnvironment, AMovedEnvironmentCarriesOnItsEpisode) {
  const parameters::Parameters p = analytic({"trial.duration=0.5"});
  BalanceEnvironment reference(p);
  const Rollout whole = supervisor_rollout(reference, 2);
  BalanceEnvironment env(p);
  const ResetResult start = env.reset(2);
  BalanceEnvironment moved(std::move(env));
  const StepResult step = moved.step(start.info.supervisor_action);
  EXPECT_EQ(step.observation, whole.observations[1]);
}

TEST(BalanceEnvironment, TheRewardIsTheTransitionsFromTheSlidingSurface) {
  const parameters::Parameters p = analytic({"trial.duration=3"});
  BalanceEnvironment env(p);
  const Rollout rollout = supervisor_rollout(env, 1);
  auto surface = [&p](const Vector& y) {
    return p.reward.a1 * y[blocks::kMeasuredThetaB] + p.reward.a2 * y[blocks::kMeasuredThetaBDot];
  };
  int grew = 0;
  for (std::size_t k = 0; k < rollout.rewards.size(); ++k) {
    const double before = surface(rollout.observations[k]);
    const double after = surface(rollout.observations[k + 1]);
    EXPECT_EQ(rollout.rewards[k], after * after <= before * before ? 0.0 : -1.0) << k;
    grew += rollout.rewards[k] < 0.0 ? 1 : 0;
  }
  EXPECT_GT(grew, 0);  // both rewards occur
  EXPECT_LT(grew, static_cast<int>(rollout.rewards.size()));
}

TEST(BalanceEnvironment, TerminatedWhenTheRobotFalls) {
  const parameters::Parameters p = analytic();
  BalanceEnvironment env(p);
  env.reset(std::nullopt, 0.1);
  StepResult step;
  int steps = 0;
  do {
    step = env.step(0.0);
    ++steps;
  } while (!step.terminated && !step.truncated);
  EXPECT_TRUE(step.terminated);
  EXPECT_FALSE(step.truncated);
  EXPECT_EQ(step.reward, -1.0);
  EXPECT_GT(std::abs(step.observation[blocks::kMeasuredThetaB]), p.trial.failure_angle);
  EXPECT_THAT(step.info.failure_reason, HasSubstr("exceeded trial.failure_angle = 0.5236 rad"));
  EXPECT_DOUBLE_EQ(step.info.time, steps * p.trial.period);
  EXPECT_LT(step.info.time, p.trial.duration);
  EXPECT_THAT([&] { env.step(0.0); },
              ThrowsMessage<std::logic_error>(
                  "step: the episode has ended (terminated or truncated); call reset() to start "
                  "another"));
  // reset starts another.
  EXPECT_EQ(env.reset(std::nullopt, 0.1).info.time, 0.0);
  EXPECT_FALSE(env.step(0.0).terminated);
}

TEST(BalanceEnvironment, TruncatedAtTheTrialsDuration) {
  BalanceEnvironment env(analytic({"trial.duration=0.05"}));
  ResetResult start = env.reset(1);
  double action = start.info.supervisor_action;
  for (int k = 1; k <= 5; ++k) {
    const StepResult step = env.step(action);
    action = step.info.supervisor_action;
    EXPECT_FALSE(step.terminated);
    EXPECT_EQ(step.truncated, k == 5) << k;
    EXPECT_DOUBLE_EQ(step.info.time, 0.01 * k);
    EXPECT_TRUE(step.info.failure_reason.empty());
  }
  EXPECT_THAT([&] { env.step(action); },
              ThrowsMessage<std::logic_error>(HasSubstr("call reset() to start another")));
}

TEST(BalanceEnvironment, ALastPeriodShorterThanTheOthersEndsAtTheDuration) {
  BalanceEnvironment env(analytic({"trial.duration=0.035"}));
  env.reset();
  for (int k = 1; k <= 3; ++k) EXPECT_FALSE(env.step(0.0).truncated);
  const StepResult last = env.step(0.0);
  EXPECT_TRUE(last.truncated);
  EXPECT_EQ(last.info.time, 0.035);
}

TEST(BalanceEnvironment, StepAsksForAFiniteActionAfterAReset) {
  BalanceEnvironment env(analytic());
  EXPECT_THAT([&] { env.step(0.0); },
              ThrowsMessage<std::logic_error>("step: no episode has started; call reset() first"));
  env.reset();
  EXPECT_THAT([&] { env.step(std::numeric_limits<double>::quiet_NaN()); },
              ThrowsMessage<std::invalid_argument>(
                  "step: the action must be a finite torque in N m; got nan"));
  EXPECT_THAT([&] { env.step(-std::numeric_limits<double>::infinity()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("got -inf")));
  // A refused action changes nothing: the episode goes on from t = 0.
  EXPECT_DOUBLE_EQ(env.step(0.0).info.time, 0.01);
}

TEST(BalanceEnvironment, ResetRefusesAnInitialPitchOutsideTheFailureAngle) {
  BalanceEnvironment env(analytic());
  EXPECT_THAT([&] { env.reset(std::nullopt, 0.6); },
              ThrowsMessage<std::invalid_argument>(
                  "reset: the initial pitch must be finite and strictly inside "
                  "+-trial.failure_angle (0.5236 rad); got 0.6"));
  EXPECT_THROW(env.reset(std::nullopt, std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
  EXPECT_EQ(env.reset(std::nullopt, -0.2).observation[blocks::kMeasuredThetaB], -0.2);
}

TEST(BalanceEnvironment, AnObservationBeyondTheAngleAtResetEndsTheFirstStepBeforeItActs) {
  // Noise of 1 rad on the pitch: some seed measures the robot beyond the angle at t = 0.
  BalanceEnvironment env(analytic({"sensors.noise_std=[1, 0, 0, 0, 0, 0]", "trial.theta0=0.1"}));
  ResetResult start;
  std::uint64_t seed = 1;
  for (;; ++seed) {
    start = env.reset(seed);
    if (std::abs(start.observation[blocks::kMeasuredThetaB]) > 0.5236) break;
  }
  const StepResult step = env.step(1.0);
  EXPECT_TRUE(step.terminated);
  EXPECT_EQ(step.reward, -1.0);
  EXPECT_EQ(step.observation, start.observation);
  EXPECT_EQ(step.info.time, 0.0);
  EXPECT_EQ(step.info.failure_reason, "|theta_b| exceeded trial.failure_angle");
  EXPECT_THROW(env.step(0.0), std::logic_error);
}

// Every observation lies in the observation space, a terminated episode's last one too.
TEST(BalanceEnvironment, TheObservationSpaceIsUnboundedAndTheActionSpaceTheTorqueLimit) {
  const BalanceEnvironment env(analytic({"plant.torque_limit=3", "trial.period=0.02"}));
  const Vector high = Vector::Constant(6, std::numeric_limits<double>::infinity());
  EXPECT_EQ(env.observation_high(), high);
  EXPECT_EQ(env.observation_low(), -high);
  EXPECT_EQ(env.failure_angle(), 0.5236);
  EXPECT_EQ(env.action_low(), -3.0);
  EXPECT_EQ(env.action_high(), 3.0);
  EXPECT_EQ(env.period(), 0.02);
  EXPECT_EQ(env.duration(), 20.0);
  EXPECT_EQ(env.signal_names(), plant::two_wheeler_signals());
}

using cbbg::testing::PendulumRobot;

const diagrams::PlantFactory kPendulum = [](const std::string& name,
                                            const parameters::Parameters&) {
  return std::make_unique<PendulumRobot>(name);
};

TEST(BalanceEnvironment, AUsersOwnPlantRunsThroughTheOptions) {
  const parameters::Parameters p = analytic({"trial.duration=1"});
  BalanceEnvironment env(p, {.plant = kPendulum});
  const std::vector<std::string> names{"wheel", "pitch", "wheel_rate", "pitch_rate"};
  EXPECT_EQ(env.signal_names(), names);
  const ResetResult start = env.reset(1, 0.1);
  EXPECT_EQ(start.info.signal_names, names);
  EXPECT_EQ(start.info.state, (Vector(4) << 0.0, 0.1, 0.0, 0.0).finished());
  // Its one wheel is measured for both sides.
  EXPECT_EQ(start.observation, (Vector(6) << 0.1, 0.0, 0.0, 0.0, 0.0, 0.0).finished());
  expect_same_as_trial(supervisor_rollout(env, 1), pd_only_trial(p, 1, {.plant = kPendulum}));
  // Left alone it falls.
  env.reset(1, 0.1);
  StepResult step;
  do {
    step = env.step(0.0);
  } while (!step.terminated && !step.truncated);
  EXPECT_TRUE(step.terminated);
  EXPECT_GT(step.info.state[1], 0.5236);
}

TEST(BalanceEnvironment, TheSupervisorsActionIsSaturatedAtTheActionSpace) {
  BalanceEnvironment env(analytic());
  const Info info = env.reset(1, 0.4).info;
  EXPECT_EQ(info.supervisor_action, 5.0);
  EXPECT_EQ(info.unsaturated_supervisor_action, 20.0);  // 50 x 0.4, the robot at rest
  EXPECT_EQ(env.reset(1, -0.4).info.supervisor_action, -5.0);
}

TEST(BalanceEnvironment, TheResetDistributionDrawsFromTheSeed) {
  BalanceEnvironment fixed(analytic());
  EXPECT_EQ(fixed.reset(1).info.state[0], fixed.parameters().trial.theta0);
  BalanceEnvironment spread(analytic(),
                            EnvironmentOptions{.initial_pitch = InitialPitch{-0.2, 0.2}});
  const double first = spread.reset(7).info.state[0];
  EXPECT_NE(spread.reset(8).info.state[0], first);
  EXPECT_EQ(spread.reset(7).info.state[0], first);
  EXPECT_LE(std::abs(first), 0.2);
  EXPECT_THAT(
      [] {
        BalanceEnvironment(analytic(), {.initial_pitch = InitialPitch{0.3, -0.3}});
      },
      ThrowsMessage<std::invalid_argument>(
          "the initial pitch range must have low <= high; got [0.3, -0.3]"));
}

TEST(BalanceEnvironment, StepIntoIsStepWithoutTheInfo) {
  BalanceEnvironment env(analytic({"trial.duration=0.05"})),
      lean(analytic({"trial.duration=0.05"}));
  env.reset(3);
  double observation[6];
  lean.reset_into(3, std::nullopt, observation);
  for (int k = 0; k < 5; ++k) {
    const StepResult step = env.step(0.5);
    const StepFlags flags = lean.step_into(0.5, observation);
    EXPECT_EQ(Vector(Eigen::Map<const Vector>(observation, 6)), step.observation);
    EXPECT_EQ(flags.reward, step.reward);
    EXPECT_EQ(flags.truncated, step.truncated);
    EXPECT_EQ(lean.supervisor_action(), step.info.supervisor_action);
  }
  EXPECT_THROW(lean.step_into(0.0, observation), std::logic_error);  // truncated at 0.05 s
}

}  // namespace
}  // namespace cbbg::environment
