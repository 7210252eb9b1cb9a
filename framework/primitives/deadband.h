#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// Deadband (Simulink's Dead Zone): zero inside [lower, upper], the distance past the nearer
/// limit outside it, elementwise:
///
///   y_i = 0              if lower_i <= u_i <= upper_i
///   y_i = u_i - upper_i  if u_i > upper_i
///   y_i = u_i - lower_i  if u_i < lower_i
///
/// | port | dir | size | meaning                  |
/// |------|-----|------|--------------------------|
/// | u    | in  | n    | input                    |
/// | y    | out | n    | u less the dead zone     |
///
/// The limits are one pair for every element or a pair per element; -inf below or inf above
/// leaves that side without a zone. A NaN input gives NaN. y reads u directly (direct
/// feedthrough).
class Deadband final : public Block {
 public:
  // The same limits for each of `size` elements. Throws std::invalid_argument naming the
  // block unless size >= 1, lower <= upper, neither is NaN, lower < inf and upper > -inf.
  Deadband(std::string name, double lower, double upper, int size);
  // Limits per element (n = their size, the same for both), checked as above element by
  // element.
  Deadband(std::string name, Vector lower, Vector upper);

 private:
  void declare_ports(bool per_element);
  // "y": u less the dead zone, elementwise.
  void calc_y(const BlockContext& context, VectorRef y) const;

  Vector lower_;
  Vector upper_;
  const InputPort* u_;
};

}  // namespace cbbg
