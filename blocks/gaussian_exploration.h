#pragma once

#include <string>

#include "cbbg/blocks/exploration_params.h"
#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"

namespace cbbg::blocks {

/// GaussianExploration: exploration.kind gaussian, a temperature-free alternative to the
/// BoltzmannSampler (docs/model.md §5.4).
///
/// | port               | dir | size | meaning                          |
/// |--------------------|-----|------|----------------------------------|
/// | actor_action       | in  | 1    | a_A(t), from the Actor           |
/// | exploration_action | out | 1    | a_E(t) = a_A + sigma(t) eps      |
///
/// Equations: a_E = a_A + sigma(t) eps, sigma(t) = sigma_0 2^(-elapsed / half_life)
/// (sigma_0 when half_life = 0), elapsed the learning time the block has run. eps is a
/// standard normal held in the discrete state, drawn from the block's own generator by the
/// initialization update (first tick) and by each periodic update (next tick), exactly as
/// the BoltzmannSampler draws its own: at the same path and seed both see the same eps.
/// Each periodic update advances elapsed by the period.
/// Parameters: sigma_0 = exploration.sigma, half_life = exploration.half_life, the period
/// trial.period.
///
/// Discrete state: per trial, noise eps (1); persistent, elapsed (1, s), carried across
/// trials as learning goes on.
class GaussianExploration final : public Block, public codegen::EmitsC {
 public:
  GaussianExploration(std::string name, const ExplorationParams& params, double period);

  // Its outputs and updates as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;
  codegen::CCalculation c_initialization(int update, const Context& context) const override;

  // sigma(t) after `elapsed` s of learning.
  double sigma_at(double elapsed) const;
  // The learning time elapsed in `context`, s.
  double elapsed(const Context& context) const;

 private:
  // "exploration_action": a_E = a_A + sigma(t) eps.
  void calc_exploration_action(const BlockContext& context, VectorRef action) const;
  // The initialization update: draws eps for the first tick.
  EventStatus draw_first(BlockContext& context, VectorRef next) const;
  // The periodic update: draws eps for the next tick and advances elapsed by the period.
  EventStatus draw_next(BlockContext& context, VectorRef next) const;

  ExplorationParams params_;
  double period_;
  const InputPort* actor_action_;
  StatePart noise_;
  StatePart elapsed_;
};

}  // namespace cbbg::blocks
