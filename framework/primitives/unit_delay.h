#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// UnitDelay (z^-1): delays its input by one sample period h. At the sample instants
/// t_k = offset + k h:
///
///   y_k = x_k,  x_{k+1} = u_k,  x_0 = initial value
///
/// | port | dir | size | meaning                                        |
/// |------|-----|------|------------------------------------------------|
/// | u    | in  | n    | the signal to delay                            |
/// | y    | out | n    | the sample before (the initial value at first) |
///
/// Timing (simulator.h step 2): at t_k every output is evaluated before any update, so what
/// other blocks' updates and logs read at t_k is y_k = u_{k-1} (the initial value at t_0);
/// the update then stores u_k, which y shows from just after t_k until t_{k+1}. A discrete
/// block at the same period thus sees u one period late; a continuous block sees the latest
/// sample held, as ZeroOrderHold's output (the two blocks compute the same; their names say
/// what they are for). y reads only the state, never u directly: a delay breaks feedback
/// loops. The state is per trial: Context::reset_trial_state puts the initial value back.
class UnitDelay final : public Block {
 public:
  // From zero. Throws std::invalid_argument naming the block unless size >= 1, the period
  // is positive and finite and the offset is finite and >= 0.
  UnitDelay(std::string name, int size, double period, double offset = 0.0);
  // From `initial_value` (n = its size, every element finite), checked as above.
  UnitDelay(std::string name, const Vector& initial_value, double period, double offset = 0.0);

 private:
  // "y": the state, the sample before.
  void calc_y(const BlockContext& context, VectorRef y) const;
  // Stores u_k. Writes in place: it writes only.
  EventStatus latch(BlockContext& context, VectorRef next) const;

  const InputPort* u_;
};

}  // namespace cbbg
