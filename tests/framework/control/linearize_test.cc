#include "cbbg/framework/control/linearize.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "tests/framework/test_blocks.h"

namespace cbbg::control {
namespace {

using Eigen::MatrixXd;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr double kGOverL = 9.81 / 0.5;  // g / l of a 0.5 m pendulum

// A pendulum driven by an angular acceleration u: x = (theta, omega),
// x' = (omega, -g/l sin theta + u), y = theta.
class Pendulum final : public Block {
 public:
  explicit Pendulum(std::string name) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_continuous_state(Vector::Zero(2), [&u](const BlockContext& context, VectorRef x_dot) {
      const auto x = context.continuous_state();
      x_dot[0] = x[1];
      x_dot[1] = -kGOverL * std::sin(x[0]) + context.input(u)[0];
    });
    declare_output_port(
        "angle", 1,
        [](const BlockContext& context, VectorRef y) { y[0] = context.continuous_state()[0]; }, {});
  }
};

// The same pendulum stepped by explicit Euler every `period`: x+ = x + period x'.
class EulerPendulum final : public Block {
 public:
  EulerPendulum(std::string name, double period) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_discrete_state("state", Vector::Zero(2), StateLifetime::kPersistent);
    declare_periodic_update(period, 0.0, [&u, period](BlockContext& context, VectorRef next) {
      const auto x = context.discrete_state();
      next[0] = x[0] + period * x[1];
      next[1] = x[1] + period * (-kGOverL * std::sin(x[0]) + context.input(u)[0]);
      return EventStatus::succeeded();
    });
    declare_output_port(
        "angle", 1,
        [](const BlockContext& context, VectorRef y) { y[0] = context.discrete_state()[0]; }, {});
  }
};

// y = gain u: direct feedthrough, no state.
class Scale final : public Block {
 public:
  Scale(std::string name, double gain) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_output_port(
        "y", 1,
        [&u, gain](const BlockContext& context, VectorRef y) { y = gain * context.input(u); },
        {&u});
  }
};

// The block alone in a diagram that exports its ports, as linearize.h describes.
template <typename B, typename... Args>
std::unique_ptr<Diagram> alone(Args&&... args) {
  DiagramBuilder builder("linearized");
  const auto& block = builder.emplace<B>("block", std::forward<Args>(args)...);
  for (int port = 0; port < block.num_input_ports(); ++port) {
    builder.export_input(block.input_port(port));
  }
  for (int port = 0; port < block.num_output_ports(); ++port) {
    builder.export_output(block.output_port(port));
  }
  return builder.build();
}

MatrixXd matrix(int rows, int cols, std::initializer_list<double> values) {
  MatrixXd M(rows, cols);
  auto value = values.begin();
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) M(i, j) = *value++;
  }
  return M;
}

TEST(Linearize, GivesThePendulumsJacobianAtRest) {
  // At theta = omega = u = 0, sin theta ~ theta: A = [[0, 1], [-g/l, 0]], B = [0; 1],
  // C = [1, 0], D = 0.
  const auto diagram = alone<Pendulum>();
  auto context = diagram->create_context();
  context->fix_input(diagram->input_port(0), Vector::Zero(1));
  const StateSpace linear = linearize(*diagram, *context);
  EXPECT_FALSE(linear.is_discrete());
  EXPECT_EQ(linear.time_period, 0.0);
  EXPECT_LT((linear.A - matrix(2, 2, {0, 1, -kGOverL, 0})).norm(), 1e-6);
  EXPECT_LT((linear.B - matrix(2, 1, {0, 1})).norm(), 1e-6);
  EXPECT_LT((linear.C - matrix(1, 2, {1, 0})).norm(), 1e-6);
  EXPECT_LT(linear.D.norm(), 1e-6);
  EXPECT_EQ(linear.D.rows(), 1);
  EXPECT_EQ(linear.D.cols(), 1);
}

