#pragma once

#include <string>

#include "cbbg/framework/block.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// A push on the robot (cbbg eval --push-time, --push-torque, --push-duration).
struct PushParams {
  double start = 5.0;     // push.start: when it begins, s from the trial's start, >= 0
  double torque = 0.0;    // push.torque: added to each wheel's torque, N m, finite
  double duration = 0.2;  // push.duration: how long it lasts, s, > 0

  static constexpr const char* kSection = "push";
  template <class Archive>
  void describe(Archive& a) {
    a.number("torque", torque,
             "a torque pulse added to each wheel in every trial, N m; 0 = none (disturbance)",
             kFinite);
    a.number("start", start, "when the push begins, s from the trial's start", kNonNegative);
    a.number("duration", duration, "how long the push lasts, s", kPositive);
  }

  // Throws std::invalid_argument naming push.start, push.torque or push.duration unless
  // each is finite and in its range.
  void validate() const;
};

/// TorquePush: a disturbance, as a torque pulse added to the held action of both wheels.
///
/// | port   | dir | size | meaning                                    |
/// |--------|-----|------|--------------------------------------------|
/// | action | in  | 1    | a, the held (zero-order hold) action, N m  |
/// | torque | out | 1    | a + p, the torque each wheel gets, N m     |
///
/// Equations: at each tick t_k = k Ts the periodic update sets
///   p = torque if start <= t_k < start + duration, else 0
/// (comparisons within the simulator's 1e-9 * max(1, |t|) of simultaneity) and p holds until
/// t_{k+1}. The push therefore switches only at tick instants, where the action does too: the
/// torque is piecewise constant between ticks and both plants integrate it exactly. It starts
/// at the first tick at or after `start` and covers the ticks before start + duration. The
/// plant saturates the sum a + p (plant.torque_limit).
/// Parameters: PushParams, the period Ts = trial.period.
///
/// Discrete state: [p].
class TorquePush final : public Block {
 public:
  TorquePush(std::string name, const PushParams& params, double period);

 private:
  PushParams params_;
};

}  // namespace cbbg::blocks
