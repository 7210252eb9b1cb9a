// Plant kinds: the built-in two, and a user's registered with its own parameters, the change
// of the robot it applies and the linearisation an LQR supervisor designs from.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/training_disturbances.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::diagrams {
namespace {

using ::testing::ThrowsMessage;

// pendulum.*: an inverted pendulum on one wheel, its own parameters.
struct PendulumParams {
  double mass = 1.0;           // kg
  double gravity_term = 24.5;  // theta'' = gravity_term theta - tau / (2 mass)

  template <class Archive>
  void describe(Archive& a) {
    a.number("mass", mass, "pendulum mass, kg", kPositive);
    a.number("gravity_term", gravity_term, "g / l, 1/s^2", kPositive);
  }
};

class Pendulum final : public plant::RobotPlant {
 public:
  Pendulum(std::string name, const PendulumParams& params) : RobotPlant(std::move(name)) {
    const InputPort& torque = declare_input_port("torque", plant::kTorqueSize);
    declare_continuous_state(
        Vector::Zero(4), [&torque, params](const BlockContext& context, VectorRef d) {
          const auto x = context.continuous_state();  // theta, theta', phi, phi'
          const double tau = context.input(torque).sum();
          d << x[1], params.gravity_term * x[0] - tau / (2.0 * params.mass), x[3], tau;
        });
    declare_output_port(
        "state", 4,
        [](const BlockContext& context, VectorRef y) { y = context.continuous_state(); }, {});
  }
  std::vector<std::string> signals() const override {
    return {"pitch", "pitch_rate", "wheel", "wheel_rate"};
  }
  void reset(Context& context, double initial_pitch) const override {
    auto x = context.continuous_state(*this);
    x.setZero();
    x[0] = initial_pitch;
  }
};

PendulumParams pendulum_params(const parameters::Parameters& p) {
  return config::read_section<PendulumParams>(p.own, "pendulum");
}

// x = (theta, phi, theta', phi'), u = the torque on both wheels (2 tau).
plant::LinearModel pendulum_model(const parameters::Parameters& p) {
  const PendulumParams pendulum = pendulum_params(p);
  plant::LinearModel model{Eigen::MatrixXd::Zero(4, 4), Eigen::MatrixXd::Zero(4, 1)};
  model.A(0, 2) = model.A(1, 3) = 1.0;
  model.A(2, 0) = pendulum.gravity_term;
  model.B(2, 0) = -1.0 / pendulum.mass;
  model.B(3, 0) = 2.0;
  return model;
}

// Registered once per process, before any config: pendulum (mass changes; no CoM height) and
// rigid (no change, no linearisation).
void register_kinds() {
  static const bool done = [] {
    config::register_section<PendulumParams>("pendulum");
    register_plant_kind({.name = "pendulum",
                         .description = "an inverted pendulum on one wheel",
                         .make =
                             [](const std::string& name, const parameters::Parameters& p) {
                               return std::make_unique<Pendulum>(name, pendulum_params(p));
                             },
                         .change =
                             [](parameters::Parameters& p, RobotChange change, double factor) {
                               if (change != RobotChange::kBodyMass) return false;
                               std::get<double>(p.own.values.at("pendulum.mass")) *= factor;
                               return true;
                             },
                         .linearize = pendulum_model});
    register_plant_kind({.name = "rigid",
                         .description = "",
                         .make = [](const std::string& name, const parameters::Parameters& p) {
                           return std::make_unique<Pendulum>(name, pendulum_params(p));
                         }});
    return true;
  }();
  (void)done;
}

config::Config config_of(const std::string& kind) {
  register_kinds();
  config::Config config;
  config.set("plant.kind=" + kind);
  config.set("seeds=1");
  config.set("max_trials=2");
  config.set("trial.duration=0.5");
  config.set("evaluation.angles=[0.1]");
  return config;
}

TEST(PlantKinds, TheBuiltInKindsAreThoseThePlantKindKeyDeclares) {
  const std::vector<std::string> declared =
      config::declared_keys(parameters::PlantSection{}, "plant").front().choices;
  std::vector<std::string> kinds;
  for (const PlantKind& kind : plant_kinds()) kinds.push_back(kind.name);
  ASSERT_GE(kinds.size(), 2U);
  EXPECT_EQ(std::vector<std::string>(kinds.begin(), kinds.begin() + 2),
            (std::vector<std::string>{"simbody", "analytic"}));
  EXPECT_EQ(declared, kinds);  // the library's others (mujoco) and the registered ones too
  EXPECT_THAT([] { plant_kind("cartpole"); },
              ThrowsMessage<std::invalid_argument>(
                  ::testing::StartsWith("no plant kind 'cartpole' (there are simbody, analytic")));
}

TEST(PlantKinds, ARegisteredKindIsAPlantKindWordAndBuildsItsPlant) {
  config::Config config = config_of("pendulum");
  config.set("pendulum.mass=2");
  const parameters::Parameters p = validated_parameters(config);
  const ClosedLoop loop = build_preset("pd_only", p);
  EXPECT_NE(dynamic_cast<const Pendulum*>(loop.plant), nullptr);
  EXPECT_THAT([] { register_plant_kind({.name = "pendulum", .make = {}}); },
              ThrowsMessage<std::invalid_argument>("plant kind 'pendulum' is registered twice"));
  EXPECT_THAT([] { register_plant_kind({.name = "two words", .make = {}}); },
              ThrowsMessage<std::invalid_argument>(
                  "plant kind 'two words': a name is letters, digits, '_', '-' and '.'"));
  EXPECT_THAT([] { config::Config().set("plant.kind=cartpole"); },
              ::testing::Throws<config::ConfigError>());
}

TEST(PlantKinds, AnEvaluationChangesTheRobotThroughTheKindOrIsRefused) {
  config::Config config = config_of("pendulum");
  config.set("evaluation.body_mass_scale=3");
  const parameters::Parameters evaluated =
      experiments::evaluation_parameters(validated_parameters(config));
  EXPECT_EQ(pendulum_params(evaluated).mass, 3.0);
  EXPECT_EQ(evaluated.plant.robot.body_mass, parameters::Parameters{}.plant.robot.body_mass);

  config.set("evaluation.com_height_scale=0.5");
  EXPECT_THAT([&] { experiments::check_evaluation_conditions(validated_parameters(config)); },
              ThrowsMessage<config::ConfigError>(
                  "evaluation.com_height_scale is 0.5, but plant.kind 'pendulum' has no "
                  "parameter it changes; keep it at 1 for this plant"));
  config::Config rigid = config_of("rigid");
  rigid.set("evaluation.body_mass_scale=3");
  EXPECT_THAT([&] { experiments::run_exp1(validated_parameters(rigid), {preset_arm("pd_only")}); },
              ThrowsMessage<config::ConfigError>(
                  "evaluation.body_mass_scale is 3, but plant.kind 'rigid' has no parameter it "
                  "changes; keep it at 1 for this plant"));
}

TEST(PlantKinds, LearningUnderASpreadOfBodyMassesChangesTheRobotThroughTheKindOrIsRefused) {
  config::Config config = config_of("pendulum");
  config.set("pendulum.mass=2");
  config.set("training.body_mass_spread=0.5");
  const parameters::Parameters p = validated_parameters(config);
  experiments::TrainingDisturbances disturbances(p, 3);
  const double mass = pendulum_params(disturbances.trial_robot(p, 1)).mass;
  EXPECT_NE(mass, 2.0);
  EXPECT_GE(mass, 1.0);
  EXPECT_LE(mass, 3.0);
  config.set("training.body_mass_spread=0");
  const auto first_trial = [](const parameters::Parameters& parameters) {
    return experiments::run_exp1(parameters, {preset_arm("cbbg")}).run(0, 0).trials.front();
  };
  EXPECT_NE(first_trial(p).outcome.final_theta,
            first_trial(validated_parameters(config)).outcome.final_theta);

  config::Config rigid = config_of("rigid");
  rigid.set("training.body_mass_spread=0.5");
  EXPECT_THAT([&] { experiments::run_exp1(validated_parameters(rigid), {preset_arm("cbbg")}); },
              ThrowsMessage<config::ConfigError>(
                  "training.body_mass_spread is 0.5, but plant.kind 'rigid' has no body mass it "
                  "changes; keep it 0 for this plant"));
}

TEST(PlantKinds, AnLqrSupervisorDesignsFromThePlantInTheLoop) {
  config::Config config = config_of("pendulum");
  config.set("supervisor.kind=lqr");
  const parameters::Parameters p = validated_parameters(config);
  const blocks::LqrSupervisor designed("supervisor", planar_linearization(p), p.supervisor.lqr);
  const blocks::LqrSupervisor expected("supervisor", pendulum_model(p), p.supervisor.lqr);
  const blocks::LqrSupervisor robot("supervisor", p.plant.robot, p.supervisor.lqr);
  EXPECT_EQ(designed.gain(), expected.gain());
  EXPECT_NE(designed.gain(), robot.gain());
  // The closed loop of the LQR supervisor alone balances the pendulum.
  const ClosedLoop loop = build_preset("pd_only", p);
  experiments::TrialRunner runner(loop, 1, p.trial.period);
  EXPECT_EQ(runner.run_trial(0.1, 3.0).status, experiments::TrialStatus::kSuccess);

  config::Config rigid = config_of("rigid");
  rigid.set("supervisor.kind=lqr");
  EXPECT_THAT([&] { validated_parameters(rigid); },
              ThrowsMessage<config::ConfigError>(
                  "plant.kind 'rigid' offers no linearisation, which a model-based supervisor "
                  "(supervisor.kind: lqr) designs from"));
}

TEST(PlantKinds, AnLqrSupervisorRefusesALinearisationOfAnotherShape) {
  const plant::LinearModel wrong{Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(2, 1)};
  EXPECT_THAT([&] { blocks::LqrSupervisor("supervisor", wrong, {}); },
              ThrowsMessage<std::invalid_argument>(
                  "block 'supervisor': the plant's linearisation must have 4 states (theta_b, "
                  "phi, theta_b', phi') and 1 input; it has A 2x2, B 2x1"));
}

}  // namespace
}  // namespace cbbg::diagrams
