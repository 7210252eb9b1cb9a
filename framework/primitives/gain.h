#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// Gain: y = k u, elementwise with a scalar k.
///
/// | port | dir | size | meaning |
/// |------|-----|------|---------|
/// | u    | in  | n    | input   |
/// | y    | out | n    | k u     |
class Gain final : public Block {
 public:
  Gain(std::string name, double gain, int size);

 private:
  double gain_;
};

}  // namespace cbbg