TEST(Linearize, GivesTheJacobianAwayFromEquilibriumAndLeavesTheContextAlone) {
  // At theta = 0.7 the pendulum's A[1][0] is -g/l cos 0.7; the rest is as at rest.
  const auto diagram = alone<Pendulum>();
  const Block& pendulum = diagram->block("block");
  auto context = diagram->create_context();
  context->fix_input(diagram->input_port(0), Vector::Constant(1, 0.2));
  context->continuous_state(pendulum) << 0.7, 0.3;
  context->set_time(1.5);
  const auto before = context->clone();
  const StateSpace linear = linearize(*diagram, *context);
  EXPECT_LT((linear.A - matrix(2, 2, {0, 1, -kGOverL * std::cos(0.7), 0})).norm(), 1e-6);
  EXPECT_LT((linear.B - matrix(2, 1, {0, 1})).norm(), 1e-6);
  EXPECT_EQ(context->continuous_states(), before->continuous_states());
  EXPECT_TRUE(context->signals().cwiseEqual(before->signals()).all());
  EXPECT_EQ(context->time(), 1.5);
}

TEST(Linearize, ConcatenatesTheRootPortsThroughNestedDiagramsAndFeedthrough) {
  // u -> scale (3 u) -> a pendulum inside a sub-diagram; y = (theta, 3 u). So B = [0; 3] and
  // D = [0; 3]: the second output reads the input directly.
  DiagramBuilder inner_builder("inner");
  const auto& pendulum = inner_builder.emplace<Pendulum>("pendulum");
  inner_builder.export_input(pendulum.input_port("u"), "u");
  inner_builder.export_output(pendulum.output_port("angle"), "angle");
  DiagramBuilder builder("outer");
  const auto& inner = builder.add(inner_builder.build());
  const auto& scale = builder.emplace<Scale>("scale", 3.0);
  builder.connect(scale, "y", inner, "u");
  builder.export_input(scale.input_port("u"), "u");
  builder.export_output(inner.output_port("angle"), "angle");
  builder.export_output(scale.output_port("y"), "scaled");
  const auto diagram = builder.build();
  auto context = diagram->create_context();
  context->fix_input(diagram->input_port(0), Vector::Zero(1));
  const StateSpace linear = linearize(*diagram, *context);
  EXPECT_LT((linear.A - matrix(2, 2, {0, 1, -kGOverL, 0})).norm(), 1e-6);
  EXPECT_LT((linear.B - matrix(2, 1, {0, 3})).norm(), 1e-6);
  EXPECT_LT((linear.C - matrix(2, 2, {1, 0, 0, 0})).norm(), 1e-6);
  EXPECT_LT((linear.D - matrix(2, 1, {0, 3})).norm(), 1e-6);
}

TEST(Linearize, LinearisesAStatelessDiagramToItsFeedthrough) {
  const auto diagram = alone<Scale>(-2.5);
  auto context = diagram->create_context();
  context->fix_input(diagram->input_port(0), Vector::Constant(1, 4.0));
  const StateSpace linear = linearize(*diagram, *context);
  EXPECT_EQ(linear.num_states(), 0);
  EXPECT_EQ(linear.B.rows(), 0);
  EXPECT_EQ(linear.C.cols(), 0);
  EXPECT_NEAR(linear.D(0, 0), -2.5, 1e-9);
}

TEST(Linearize, ChecksTheEquilibriumWhenAskedTo) {
  const auto diagram = alone<Pendulum>();
  auto context = diagram->create_context();
  context->continuous_state(diagram->block("block")) << 0.5, 0.0;
  context->fix_input(diagram->input_port(0), Vector::Zero(1));
  LinearizeOptions options;
  options.equilibrium_tolerance = 1e-9;
  EXPECT_THAT([&] { linearize(*diagram, *context, options); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("linearize: the operating point is not an equilibrium: the largest "
                            "state derivative is")));
  // Held at theta = 0.5 by u = g/l sin 0.5, it is one.
  context->fix_input(diagram->input_port(0), Vector::Constant(1, kGOverL * std::sin(0.5)));
  const StateSpace linear = linearize(*diagram, *context, options);
  EXPECT_NEAR(linear.A(1, 0), -kGOverL * std::cos(0.5), 1e-6);
}

TEST(Linearize, GivesTheDiscreteModelOfADiscreteBlock) {
  // x+ = (x1 + h x2, x2 + h (-g/l sin x1 + u)) at rest: A = [[1, h], [-h g/l, 1]],
  // B = [0; h], C = [1, 0], D = 0, with period h.
  const double h = 0.01;
  const auto diagram = alone<EulerPendulum>(h);
  auto context = diagram->create_context();
  context->fix_input(diagram->input_port(0), Vector::Zero(1));
  const StateSpace linear = linearize(*diagram, *context);
  EXPECT_TRUE(linear.is_discrete());
  EXPECT_EQ(linear.time_period, h);
  EXPECT_LT((linear.A - matrix(2, 2, {1, h, -h * kGOverL, 1})).norm(), 1e-6);
  EXPECT_LT((linear.B - matrix(2, 1, {0, h})).norm(), 1e-6);
  EXPECT_LT((linear.C - matrix(1, 2, {1, 0})).norm(), 1e-6);
  EXPECT_LT(linear.D.norm(), 1e-6);
}

