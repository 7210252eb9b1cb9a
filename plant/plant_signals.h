#pragma once
// A plant's "state" output, by name: each plant says which signal sits at which index, and
// the closed loop (sensors, task, telemetry, steps.csv, the replay) finds what it needs by
// those names. The two-wheeler's ten signals are plant_ports.h's; a plant of another shape
// (a cart-pole, a plant without a pose) names its own.
//
//   required  pitch, pitch_rate                      body pitch, rad (> 0 leans forward); rad/s
//             wheel_left, wheel_right,               each wheel's angle, rad, and rate, rad/s;
//             wheel_left_rate, wheel_right_rate      or, for one driven wheel (or a cart),
//             (or wheel, wheel_rate)                 wheel and wheel_rate, read for both sides
//   optional  x, y, yaw                              the true pose, m, m, rad
//             yaw_rate and any name of the plant's   carried, not read; recorded in
//                                                    steps.csv when the plant logs it
//
// A pose signal a plant lacks is NaN in the telemetry and absent from steps.csv. A plant's
// logged signals (RobotPlant::logged_signals) are steps.csv's last columns, named as the
// plant names them.

#include <string>
#include <vector>

namespace cbbg::plant {

// The two-wheeler's signals, in plant_ports.h's order (StateIndex).
const std::vector<std::string>& two_wheeler_signals();

// A signal the plant asks the loop to record: its name (its steps.csv column) and where it
// sits in the state output.
struct LoggedSignal {
  std::string name;
  int index = -1;
  bool operator==(const LoggedSignal&) const = default;
};

// Where each signal the closed loop reads or records sits in a plant's state output.
struct SignalIndex {
  int pitch = -1;
  int pitch_rate = -1;
  int wheel_left = -1;
  int wheel_right = -1;
  int wheel_left_rate = -1;
  int wheel_right_rate = -1;
  int x = -1;  // -1: the plant has no such signal
  int y = -1;
  int yaw = -1;
  std::vector<LoggedSignal> logged;  // in the order the plant logs them

  bool has_pose() const { return x >= 0 && y >= 0 && yaw >= 0; }
};

// The indices of `signals`, the names of plant `plant`'s state output, and of `logged`, those
// it logs. Throws std::invalid_argument naming the plant and the signal when a required one
// is missing, a name is given twice, or a logged one is not a signal, is logged twice or is
// the pose (recorded anyway).
SignalIndex index_signals(const std::string& plant, const std::vector<std::string>& signals,
                          const std::vector<std::string>& logged = {});
// The two-wheeler's: index_signals of two_wheeler_signals().
const SignalIndex& two_wheeler_index();

}  // namespace cbbg::plant
