#include "cbbg/framework/primitives/constant_source.h"

namespace cbbg {

ConstantSource::ConstantSource(std::string name, Vector value)
    : Block(std::move(name)), value_(std::move(value)) {
  declare_output_port(
      "y", static_cast<int>(value_.size()),
      [this](const BlockContext&, VectorRef y) { y = value_; }, {}, "the constant value",
      OutputSources::kDiscreteState);
}

}  // namespace cbbg