TEST(Linearize, StepsEveryDiscreteBlockOfTheDiagramAtOnce) {
  // u -> zero-order hold -> Euler pendulum: x = (hold, theta, omega). One instant's updates
  // all read the values from before it: hold+ = u, and the pendulum sees the old hold.
  const double h = 0.02;
  DiagramBuilder builder("sampled");
  const auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, h);
  const auto& pendulum = builder.emplace<EulerPendulum>("pendulum", h);
  builder.connect(hold, "y", pendulum, "u");
  builder.export_input(hold.input_port("u"), "u");
  builder.export_output(pendulum.output_port("angle"), "angle");
  const auto diagram = builder.build();
  auto context = diagram->create_context();
  context->fix_input(diagram->input_port(0), Vector::Zero(1));
  const StateSpace linear = linearize(*diagram, *context);
  EXPECT_EQ(linear.time_period, h);
  EXPECT_LT((linear.A - matrix(3, 3, {0, 0, 0, 0, 1, h, h, -h * kGOverL, 1})).norm(), 1e-6);
  EXPECT_LT((linear.B - matrix(3, 1, {1, 0, 0})).norm(), 1e-6);
  EXPECT_LT((linear.C - matrix(1, 3, {0, 1, 0})).norm(), 1e-6);
}

TEST(Linearize, RejectsMixedStateSeveralRatesAndSelfIntegratingBlocks) {
  {
    DiagramBuilder builder("mixed");
    const auto& integrator = builder.emplace<testing::Integrator>("integrator");
    builder.emplace<testing::Counter>("counter", 0.1);
    builder.export_input(integrator.input_port("u"), "u");
    const auto diagram = builder.build();
    auto context = diagram->create_context();
    context->fix_input(diagram->input_port(0), Vector::Zero(1));
    EXPECT_THAT([&] { linearize(*diagram, *context); },
                ThrowsMessage<std::invalid_argument>(HasSubstr(
                    "linearize: diagram 'mixed' has both continuous state ('mixed/integrator') "
                    "and periodically updated discrete state ('mixed/counter'); linearize "
                    "supports one kind only")));
  }
  {
    DiagramBuilder builder("two_rates");
    builder.emplace<testing::Counter>("fast", 0.1);
    builder.emplace<testing::Counter>("slow", 0.2);
    const auto diagram = builder.build();
    EXPECT_THAT([&] { linearize(*diagram, *diagram->create_context()); },
                ThrowsMessage<std::invalid_argument>(
                    HasSubstr("linearize: diagram 'two_rates' updates its discrete state at more "
                              "than one rate (period 0.1 s, offset 0 s, and block "
                              "'two_rates/slow' with period 0.2 s, offset 0 s)")));
  }
  {
    const auto diagram = alone<testing::SelfIntegrator>();
    auto context = diagram->create_context();
    context->fix_input(diagram->input_port(0), Vector::Zero(1));
    EXPECT_THAT([&] { linearize(*diagram, *context); },
                ThrowsMessage<std::invalid_argument>(
                    HasSubstr("linearize: diagram 'linearized' has self-integrating blocks "
                              "('linearized/block')")));
  }
}

TEST(Linearize, RejectsAnOperatingPointWithoutInputsOrOfAnotherDiagram) {
  const auto diagram = alone<Pendulum>();
  const auto other = alone<Pendulum>();
  EXPECT_THAT([&] { linearize(*diagram, *diagram->create_context()); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("linearize: input 'linearized.u' of the root diagram has no value; "
                            "fix the operating input with Context::fix_input")));
  auto context = other->create_context();
  context->fix_input(other->input_port(0), Vector::Zero(1));
  EXPECT_THAT([&] { linearize(*diagram, *context); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("linearize: the context does not belong to diagram 'linearized'")));
  LinearizeOptions options;
  options.relative_step = 0.0;
  EXPECT_THAT([&] { linearize(*other, *context, options); },
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("linearize: relative_step must be positive and finite; got 0")));
}

}  // namespace
}  // namespace cbbg::control
