#pragma once
// The cerebellum of the CB-BG controller (the paper's Fig. 5): a supervisor that maps the
// measured state to the target action a_S the actor learns towards. The paper's is a PD law
// (blocks::PdSupervisor); blocks::LqrSupervisor and any block of the user's with the same
// two ports take its place.

#include <memory>
#include <string>

#include "cbbg/framework/diagram.h"

namespace cbbg::diagrams {

/// Cerebellum: measured state -> supervisor -> a_S.
///
/// | port     | dir | size | meaning                                        |
/// |----------|-----|------|------------------------------------------------|
/// | measured | in  | m    | the supervisor's input "measured" (m its size) |
/// | action   | out | 1    | a_S(t), N m                                    |
///
/// Blocks: "supervisor" (the slot: any block with input "measured" and output "action" of
/// size 1).
class Cerebellum final : public Diagram {
 public:
  Cerebellum(std::string name, std::shared_ptr<Block> supervisor);

  const InputPort& measured() const { return *measured_; }
  const OutputPort& action() const { return *action_; }
  const Block& supervisor() const { return *supervisor_; }

 private:
  const InputPort* measured_;
  const OutputPort* action_;
  const Block* supervisor_;
};

}  // namespace cbbg::diagrams
