#pragma once

#include <string>

#include "cbbg/blocks/exploration_params.h"
#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"

namespace cbbg::blocks {

/// OuExploration: exploration.kind ou, temporally correlated exploration: the actor's action
/// plus an Ornstein-Uhlenbeck process (docs/model.md §5.4).
///
/// | port               | dir | size | meaning                  |
/// |--------------------|-----|------|--------------------------|
/// | actor_action       | in  | 1    | a_A(t), from the Actor   |
/// | exploration_action | out | 1    | a_E(t) = a_A + x(t)      |
///
/// Equations: dx = -theta x dt + sigma sqrt(2 theta) dW, stationary law N(0, sigma^2),
/// sampled exactly at the ticks: the initialization update draws x from the stationary law,
/// x = sigma eps_0; each periodic update sets
///   x <- x e^(-theta Ts) + sigma sqrt(1 - e^(-2 theta Ts)) eps_k,
/// so the lag-one autocorrelation is e^(-theta Ts). eps is a standard normal from the
/// block's own generator, one per update in the BoltzmannSampler's order (common random
/// numbers); for theta Ts large enough that e^(-theta Ts) is 0, a_E is GaussianExploration's
/// with a fixed sigma, bit for bit.
/// Parameters: sigma = exploration.sigma, theta = exploration.ou_theta, the period Ts =
/// trial.period.
///
/// Discrete state, per trial: noise x (1, N m); a new trial draws it afresh.
class OuExploration final : public Block, public codegen::EmitsC {
 public:
  OuExploration(std::string name, const ExplorationParams& params, double period);

  // Its outputs and updates as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;
  codegen::CCalculation c_initialization(int update, const Context& context) const override;

 private:
  // "exploration_action": a_E = a_A + x.
  void calc_exploration_action(const BlockContext& context, VectorRef action) const;
  // The initialization update: x = sigma eps_0, from the stationary law.
  EventStatus draw_stationary(BlockContext& context, VectorRef next) const;
  // The periodic update: x <- x e^(-theta Ts) + sigma sqrt(1 - e^(-2 theta Ts)) eps_k.
  EventStatus evolve(BlockContext& context, VectorRef next) const;

  ExplorationParams params_;
  double decay_;       // e^(-theta Ts)
  double innovation_;  // sigma sqrt(1 - e^(-2 theta Ts))
  const InputPort* actor_action_;
};

}  // namespace cbbg::blocks
