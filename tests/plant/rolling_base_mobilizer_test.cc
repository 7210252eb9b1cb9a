// The rolling base mobilizer's kinematics, operator by operator: H is the derivative of the
// mobilizer's transform along qdot = N u, every transposed product is the adjoint of its
// product, the dotted operators are time derivatives along the motion, and the fitting
// routines invert the transform and H. (The dynamics are tested against the analytic plant
// in plant_agreement_test.cc.)

#include "cbbg/plant/simbody/rolling_base_mobilizer.h"

#include <cmath>

#include <gtest/gtest.h>

#include "cbbg/plant/robot_dynamics.h"

namespace cbbg::plant::simbody {
namespace {

using SimTK::Real;
using SimTK::SpatialVec;
using SimTK::Vec3;

constexpr int kQ = RollingBaseMobilizer::kQ;
constexpr int kU = RollingBaseMobilizer::kU;
constexpr double kStep = 1e-7;  // finite-difference step
constexpr double kFdTolerance = 1e-6;

class RollingBaseMobilizerTest : public ::testing::Test {
 protected:
  RollingBaseMobilizerTest() : matter_(system_) {
    mobilizer_ = new RollingBaseMobilizer(matter_, params_);
    base_ = SimTK::MobilizedBody::Custom(
        matter_.Ground(), mobilizer_,
        SimTK::Body::Rigid(SimTK::MassProperties(1.0, Vec3(0), SimTK::Inertia(1.0))));
    mobilizer_->attach(base_.getMobilizedBodyIndex());
    state_ = system_.realizeTopology();
    system_.realizeModel(state_);
    set_motion(0.7, 1.3, -0.4);
  }

  // Puts the base at heading `yaw`, (x, y) = (0.2, -0.5), wheel angles (0.3, 0.9), wheel rates u.
  void set_motion(double yaw, double left_rate, double right_rate) {
    const Real q[kQ] = {yaw, 0.2, -0.5, 0.3, 0.9};
    for (int i = 0; i < kQ; ++i) base_.setOneQ(state_, i, q[i]);
    base_.setOneU(state_, 0, left_rate);
    base_.setOneU(state_, 1, right_rate);
    system_.realize(state_, SimTK::Stage::Velocity);
  }
  void q_of(Real* q) const {
    for (int i = 0; i < kQ; ++i) q[i] = base_.getOneQ(state_, i);
  }
  void u_of(Real* u) const {
    for (int i = 0; i < kU; ++i) u[i] = base_.getOneU(state_, i);
  }
  double yaw_rate() const { return plant::yaw_rate(params_, rate(0), rate(1)); }
  double rate(int i) const { return base_.getOneU(state_, i); }

