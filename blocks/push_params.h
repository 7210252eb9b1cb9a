#pragma once
// push.*: a pulse that disturbs the robot during each trial, through its motors
// (TorquePush), from outside (ExternalPush), or both.

#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

struct PushParams {
  double start = 5.0;         // push.start: when it begins, s from the trial's start, >= 0
  double torque = 0.0;        // push.torque: added to each wheel's held action, N m, finite
  double duration = 0.2;      // push.duration: how long it lasts, s, > 0
  double force = 0.0;         // push.force: at the body's centre of mass, N, finite
  double pitch_torque = 0.0;  // push.pitch_torque: on the body about the axle, N m, finite

  static constexpr const char* kSection = "push";
  template <class Archive>
  void describe(Archive& a) {
    a.number("torque", torque,
             "through the motors: N m added to each wheel's held action before the motors' "
             "limit (plant.torque_limit), which therefore bounds the sum; 0 = none",
             kFinite);
    a.number("force", force,
             "from outside: a horizontal force on the body's centre of mass along the heading, "
             "N (> 0 pushes forward); 0 = none",
             kFinite);
    a.number("pitch_torque", pitch_torque,
             "from outside: a torque on the body about the axle, N m (> 0 leans it forward); "
             "0 = none",
             kFinite);
    a.number("start", start, "when the push begins, s from the trial's start", kNonNegative);
    a.number("duration", duration, "how long the push lasts, s", kPositive);
  }

  // Throws std::invalid_argument naming the push.* key unless each is finite and in range.
  void validate() const;

  bool through_motors() const { return torque != 0.0; }
  bool from_outside() const { return force != 0.0 || pitch_torque != 0.0; }
  bool any() const { return through_motors() || from_outside(); }
  // Whether the push is on at the tick t: start <= t < start + duration, within the
  // simulator's 1e-9 * max(1, |t|) of simultaneity, so that k Ts rounding never moves it by a
  // tick.
  bool on_at(double t) const;
};

}  // namespace cbbg::blocks
