#pragma once

#include "cbbg/framework/block.h"

namespace cbbg {

/// RateLimiter: a discrete rate limit of period h. At the sample instants t_k = offset + k h,
/// its output moves toward the input by at most rising h up or falling h down:
///
///   y_k = y_{k-1} + clamp(u_k - y_{k-1}, -falling h, rising h),  y_{-1} = initial value
///
/// elementwise; where the step is within the limits, y_k = u_k exactly. Both rates are
/// magnitudes (>= 0, in units of u per second); inf leaves that direction unlimited.
///
/// | port | dir | size | meaning                  |
/// |------|-----|------|--------------------------|
/// | u    | in  | n    | the signal to limit      |
/// | y    | out | n    | the rate-limited signal  |
///
/// The state holds y; y reads only the state, never u directly, so a rate limiter breaks
/// feedback loops. Timing (simulator.h step 2): at t_k every output is evaluated before any
/// update, so what other blocks' updates and logs read at t_k is y_{k-1}; the update at t_k
/// then computes y_k from u_k, which y shows from just after t_k until t_{k+1} included. A
/// discrete block at the same period therefore sees the limited signal one period late (as
/// through a UnitDelay); a continuous block sees y_k during (t_k, t_{k+1}]. The state is per
/// trial: Context::reset_trial_state puts the initial value back.
class RateLimiter final : public Block {
 public:
  // From zero. Throws std::invalid_argument naming the block unless size >= 1, both rates
  // are >= 0 (inf allowed, NaN not), the period is positive and finite and the offset is
  // finite and >= 0.
  RateLimiter(std::string name, int size, double rising_rate, double falling_rate, double period,
              double offset = 0.0);
  // From `initial_value` (n = its size, every element finite), checked as above.
  RateLimiter(std::string name, const Vector& initial_value, double rising_rate,
              double falling_rate, double period, double offset = 0.0);

 private:
  // "y": the state, y_{k-1} until the update at t_k.
  void calc_y(const BlockContext& context, VectorRef y) const;
  // y_k = y_{k-1} + clamp(u_k - y_{k-1}, -falling h, rising h). Writes in place: it reads and
  // writes its state through `next` alone.
  EventStatus limit(BlockContext& context, VectorRef next) const;

  double max_rise_;  // rising h
  double max_fall_;  // falling h
  const InputPort* u_;
};

}  // namespace cbbg
