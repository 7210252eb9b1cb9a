// control::linearize of the analytic plant block against the plant's own linearisation.

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "cbbg/framework/control/linearize.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/linearization.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/robot_params.h"

namespace cbbg::plant {
namespace {

TEST(AnalyticPlantLinearization, MatchesLinearizeUprightAtRest) {
  // The plant alone in a diagram exporting its ports, upright at rest with no torque. Its
  // continuous state is (theta_b, phi_l, phi_r, theta_b', phi_l', phi_r', x, y, yaw): the
  // first six are linearize_upright's x, in the same order, and the torque its u.
  const RobotParams params;
  DiagramBuilder builder("linearized");
  const auto& plant = builder.emplace<AnalyticPlant>("plant", params);
  builder.export_input(plant.input_port("torque"));
  builder.export_output(plant.output_port("state"));
  const auto diagram = builder.build();
  auto context = diagram->create_context();
  plant.reset(*context, 0.0);
  context->fix_input(diagram->input_port(0), Vector::Zero(kTorqueSize));

  control::LinearizeOptions options;
  options.equilibrium_tolerance = 1e-12;
  const control::StateSpace linear = control::linearize(*diagram, *context, options);
  const LinearModel expected = linearize_upright(params);
  ASSERT_EQ(linear.num_states(), 9);
  ASSERT_EQ(linear.num_inputs(), kTorqueSize);
  ASSERT_EQ(linear.num_outputs(), kStateSize);
  EXPECT_FALSE(linear.is_discrete());
  const double scale = 1.0 + expected.A.norm() + expected.B.norm();
  EXPECT_LT((linear.A.topLeftCorner(6, 6) - expected.A).norm(), 1e-6 * scale);
  EXPECT_LT((linear.B.topRows(6) - expected.B).norm(), 1e-6 * scale);
  // Nothing of the upright model depends on the pose (x, y, yaw).
  EXPECT_LT(linear.A.topRightCorner(6, 3).norm(), 1e-9);

  // The pose at yaw = 0: x' = R (phi_l' + phi_r') / 2, y' = 0, yaw' = R (phi_r' - phi_l') / d.
  const double r = params.wheel_radius;
  const double d = params.track_width;
  Eigen::MatrixXd pose = Eigen::MatrixXd::Zero(3, 9);
  pose(0, 4) = r / 2.0;
  pose(0, 5) = r / 2.0;
  pose(2, 4) = -r / d;
  pose(2, 5) = r / d;
  EXPECT_LT((linear.A.bottomRows(3) - pose).norm(), 1e-6);
  EXPECT_LT(linear.B.bottomRows(3).norm(), 1e-9);

  // y is the state in the output layout (plant_ports.h), read without the torque.
  EXPECT_NEAR(linear.C(kThetaB, 0), 1.0, 1e-9);
  EXPECT_NEAR(linear.C(kThetaBDot, 3), 1.0, 1e-9);
  EXPECT_NEAR(linear.C(kPhiLeft, 1), 1.0, 1e-9);
  EXPECT_NEAR(linear.C(kPhiRightDot, 5), 1.0, 1e-9);
  EXPECT_NEAR(linear.C(kYaw, 8), 1.0, 1e-9);
  EXPECT_NEAR(linear.C(kYawRate, 5), r / d, 1e-9);
  EXPECT_LT(linear.D.norm(), 1e-12);
}

}  // namespace
}  // namespace cbbg::plant
