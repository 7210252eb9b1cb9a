#include "cbbg/experiments/training_disturbances.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "cbbg/blocks/external_push.h"
#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/sensors.h"
#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::experiments {
namespace {

constexpr const char* kStream = "training";  // the seed's stream of training draws

// The loop's block named `name` of type T, a direct child of its diagram, or null.
template <class T>
const Block* find_block(const diagrams::ClosedLoop& loop, const std::string& name) {
  for (const auto& block : loop.diagram->blocks()) {
    if (block->name() == name) return dynamic_cast<const T*>(block.get());
  }
  return nullptr;
}

}  // namespace

bool register_training_section() {
  static const bool registered = [] {
    config::register_keys(config::declared_keys(TrainingParams{}, TrainingParams::kSection),
                          TrainingParams::kKeysAfter);
    return true;
  }();
  return registered;
}

TrainingParams training_params(const parameters::Parameters& p) {
  return config::read_section<TrainingParams>(p.own, TrainingParams::kSection);
}

void check_training(const parameters::Parameters& p) {
  const TrainingParams training = training_params(p);
  if (training.push_force > 0.0 && p.push.any()) {
    throw config::ConfigError(
        "training.push_force is " + format_number(training.push_force) +
        ", but push.* pushes every trial already; a learning trial takes one push: set "
        "push.torque, push.force and push.pitch_torque to 0, or training.push_force to 0");
  }
  if (training.pitch_spread > 0.0) {
    p.check_inside_failure_angle("trial.theta0 - training.pitch_spread",
                                 p.trial.theta0 - training.pitch_spread);
    p.check_inside_failure_angle("trial.theta0 + training.pitch_spread",
                                 p.trial.theta0 + training.pitch_spread);
  }
  if (training.body_mass_spread > 0.0) {
    for (const double factor : {1.0 - training.body_mass_spread, 1.0 + training.body_mass_spread}) {
      const parameters::Parameters robot = with_body_mass_scale(p, factor);
      try {
        diagrams::validate_parameters(robot);
      } catch (const config::ConfigError& error) {
        throw config::ConfigError(
            "training.body_mass_spread is " + format_number(training.body_mass_spread) +
            ": the robot of body mass x" + format_number(factor) + " is invalid: " + error.what());
      }
    }
  }
}

parameters::Parameters with_body_mass_scale(const parameters::Parameters& p, double factor) {
  parameters::Parameters robot = p;
  const diagrams::PlantKind& kind = diagrams::plant_kind(p.plant.kind);
  if (!kind.change || !kind.change(robot, diagrams::RobotChange::kBodyMass, factor)) {
    throw config::ConfigError("training.body_mass_spread is " +
                              format_number(training_params(p).body_mass_spread) +
                              ", but plant.kind '" + kind.name +
                              "' has no body mass it changes; keep it 0 for this plant");
  }
  return robot;
}

parameters::Parameters training_loop_parameters(const parameters::Parameters& p) {
  const TrainingParams training = training_params(p);
  if (training.noise_std == 0.0 && training.push_force == 0.0) return p;
  parameters::Parameters loop = p;
  for (const int signal : {blocks::kMeasuredThetaB, blocks::kMeasuredThetaBDot}) {
    double& noise = loop.sensors.noise_std[static_cast<std::size_t>(signal)];
    noise = std::hypot(noise, training.noise_std);
  }
  if (training.push_force > 0.0) {
    loop.push = blocks::PushParams{.start = 0.0,
                                   .torque = 0.0,
                                   .duration = training.push_duration,
                                   .force = training.push_force,
                                   .pitch_torque = 0.0};
  }
  return loop;
}

TrainingDisturbances::TrainingDisturbances(const parameters::Parameters& p, std::uint64_t seed)
    : params_(training_params(p)),
      duration_(p.trial.duration),
      base_noise_{p.sensors.noise_std[blocks::kMeasuredThetaB],
                  p.sensors.noise_std[blocks::kMeasuredThetaBDot]},
      generator_(derive_seed(seed, kStream)) {}

void TrainingDisturbances::check(const diagrams::ClosedLoop& loop) const {
  if (params_.noise_std > 0.0 && find_block<blocks::Sensors>(loop, "sensors") == nullptr) {
    throw config::ConfigError(
        "training.noise_std is " + format_number(params_.noise_std) +
        ", but the loop's sensors are a block of the arm's own, which training.* cannot make "
        "noisier; add the noise in that block, or keep training.noise_std 0");
  }
  if (varies_robot() && !loop.plant_of_kind) {
    throw config::ConfigError("training.body_mass_spread is " +
                              format_number(params_.body_mass_spread) + ", but plant '" +
                              loop.plant->path() +
                              "' is the arm's own, not plant.kind's, and would learn unchanged; "
                              "keep training.body_mass_spread 0 for it, or register the plant as "
                              "a kind (diagrams/plant_kinds.h)");
  }
}

parameters::Parameters TrainingDisturbances::trial_robot(const parameters::Parameters& p,
                                                         int trial) {
  const double spread = share(trial) * params_.body_mass_spread;
  return with_body_mass_scale(p, 1.0 + spread * (2.0 * draw_uniform(generator_) - 1.0));
}

double TrainingDisturbances::share(int trial) const {
  if (params_.curriculum_trials == 0) return 1.0;
  return std::min(1.0,
                  static_cast<double>(trial - 1) / static_cast<double>(params_.curriculum_trials));
}

double TrainingDisturbances::before_trial(const diagrams::ClosedLoop& loop, Context& context,
                                          int trial, double theta0) {
  const double grown = share(trial);
  if (params_.noise_std > 0.0) {
    set_noise(*find_block<blocks::Sensors>(loop, "sensors"), context, grown);
  }
  if (params_.push_force > 0.0) {
    set_push(*find_block<blocks::ExternalPush>(loop, "external_push"), context, grown);
  }
  if (params_.pitch_spread == 0.0) return theta0;
  return theta0 + grown * params_.pitch_spread * (2.0 * draw_uniform(generator_) - 1.0);
}

// The pitch and pitch-rate noise of this trial: sqrt(base^2 + (share sigma)^2) of the
// sqrt(base^2 + sigma^2) the sensors were built with.
void TrainingDisturbances::set_noise(const Block& sensors, Context& context, double share) const {
  Vector scale = Vector::Ones(blocks::kMeasuredSize);
  for (const int signal : {blocks::kMeasuredThetaB, blocks::kMeasuredThetaBDot}) {
    const double base = base_noise_[signal];
    scale[signal] =
        std::hypot(base, share * params_.noise_std) / std::hypot(base, params_.noise_std);
  }
  context.set_parameter(sensors, "noise_scale", scale);
}

// One push this trial: a force uniform on [-F, F] (F the share of training.push_force), from
// a start uniform over the trial, for training.push_duration.
void TrainingDisturbances::set_push(const Block& push, Context& context, double share) {
  const double latest = std::max(0.0, duration_ - params_.push_duration);
  const double start = latest * draw_uniform(generator_);
  const double force = share * params_.push_force * (2.0 * draw_uniform(generator_) - 1.0);
  Vector pulse(4);
  pulse << start, params_.push_duration, force, 0.0;
  context.set_parameter(push, "pulse", pulse);
}

}  // namespace cbbg::experiments
