#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// ConstantSource: outputs a constant vector.
///
/// | port | dir | size | meaning       |
/// |------|-----|------|---------------|
/// | y    | out | n    | the value     |
class ConstantSource final : public Block {
 public:
  ConstantSource(std::string name, Vector value);

  const Vector& value() const { return value_; }

 private:
  // "y": the value.
  void calc_y(const BlockContext& context, VectorRef y) const;

  Vector value_;
};

}  // namespace cbbg
