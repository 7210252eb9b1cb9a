#include "cbbg/plant/simbody/rolling_base_mobilizer.h"

#include <cmath>

#include "cbbg/plant/robot_dynamics.h"

namespace cbbg::plant::simbody {

using SimTK::Real;
using SimTK::SpatialVec;
using SimTK::Vec3;

namespace {
enum Q { kYawQ, kXQ, kYQ, kPhiLeftQ, kPhiRightQ };
}  // namespace

RollingBaseMobilizer::RollingBaseMobilizer(SimTK::SimbodyMatterSubsystem& matter,
                                           const RobotParams& params)
    : Implementation(matter, kU, kQ), matter_(&matter) {
  for (int j = 0; j < kU; ++j) {
    const double left = j == 0 ? 1.0 : 0.0;
    speed_[j] = forward_speed(params, left, 1.0 - left);
    turn_[j] = plant::yaw_rate(params, left, 1.0 - left);
  }
}

// The state's layout is fixed once the model stage is realised; the first call looks up
// where this mobilizer's q and u are, the later ones read them directly.
void RollingBaseMobilizer::locate(const SimTK::State& state) const {
  if (first_q_.isValid()) return;
  const SimTK::MobilizedBody& base = matter_->getMobilizedBody(index_);
  first_q_ = base.getFirstQIndex(state);
  first_u_ = base.getFirstUIndex(state);
}

double RollingBaseMobilizer::yaw(const SimTK::State& state) const {
  locate(state);
  return state.getQ()[first_q_ + kYawQ];
}

double RollingBaseMobilizer::yaw_rate(const SimTK::State& state) const {
  locate(state);
  const SimTK::Vector& u = state.getU();
  return turn_[0] * u[first_u_] + turn_[1] * u[first_u_ + 1];
}

SimTK::Transform RollingBaseMobilizer::calcMobilizerTransformFromQ(const SimTK::State&, int,
                                                                   const Real* q) const {
  return SimTK::Transform(SimTK::Rotation(q[kYawQ], SimTK::ZAxis), Vec3(q[kXQ], q[kYQ], 0));
}

// V_FM = H u, in the ground-fixed frame F: the yaw rate, and the forward speed along the heading.
SpatialVec RollingBaseMobilizer::multiplyByHMatrix(const SimTK::State& state, int,
                                                   const Real* u) const {
  const double psi = yaw(state);
  const double turn = turn_[0] * u[0] + turn_[1] * u[1];
  const double speed = speed_[0] * u[0] + speed_[1] * u[1];
  return SpatialVec(Vec3(0, 0, turn), Vec3(speed * std::cos(psi), speed * std::sin(psi), 0));
}

void RollingBaseMobilizer::multiplyByHTranspose(const SimTK::State& state, const SpatialVec& force,
                                                int, Real* f) const {
  const double psi = yaw(state);
  const double along = force[1][0] * std::cos(psi) + force[1][1] * std::sin(psi);
  for (int j = 0; j < kU; ++j) f[j] = turn_[j] * force[0][2] + speed_[j] * along;
}

// HDot u: the heading turns at the yaw rate, so the velocity's direction does.
SpatialVec RollingBaseMobilizer::multiplyByHDotMatrix(const SimTK::State& state, int,
                                                      const Real* u) const {
  const double psi = yaw(state);
  const double turning = (speed_[0] * u[0] + speed_[1] * u[1]) * yaw_rate(state);
  return SpatialVec(Vec3(0), Vec3(-turning * std::sin(psi), turning * std::cos(psi), 0));
}

void RollingBaseMobilizer::multiplyByHDotTranspose(const SimTK::State& state,
                                                   const SpatialVec& force, int, Real* f) const {
  const double psi = yaw(state);
  const double across = -force[1][0] * std::sin(psi) + force[1][1] * std::cos(psi);
  const double rate = yaw_rate(state);
  for (int j = 0; j < kU; ++j) f[j] = speed_[j] * rate * across;
}

// qdot = N u, or (transposed) the u-like N^T times a q-like input.
void RollingBaseMobilizer::multiplyByN(const SimTK::State& state, bool transpose, int,
                                       const Real* in, int, Real* out) const {
  const double psi = yaw(state);
  const double c = std::cos(psi);
  const double s = std::sin(psi);
  if (transpose) {
    for (int j = 0; j < kU; ++j) {
      out[j] = turn_[j] * in[kYawQ] + speed_[j] * (c * in[kXQ] + s * in[kYQ]) + in[kPhiLeftQ + j];
    }
    return;
  }
  const double speed = speed_[0] * in[0] + speed_[1] * in[1];
  out[kYawQ] = turn_[0] * in[0] + turn_[1] * in[1];
  out[kXQ] = speed * c;
  out[kYQ] = speed * s;
  out[kPhiLeftQ] = in[0];
  out[kPhiRightQ] = in[1];
}

// A left inverse of N: the wheel rates are the last two rows of qdot.
void RollingBaseMobilizer::multiplyByNInv(const SimTK::State&, bool transpose, int, const Real* in,
                                          int, Real* out) const {
  if (transpose) {
    out[kYawQ] = out[kXQ] = out[kYQ] = 0.0;
    out[kPhiLeftQ] = in[0];
    out[kPhiRightQ] = in[1];
    return;
  }
  out[0] = in[kPhiLeftQ];
  out[1] = in[kPhiRightQ];
}

void RollingBaseMobilizer::multiplyByNDot(const SimTK::State& state, bool transpose, int,
                                          const Real* in, int, Real* out) const {
  const double psi = yaw(state);
  const double rate = yaw_rate(state);
  const double dc = -std::sin(psi) * rate;  // d/dt cos(yaw)
  const double ds = std::cos(psi) * rate;   // d/dt sin(yaw)
  if (transpose) {
    for (int j = 0; j < kU; ++j) out[j] = speed_[j] * (dc * in[kXQ] + ds * in[kYQ]);
    return;
  }
  const double speed = speed_[0] * in[0] + speed_[1] * in[1];
  out[kYawQ] = out[kPhiLeftQ] = out[kPhiRightQ] = 0.0;
  out[kXQ] = speed * dc;
  out[kYQ] = speed * ds;
}

// The pose's yaw and position; the wheel angles are left as they are.
void RollingBaseMobilizer::setQToFitTransform(const SimTK::State&, const SimTK::Transform& pose,
                                              int, Real* q) const {
  const SimTK::Mat33& r = pose.R().asMat33();
  q[kYawQ] = std::atan2(r(1, 0), r(0, 0));
  q[kXQ] = pose.p()[0];
  q[kYQ] = pose.p()[1];
}

// The wheel rates that give the velocity's yaw rate and its speed along the heading.
void RollingBaseMobilizer::setUToFitVelocity(const SimTK::State& state, const SpatialVec& velocity,
                                             int, Real* u) const {
  const double psi = yaw(state);
  const double turn = velocity[0][2];
  const double speed = velocity[1][0] * std::cos(psi) + velocity[1][1] * std::sin(psi);
  const double det = speed_[0] * turn_[1] - speed_[1] * turn_[0];
  u[0] = (speed * turn_[1] - turn * speed_[1]) / det;
  u[1] = (turn * speed_[0] - speed * turn_[0]) / det;
}

}  // namespace cbbg::plant::simbody
