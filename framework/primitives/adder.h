#pragma once

#include <string>
#include <vector>

#include "cbbg/framework/block.h"

namespace cbbg {

/// Adder: the signed sum of its inputs, elementwise: y = sum_i s_i u_i, each sign s_i +1 or
/// -1. A comparison is Adder("err", {{"r", +1}, {"y", -1}}, n): err = r - y.
///
/// | port         | dir | size | meaning                      |
/// |--------------|-----|------|------------------------------|
/// | (each input) | in  | n    | one per declared input, u_i  |
/// | y            | out | n    | sum_i s_i u_i                |
///
/// y reads every input directly (direct feedthrough). The first input is taken with its sign
/// (y = u_0 or -u_0), then each next one added or subtracted in order, so a two-input
/// difference is exactly r - y.
class Adder final : public Block {
 public:
  struct Input {
    std::string name;
    int sign;  // +1 or -1
  };
  // Throws std::invalid_argument naming the block unless there is at least one input, each
  // sign is +1 or -1 and size >= 1.
  Adder(std::string name, const std::vector<Input>& inputs, int size);

 private:
  // "y": the signed sum of the inputs, in order.
  void calc_sum(const BlockContext& context, VectorRef y) const;

  struct Term {
    const InputPort* port;
    bool subtract;
  };
  std::vector<Term> terms_;
};

}  // namespace cbbg
