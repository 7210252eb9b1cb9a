#pragma once
// A plant of any kind alone, stepped one period at a time with a held torque: what
// `cbbg robot` serves. It integrates as a closed loop's simulator does, period by period, so
// a real-time run without deadline misses meets the same robot as a simulated run.

#include <memory>
#include <string>
#include <vector>

#include "cbbg/framework/diagram.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::realtime {

class SimulatedRobot {
 public:
  // `plant` stepped every `period` s, integrated at `accuracy` (trial.period and
  // plant.accuracy, as a closed loop does). Throws std::invalid_argument for a plant whose
  // signals are not the two-wheeler's (the wire's).
  SimulatedRobot(std::shared_ptr<plant::RobotPlant> plant, double period, double accuracy);

  // At rest at theta_b = theta0, the clock at 0.
  void reset(double theta0);
  // One period with the wheel torques held.
  void step(double tau_left, double tau_right);
  // The plant's signals now.
  std::vector<double> signals() const;
  const std::vector<std::string>& signal_names() const { return names_; }
  double period() const { return period_; }

 private:
  std::unique_ptr<Diagram> diagram_;
  const plant::RobotPlant* plant_ = nullptr;
  std::unique_ptr<Simulator> simulator_;
  std::vector<std::string> names_;
  double period_;
  long long ticks_ = 0;
};

}  // namespace cbbg::realtime
