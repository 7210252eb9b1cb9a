#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// ZeroOrderHold: samples its input every `period` and holds it until the next sample.
///
/// | port  | dir | size | meaning                               |
/// |-------|-----|------|---------------------------------------|
/// | u     | in  | n    | the signal to sample                  |
/// | y     | out | n    | the last sample (initial value first) |
///
/// y reads only the block's state, never u directly: a hold breaks feedback loops.
class ZeroOrderHold final : public Block {
 public:
  ZeroOrderHold(std::string name, int size, double period, double offset = 0.0);
  ZeroOrderHold(std::string name, const Vector& initial_value, double period, double offset = 0.0);

 private:
  // "y": the state, the held sample.
  void calc_y(const BlockContext& context, VectorRef y) const;
  // Stores u's sample. Writes in place: it writes only.
  EventStatus sample(BlockContext& context, VectorRef next) const;

  const InputPort* u_;
};

}  // namespace cbbg
