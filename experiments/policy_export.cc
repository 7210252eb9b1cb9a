#include "cbbg/experiments/policy_export.h"

#include <stdexcept>

#include "cbbg/framework/diagram.h"

namespace cbbg::experiments {
namespace {

// The leaf block's output behind `port`, through the diagrams that export it.
const OutputPort& leaf_output(const OutputPort& port) {
  if (!port.block().is_diagram()) return port;
  const auto& diagram = static_cast<const Diagram&>(port.block());
  return leaf_output(*diagram.exported_outputs()[static_cast<std::size_t>(port.index())]);
}

// The leaf output behind the controller's output `name`.
const OutputPort& controller_output(const Diagram& controller, const char* name) {
  const OutputPort* port = controller.find_output_port(name);
  if (port == nullptr) {
    throw std::invalid_argument("controller '" + controller.path() + "' has no output '" + name +
                                "' (it has: " + controller.output_port_names() + ")");
  }
  return leaf_output(*port);
}

}  // namespace

codegen::CSources export_policy(const parameters::Parameters& parameters,
                                const diagrams::ClosedLoopFactory& policy,
                                const LearntWeights& weights,
                                const codegen::CExportOptions& options) {
  const diagrams::ClosedLoop loop = policy(parameters);
  if (loop.learner.actor == nullptr || loop.controller == nullptr) {
    throw std::invalid_argument("diagram '" + loop.diagram->name() +
                                "' has no actor in a controller: it has no policy to export");
  }
  const auto context = loop.diagram->create_context(parameters.run.seed);
  load_learnt_weights(loop, *context, weights);
  const Block& actor = loop.learner.actor->learner_block();
  const OutputPort* action = actor.find_output_port("actor_action");
  if (action == nullptr) {
    throw std::invalid_argument(
        "the actor '" + actor.path() +
        "' has no output 'actor_action' to export (it has: " + actor.output_port_names() + ")");
  }
  return codegen::export_c(*loop.controller, *action, *context, options);
}

codegen::CSources export_mixed_policy(const parameters::Parameters& parameters,
                                      const diagrams::ClosedLoopFactory& learner,
                                      const LearntWeights& weights, double omega,
                                      codegen::CExportOptions options) {
  const diagrams::ClosedLoop loop = learner(parameters);
  if (loop.controller == nullptr) {
    throw std::invalid_argument("diagram '" + loop.diagram->name() +
                                "' has no controller: it has no policy to export");
  }
  const auto context = loop.diagram->create_context(parameters.run.seed);
  load_learnt_weights(loop, *context, weights);
  const Diagram& controller = *loop.controller;
  options.read_as[&controller_output(controller, "exploration_action")] =
      &controller_output(controller, "actor_action");
  options.held[&controller_output(controller, "omega")] = omega;
  return codegen::export_c(controller, controller_output(controller, "action"), *context, options);
}

codegen::CSources export_learner(const diagrams::ClosedLoop& loop, const Context& context,
                                 codegen::CLearnerOptions options) {
  if (loop.controller == nullptr) {
    throw std::invalid_argument("diagram '" + loop.diagram->name() +
                                "' has no controller: it has no learner to export");
  }
  const Diagram& diagram = *loop.diagram;
  options.given[&leaf_output(diagram.block("sensors").output_port("measured"))] = "measured";
  options.watched.push_back(&leaf_output(diagram.block("failure").output_port("failed")));
  return codegen::export_learner_c(diagram, controller_output(*loop.controller, "action"), context,
                                   options);
}

codegen::CSources export_learner(const parameters::Parameters& parameters,
                                 const diagrams::ClosedLoopFactory& learner,
                                 const LearntWeights& weights, codegen::CLearnerOptions options) {
  const diagrams::ClosedLoop loop = learner(parameters);
  const auto context = loop.diagram->create_context(parameters.run.seed);
  load_learnt_weights(loop, *context, weights);
  options.period = parameters.trial.period;
  return export_learner(loop, *context, std::move(options));
}

}  // namespace cbbg::experiments
