#include "cbbg/apps/export_command.h"

#include <cstdio>
#include <stdexcept>

#include "cbbg/apps/errors.h"
#include "cbbg/apps/learnt_policy.h"
#include "cbbg/config/config.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/policy_export.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"
#include "cbbg/store/weights_file.h"

namespace cbbg::app {
namespace {

// What the head comment of an exported file carries, and what marks it as cbbg's to replace.
constexpr const char* kExportTag = "written by cbbg export";

void check_omega(double omega) {
  if (!(omega >= 0.0 && omega <= 1.0)) {
    throw config::ConfigError("--omega must be a number from 0 to 1; got " + format_number(omega));
  }
}

// The C of the weights' policy: the actor alone, with --omega the arm's whole controller, or
// with --learner its whole online learner.
codegen::CSources policy_sources(const ExportOptions& options,
                                 const parameters::Parameters& parameters,
                                 const experiments::LearntWeights& weights,
                                 const diagrams::ClosedLoopFactory& policy,
                                 const codegen::CExportOptions& c) {
  try {
    if (!options.omega && !options.learner)
      return experiments::export_policy(parameters, policy, weights, c);
    const diagrams::Arm arm = diagrams::named_arm(weights.provenance.arm);
    if (options.learner) {
      codegen::CLearnerOptions learner;
      learner.name = c.name;
      learner.scalar = c.scalar;
      learner.provenance = c.provenance;
      return experiments::export_learner(parameters, arm.learner, weights, learner);
    }
    return experiments::export_mixed_policy(parameters, arm.learner, weights, *options.omega, c);
  } catch (const std::invalid_argument& error) {
    throw config::ConfigError(std::string(options.learner ? "cannot export the learner: "
                                                          : "cannot export the policy: ") +
                              error.what());
  }
}

codegen::Scalar scalar_of(const std::string& text) {
  if (text == "double") return codegen::Scalar::kDouble;
  if (text == "float") return codegen::Scalar::kFloat;
  throw config::ConfigError("--scalar must be double or float; got '" + text + "'");
}

// The weights' plant, the config file and the overrides, validated.
parameters::Parameters parameters_of(const ExportOptions& options,
                                     const experiments::LearntWeights& weights) {
  return diagrams::validated_parameters(weights_config(weights, options.config_file, options.sets));
}

std::string what_is_exported(const ExportOptions& options) {
  if (options.learner) return "the whole online learner, its generators as run.seed's";
  if (options.omega) {
    return "the whole controller at omega " + format_number(*options.omega) + ", no exploration";
  }
  return "the actor alone";
}

// Where the code comes from: the weights file (its hash), who learnt them, and the keys that
// give the weights their meaning.
std::vector<std::string> provenance(const ExportOptions& options,
                                    const experiments::LearntWeights& weights) {
  const experiments::WeightsProvenance& from = weights.provenance;
  std::vector<std::string> lines = {
      "From weights file '" + options.weights_file.filename().string() +
          "' (FNV-1a 64 of its bytes: " + store::text_hash(store::read_text(options.weights_file)) +
          "),",
      "learnt by arm " + from.arm + ", seed " + std::to_string(from.seed) + ", over " +
          std::to_string(from.trials) + " trials on plant kind " + from.plant + ".",
      "Scalar: " + options.scalar + "; " + what_is_exported(options) + ". Made with these keys:"};
  for (const blocks::LayoutEntry& entry : weights.layout) {
    std::string values;
    for (const double value : entry.values)
      values += (values.empty() ? "" : ", ") + format_number(value);
    lines.push_back("  " + entry.key + " = " +
                    (entry.values.size() == 1 ? values : "[" + values + "]"));
  }
  return lines;
}

}  // namespace

int export_command(const ExportOptions& options) {
  codegen::CSources sources;
  std::filesystem::path header, source;
  try {
    if (options.weights_file.empty()) throw config::ConfigError("--load-weights FILE is required");
    if (options.out.empty()) throw config::ConfigError("--out DIR is required");
    const std::string name = options.name_or_default();
    if (!codegen::is_c_identifier(name)) {
      throw config::ConfigError(
          "--name must be a C identifier (letters, digits and '_', not "
          "first a digit); got '" +
          name + "'");
    }
    codegen::CExportOptions c;
    c.name = name;
    c.scalar = scalar_of(options.scalar);
    if (options.omega) check_omega(*options.omega);
    if (options.omega && options.learner) {
      throw config::ConfigError(
          "--learner and --omega exclude each other: the learner mixes at its own omega "
          "schedule");
    }
    check_output_directory(options.out, "--out");
    header = options.out / (name + ".h");
    source = options.out / (name + ".c");
    for (const auto& file : {header, source})
      store::check_replaceable_file(file, "--out", kExportTag);
    const experiments::LearntWeights weights = store::load_weights(options.weights_file);
    const parameters::Parameters parameters = parameters_of(options, weights);
    const diagrams::ClosedLoopFactory policy = policy_of(weights.provenance.arm);
    experiments::check_weights(weights, parameters.plant.kind, policy(parameters),
                               options.weights_file);
    c.provenance = provenance(options, weights);
    sources = policy_sources(options, parameters, weights, policy, c);
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  try {
    std::filesystem::create_directories(options.out);
    store::write_atomically(header, sources.header);
    store::write_atomically(source, sources.source);
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  std::printf("wrote %s and %s\n", header.string().c_str(), source.string().c_str());
  return 0;
}

}  // namespace cbbg::app
