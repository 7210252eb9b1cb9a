#include "cbbg/blocks/ou_exploration.h"

#include <cmath>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/random.h"

namespace cbbg::blocks {

OuExploration::OuExploration(std::string name, const ExplorationParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  const double rate = params_.ou_theta * period;
  decay_ = std::exp(-rate);
  // expm1 keeps the innovation accurate when theta Ts is small.
  innovation_ = params_.sigma * std::sqrt(-std::expm1(-2.0 * rate));
  actor_action_ = &declare_input_port("actor_action", 1, "a_A(t)");
  declare_discrete_state("noise", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port<&OuExploration::calc_exploration_action>(
      "exploration_action", 1, {actor_action_}, "a_E(t) = a_A + x(t)");
  declare_initialization_update<&OuExploration::draw_stationary>();
  declare_periodic_update<&OuExploration::evolve>(
      period, 0.0, UpdateWrites::kInPlace);  // x is read before it is written
}

void OuExploration::calc_exploration_action(const BlockContext& context, VectorRef action) const {
  action[0] = context.input(*actor_action_)[0] + context.discrete_state()[0];
}

EventStatus OuExploration::draw_stationary(BlockContext& context, VectorRef next) const {
  next[0] = params_.sigma * draw_standard_normal(context.random_generator());
  return EventStatus::succeeded();
}

EventStatus OuExploration::evolve(BlockContext& context, VectorRef next) const {
  const double x = context.discrete_state()[0];
  next[0] = decay_ * x + innovation_ * draw_standard_normal(context.random_generator());
  return EventStatus::succeeded();
}

codegen::CCalculation OuExploration::c_calculation(int, const Context&) const {
  return {{}, "  out[0] = in0[0] + @noise[0];\n"};  // in0 a_A
}

codegen::CCalculation OuExploration::c_update(int, const Context&) const {
  return {{codegen::c_number("decay", decay_), codegen::c_number("innovation", innovation_)},
          "  @@noise[0] = $decay * @noise[0] + $innovation * CBBG_NORMAL(rng);\n",
          true};
}

codegen::CCalculation OuExploration::c_initialization(int, const Context&) const {
  return {{codegen::c_number("sigma", params_.sigma)},
          "  @@noise[0] = $sigma * CBBG_NORMAL(rng);\n",
          true};
}

}  // namespace cbbg::blocks
