#pragma once

#include <string>

#include "cbbg/framework/block.h"

namespace cbbg {

/// SineSource: a sinusoid, elementwise, with its frequency in radians per second:
///
///     y(t) = b + a sin(omega t + phi)
///
/// (a: amplitude; omega: angular frequency in rad/s, 2 pi times the frequency in Hz; phi:
/// phase in rad; b: bias).
///
/// | port | dir | size | meaning                  |
/// |------|-----|------|--------------------------|
/// | y    | out | n    | b + a sin(omega t + phi) |
///
/// y depends on the context's time alone (no input, no state).
class SineSource final : public Block {
 public:
  // Throws std::invalid_argument naming the block and the argument unless the four have the
  // same size n >= 1 and every element is finite.
  SineSource(std::string name, const Vector& amplitude, const Vector& angular_frequency,
             const Vector& phase, const Vector& bias);
  // n = 1.
  SineSource(std::string name, double amplitude, double angular_frequency, double phase = 0.0,
             double bias = 0.0);

 private:
  // "y": b + a sin(omega t + phi).
  void calc_y(const BlockContext& context, VectorRef y) const;

  Vector amplitude_;
  Vector angular_frequency_;
  Vector phase_;
  Vector bias_;
};

}  // namespace cbbg
