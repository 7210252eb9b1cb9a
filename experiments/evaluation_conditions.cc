#include "experiments/evaluation_conditions.h"

#include <cmath>
#include <string>
#include <vector>

#include "blocks/measured_signals.h"
#include "diagrams/validated_parameters.h"
#include "framework/number_text.h"

namespace cbbg::experiments {
namespace {

void scale(config::Config& config, const std::string& key, const char* scale_key) {
  const double factor = config.number(scale_key);
  const double scaled = config.number(key) * factor;
  if (!std::isfinite(scaled) || scaled <= 0.0) {
    throw config::ConfigError(std::string(scale_key) + " (" + format_number(factor) + ") makes " +
                              key + " " + format_number(scaled) +
                              "; the scaled value must be a finite number > 0");
  }
  config.set(key + "=" + format_number(scaled), scale_key);
}

void add_pitch_noise(config::Config& config, double std) {
  std::vector<double> noise = config.numbers("sensors.noise_std");
  for (const int signal : {blocks::kMeasuredThetaB, blocks::kMeasuredThetaBDot}) {
    noise[signal] = std::hypot(noise[signal], std);
  }
  std::string list;
  for (std::size_t i = 0; i < noise.size(); ++i) {
    list += i == 0 ? "[" : ", ";
    list += format_number(noise[i]);
  }
  list += "]";
  config.set("sensors.noise_std=" + list, "evaluation");
}

}  // namespace

config::Config evaluation_config(const config::Config& training) {
  config::Config config = training;
  const double mass = training.number("evaluation.body_mass_scale");
  if (mass != 1.0) {
    for (const char* key : {"plant.body_mass", "plant.body_pitch_inertia", "plant.body_yaw_inertia",
                            "plant.body_roll_inertia"}) {
      scale(config, key, "evaluation.body_mass_scale");
    }
  }
  const double height = training.number("evaluation.com_height_scale");
  if (height != 1.0) scale(config, "plant.com_height", "evaluation.com_height_scale");
  const double noise = training.number("evaluation.noise_std");
  if (noise != 0.0) add_pitch_noise(config, noise);
  const double push = training.number("evaluation.push_torque");
  if (push != 0.0) {
    config.set("push.torque=" + format_number(push), "evaluation");
    config.set("push.start=" + format_number(training.number("evaluation.push_start")),
               "evaluation");
    config.set("push.duration=" + format_number(training.number("evaluation.push_duration")),
               "evaluation");
  }
  return config;
}

void check_evaluation_conditions(const config::Config& training) {
  const config::Config evaluated = evaluation_config(training);
  try {
    diagrams::validated_parameters(evaluated);
  } catch (const config::ConfigError& error) {
    throw config::ConfigError("the evaluated robot (" + describe_conditions(training) +
                              ") is invalid: " + error.what());
  }
}

std::string describe_conditions(const config::Config& config) {
  std::string words;
  auto add = [&words](const std::string& part) {
    if (!words.empty()) words += ", ";
    words += part;
  };
  const double mass = config.number("evaluation.body_mass_scale");
  if (mass != 1.0) add("body mass x" + format_number(mass));
  const double height = config.number("evaluation.com_height_scale");
  if (height != 1.0) add("CoM height x" + format_number(height));
  const double noise = config.number("evaluation.noise_std");
  if (noise != 0.0) add("pitch noise " + format_number(noise));
  const double push = config.number("evaluation.push_torque");
  if (push != 0.0) {
    add("push " + format_number(push) + " N m from " +
        format_number(config.number("evaluation.push_start")) + " s for " +
        format_number(config.number("evaluation.push_duration")) + " s");
  }
  return words;
}

}  // namespace cbbg::experiments
