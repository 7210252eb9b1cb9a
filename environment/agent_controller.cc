#include "cbbg/environment/agent_controller.h"

#include <memory>

#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/framework/diagram_builder.h"

namespace cbbg::environment {
namespace {

// supervisor.kind's block, the choice diagrams/cbbg_controller.cc makes for the cerebellum
// (kept there in an anonymous namespace; the few lines are repeated here).
std::unique_ptr<Block> configured_supervisor(const std::string& name,
                                             const parameters::Parameters& p) {
  if (p.supervisor.kind == "lqr") {
    return std::make_unique<blocks::LqrSupervisor>(name, diagrams::planar_linearization(p),
                                                   p.supervisor.lqr);
  }
  return std::make_unique<blocks::PdSupervisor>(name, p.supervisor.pd);
}

}  // namespace

AgentController::AgentController(std::string name, const parameters::Parameters& parameters)
    : Diagram(std::move(name)) {
  DiagramBuilder builder(*this);
  const Block& supervisor = builder.add(configured_supervisor("supervisor", parameters));
  held_action_ = &builder.emplace<HeldAction>("agent");
  builder.export_input(supervisor.input_port("measured"), "measured");
  builder.export_output(held_action_->output_port("action"), "action");
  builder.export_output(supervisor.output_port("action"), "supervisor_action");
  builder.build_into();
}

}  // namespace cbbg::environment
