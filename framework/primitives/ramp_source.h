#pragma once

#include <string>

#include "cbbg/framework/block.h"

namespace cbbg {

/// RampSource: a ramp of a given slope from a start time, elementwise:
///
///     y(t) = y0 for t < t_start,    y(t) = y0 + s (t - t_start) for t >= t_start.
///
/// | port | dir | size | meaning                        |
/// |------|-----|------|--------------------------------|
/// | y    | out | n    | y0 + s max(0, t - t_start)     |
///
/// y depends on the context's time alone (no input, no state).
class RampSource final : public Block {
 public:
  // Throws std::invalid_argument naming the block and the argument unless the slope s and y0
  // have the same size n >= 1 and every value, t_start included, is finite.
  RampSource(std::string name, const Vector& slope, double start_time, const Vector& initial_value);
  // n = 1.
  RampSource(std::string name, double slope, double start_time, double initial_value = 0.0);

 private:
  // "y": y0 + s max(0, t - t_start).
  void calc_y(const BlockContext& context, VectorRef y) const;

  Vector slope_;
  double start_time_;
  Vector initial_value_;
};

}  // namespace cbbg
