#include "cbbg/experiments/evaluation_conditions.h"

#include <cmath>
#include <string>
#include <vector>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/config/parameters.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::experiments {
namespace {

// `value` times the factor of `scale_key`, refused unless it is a finite number > 0.
double scaled(double value, double factor, const char* key, const char* scale_key) {
  const double result = value * factor;
  if (!std::isfinite(result) || result <= 0.0) {
    throw config::ConfigError(std::string(scale_key) + " (" + format_number(factor) + ") makes " +
                              key + " " + format_number(result) +
                              "; the scaled value must be a finite number > 0");
  }
  return result;
}

void scale_body(plant::RobotParams& robot, double factor) {
  constexpr const char* kKey = "evaluation.body_mass_scale";
  robot.body_mass = scaled(robot.body_mass, factor, "plant.body_mass", kKey);
  robot.body_pitch_inertia =
      scaled(robot.body_pitch_inertia, factor, "plant.body_pitch_inertia", kKey);
  robot.body_yaw_inertia = scaled(robot.body_yaw_inertia, factor, "plant.body_yaw_inertia", kKey);
  robot.body_roll_inertia =
      scaled(robot.body_roll_inertia, factor, "plant.body_roll_inertia", kKey);
}

}  // namespace

config::Parameters evaluation_parameters(const config::Parameters& training) {
  config::Parameters p = training;
  const config::EvaluationParams& evaluation = p.evaluation;
  if (evaluation.body_mass_scale != 1.0) scale_body(p.plant.robot, evaluation.body_mass_scale);
  if (evaluation.com_height_scale != 1.0) {
    p.plant.robot.com_height = scaled(p.plant.robot.com_height, evaluation.com_height_scale,
                                      "plant.com_height", "evaluation.com_height_scale");
  }
  if (evaluation.noise_std != 0.0) {
    for (const int signal : {blocks::kMeasuredThetaB, blocks::kMeasuredThetaBDot}) {
      double& noise = p.sensors.noise_std[static_cast<std::size_t>(signal)];
      noise = std::hypot(noise, evaluation.noise_std);
    }
  }
  if (evaluation.push_torque != 0.0) {
    p.push =
        blocks::PushParams{evaluation.push_start, evaluation.push_torque, evaluation.push_duration};
  }
  return p;
}

void check_evaluation_conditions(const config::Parameters& training) {
  const config::Parameters evaluated = evaluation_parameters(training);
  try {
    diagrams::validate_parameters(evaluated);
  } catch (const config::ConfigError& error) {
    throw config::ConfigError("the evaluated robot (" + describe_conditions(training.evaluation) +
                              ") is invalid: " + error.what());
  }
}

bool changes_robot(const config::EvaluationParams& evaluation) {
  return evaluation.body_mass_scale != 1.0 || evaluation.com_height_scale != 1.0;
}

void check_plant_takes_conditions(const config::EvaluationParams& evaluation,
                                  const plant::RobotPlant& plant) {
  if (plant.built_from_robot_params()) return;
  for (const auto& [key, scale] :
       {std::pair{"evaluation.body_mass_scale", evaluation.body_mass_scale},
        std::pair{"evaluation.com_height_scale", evaluation.com_height_scale}}) {
    if (scale == 1.0) continue;
    throw config::ConfigError(std::string(key) + " is " + format_number(scale) + ", but plant '" +
                              plant.path() +
                              "' is not built from plant.* and would be evaluated unchanged; keep "
                              "it at 1 for this plant, or give the plant the change itself");
  }
}

std::string describe_conditions(const config::EvaluationParams& evaluation) {
  std::string words;
  auto add = [&words](const std::string& part) {
    if (!words.empty()) words += ", ";
    words += part;
  };
  if (evaluation.body_mass_scale != 1.0) {
    add("body mass x" + format_number(evaluation.body_mass_scale));
  }
  if (evaluation.com_height_scale != 1.0) {
    add("CoM height x" + format_number(evaluation.com_height_scale));
  }
  if (evaluation.noise_std != 0.0) add("pitch noise " + format_number(evaluation.noise_std));
  if (evaluation.push_torque != 0.0) {
    add("push " + format_number(evaluation.push_torque) + " N m from " +
        format_number(evaluation.push_start) + " s for " + format_number(evaluation.push_duration) +
        " s");
  }
  return words;
}

}  // namespace cbbg::experiments
