// The learnt actor's slopes at rest against the derivative of its RBF law worked out by hand,
// and the modes of the loop it closes.

#include "cbbg/experiments/actor_linearisation.h"

#include <cmath>
#include <complex>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/presets.h"

namespace cbbg::experiments {
namespace {

parameters::Parameters analytic() {
  config::Config config;
  config.set("plant.kind=analytic");
  return parameters::read_parameters(config);
}

const diagrams::ClosedLoopFactory& policy() {
  static const diagrams::ClosedLoopFactory factory = diagrams::closed_loop_factory(
      diagrams::kLearntActor, diagrams::preset(diagrams::kLearntActor).options);
  return factory;
}

LearntWeights random_weights(const parameters::Parameters& p, std::uint64_t seed) {
  LearntWeights weights;
  weights.layout = policy()(p).layout;
  const int n = 49;
  weights.features = n;
  weights.actor = LearntState::of_weights(Vector::Zero(n));
  weights.critic = LearntState::of_weights(Vector::Zero(n));
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 2.0);
  for (int k = 0; k < n; ++k) weights.actor.weights("actor")[k] = normal(generator);
  return weights;
}

// a = sum_k theta_k exp(-((x_0 - c_i)^2 + (x_1 - c_j)^2) / (2 b^2)), x = (theta_b / n_theta,
// theta_b' / n_dtheta): at x = 0, da/dtheta_b = sum_k theta_k phi_k(0) c_i / (b^2 n_theta).
TEST(ActorLinearisation, SlopesAreTheDerivativeOfTheRbfLawAtRest) {
  const parameters::Parameters p = analytic();
  const LearntWeights weights = random_weights(p, 4);
  const std::vector<double>& c = p.rbf.centres;
  const double b2 = p.rbf.width * p.rbf.width;
  double pitch = 0.0;
  double rate = 0.0;
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) {
      const double ci = c[static_cast<size_t>(i)];
      const double cj = c[static_cast<size_t>(j)];
      const double phi = std::exp(-(ci * ci + cj * cj) / (2.0 * b2));
      pitch +=
          weights.actor.weights("actor")[i * 7 + j] * phi * ci / (b2 * p.normaliser.scale_theta);
      rate +=
          weights.actor.weights("actor")[i * 7 + j] * phi * cj / (b2 * p.normaliser.scale_dtheta);
    }
  }
  const ActorLinearisation linear = linearise_actor(p, policy(), weights);
  EXPECT_NEAR(linear.slopes[0], pitch, 1e-6 * std::abs(pitch));
  EXPECT_NEAR(linear.slopes[2], rate, 1e-6 * std::abs(rate));
  EXPECT_EQ(linear.slopes[1], 0.0);  // the paper's features do not see the wheels
  EXPECT_EQ(linear.slopes[3], 0.0);
}

// No action: the modes are the held robot's own, the fall among them (|z| > 1, a real s of
// about sqrt(M g L / inertia)); sorted, largest first.
TEST(ActorLinearisation, WithoutAnActionTheRobotFalls) {
  const parameters::Parameters p = analytic();
  LearntWeights weights = random_weights(p, 1);
  weights.actor.weights("actor").setZero();
  const ActorLinearisation linear = linearise_actor(p, policy(), weights);
  ASSERT_EQ(linear.modes.size(), 4u);
  EXPECT_GT(std::abs(linear.modes[0].z), 1.0);
  EXPECT_NEAR(linear.modes[0].z.imag(), 0.0, 1e-12);
  EXPECT_GT(linear.modes[0].s.real(), 2.0);
  EXPECT_NEAR(std::abs(std::exp(linear.modes[0].s * p.trial.period)), std::abs(linear.modes[0].z),
              1e-12);
  for (std::size_t i = 1; i < linear.modes.size(); ++i) {
    EXPECT_GE(std::abs(linear.modes[i - 1].z), std::abs(linear.modes[i].z));
  }
}

TEST(ActorLinearisation, RefusesWeightsThatDoNotFitTheActor) {
  const parameters::Parameters p = analytic();
  LearntWeights short_weights = random_weights(p, 2);
  short_weights.actor = LearntState::of_weights(Vector::Zero(3));
  EXPECT_THROW(linearise_actor(p, policy(), short_weights), std::invalid_argument);
}

}  // namespace
}  // namespace cbbg::experiments
