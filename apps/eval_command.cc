// cbbg eval: load learnt weights, check them against the config (on the weights' plant unless
// it names another), run the policy alone.

#include "cbbg/apps/eval_command.h"
#include "cbbg/apps/errors.h"
#include "cbbg/apps/learnt_policy.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <tuple>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/actor_linearisation.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/experiments/policy_evaluation.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"
#include "cbbg/store/weights_file.h"

namespace cbbg::app {
namespace {

constexpr const char* kEvaluationFile = "evaluation.csv";

// More runs per angle than this is a typing slip, not a study.
constexpr int kMaxRepeats = 10000;

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

// The push of --push-time, --push-duration and its sizes (--push-torque, --push-force,
// --push-pitch-torque, at least one): all of the push or none.
std::optional<blocks::PushParams> push_from(const EvalOptions& options) {
  const bool sized = options.push_torque || options.push_force || options.push_pitch_torque;
  if (!sized && !options.push_time && !options.push_duration) return std::nullopt;
  std::string missing;
  for (const auto& [name, given] :
       {std::pair{"--push-time", options.push_time.has_value()},
        {"--push-duration", options.push_duration.has_value()},
        {"--push-torque, --push-force or --push-pitch-torque", sized}}) {
    if (!given) missing += (missing.empty() ? "" : " and ") + std::string(name);
  }
  if (!missing.empty()) {
    throw config::ConfigError(
        "a push needs --push-time, --push-duration and at least one of --push-torque, "
        "--push-force and --push-pitch-torque; missing " +
        missing);
  }
  auto require = [](const char* name, double value, bool ok, const char* range) {
    if (!std::isfinite(value) || !ok) {
      throw config::ConfigError(std::string(name) + " must be a finite number " + range + "; got " +
                                format_number(value));
    }
  };
  require("--push-time", *options.push_time, *options.push_time >= 0.0, ">= 0 (s)");
  require("--push-duration", *options.push_duration, *options.push_duration > 0.0, "> 0 (s)");
  blocks::PushParams push{*options.push_time, 0.0, *options.push_duration};
  for (const auto& [name, given, size, unit] :
       {std::tuple{"--push-torque", &options.push_torque, &push.torque, "(N m)"},
        {"--push-force", &options.push_force, &push.force, "(N)"},
        {"--push-pitch-torque", &options.push_pitch_torque, &push.pitch_torque, "(N m)"}}) {
    if (!*given) continue;
    require(name, **given, true, unit);
    *size = **given;
  }
  return push;
}

// --angles as typed: finite numbers separated by single commas ("0.1,,0.2" is refused).
std::vector<double> parse_angles(const std::string& text) {
  std::vector<double> angles;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    double angle = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), angle);
    if (item.empty() || error != std::errc() || end != item.data() + item.size() ||
        !std::isfinite(angle)) {
      throw config::ConfigError(
          "--angles must be finite numbers separated by commas (rad), "
          "e.g. 0.1,0.2; got '" +
          text + "'");
    }
    angles.push_back(angle);
    if (comma == text.size()) return angles;
    start = comma + 1;
  }
}

// The evaluation's parameters: the weights' plant, the file, the overrides and --angles,
// validated, with the evaluation.* conditions applied.
parameters::Parameters resolve(const EvalOptions& options,
                               const experiments::LearntWeights& weights) {
  config::Config config = weights_config(weights, options.config_file, options.sets);
  if (!options.angles.empty()) {
    std::string list = "[";
    for (const double angle : parse_angles(options.angles)) {
      list += (list.size() > 1 ? ", " : "") + format_number(angle);
    }
    config.set("evaluation.angles=" + list + "]", "--angles");
  }
  const parameters::Parameters training = diagrams::validated_parameters(config);
  if (training.evaluation.angles.empty()) {
    throw config::ConfigError("evaluation.angles is empty: give --angles or set some");
  }
  experiments::check_evaluation_conditions(training);
  return experiments::evaluation_parameters(training);
}

std::string evaluation_csv(const experiments::PolicyEvaluation& evaluation) {
  std::string csv = "theta0,seed,balanced,steps,final_theta,status\n";
  for (const auto& angle : evaluation.angles) {
    for (std::size_t r = 0; r < angle.runs.size(); ++r) {
      const experiments::TrialOutcome& run = angle.runs[r];
      csv += format_number(angle.theta0) + "," +
             std::to_string(evaluation.first_seed + static_cast<long long>(r)) + "," +
             (run.status == experiments::TrialStatus::kSuccess ? "1" : "0") + "," +
             std::to_string(run.steps) + "," + format_number(run.final_theta) + "," +
             experiments::to_string(run.status) + "\n";
    }
  }
  return csv;
}

