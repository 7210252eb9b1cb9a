#pragma once
// Test rigs for the plants: the PD law of docs/model.md §2.4 as small test-local blocks (the
// project's PD supervisor block lives in blocks/ and is tested there), and diagrams that put either
// plant behind them.

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/framework/random.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/robot_params.h"
#include "cbbg/plant/simbody_plant.h"
#ifdef CBBG_WITH_MUJOCO
#include "cbbg/plant/mujoco/mujoco_plant.h"
#endif

namespace cbbg::plant::testing {

inline constexpr double kPeriod = 0.01;  // trial.period

// a = sign (50 theta_b + 10 theta_b' + (phi_l + phi_r) / 2 + (phi_l' + phi_r') / 2),
// tau_l = tau_r = a (docs/model.md §2.4; the plant saturates). Direct feedthrough: a hold follows
// it.
inline double pd_action(const ConstVectorView& x, double sign) {
  return sign * (50.0 * x[kThetaB] + 10.0 * x[kThetaBDot] + (x[kPhiLeft] + x[kPhiRight]) / 2.0 +
                 (x[kPhiLeftDot] + x[kPhiRightDot]) / 2.0);
}

class PdLaw final : public Block {
 public:
  PdLaw(std::string name, double sign) : Block(std::move(name)) {
    const InputPort& state = declare_input_port("state", kStateSize);
    declare_output_port("torque", kTorqueSize,
                        [&state, sign](const BlockContext& context, VectorRef torque) {
                          torque.setConstant(pd_action(context.input(state), sign));
                        },
                        {&state});
  }
};

// The PD action plus noise drawn every period, e ~ N(0, sigma^2) from the context's
// generator: kDifferential makes the robot turn, the held torques (a + e, a - e);
// kCommon explores as a learner's sampler does, (a + e, a + e).
enum class Noise { kDifferential, kCommon };

class NoisyPdLaw final : public Block {
 public:
  NoisyPdLaw(std::string name, double sigma, Noise noise) : Block(std::move(name)) {
    const InputPort& state = declare_input_port("state", kStateSize);
    declare_discrete_state("state", Vector::Zero(kTorqueSize), StateLifetime::kPersistent);
    declare_output_port(
        "torque", kTorqueSize,
        [](const BlockContext& context, VectorRef torque) { torque = context.discrete_state(); },
        {});
    declare_periodic_update(
        kPeriod, 0.0, [&state, sigma, noise](BlockContext& context, VectorRef next) {
          const double a = pd_action(context.input(state), 1.0);
          const double e = sigma * draw_standard_normal(context.random_generator());
          next[kTauLeft] = a + e;
          next[kTauRight] = noise == Noise::kCommon ? a + e : a - e;
          return EventStatus::succeeded();
        });
  }
};

enum class PlantKind { kAnalytic, kSimbody, kMujoco };

inline std::string plant_name(PlantKind kind) {
  return kind == PlantKind::kAnalytic  ? "Analytic"
         : kind == PlantKind::kSimbody ? "Simbody"
                                       : "Mujoco";
}

enum class Control { kFixedTorque, kPd, kPdFlipped, kTurningPd, kExploringPd };

// A diagram "robot" with the plant "plant" behind the chosen control.
struct Rig {
  std::unique_ptr<Diagram> diagram;
  PlantKind kind;
  const Block* plant = nullptr;
  const InputPort* torque_input = nullptr;  // the diagram's input, for kFixedTorque

  const OutputPort& state() const { return plant->output_port("state"); }
  void reset(Context& context, double pitch) const {
    static_cast<const RobotPlant&>(*plant).reset(context, pitch);
  }
  void set_state(Context& context, const Vector& state) const {
    if (kind == PlantKind::kAnalytic) {
      static_cast<const AnalyticPlant&>(*plant).set_state(context, state);
    } else {
      static_cast<const SimbodyPlant&>(*plant).set_state(context, state);
    }
  }
};

// With `disturbance` (force N, pitch torque N m), the plant declares its input "disturbance"
// and it is fixed to that value.
// kMujoco: the two-wheeler of `params` at MuJoCo's step `mujoco_step` (0: the model's).
inline Rig make_rig(PlantKind kind, const RobotParams& params, double pitch, Control control,
                    double sigma = 1.0, const std::optional<Vector>& disturbance = std::nullopt,
                    [[maybe_unused]] double mujoco_step = 0.0) {
  DiagramBuilder builder("robot");
  Rig rig;
  rig.kind = kind;
  const DisturbanceInput pushed =
      disturbance ? DisturbanceInput::kDeclared : DisturbanceInput::kNone;
  RobotPlant* plant = nullptr;
  if (kind == PlantKind::kAnalytic) {
    plant = &builder.emplace<AnalyticPlant>("plant", params, pitch, pushed);
  } else if (kind == PlantKind::kSimbody) {
    plant = &builder.emplace<SimbodyPlant>("plant", params, pitch, pushed);
  } else {
#ifdef CBBG_WITH_MUJOCO
    MujocoParams mujoco;
    mujoco.timestep = mujoco_step;
    plant = &builder.emplace<MujocoPlant>("plant", mujoco, params, pitch, pushed);
#else
    throw std::invalid_argument("a build without MuJoCo has no MuJoCo plant");
#endif
  }
  if (disturbance) builder.fix_input(*plant->disturbance_input(), *disturbance);
  rig.plant = plant;
  if (control == Control::kFixedTorque) {
    builder.export_input(plant->input_port("torque"), "torque");
  } else if (control == Control::kTurningPd || control == Control::kExploringPd) {
    auto& law = builder.emplace<NoisyPdLaw>(
        "law", sigma, control == Control::kTurningPd ? Noise::kDifferential : Noise::kCommon);
    builder.connect(*plant, "state", law, "state");
    builder.connect(law, "torque", *plant, "torque");
  } else {
    auto& law = builder.emplace<PdLaw>("law", control == Control::kPd ? 1.0 : -1.0);
    auto& hold = builder.emplace<ZeroOrderHold>("hold", kTorqueSize, kPeriod);
    builder.connect(*plant, "state", law, "state");
    builder.connect(law, "torque", hold, "u");
    builder.connect(hold, "y", *plant, "torque");
  }
  rig.diagram = builder.build();
  if (control == Control::kFixedTorque) rig.torque_input = &rig.diagram->input_port("torque");
  return rig;
}

// The Simulator for a rig, at params.accuracy (what the Simbody plant uses too).
inline std::unique_ptr<Simulator> make_simulator(const Rig& rig, const RobotParams& params,
                                                 const Vector& fixed_torque = Vector::Zero(2)) {
  auto simulator = std::make_unique<Simulator>(*rig.diagram, SimulatorOptions{params.accuracy});
  if (rig.torque_input != nullptr) simulator->context().fix_input(*rig.torque_input, fixed_torque);
  return simulator;
}

}  // namespace cbbg::plant::testing
