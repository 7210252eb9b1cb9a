#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// Saturation: clamps its input elementwise between a lower and an upper limit:
///
///   y_i = min(max(u_i, lower_i), upper_i)
///
/// | port | dir | size | meaning                 |
/// |------|-----|------|-------------------------|
/// | u    | in  | n    | input                   |
/// | y    | out | n    | u clamped to the limits |
///
/// The limits are one pair for every element or a pair per element; -inf below or inf above
/// leaves that side open. y reads u directly (direct feedthrough).
class Saturation final : public Block {
 public:
  // The same limits for each of `size` elements. Throws std::invalid_argument naming the
  // block unless size >= 1, lower <= upper, neither is NaN, lower < inf and upper > -inf.
  Saturation(std::string name, double lower, double upper, int size);
  // Limits per element (n = their size, the same for both), checked as above element by
  // element.
  Saturation(std::string name, Vector lower, Vector upper);

 private:
  void declare_ports(bool per_element);
  // "y": u clamped to the limits, elementwise.
  void calc_y(const BlockContext& context, VectorRef y) const;

  Vector lower_;
  Vector upper_;
  const InputPort* u_;
};

}  // namespace cbbg
