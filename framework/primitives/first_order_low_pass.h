#pragma once

#include <string>

#include "cbbg/framework/block.h"

namespace cbbg {

/// FirstOrderLowPass: a first-order lag of time constant tau > 0, elementwise on n signals:
///
///     x' = (u - x) / tau,    y = x,    x(0) = x0,
///
/// so under a constant input u, y(t) = u + (x0 - u) exp(-t / tau): a unit step from x0 = 0
/// gives 1 - exp(-t / tau). Its DC gain is 1 and its cut-off frequency 1 / tau rad/s.
///
/// | port | dir | size | meaning                 |
/// |------|-----|------|-------------------------|
/// | u    | in  | n    | the signal to smooth    |
/// | y    | out | n    | x, the smoothed signal  |
///
/// y reads the state alone, never u directly: the filter can close a feedback loop. x is
/// continuous state, integrated by the simulator (simulator.h step 3); reset_trial_state
/// keeps it, Context::reset_state puts x0 back.
class FirstOrderLowPass final : public Block {
 public:
  // x0 = 0. Throws std::invalid_argument naming the block unless tau is positive and finite
  // and size >= 1.
  FirstOrderLowPass(std::string name, double time_constant, int size);
  // n = the size of x0; throws also unless x0 is finite and has at least one element.
  FirstOrderLowPass(std::string name, double time_constant, const Vector& initial_value);

  double time_constant() const { return time_constant_; }

 private:
  // x' = (u - x) / tau.
  void calc_derivatives(const BlockContext& context, VectorRef derivatives) const;
  // "y": x.
  void calc_y(const BlockContext& context, VectorRef y) const;

  double time_constant_;
  const InputPort* u_;
};

}  // namespace cbbg
