#include "cbbg/plant/simbody_plant.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/multibody_robot.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/plant_state.h"
#include "cbbg/plant/robot_dynamics.h"

#include "cbbg/framework/number_text.h"

namespace cbbg::plant {
namespace {}  // namespace

// One context's multibody system and run, and the time and state at which the run last
// matched the context.
class SimbodyPlant::Scratch final : public BlockScratch {
 public:
  explicit Scratch(const RobotParams& params)
      : run(std::make_shared<const MultibodyRobot>(params)) {}

  // A copy gets a system of its own; its run starts where this one is (its integrator
  // restarts from that state).
  std::unique_ptr<BlockScratch> clone() const override {
    auto copy = std::make_unique<Scratch>(run.robot().params());
    if (std::isfinite(synced_time)) {
      Eigen::Matrix<double, kStateSize, 1> state;
      run.get_state(state);
      copy->run.set_state(run.time(), state);
      copy->synced_time = synced_time;
      copy->synced_state = synced_state;
    }
    return copy;
  }

  // Restarts the run from the context's state unless it is still where the run left it.
  void sync(const Block& plant, double time, const Eigen::Ref<const Eigen::VectorXd>& state) {
    if (time == synced_time && state == synced_state) return;
    check_state_finite(plant, state, time);
    run.set_state(time, state);
    synced_time = time;
    synced_state = state;
  }

  MultibodyRobotRun run;
  double synced_time = std::numeric_limits<double>::quiet_NaN();
  Eigen::Matrix<double, kStateSize, 1> synced_state = Eigen::Matrix<double, kStateSize, 1>::Zero();
};

SimbodyPlant::SimbodyPlant(std::string name, const RobotParams& params, double initial_pitch,
                           DisturbanceInput disturbance)
    : RobotPlant(std::move(name)), params_(params) {
  params_.validate_rigid_bodies();
  torque_ = &declare_input_port("torque", kTorqueSize,
                                "tau_l, tau_r: motor torques body -> wheel, N m (saturated here)");
  disturbance_ = declare_disturbance_input(disturbance);
  declare_output_port<&SimbodyPlant::calc_state>(
      "state", kStateSize, {},
      "theta_b, theta_b', phi_l, phi_r, phi_l', phi_r', x, y, yaw, yaw rate");
  declare_self_integrated_state<&SimbodyPlant::advance>(initial_state_vector(initial_pitch));
}

void SimbodyPlant::calc_state(const BlockContext& context, VectorRef y) const {
  y = context.continuous_state();
}

void SimbodyPlant::advance(BlockContext& context, double end_time) const {
  const ConstVectorView tau = context.input(*torque_);
  check_torque_finite(*this, tau);
  Scratch& scratch = context.scratch<Scratch>();
  VectorView state = context.mutable_continuous_state();
  const double start_time = context.time();
  scratch.sync(*this, start_time, state);
  const Torques applied =
      saturate_torque(Torques(tau[kTauLeft], tau[kTauRight]), params_.torque_limit);
  scratch.run.set_torque(applied[kTauLeft], applied[kTauRight]);
  if (disturbance_ != nullptr) {
    const ConstVectorView push = context.input(*disturbance_);
    check_disturbance_finite(*this, push);
    scratch.run.set_disturbance(push[kPushForce], push[kPushPitchTorque]);
  }
  try {
    scratch.run.advance_to(end_time);
  } catch (const std::exception& error) {
    scratch.synced_time = std::numeric_limits<double>::quiet_NaN();  // restart next time
    throw SimulationError("block '" + path() +
                          "': Simbody could not advance from t = " + format_number(start_time) +
                          " to " + format_number(end_time) + ": " + error.what());
  }
  scratch.run.get_state(state);
  check_state_finite(*this, state, end_time);
  scratch.synced_time = end_time;
  scratch.synced_state = state;
}

SimbodyPlant::~SimbodyPlant() = default;

std::unique_ptr<BlockScratch> SimbodyPlant::make_scratch() const {
  return std::make_unique<Scratch>(params_);
}

void SimbodyPlant::reset(Context& context, double initial_pitch) const {
  set_state(context, initial_state_vector(initial_pitch));
}

void SimbodyPlant::set_state(Context& context, const Vector& state) const {
  check_state_argument(*this, state);
  Vector consistent = state;
  consistent[kYawRate] = yaw_rate(params(), state[kPhiLeftDot], state[kPhiRightDot]);
  context.continuous_state(*this) = consistent;
}

SimbodyPlant::Scratch& SimbodyPlant::synced_scratch(Context& context) const {
  auto& scratch = static_cast<Scratch&>(*context.scratch(context.diagram().leaf_index(*this)));
  scratch.sync(*this, context.time(), context.continuous_state(*this));
  return scratch;
}

double SimbodyPlant::multibody_energy(Context& context) const {
  return synced_scratch(context).run.mechanical_energy();
}

}  // namespace cbbg::plant
