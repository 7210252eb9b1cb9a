#pragma once

#include <string>
#include <vector>

#include "cbbg/framework/block.h"

namespace cbbg {

/// Demultiplexer: splits its input, in order, into named outputs of given sizes (the mirror
/// of Multiplexer): output i is u[o_i, o_i + n_i), where o_i = n_0 + ... + n_{i-1}.
///
/// | port          | dir | size        | meaning                        |
/// |---------------|-----|-------------|--------------------------------|
/// | u             | in  | sum of n_i  | the vector to split            |
/// | (each output) | out | n_i         | one per declared output, a cut |
///
/// Every output reads u directly (direct feedthrough).
class Demultiplexer final : public Block {
 public:
  struct Output {
    std::string name;
    int size;
  };
  // Throws std::invalid_argument naming the block unless there is at least one output and
  // each size is >= 1.
  Demultiplexer(std::string name, const std::vector<Output>& outputs);
};

}  // namespace cbbg
