#include "cbbg/diagrams/cerebellum.h"

#include "cbbg/diagrams/slot_check.h"
#include "cbbg/framework/diagram_builder.h"

namespace cbbg::diagrams {

Cerebellum::Cerebellum(std::string name, std::shared_ptr<Block> supervisor)
    : Diagram(std::move(name)) {
  check_slot_block(supervisor.get(), "cerebellum '" + this->name() + "'", "measured", "action", 1);
  DiagramBuilder builder(*this);
  supervisor_ = &builder.add(std::move(supervisor));
  measured_ = &builder.export_input(supervisor_->input_port("measured"));
  action_ = &builder.export_output(supervisor_->output_port("action"));
  builder.build_into();
}

}  // namespace cbbg::diagrams
