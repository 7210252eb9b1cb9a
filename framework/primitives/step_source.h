#pragma once

#include <string>

#include "cbbg/framework/block.h"

namespace cbbg {

/// StepSource: a step from an initial to a final value at a step time, elementwise:
///
///     y(t) = y0 for t < t_step,    y(t) = y1 for t >= t_step.
///
/// | port | dir | size | meaning                 |
/// |------|-----|------|-------------------------|
/// | y    | out | n    | y0 before t_step, y1 on |
///
/// y depends on the context's time alone (no input, no state). A continuous block fed by it
/// sees the jump wherever it falls: the integrator's error control shortens its steps there.
class StepSource final : public Block {
 public:
  // Throws std::invalid_argument naming the block and the argument unless y0 and y1 have the
  // same size n >= 1 and every value, t_step included, is finite.
  StepSource(std::string name, const Vector& initial_value, const Vector& final_value,
             double step_time);
  // n = 1.
  StepSource(std::string name, double initial_value, double final_value, double step_time);

 private:
  // "y": y0 before t_step, y1 from it on.
  void calc_y(const BlockContext& context, VectorRef y) const;

  Vector initial_value_;
  Vector final_value_;
  double step_time_;
};

}  // namespace cbbg