  RobotParams params_;
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  RollingBaseMobilizer* mobilizer_ = nullptr;  // owned by base_
  SimTK::MobilizedBody::Custom base_;
  SimTK::State state_;
};

double dot(const SpatialVec& a, const SpatialVec& b) {
  return SimTK::dot(a[0], b[0]) + SimTK::dot(a[1], b[1]);
}

const SpatialVec kForce(Vec3(0.3, -1.1, 0.8), Vec3(2.0, 0.5, -0.7));

TEST_F(RollingBaseMobilizerTest, HIsTheTransformsRateAlongQDotEqualsNU) {
  Real q[kQ], u[kU], q_dot[kQ], ahead[kQ];
  q_of(q);
  u_of(u);
  mobilizer_->multiplyByN(state_, false, kU, u, kQ, q_dot);
  for (int i = 0; i < kQ; ++i) ahead[i] = q[i] + kStep * q_dot[i];
  const SimTK::Transform now = mobilizer_->calcMobilizerTransformFromQ(state_, kQ, q);
  const SimTK::Transform next = mobilizer_->calcMobilizerTransformFromQ(state_, kQ, ahead);
  const SpatialVec velocity = mobilizer_->multiplyByHMatrix(state_, kU, u);
  const SimTK::Vec4 turn = (next.R() * ~now.R()).convertRotationToAngleAxis();  // angle, axis
  const Vec3 angular = turn.drop1(0) * (turn[0] / kStep);
  EXPECT_NEAR((angular - velocity[0]).norm(), 0.0, kFdTolerance);
  EXPECT_NEAR(((next.p() - now.p()) / kStep - velocity[1]).norm(), 0.0, kFdTolerance);
  // The velocity is along the heading: no sideways slip, and no vertical motion.
  EXPECT_NEAR(velocity[1][0] * -std::sin(q[0]) + velocity[1][1] * std::cos(q[0]), 0.0, 1e-15);
  EXPECT_EQ(velocity[1][2], 0.0);
  EXPECT_DOUBLE_EQ(velocity[0][2], yaw_rate());
  EXPECT_DOUBLE_EQ(velocity[1].norm(), std::abs(forward_speed(params_, u[0], u[1])));
}

TEST_F(RollingBaseMobilizerTest, EveryTransposedProductIsTheAdjointOfItsProduct) {
  const Real u[kU] = {0.6, -1.7};
  const Real q_like[kQ] = {0.4, -0.3, 1.2, 0.8, -2.0};
  Real f[kU], out_q[kQ], out_u[kU];
  mobilizer_->multiplyByHTranspose(state_, kForce, kU, f);
  EXPECT_NEAR(dot(kForce, mobilizer_->multiplyByHMatrix(state_, kU, u)), f[0] * u[0] + f[1] * u[1],
              1e-12);
  mobilizer_->multiplyByHDotTranspose(state_, kForce, kU, f);
  EXPECT_NEAR(dot(kForce, mobilizer_->multiplyByHDotMatrix(state_, kU, u)),
              f[0] * u[0] + f[1] * u[1], 1e-12);
  using Product =
      void (RollingBaseMobilizer::*)(const SimTK::State&, bool, int, const Real*, int, Real*) const;
  for (const Product product :
       {&RollingBaseMobilizer::multiplyByN, &RollingBaseMobilizer::multiplyByNDot}) {
    (mobilizer_->*product)(state_, false, kU, u, kQ, out_q);      // q-like = M u
    (mobilizer_->*product)(state_, true, kQ, q_like, kU, out_u);  // u-like = M^T q
    double left = 0.0;
    for (int i = 0; i < kQ; ++i) left += q_like[i] * out_q[i];
    EXPECT_NEAR(left, out_u[0] * u[0] + out_u[1] * u[1], 1e-12);
  }
  mobilizer_->multiplyByNInv(state_, false, kQ, q_like, kU, out_u);  // u-like = NInv q
  mobilizer_->multiplyByNInv(state_, true, kU, u, kQ, out_q);        // q-like = NInv^T u
  double left = 0.0;
  for (int i = 0; i < kQ; ++i) left += q_like[i] * out_q[i];
  EXPECT_NEAR(left, out_u[0] * u[0] + out_u[1] * u[1], 1e-12);
}

TEST_F(RollingBaseMobilizerTest, NInvIsALeftInverseOfN) {
  const Real u[kU] = {0.6, -1.7};
  Real q_dot[kQ], back[kU];
  mobilizer_->multiplyByN(state_, false, kU, u, kQ, q_dot);
  mobilizer_->multiplyByNInv(state_, false, kQ, q_dot, kU, back);
  EXPECT_DOUBLE_EQ(back[0], u[0]);
  EXPECT_DOUBLE_EQ(back[1], u[1]);
}

// HDot u and NDot u are the rates of H u and N u, u held, as the heading turns.
TEST_F(RollingBaseMobilizerTest, HDotAndNDotAreTheRatesOfHAndNAlongTheMotion) {
  const Real u[kU] = {0.6, -1.7};
  Real q[kQ], n_now[kQ], n_next[kQ], n_dot[kQ];
  q_of(q);
  const SpatialVec h_now = mobilizer_->multiplyByHMatrix(state_, kU, u);
  const SpatialVec h_dot = mobilizer_->multiplyByHDotMatrix(state_, kU, u);
  mobilizer_->multiplyByN(state_, false, kU, u, kQ, n_now);
  mobilizer_->multiplyByNDot(state_, false, kU, u, kQ, n_dot);
  set_motion(q[0] + kStep * yaw_rate(), rate(0), rate(1));
  const SpatialVec h_next = mobilizer_->multiplyByHMatrix(state_, kU, u);
  mobilizer_->multiplyByN(state_, false, kU, u, kQ, n_next);
  EXPECT_NEAR(((h_next[1] - h_now[1]) / kStep - h_dot[1]).norm(), 0.0, kFdTolerance);
  EXPECT_EQ(h_dot[0].norm(), 0.0);
  for (int i = 0; i < kQ; ++i) {
    EXPECT_NEAR((n_next[i] - n_now[i]) / kStep, n_dot[i], kFdTolerance) << "q " << i;
  }
}

TEST_F(RollingBaseMobilizerTest, FittingRoutinesInvertTheTransformAndH) {
  Real q[kQ], u[kU];
  q_of(q);
  u_of(u);
  const SimTK::Transform pose = mobilizer_->calcMobilizerTransformFromQ(state_, kQ, q);
  const SpatialVec velocity = mobilizer_->multiplyByHMatrix(state_, kU, u);
  Real fitted_q[kQ] = {0.0, 0.0, 0.0, q[3], q[4]};
  Real fitted_u[kU] = {};
  mobilizer_->setQToFitTransform(state_, pose, kQ, fitted_q);
  mobilizer_->setUToFitVelocity(state_, velocity, kU, fitted_u);
  for (int i = 0; i < kQ; ++i) EXPECT_NEAR(fitted_q[i], q[i], 1e-15) << "q " << i;
  for (int i = 0; i < kU; ++i) EXPECT_NEAR(fitted_u[i], u[i], 1e-14) << "u " << i;
}

}  // namespace
}  // namespace cbbg::plant::simbody
