#pragma once

#include <string>

#include "cbbg/framework/block.h"

namespace cbbg::blocks {

// The entropy uses the sampler's constant, config key sampler.k_b.
struct EntropyParams {
  double k_b = 1.0;  // sampler.k_b: K_B, as the BoltzmannSampler uses it

  // Throws naming sampler.k_b unless it is finite and > 0.
  void validate() const;
};

/// Entropy: the differential entropy of the exploration law, for logging (docs/model.md §2.12).
///
/// | port        | dir | size | meaning                            |
/// |-------------|-----|------|------------------------------------|
/// | temperature | in  | 1    | T, from the Tropism                |
/// | entropy     | out | 1    | E, bits (negative for small K_B T) |
///
/// Equation: E = (1/2) log2(pi e K_B T), the entropy of N(a_A, K_B T / 2); -inf at T = 0.
/// Parameter: K_B = sampler.k_b.
class Entropy final : public Block {
 public:
  Entropy(std::string name, const EntropyParams& params);

 private:
  // "entropy": E = (1/2) log2(pi e K_B T).
  void calc_entropy(const BlockContext& context, VectorRef entropy) const;

  EntropyParams params_;
  const InputPort* temperature_;
};

}  // namespace cbbg::blocks
