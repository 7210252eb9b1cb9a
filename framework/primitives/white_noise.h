#pragma once

#include <string>

#include "cbbg/framework/block.h"

namespace cbbg {

/// WhiteNoise: discrete Gaussian white noise, a fresh independent draw every `period` h from
/// `offset` t_0 (t_k = t_0 + k h), held in between (a zero-order hold), elementwise:
///
///     y = mu + sigma z,    z ~ N(0, 1) independently for each element and draw.
///
/// | port | dir | size | meaning                              |
/// |------|-----|------|--------------------------------------|
/// | y    | out | n    | the last draw, mu + sigma z          |
///
/// Each Simulator::initialize draws y's first value, and each sample t_k draws the next,
/// held from t_k until t_{k+1}; a log of the same period and offset records every draw once
/// (the first at t_0, the one drawn at t_k at t_{k+1}). Each draw takes one standard normal
/// per element, in element order, from the block's generator in the Context
/// (BlockContext::random_generator, seeded from the root seed and the block's path), so a
/// run repeats exactly under the same root seed, another seed gives another sequence, and a
/// clone of a context draws what the original would. y has no input and reads the state
/// part "value", StateLifetime::kPerTrial: reset_trial_state puts mu back until the next
/// initialisation draws, and keeps the generator, so a new trial gets new noise.
class WhiteNoise final : public Block {
 public:
  // Throws std::invalid_argument naming the block and the argument unless mu and sigma have
  // the same size n >= 1, every mean is finite, every standard deviation finite and >= 0,
  // the period positive and finite and the offset finite and >= 0.
  WhiteNoise(std::string name, const Vector& mean, const Vector& standard_deviation, double period,
             double offset = 0.0);
  // The same mean and standard deviation for each of `size` elements.
  WhiteNoise(std::string name, double mean, double standard_deviation, int size, double period,
             double offset = 0.0);

 private:
  // "y": the state, the last draw.
  void calc_y(const BlockContext& context, VectorRef y) const;
  // A fresh draw, mu + sigma z, at initialisation and at each sample. Writes in place: it
  // writes only.
  EventStatus draw(BlockContext& context, VectorRef next) const;

  Vector mean_;
  Vector standard_deviation_;
};

}  // namespace cbbg
