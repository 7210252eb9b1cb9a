#include "cbbg/framework/primitives/adder.h"

#include <stdexcept>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

Adder::Adder(std::string name, const std::vector<Input>& inputs, int size)
    : Block(std::move(name)) {
  const std::string label = primitive_checks::label("Adder", this->name());
  if (inputs.empty()) {
    throw std::invalid_argument(label + ": no inputs; give at least one");
  }
  primitive_checks::checked_size(label, size);
  for (const auto& input : inputs) {
    if (input.sign != 1 && input.sign != -1) {
      throw std::invalid_argument(label + ": input '" + input.name + "' has sign " +
                                  std::to_string(input.sign) + "; a sign is +1 or -1");
    }
  }
  std::vector<const InputPort*> ports;
  for (const auto& input : inputs) {
    ports.push_back(&declare_input_port(input.name, size));
    terms_.push_back({ports.back(), input.sign < 0});
  }
  declare_output_port<&Adder::calc_sum>("y", size, ports, "the signed sum of the inputs",
                                        OutputSources::kDiscreteState);
}

void Adder::calc_sum(const BlockContext& context, VectorRef y) const {
  const Term& first = terms_.front();
  if (first.subtract) {
    y = -context.input(*first.port);
  } else {
    y = context.input(*first.port);
  }
  for (std::size_t i = 1; i < terms_.size(); ++i) {
    if (terms_[i].subtract) {
      y -= context.input(*terms_[i].port);
    } else {
      y += context.input(*terms_[i].port);
    }
  }
}

}  // namespace cbbg
