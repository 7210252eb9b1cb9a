#pragma once
// Internal (includes Simbody): a custom mobilizer that rolls the robot's level base over the
// ground on its two wheels, so that rolling without slip needs no constraint.
//
// q = (yaw, x, y, phi_l, phi_r), u = (phi_l', phi_r'): the generalized speeds are the wheel
// rates, and the pose follows from them as rolling dictates,
//   yaw' = psi'(u) = R (phi_r' - phi_l') / d,   (x', y') = v(u) (cos yaw, sin yaw),
//   v(u) = R (phi_l' + phi_r') / 2,             phi' = u,
// so qdot = N(q) u with N 5 x 2: the base cannot slip sideways (its velocity is along its
// heading) nor forwards (its speed and yaw rate are the wheels'). The wheel angles ride along
// as coordinates that move no body; the base body carries the wheels, their spin entering
// as the equivalent inertia of RollingModel.

#include <Simbody.h>

#include "cbbg/plant/robot_params.h"

namespace cbbg::plant::simbody {

class RollingBaseMobilizer final : public SimTK::MobilizedBody::Custom::Implementation {
 public:
  static constexpr int kQ = 5;
  static constexpr int kU = 2;

  RollingBaseMobilizer(SimTK::SimbodyMatterSubsystem& matter, const RobotParams& params);

  // The mobilized body it belongs to, once added: it reads its yaw and rates from the state.
  void attach(SimTK::MobilizedBodyIndex index) { index_ = index; }

  Implementation* clone() const override { return new RollingBaseMobilizer(*this); }
  SimTK::Transform calcMobilizerTransformFromQ(const SimTK::State& state, int nq,
                                               const SimTK::Real* q) const override;
  SimTK::SpatialVec multiplyByHMatrix(const SimTK::State& state, int nu,
                                      const SimTK::Real* u) const override;
  void multiplyByHTranspose(const SimTK::State& state, const SimTK::SpatialVec& force, int nu,
                            SimTK::Real* f) const override;
  SimTK::SpatialVec multiplyByHDotMatrix(const SimTK::State& state, int nu,
                                         const SimTK::Real* u) const override;
  void multiplyByHDotTranspose(const SimTK::State& state, const SimTK::SpatialVec& force, int nu,
                               SimTK::Real* f) const override;
  void multiplyByN(const SimTK::State& state, bool transpose, int n_in, const SimTK::Real* in,
                   int n_out, SimTK::Real* out) const override;
  void multiplyByNInv(const SimTK::State& state, bool transpose, int n_in, const SimTK::Real* in,
                      int n_out, SimTK::Real* out) const override;
  void multiplyByNDot(const SimTK::State& state, bool transpose, int n_in, const SimTK::Real* in,
                      int n_out, SimTK::Real* out) const override;
  void setQToFitTransform(const SimTK::State& state, const SimTK::Transform& pose, int nq,
                          SimTK::Real* q) const override;
  void setUToFitVelocity(const SimTK::State& state, const SimTK::SpatialVec& velocity, int nu,
                         SimTK::Real* u) const override;

 private:
  void locate(const SimTK::State& state) const;
  double yaw(const SimTK::State& state) const;
  double yaw_rate(const SimTK::State& state) const;

  const SimTK::SimbodyMatterSubsystem* matter_;
  SimTK::MobilizedBodyIndex index_;
  mutable SimTK::QIndex first_q_;  // where its q and u are in the state, once looked up
  mutable SimTK::UIndex first_u_;
  // Per unit rate of wheel j (0 left, 1 right): the base's forward speed and yaw rate.
  double speed_[kU];
  double turn_[kU];
};

}  // namespace cbbg::plant::simbody
