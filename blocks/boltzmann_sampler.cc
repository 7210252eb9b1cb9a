#include "cbbg/blocks/boltzmann_sampler.h"

#include <cmath>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/random.h"

namespace cbbg::blocks {

void SamplerParams::validate() const { check_declared(*this, kSection); }

BoltzmannSampler::BoltzmannSampler(std::string name, const SamplerParams& params, double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  actor_action_ = &declare_input_port("actor_action", 1, "a_A(t)");
  temperature_ = &declare_input_port("temperature", 1, "T(t)");
  declare_discrete_state("noise", Vector::Zero(1), StateLifetime::kPerTrial);
  declare_output_port<&BoltzmannSampler::calc_exploration_action>(
      "exploration_action", 1, {actor_action_, temperature_}, "a_E(t) ~ N(a_A, K_B T / 2)");
  declare_initialization_update<&BoltzmannSampler::draw>();
  declare_periodic_update<&BoltzmannSampler::draw>(period, 0.0,
                                                   UpdateWrites::kInPlace);  // writes only
}

void BoltzmannSampler::calc_exploration_action(const BlockContext& context,
                                               VectorRef action) const {
  const double deviation = std::sqrt(params_.k_b * context.input(*temperature_)[0] / 2.0);
  action[0] = context.input(*actor_action_)[0] + deviation * context.discrete_state()[0];
}

EventStatus BoltzmannSampler::draw(BlockContext& context, VectorRef next) const {
  next[0] = draw_standard_normal(context.random_generator());
  return EventStatus::succeeded();
}

codegen::CCalculation BoltzmannSampler::c_calculation(int, const Context&) const {
  // in0 a_A, in1 T.
  return {{codegen::c_number("k_b", params_.k_b)},
          "  const real deviation = CBBG_SQRT($k_b * in1[0] / (real)2);\n"
          "  out[0] = in0[0] + deviation * @noise[0];\n"};
}

codegen::CCalculation BoltzmannSampler::c_update(int, const Context&) const {
  return {{}, "  @@noise[0] = CBBG_NORMAL(rng);\n", true};
}

codegen::CCalculation BoltzmannSampler::c_initialization(int, const Context& context) const {
  return c_update(0, context);  // the same draw, as the constructor declares both
}

}  // namespace cbbg::blocks
