#include "cbbg/blocks/gaussian_exploration.h"

#include <cmath>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/random.h"

namespace cbbg::blocks {

GaussianExploration::GaussianExploration(std::string name, const ExplorationParams& params,
                                         double period)
    : Block(std::move(name)), params_(params), period_(period) {
  params_.validate();
  check_period(period);
  actor_action_ = &declare_input_port("actor_action", 1, "a_A(t)");
  noise_ = declare_discrete_state("noise", Vector::Zero(1), StateLifetime::kPerTrial);
  elapsed_ = declare_discrete_state("elapsed", Vector::Zero(1), StateLifetime::kPersistent);
  declare_output_port<&GaussianExploration::calc_exploration_action>(
      "exploration_action", 1, {actor_action_}, "a_E(t) = a_A + sigma(t) eps");
  // The draws of the BoltzmannSampler, in the same order: common random numbers.
  declare_initialization_update<&GaussianExploration::draw_first>();
  declare_periodic_update<&GaussianExploration::draw_next>(
      period, 0.0,
      UpdateWrites::kInPlace);  // noise is only written, elapsed read before it is written
}

void GaussianExploration::calc_exploration_action(const BlockContext& context,
                                                  VectorRef action) const {
  const auto state = context.discrete_state();
  action[0] =
      context.input(*actor_action_)[0] + sigma_at(elapsed_.of(state)[0]) * noise_.of(state)[0];
}

EventStatus GaussianExploration::draw_first(BlockContext& context, VectorRef next) const {
  noise_.of(next)[0] = draw_standard_normal(context.random_generator());
  return EventStatus::succeeded();
}

EventStatus GaussianExploration::draw_next(BlockContext& context, VectorRef next) const {
  noise_.of(next)[0] = draw_standard_normal(context.random_generator());
  elapsed_.of(next)[0] = elapsed_.of(context.discrete_state())[0] + period_;
  return EventStatus::succeeded();
}

double GaussianExploration::sigma_at(double elapsed) const {
  if (params_.half_life == 0.0) return params_.sigma;
  return params_.sigma * std::exp2(-elapsed / params_.half_life);
}

double GaussianExploration::elapsed(const Context& context) const {
  return context.discrete_state(*this)[elapsed_.offset];
}

codegen::CCalculation GaussianExploration::c_calculation(int, const Context&) const {
  // in0 a_A; sigma_at(elapsed), then the action.
  codegen::CCalculation c;
  c.constants = {codegen::c_number("sigma", params_.sigma)};
  if (params_.half_life == 0.0) {
    c.body = "  const real sigma = $sigma;\n";
  } else {
    c.constants.push_back(codegen::c_number("half_life", params_.half_life));
    c.body = "  const real sigma = $sigma * CBBG_EXP2(-@elapsed[0] / $half_life);\n";
  }
  c.body += "  out[0] = in0[0] + sigma * @noise[0];\n";
  return c;
}

codegen::CCalculation GaussianExploration::c_update(int, const Context&) const {
  return {{codegen::c_number("period", period_)},
          "  @@noise[0] = CBBG_NORMAL(rng);\n  @@elapsed[0] = @elapsed[0] + $period;\n",
          true};
}

codegen::CCalculation GaussianExploration::c_initialization(int, const Context&) const {
  return {{}, "  @@noise[0] = CBBG_NORMAL(rng);\n", true};
}

}  // namespace cbbg::blocks
