#include "cbbg/experiments/evaluation_conditions.h"

#include <cmath>
#include <string>
#include <vector>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {
parameters::Parameters evaluation_parameters(const parameters::Parameters& training) {
  parameters::Parameters p = training;
  const parameters::EvaluationParams& evaluation = p.evaluation;
  const diagrams::PlantKind& kind = diagrams::plant_kind(p.plant.kind);
  for (const auto& [change, factor] :
       {std::pair{diagrams::RobotChange::kBodyMass, evaluation.body_mass_scale},
        std::pair{diagrams::RobotChange::kComHeight, evaluation.com_height_scale}}) {
    if (factor == 1.0) continue;
    if (!kind.change || !kind.change(p, change, factor)) {
      throw config::ConfigError(std::string(diagrams::change_key(change)) + " is " +
                                format_number(factor) + ", but plant.kind '" + kind.name +
                                "' has no parameter it changes; keep it at 1 for this plant");
    }
  }
  if (evaluation.noise_std != 0.0) {
    for (const int signal : {blocks::kMeasuredThetaB, blocks::kMeasuredThetaBDot}) {
      double& noise = p.sensors.noise_std[static_cast<std::size_t>(signal)];
      noise = std::hypot(noise, evaluation.noise_std);
    }
  }
  if (evaluation.push_torque != 0.0 || evaluation.push_force != 0.0 ||
      evaluation.push_pitch_torque != 0.0) {
    p.push =
        blocks::PushParams{evaluation.push_start, evaluation.push_torque, evaluation.push_duration,
                           evaluation.push_force, evaluation.push_pitch_torque};
  }
  return p;
}

void check_evaluation_conditions(const parameters::Parameters& training) {
  const parameters::Parameters evaluated = evaluation_parameters(training);
  try {
    diagrams::validate_parameters(evaluated);
  } catch (const config::ConfigError& error) {
    throw config::ConfigError("the evaluated robot (" + describe_conditions(training.evaluation) +
                              ") is invalid: " + error.what());
  }
}

bool changes_robot(const parameters::EvaluationParams& evaluation) {
  return evaluation.body_mass_scale != 1.0 || evaluation.com_height_scale != 1.0;
}

void check_plant_takes_conditions(const parameters::EvaluationParams& evaluation,
                                  const diagrams::ClosedLoop& loop) {
  if (loop.plant_of_kind) return;
  for (const auto& [key, scale] :
       {std::pair{"evaluation.body_mass_scale", evaluation.body_mass_scale},
        std::pair{"evaluation.com_height_scale", evaluation.com_height_scale}}) {
    if (scale == 1.0) continue;
    throw config::ConfigError(std::string(key) + " is " + format_number(scale) + ", but plant '" +
                              loop.plant->path() +
                              "' is the arm's own, not plant.kind's, and would be evaluated "
                              "unchanged; keep it at 1, or register the plant as a kind that "
                              "applies the change (diagrams/plant_kinds.h)");
  }
}

bool pushes_from_outside(const parameters::EvaluationParams& evaluation) {
  return evaluation.push_force != 0.0 || evaluation.push_pitch_torque != 0.0;
}

void check_plant_takes_push(const parameters::Parameters& training,
                            const diagrams::ClosedLoopFactory& loop) {
  if (!pushes_from_outside(training.evaluation)) return;
  try {
    (void)loop(evaluation_parameters(training));
  } catch (const config::ConfigError& error) {
    throw config::ConfigError("evaluation.push_force and evaluation.push_pitch_torque: " +
                              std::string(error.what()));
  }
}

std::string describe_conditions(const parameters::EvaluationParams& evaluation) {
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
  std::string push;
  auto add_push = [&push](double value, const char* what) {
    if (value == 0.0) return;
    push += (push.empty() ? "" : " and ") + format_number(value) + what;
  };
  add_push(evaluation.push_torque, " N m on each wheel");
  add_push(evaluation.push_force, " N at the centre of mass");
  add_push(evaluation.push_pitch_torque, " N m on the body");
  if (!push.empty()) {
    add("push " + push + " from " + format_number(evaluation.push_start) + " s for " +
        format_number(evaluation.push_duration) + " s");
  }
  return words;
}

}  // namespace cbbg::experiments
