#include "cbbg/framework/primitives/constant_source.h"

namespace cbbg {

ConstantSource::ConstantSource(std::string name, Vector value)
    : Block(std::move(name)), value_(std::move(value)) {
  declare_output_port<&ConstantSource::calc_y>("y", static_cast<int>(value_.size()), {},
                                               "the constant value", OutputSources::kDiscreteState);
}

void ConstantSource::calc_y(const BlockContext&, VectorRef y) const { y = value_; }

}  // namespace cbbg
