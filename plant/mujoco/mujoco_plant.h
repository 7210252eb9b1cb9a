#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/plant/mujoco/mujoco_params.h"
#include "cbbg/plant/robot_params.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::plant {

/// MujocoPlant: any robot from its model file (MJCF or URDF), simulated by MuJoCo; with no
/// file, the paper's two-wheeler written from plant.* (two_wheeler_mjcf.h), its wheels in
/// contact with the ground.
///
/// | port   | dir | size | meaning                                                         |
/// |--------|-----|------|-----------------------------------------------------------------|
/// | torque | in  | 2    | tau_l, tau_r, N m: to mujoco.actuators (two: one each; one:     |
/// |        |     |      | their sum), each clamped by its ctrlrange where the model has one |
/// | disturbance | in | 2 | with DisturbanceInput::kDeclared only: a force along the heading |
/// |        |     |      | at mujoco.body's centre of mass, N; a torque leaning it forward |
/// |        |     |      | about the horizontal across the heading, N m (held for the tick) |
/// | state  | out | n    | the model's sensors, one signal each, named by the sensors      |
///
/// Signals: every sensor of the model must be one number (jointpos, jointvel, ...), and the
/// names must include what the loop reads (plant/plant_signals.h): the two-wheeler's sensors
/// are pitch, pitch_rate, wheel_left, ... yaw_rate. A model with no sensor (a URDF file)
/// gives each hinge or slide joint as two signals, NAME and NAME_rate; a joint named in
/// mujoco.actuators takes its torque as a force between its body and the parent.
/// Continuous state: the signals, then MuJoCo's qpos, qvel, act and its solver's warm start,
/// so a context copied or restored mid-run continues as the original does (to rounding: MuJoCo
/// keeps a few internals of its own) and every copy alike. Each context's
/// scratch holds its own mjData on the plant's one mjModel (read only while running).
/// Between the simulator's instants the plant takes (end - start) / timestep steps of MuJoCo
/// with the inputs held, then computes the sensors at the end.
/// Drawing (the replay page's): a model file's own shapes (model_drawing.h); the built-in
/// two-wheeler is drawn as the other plants' two-wheeler is.
/// Errors: the constructor throws std::invalid_argument naming the mujoco.* key and the
/// model's element it misses; a non-finite input or state, or MuJoCo resetting a diverged
/// simulation, throws SimulationError naming the block.
class MujocoPlant final : public RobotPlant {
 public:
  MujocoPlant(std::string name, const MujocoParams& params, const RobotParams& robot,
              double initial_pitch = kDefaultInitialPitch,
              DisturbanceInput disturbance = DisturbanceInput::kNone);
  ~MujocoPlant() override;

  // Every joint at the model's qpos0 but mujoco.pitch_joint at initial_pitch, at rest.
  void reset(Context& context, double initial_pitch) const override;
  std::vector<std::string> signals() const override { return signals_; }
  double wheel_radius() const override { return wheel_radius_; }
  PlantDrawing drawing() const override { return drawing_; }
  std::unique_ptr<BlockScratch> make_scratch() const override;

  // MuJoCo's step, s (mujoco.timestep or the model's).
  double timestep() const;

 private:
  struct Model;
  class Scratch;

  // "state": the signals, the head of the continuous state.
  void calc_state(const BlockContext& context, VectorRef y) const;
  // Takes MuJoCo's steps to `end_time` with the torque (and the push) held, then packs the
  // continuous state; throws when MuJoCo diverges or the state is not finite.
  void advance(BlockContext& context, double end_time) const;

  std::shared_ptr<const Model> model_;
  const InputPort* torque_;
  const InputPort* disturbance_;  // null without DisturbanceInput::kDeclared
  std::vector<std::string> signals_;
  double wheel_radius_;
  PlantDrawing drawing_;
};

}  // namespace cbbg::plant