// `push`: the flags' push (push_from), already checked.
void print_table(const experiments::PolicyEvaluation& evaluation, const parameters::Parameters& p,
                 const experiments::LearntWeights& weights, const EvalOptions& options,
                 const std::optional<blocks::PushParams>& push) {
  const experiments::WeightsProvenance& from = weights.provenance;
  std::printf("weights %s: %s, seed %lld, %lld trial(s) on the %s plant\n",
              options.weights_file.string().c_str(), from.arm.c_str(), from.seed, from.trials,
              from.plant.c_str());
  std::printf("policy alone on the %s plant for %g s, seeds %lld..%lld", p.plant.kind.c_str(),
              p.trial.duration, evaluation.first_seed, evaluation.first_seed + options.repeats - 1);
  if (push) {
    std::printf("; push");
    const char* joint = " ";
    for (const auto& [size, unit] : {std::pair{push->torque, "N m on each wheel"},
                                     {push->force, "N at the centre of mass"},
                                     {push->pitch_torque, "N m on the body"}}) {
      if (size == 0.0) continue;
      std::printf("%s%g %s", joint, size, unit);
      joint = " and ";
    }
    std::printf(" from %g s for %g s", push->start, push->duration);
  }
  if (const std::string conditions = experiments::describe_conditions(p.evaluation);
      !conditions.empty()) {
    std::printf("; evaluated on a changed robot: %s", conditions.c_str());
  }
  std::printf("\n%10s %10s\n", "theta0", "balanced");
  for (const auto& angle : evaluation.angles) {
    const std::string ratio =
        std::to_string(angle.balanced()) + "/" + std::to_string(angle.runs.size());
    std::printf("%10g %10s\n", angle.theta0, ratio.c_str());
  }
}

// --linearise's analysis; a plant kind without a linearisation is the user's choice.
experiments::ActorLinearisation linearised(const parameters::Parameters& parameters,
                                           const diagrams::ClosedLoopFactory& policy,
                                           const experiments::LearntWeights& weights) {
  try {
    return experiments::linearise_actor(parameters, policy, weights);
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(std::string("--linearise: ") + error.what());
  }
}

void print_linearisation(const experiments::ActorLinearisation& linear, double period) {
  std::printf("\nthe actor near rest: slopes of its action at x = 0 (N m per rad, per rad/s)\n");
  for (int i = 0; i < 4; ++i) {
    std::printf("%10s %12.4g\n", experiments::kLinearisedStates[static_cast<size_t>(i)],
                linear.slopes[i]);
  }
  std::printf("the robot upright closed by those slopes, the action held for %g s: its modes\n",
              period);
  std::printf("%10s %22s %10s\n", "|z|", "s = ln(z) / period, 1/s", "leans on");
  for (const experiments::ClosedLoopMode& mode : linear.modes) {
    char s[64];
    std::snprintf(s, sizeof s, "%+.4g %+.4gi", mode.s.real(), mode.s.imag());
    // |z| = 1 to rounding (the position, which nothing but the actor restores) holds.
    const double size = std::abs(mode.z);
    const char* fate = size > 1.0 + 1e-9 ? "  grows" : size > 1.0 - 1e-9 ? "  holds" : "";
    std::printf("%10.5f %22s %10s%s\n", size, s,
                experiments::kLinearisedStates[static_cast<size_t>(mode.leans_on)], fate);
  }
}

}  // namespace

int eval_command(const EvalOptions& options) {
  parameters::Parameters parameters;
  experiments::LearntWeights weights;
  experiments::EvaluationSettings settings;
  diagrams::ClosedLoopOptions loop;
  diagrams::ClosedLoopFactory policy;
  std::optional<experiments::ActorLinearisation> linear;
  try {
    if (options.weights_file.empty()) throw config::ConfigError("--load-weights FILE is required");
    if (options.repeats < 1 || options.repeats > kMaxRepeats) {
      throw config::ConfigError("--repeats must be from 1 to " + std::to_string(kMaxRepeats) +
                                "; got " + std::to_string(options.repeats));
    }
    if (!options.out.empty()) {
      check_output_directory(options.out, "--out");
      store::Manifest(options.out).check_writable({kEvaluationFile}, "--out");
    }
    loop.push = push_from(options);
    weights = store::load_weights(options.weights_file);
    parameters = resolve(options, weights);
    policy = policy_of(weights.provenance.arm, loop);
    experiments::check_weights(weights, parameters.plant.kind, policy(parameters),
                               options.weights_file);
    settings.angles = parameters.evaluation.angles;
    settings.repeats = options.repeats;
    if (options.linearise) linear = linearised(parameters, policy, weights);
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  try {
    const experiments::PolicyEvaluation evaluation =
        experiments::evaluate_policy(parameters, policy, weights, settings);
    if (!options.out.empty()) {
      std::filesystem::create_directories(options.out);
      store::Manifest manifest(options.out);
      manifest.add({kEvaluationFile});
      store::write_atomically(options.out / kEvaluationFile, evaluation_csv(evaluation));
    }
    print_table(evaluation, parameters, weights, options, loop.push);
    if (linear) print_linearisation(*linear, parameters.trial.period);
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  return 0;
}

}  // namespace cbbg::app
