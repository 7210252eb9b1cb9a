#pragma once

#include <vector>

#include "cbbg/framework/block.h"

namespace cbbg {

/// Selector: some elements of its input, in the order given: y_i = u[indices_i].
///
/// | port | dir | size           | meaning          |
/// |------|-----|----------------|------------------|
/// | u    | in  | n              | input            |
/// | y    | out | indices.size() | u at the indices |
class Selector final : public Block {
 public:
  // Throws std::invalid_argument naming the block unless `indices` is non-empty and each
  // index is in [0, input_size).
  Selector(std::string name, int input_size, std::vector<int> indices);

 private:
  // "y": u at the indices, in order.
  void calc_y(const BlockContext& context, VectorRef y) const;

  std::vector<int> indices_;
  const InputPort* u_;
};

}  // namespace cbbg
