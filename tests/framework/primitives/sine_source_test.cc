#include "cbbg/framework/primitives/sine_source.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/diagram_builder.h"

namespace cbbg {
namespace {

using ::testing::ThrowsMessage;

TEST(SineSource, PortsAndNoInputs) {
  const SineSource sine("sine", Vector::Ones(2), Vector::Ones(2), Vector::Zero(2), Vector::Zero(2));
  EXPECT_EQ(sine.num_input_ports(), 0);
  ASSERT_EQ(sine.num_output_ports(), 1);
  EXPECT_EQ(sine.output_port("y").size(), 2);
  EXPECT_TRUE(sine.output_reads(0).empty());
}

TEST(SineSource, MatchesTheFormulaWithAngularFrequencyInRadiansPerSecond) {
  // y = b + a sin(omega t + phi); element 0 at 1 Hz (omega = 2 pi), element 1 slower.
  const Eigen::Vector2d a(2.0, 0.5);
  const Eigen::Vector2d omega(2.0 * std::numbers::pi, 3.0);
  const Eigen::Vector2d phi(0.0, std::numbers::pi / 4.0);
  const Eigen::Vector2d b(1.0, -1.0);
  DiagramBuilder builder("top");
  auto& sine = builder.emplace<SineSource>("sine", a, omega, phi, b);
  auto& scalar = builder.emplace<SineSource>("scalar", 3.0, 2.0, 0.5);  // bias 0
  auto diagram = builder.build();
  auto context = diagram->create_context();
  for (const double t : {0.0, 0.25, 0.6, 1.0, 7.3}) {
    context->set_time(t);
    const auto y = diagram->eval_output(*context, sine.output_port("y"));
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(y[i], b[i] + a[i] * std::sin(omega[i] * t + phi[i]), 1e-14) << t << " " << i;
    }
    EXPECT_NEAR(diagram->eval_output(*context, scalar.output_port("y"))[0],
                3.0 * std::sin(2.0 * t + 0.5), 1e-14);
  }
  context->set_time(0.25);  // a quarter period at 1 Hz: the peak
  EXPECT_NEAR(diagram->eval_output(*context, sine.output_port("y"))[0], 3.0, 1e-14);
}

TEST(SineSource, RefusesBadArguments) {
  EXPECT_THAT(
      [] {
        SineSource("sine", Vector::Ones(2), Vector::Ones(2), Vector::Zero(1), Vector::Zero(2));
      },
      ThrowsMessage<std::invalid_argument>(
          "SineSource 'sine': the phase has size 1; it must have the amplitude's size, 2"));
  EXPECT_THAT([] { SineSource("sine", 1.0, std::numeric_limits<double>::infinity()); },
              ThrowsMessage<std::invalid_argument>(
                  "SineSource 'sine': angular frequency inf must be finite"));
  EXPECT_THAT([] { SineSource("sine", Vector(), Vector(), Vector(), Vector()); },
              ThrowsMessage<std::invalid_argument>("SineSource 'sine': size 0 must be at least 1"));
}

}  // namespace
}  // namespace cbbg
