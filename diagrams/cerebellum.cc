#include "diagrams/cerebellum.h"

#include <stdexcept>

#include "framework/diagram_builder.h"

namespace cbbg::diagrams {
namespace {

void check_supervisor_block(const Block* supervisor, const std::string& diagram) {
  if (supervisor == nullptr) {
    throw std::invalid_argument("cerebellum '" + diagram + "': the supervisor block is null");
  }
  if (supervisor->num_input_ports() != 1 || supervisor->input_port(0).name() != "measured" ||
      supervisor->num_output_ports() != 1 || supervisor->output_port(0).name() != "action" ||
      supervisor->output_port(0).size() != 1) {
    throw std::invalid_argument("cerebellum '" + diagram + "': the supervisor block '" +
                                supervisor->name() +
                                "' must have one input \"measured\" and one output \"action\" "
                                "of size 1");
  }
}

}  // namespace

Cerebellum::Cerebellum(std::string name, std::unique_ptr<Block> supervisor)
    : Diagram(std::move(name)) {
  check_supervisor_block(supervisor.get(), this->name());
  DiagramBuilder builder(*this);
  supervisor_ = &builder.add(std::move(supervisor));
  measured_ = &builder.export_input(supervisor_->input_port("measured"));
  action_ = &builder.export_output(supervisor_->output_port("action"));
  builder.build_into();
}

}  // namespace cbbg::diagrams
