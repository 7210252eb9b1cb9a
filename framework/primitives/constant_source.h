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

 private:
  Vector value_;
};

}  // namespace cbbg
