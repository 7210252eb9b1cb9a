#include "cbbg/blocks/entropy.h"

#include <cmath>
#include <numbers>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

void EntropyParams::validate() const { check_positive("sampler.k_b", k_b); }

Entropy::Entropy(std::string name, const EntropyParams& params)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  temperature_ = &declare_input_port("temperature", 1, "T");
  declare_output_port<&Entropy::calc_entropy>("entropy", 1, {temperature_},
                                              "E = (1/2) log2(pi e K_B T)");
}

void Entropy::calc_entropy(const BlockContext& context, VectorRef entropy) const {
  entropy[0] = 0.5 * std::log2(std::numbers::pi * std::numbers::e * params_.k_b *
                               context.input(*temperature_)[0]);
}

}  // namespace cbbg::blocks
