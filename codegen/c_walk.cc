#include "cbbg/codegen/c_walk.h"

#include <algorithm>
#include <stdexcept>

#include "cbbg/codegen/c_export.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/primitives/constant_source.h"

namespace cbbg::codegen {

bool is_updated(const Block& block) {
  return !block.discrete_state_parts().empty() || !block.periodic_updates().empty() ||
         !block.initialization_updates().empty();
}

Walk::Walk(const Diagram& root, const Context& context, WalkOptions options)
    : root_(root), context_(context), options_(std::move(options)) {}

std::string Walk::visit(const OutputPort& port) {
  if (const auto found = visited_.find(&port); found != visited_.end()) return found->second;
  std::string signal;
  if (const auto other = options_.read_as.find(&port); other != options_.read_as.end()) {
    signal = visit(*other->second);
  } else if (const auto value = options_.held.find(&port); value != options_.held.end()) {
    signal = constant("held", Vector::Constant(1, value->second));
  } else if (const auto name = options_.given.find(&port); name != options_.given.end()) {
    signal = argument(name->second, port.size());
  } else if (const auto* source = dynamic_cast<const ConstantSource*>(&port.block())) {
    signal = constant("constant", source->value());
  } else {
    signal = visit_leaf(port);
  }
  return visited_[&port] = signal;
}

std::string Walk::visit_leaf(const OutputPort& port) {
  const Block& block = port.block();
  const auto* emitter = dynamic_cast<const EmitsC*>(&block);
  if (emitter == nullptr) {
    throw std::invalid_argument("block '" + block.path() +
                                "' cannot be written as C: it does not implement "
                                "codegen::EmitsC (the output '" +
                                port.name() + "' of the export needs it)");
  }
  Step step;
  step.block = &block;
  step.output = port.index();
  step.size = port.size();
  for (const int read : block.output_reads(port.index())) {
    step.inputs.push_back(source_of(block.input_port(read)));
  }
  step.calculation = emitter->c_calculation(port.index(), context_);
  const bool first_of_block =
      std::none_of(steps.begin(), steps.end(), [&](const Step& s) { return s.block == &block; });
  if (options_.updates && first_of_block && is_updated(block)) pending_.push_back(&block);
  steps.push_back(std::move(step));
  std::string signal = "s";  // piecewise: GCC 12 warns falsely (-Wrestrict) on "s" + ...
  signal += std::to_string(steps.size() - 1);
  return signal;
}

void Walk::visit_updated_blocks() {
  // Deferred: a block's inputs may read its own outputs through a loop that only its state
  // breaks (the actor's update reads the exploration, which reads the actor's action).
  while (!pending_.empty()) {
    const Block* block = pending_.front();
    pending_.erase(pending_.begin());
    UpdatedBlock entry;
    entry.block = block;
    for (int k = 0; k < block->num_output_ports(); ++k) {
      entry.outputs.push_back(visit(block->output_port(k)));
    }
    for (int k = 0; k < block->num_input_ports(); ++k) {
      entry.inputs.push_back(source_of(block->input_port(k)));
    }
    updated.push_back(std::move(entry));
  }
}

std::string Walk::source_of(const InputPort& input) {
  const Diagram::InputOrigin origin = root_.origin_of(input);
  if (origin.output != nullptr) return visit(*origin.output);
  if (origin.fixed != nullptr) return constant("fixed", *origin.fixed);
  const InputPort& port = root_.input_port(origin.diagram_input);
  return argument(is_c_identifier(port.name()) ? port.name() : "in" + std::to_string(port.index()),
                  port.size());
}

std::string Walk::argument(const std::string& name, int size) {
  const bool known = std::any_of(arguments.begin(), arguments.end(),
                                 [&name](const Argument& a) { return a.name == name; });
  if (!known) arguments.push_back({name, size});
  return name;
}

// A constant of the export's own (`kind`N), named as a block's body names its constants.
std::string Walk::constant(const char* kind, const Vector& values) {
  fixed.push_back(
      {kind + std::to_string(fixed.size()), std::vector<double>(values.begin(), values.end())});
  return "$" + fixed.back().name;
}

}  // namespace cbbg::codegen
