#pragma once
// RemotePlant: a robot driven over a link (robot_link.h) in real time, as a plant block, so
// that a trial runs against it exactly as against a simulated plant. Its state is the last
// measurement; advancing one period sends the held torque and waits for the next one.
//
// | port   | dir | size | meaning                                              |
// |--------|-----|------|------------------------------------------------------|
// | torque | in  | 2    | tau_l, tau_r, N m: sent to the robot at each tick    |
// | state  | out | n    | the robot's measured signals (the two-wheeler's 10)  |
//
// The robot's clock sets the pace: each advance waits for the robot's next measurement, at
// most remote.timeout_periods periods. Events other than the period's (push.start, say)
// would split a period, which a robot cannot: they are refused as SimulationError.

#include <memory>

#include "cbbg/plant/robot_params.h"
#include "cbbg/plant/robot_plant.h"
#include "cbbg/realtime/robot_link.h"

namespace cbbg::realtime {

class RemotePlant final : public plant::RobotPlant {
 public:
  // `robot`: the robot's sizes as the config states them (plant.*), for the trials' forward
  // speed and the replay's drawing.
  RemotePlant(std::string name, LinkOptions link, const plant::RobotParams& robot);

  void reset(Context& context, double initial_pitch) const override;
  std::vector<std::string> signals() const override { return link_->options().signals; }
  double wheel_radius() const override { return robot_.wheel_radius; }
  plant::PlantDrawing drawing() const override { return plant::two_wheeler_drawing(robot_); }

  RobotLink& link() const { return *link_; }

 private:
  // "state": the continuous state, the last measurement.
  void calc_state(const BlockContext& context, VectorRef y) const;
  // Sends the held torque and waits for the robot's next measurement, its new state; refuses
  // a step that is not one whole period.
  void advance(BlockContext& context, double end_time) const;

  std::unique_ptr<RobotLink> link_;  // one session per plant, opened at its first trial
  plant::RobotParams robot_;
  const InputPort* torque_;
};

}  // namespace cbbg::realtime
