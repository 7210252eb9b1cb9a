#pragma once

#include <string>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config key sampler.k_b.
struct SamplerParams {
  // sampler.k_b: K_B, temperature to action variance. The default 1 reads the temperature in
  // action units; the paper's literal Boltzmann constant 1.38e-23 is accepted too (docs/model.md
  // §2.6).
  double k_b = 1.0;

  static constexpr const char* kSection = "sampler";
  template <class Archive>
  void describe(Archive& a) {
    a.number("k_b", k_b, "K_B: a_E ~ N(a_A, K_B T / 2); the paper's 1.38e-23 works too", kPositive);
  }
  // Throws naming sampler.k_b unless it is finite and > 0.
  void validate() const;
};

/// BoltzmannSampler: the basal ganglia's exploratory action (docs/model.md §2.6).
///
/// | port               | dir | size | meaning                        |
/// |--------------------|-----|------|--------------------------------|
/// | actor_action       | in  | 1    | a_A(t), from the Actor         |
/// | temperature        | in  | 1    | T(t) >= 0, from the Tropism    |
/// | exploration_action | out | 1    | a_E(t) ~ N(a_A, K_B T / 2)     |
///
/// Equation: a_E = a_A + sqrt(K_B T / 2) eps, eps a standard normal held in the discrete
/// state, drawn from the block's own generator by the initialization update (first tick)
/// and by each periodic update (next tick). The Boltzmann law exp(-(a_E - a_A)^2 / (K_B T))
/// is this normal. Parameters: K_B = sampler.k_b, the period trial.period.
/// exploration.kind boltzmann selects it (GaussianExploration and OuExploration are the
/// alternatives, drawing the same eps).
///
/// Discrete state, per trial: noise eps (1).
class BoltzmannSampler final : public Block, public codegen::EmitsC {
 public:
  BoltzmannSampler(std::string name, const SamplerParams& params, double period);

  // Its outputs and updates as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;
  codegen::CCalculation c_initialization(int update, const Context& context) const override;

 private:
  // "exploration_action": a_E = a_A + sqrt(K_B T / 2) eps.
  void calc_exploration_action(const BlockContext& context, VectorRef action) const;
  // Draws eps for the next tick (the initialization update and each periodic update).
  EventStatus draw(BlockContext& context, VectorRef next) const;

  SamplerParams params_;
  const InputPort* actor_action_;
  const InputPort* temperature_;
};

}  // namespace cbbg::blocks
