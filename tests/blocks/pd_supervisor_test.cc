#include "cbbg/blocks/pd_supervisor.h"

#include <cmath>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/framework/block_harness.h"

namespace cbbg::blocks {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;
using Harness = testing::BlockHarness<PdSupervisor>;

Vector measured(double theta, double theta_dot, double phi_l, double phi_r, double phi_l_dot,
                double phi_r_dot) {
  Vector y(kMeasuredSize);
  y << theta, theta_dot, phi_l, phi_r, phi_l_dot, phi_r_dot;
  return y;
}

TEST(PdSupervisor, DefaultGainsAsWorkedOutByHand) {
  Harness harness("supervisor", PdSupervisorParams{});
  // 50 (0.1) + 10 (-0.2) + (1 + 3) / 2 + (0.5 - 1.5) / 2 = 5 - 2 + 2 - 0.5.
  harness.set_input("measured", measured(0.1, -0.2, 1.0, 3.0, 0.5, -1.5));
  EXPECT_NEAR(harness.scalar_output("action"), 4.5, 1e-14);
  // The start of a trial: 50 (0.1744) = 8.72, beyond the 5 N m the plant allows.
  harness.set_input("measured", measured(0.1744, 0.0, 0.0, 0.0, 0.0, 0.0));
  EXPECT_NEAR(harness.scalar_output("action"), 8.72, 1e-14);
}

TEST(PdSupervisor, UsesConfiguredGains) {
  PdSupervisorParams params;
  params.k_theta = 2.0;
  params.k_dtheta = -3.0;
  params.k_phi = 0.5;
  params.k_dphi = 4.0;
  Harness harness("supervisor", params);
  // 2 (1) - 3 (2) + 0.5 (-2 + 6) / 2 + 4 (1 + 0) / 2 = 2 - 6 + 1 + 2.
  harness.set_input("measured", measured(1.0, 2.0, -2.0, 6.0, 1.0, 0.0));
  EXPECT_NEAR(harness.scalar_output("action"), -1.0, 1e-14);
}

TEST(PdSupervisor, RejectsNonFiniteGains) {
  PdSupervisorParams infinite;
  infinite.k_dtheta = INFINITY;
  EXPECT_THAT(
      [&] { PdSupervisor("supervisor", infinite); },
      ThrowsMessage<std::invalid_argument>(StrEq("supervisor.k_dtheta must be finite; got inf")));
  PdSupervisorParams nan;
  nan.k_phi = NAN;
  EXPECT_THAT(
      [&] { PdSupervisor("supervisor", nan); },
      ThrowsMessage<std::invalid_argument>(StrEq("supervisor.k_phi must be finite; got nan")));
}

}  // namespace
}  // namespace cbbg::blocks
