#include "cbbg/experiments/policy_export.h"

#include <stdexcept>

#include "cbbg/framework/diagram.h"

namespace cbbg::experiments {

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

}  // namespace cbbg::experiments
