#pragma once
// Config keys exploration.*: which block draws the exploratory action a_E around the actor's
// a_A (the slot "sampler"), and the parameters of the alternatives to the paper's Boltzmann
// sampler (docs/model.md §5.4).

#include <string_view>

#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config key exploration.kind.
enum class ExplorationKind {
  kBoltzmann,  // "boltzmann": the paper's BoltzmannSampler, a_E ~ N(a_A, K_B T / 2)
  kGaussian,   // "gaussian": GaussianExploration, a_E ~ N(a_A, sigma(t)^2), no temperature
  kOu,         // "ou": OuExploration, a_E = a_A + an Ornstein-Uhlenbeck process
};

// "boltzmann", "gaussian" or "ou"; anything else throws naming exploration.kind.
ExplorationKind parse_exploration_kind(std::string_view text);
std::string_view to_string(ExplorationKind kind);

// Config keys exploration.*.
struct ExplorationParams {
  ExplorationKind kind = ExplorationKind::kBoltzmann;  // exploration.kind
  double sigma = 1.58;                                 // exploration.sigma: sigma_0, N m
  double half_life = 0.0;  // exploration.half_life: s of learning time; 0 = fixed sigma
  double ou_theta = 5.0;   // exploration.ou_theta: mean reversion rate, 1/s

  static constexpr const char* kSection = "exploration";
  template <class Archive>
  void describe(Archive& a) {
    a.choice("kind", kind, "boltzmann (the paper's: a_E ~ N(a_A, K_B T / 2)) | gaussian | ou",
             Choices<ExplorationKind>{{"boltzmann", ExplorationKind::kBoltzmann},
                                      {"gaussian", ExplorationKind::kGaussian},
                                      {"ou", ExplorationKind::kOu}});
    a.number("sigma", sigma,
             "gaussian, ou: the noise's standard deviation sigma_0, N m (1.58 is the Boltzmann "
             "sampler's at V = 0 with the defaults: sqrt(K_B k1 / 4))",
             kPositive);
    a.number("half_life", half_life,
             "gaussian: the learning time over which sigma halves, s; 0 = a fixed sigma",
             kNonNegative);
    a.number("ou_theta", ou_theta, "ou: the rate theta at which the noise reverts to 0, 1/s",
             kPositive);
  }
  // Throws naming the key unless every value is finite and in its range.
  void validate() const;
};

}  // namespace cbbg::blocks
