#pragma once

#include <string>
#include <vector>

#include "cbbg/framework/block.h"

namespace cbbg {

/// Multiplexer: concatenates its inputs, in order, into one vector.
///
/// | port          | dir | size        | meaning                  |
/// |---------------|-----|-------------|--------------------------|
/// | (each input)  | in  | its size    | one per declared input   |
/// | y             | out | sum of them | the inputs, concatenated |
class Multiplexer final : public Block {
 public:
  struct Input {
    std::string name;
    int size;
  };
  Multiplexer(std::string name, const std::vector<Input>& inputs);

 private:
  // "y": the inputs, copied one after the other.
  void calc_y(const BlockContext& context, VectorRef y) const;

  std::vector<const InputPort*> inputs_;
};

}  // namespace cbbg
