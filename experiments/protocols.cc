#include "cbbg/experiments/protocols.h"

#include <algorithm>
#include <stdexcept>

#include "cbbg/experiments/builtin_protocols.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/run_names.h"
#include "cbbg/experiments/training_disturbances.h"

namespace cbbg::experiments {
namespace {

std::size_t library_protocols = 0;  // the registry's first ones, which stay

std::vector<Protocol>& registry() {
  static std::vector<Protocol> all = [] {
    std::vector<Protocol> library{exp1_protocol(),     exp2_protocol(),     exp3_protocol(),
                                  evaluate_protocol(), transfer_protocol(), realtime_protocol()};
    for (const Protocol& protocol : library) {
      config::register_keys(protocol.keys, protocol.keys_after);
    }
    library_protocols = library.size();
    return library;
  }();
  return all;
}

}  // namespace

void register_protocol(Protocol protocol) {
  std::vector<std::string> taken;
  for (const Protocol& existing : registry()) taken.push_back(existing.name);
  config::check_new_name("protocol", protocol.name, taken);
  const std::vector<std::string> arms = diagrams::arm_names();
  if (std::find(arms.begin(), arms.end(), protocol.name) != arms.end()) {
    throw std::invalid_argument("protocol '" + protocol.name + "': an arm has that name");
  }
  if (!protocol.run) throw std::invalid_argument("protocol '" + protocol.name + "' has no run");
  config::register_keys(protocol.keys, protocol.keys_after);
  registry().push_back(std::move(protocol));
}

void unregister_protocol(std::string_view name) {
  const auto found =
      std::find_if(registry().begin() + static_cast<std::ptrdiff_t>(library_protocols),
                   registry().end(), [name](const Protocol& p) { return p.name == name; });
  if (found == registry().end()) {
    throw std::invalid_argument("no registered protocol '" + std::string(name) +
                                "' to unregister (the library's protocols stay)");
  }
  std::vector<std::string> paths;
  for (const config::KeySpec& key : found->keys) paths.push_back(key.path);
  config::unregister_keys(paths);
  registry().erase(found);
}

const std::vector<Protocol>& protocols() { return registry(); }

bool is_protocol_key(std::string_view key) {
  for (const Protocol& protocol : registry()) {
    for (const config::KeySpec& spec : protocol.keys) {
      if (spec.path == key) return true;
    }
  }
  return false;
}

const Protocol* find_protocol(std::string_view name) {
  for (const Protocol& protocol : registry()) {
    if (protocol.name == name) return &protocol;
  }
  return nullptr;
}

ResultsSchema results_schema(const parameters::Parameters& parameters) {
  const Protocol* protocol = find_protocol(parameters.run.experiment);
  ResultsSchema schema = protocol == nullptr ? exp1_schema(parameters)  // an arm alone
                         : protocol->schema  ? protocol->schema(parameters)
                                             : ResultsSchema{};
  check_schema(schema, parameters.run.experiment);
  return schema;
}

void check_recorded_figures(const ExperimentResults& results) {
  for (const SeedRun& run : results.runs) {
    for (const SeedFigure& figure : run.figures) {
      if (results.schema.figure(figure.name) != nullptr) continue;
      throw std::runtime_error(results.experiment + ": " + run.arm + " seed " +
                               std::to_string(run.seed) + " records the figure '" + figure.name +
                               "', which the protocol's schema does not declare "
                               "(Protocol::schema's figures)");
    }
  }
}

void check_protocol(const parameters::Parameters& parameters,
                    const LearntWeights* initial_weights) {
  check_training(parameters);  // every protocol's learning trials meet training.*
  const Protocol* protocol = find_protocol(parameters.run.experiment);
  if (protocol != nullptr && protocol->check) protocol->check(parameters, initial_weights);
}

std::vector<std::string> experiment_arms(const parameters::RunParams& run) {
  const Protocol* protocol = find_protocol(run.experiment);
  if (protocol == nullptr) return {run.experiment};
  return protocol->arms ? protocol->arms(run) : run.arms;
}

ExperimentResults run_experiment(const parameters::Parameters& parameters,
                                 const ExperimentOptions& options) {
  check_run_names(parameters.run);
  const std::vector<diagrams::Arm> arms = diagrams::named_arms(experiment_arms(parameters.run));
  ResultsSchema schema = results_schema(parameters);
  const Protocol* protocol = find_protocol(parameters.run.experiment);
  ExperimentResults results = protocol != nullptr ? protocol->run(parameters, arms, options)
                                                  : run_exp1(parameters, arms, options);
  results.experiment = parameters.run.experiment;
  results.schema = std::move(schema);
  check_recorded_figures(results);
  return results;
}

}  // namespace cbbg::experiments
