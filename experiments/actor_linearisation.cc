#include "cbbg/experiments/actor_linearisation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/telemetry.h"
#include "cbbg/framework/control/discretize.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/plant_ports.h"

namespace cbbg::experiments {
namespace {

// The two-wheeler's state output (plant_ports.h) for a linearised state x, both wheels alike.
Vector plant_state(const Eigen::Vector4d& x) {
  Vector state = Vector::Zero(plant::kStateSize);
  state[plant::kThetaB] = x[0];
  state[plant::kPhiLeft] = state[plant::kPhiRight] = x[1];
  state[plant::kThetaBDot] = x[2];
  state[plant::kPhiLeftDot] = state[plant::kPhiRightDot] = x[3];
  return state;
}

// The actor's slopes: small enough to stay on the features' smooth part, large enough for
// double precision (rad, rad, rad/s, rad/s).
Eigen::Vector4d slopes_at_rest(const parameters::Parameters& p,
                               const diagrams::ClosedLoopFactory& policy,
                               const LearntWeights& weights) {
  parameters::Parameters q = p;
  q.plant.kind = "analytic";  // the actor's law does not depend on the plant; its state is set
  q.sensors = blocks::SensorsParams{};
  const diagrams::ClosedLoop loop = policy(q);
  const auto* robot = dynamic_cast<const plant::AnalyticPlant*>(loop.plant);
  if (robot == nullptr) {
    throw std::invalid_argument(
        "linearise_actor: the policy's plant is its own, not the "
        "two-wheeler's; its state cannot be set");
  }
  auto context = loop.diagram->create_context(static_cast<std::uint64_t>(p.run.seed));
  loop.start_trial(*context, 0.0);
  load_learnt_weights(loop, *context, weights);
  auto action_at = [&](const Eigen::Vector4d& x) {
    robot->set_state(*context, plant_state(x));
    return loop.diagram->eval_output(*context, *loop.telemetry)[diagrams::kTelemetryActorAction];
  };
  const Eigen::Vector4d step(1e-5, 1e-4, 1e-5, 1e-4);
  Eigen::Vector4d slopes;
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector4d dx = Eigen::Vector4d::Zero();
    dx[i] = step[i];
    slopes[i] = (action_at(dx) - action_at(-dx)) / (2.0 * step[i]);
  }
  return slopes;
}

}  // namespace

ActorLinearisation linearise_actor(const parameters::Parameters& parameters,
                                   const diagrams::ClosedLoopFactory& policy,
                                   const LearntWeights& weights) {
  ActorLinearisation result;
  result.slopes = slopes_at_rest(parameters, policy, weights);
  const plant::LinearModel robot = diagrams::planar_linearization(parameters);
  const double period = parameters.trial.period;
  const control::StateSpace held = control::c2d(robot.A, robot.B, period);
  const Eigen::MatrixXd closed = held.A + held.B * result.slopes.transpose();
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(closed);
  for (Eigen::Index i = 0; i < closed.rows(); ++i) {
    ClosedLoopMode mode;
    mode.z = solver.eigenvalues()[i];
    mode.s = std::log(mode.z) / period;
    solver.eigenvectors().col(i).cwiseAbs().maxCoeff(&mode.leans_on);
    result.modes.push_back(mode);
  }
  std::sort(result.modes.begin(), result.modes.end(),
            [](const ClosedLoopMode& a, const ClosedLoopMode& b) {
              return std::abs(a.z) > std::abs(b.z);
            });
  return result;
}

}  // namespace cbbg::experiments
