#pragma once
// The controller an agent stands in for: the closed loop (diagrams/closed_loop.h) asks any
// controller for an action; here the action is the agent's, set from outside between ticks,
// and the configured supervisor runs beside it on the same measurements so that the agent
// can read what it would have done (imitation, residual learning).
//
//   measured -> supervisor -> "supervisor_action"      (diagnostic, not applied)
//   agent's action -> held action -> "action"          (applied by the loop's hold)

#include <string>

#include "cbbg/environment/held_action.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::environment {

// A Diagram with a controller's ports (diagrams/controller_ports.h): input "measured" (6),
// outputs "action" (1) and "supervisor_action" (1). The supervisor is supervisor.kind's, as in
// the CB-BG controller: blocks::PdSupervisor (supervisor.*) or blocks::LqrSupervisor designed
// on plant.kind's linearisation (which throws std::invalid_argument for a kind without one).
class AgentController final : public Diagram {
 public:
  AgentController(std::string name, const parameters::Parameters& parameters);

  // The block whose state is the action the loop applies.
  const HeldAction& held_action() const { return *held_action_; }

 private:
  const HeldAction* held_action_ = nullptr;
};

}  // namespace cbbg::environment
