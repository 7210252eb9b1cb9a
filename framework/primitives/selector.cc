#include "cbbg/framework/primitives/selector.h"

#include <stdexcept>
#include <string>

#include "cbbg/framework/block_context.h"

namespace cbbg {

Selector::Selector(std::string name, int input_size, std::vector<int> indices)
    : Block(std::move(name)), indices_(std::move(indices)) {
  if (indices_.empty()) {
    throw std::invalid_argument("selector '" + this->name() + "': select at least one element");
  }
  for (const int index : indices_) {
    if (index < 0 || index >= input_size) {
      throw std::invalid_argument("selector '" + this->name() + "': index " +
                                  std::to_string(index) + " is outside its input of size " +
                                  std::to_string(input_size));
    }
  }
  u_ = &declare_input_port("u", input_size);
  declare_output_port<&Selector::calc_y>("y", static_cast<int>(indices_.size()), {u_},
                                         "u at the indices", OutputSources::kDiscreteState);
}

void Selector::calc_y(const BlockContext& context, VectorRef y) const {
  const ConstVectorView input = context.input(*u_);
  for (std::size_t i = 0; i < indices_.size(); ++i)
    y[static_cast<Eigen::Index>(i)] = input[indices_[i]];
}

}  // namespace cbbg
