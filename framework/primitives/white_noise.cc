#include "cbbg/framework/primitives/white_noise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"
#include "cbbg/framework/random.h"

namespace cbbg {

WhiteNoise::WhiteNoise(std::string name, double mean, double standard_deviation, int size,
                       double period, double offset)
    : WhiteNoise(std::move(name), Vector::Constant(std::max(size, 0), mean),
                 Vector::Constant(std::max(size, 0), standard_deviation), period, offset) {}

WhiteNoise::WhiteNoise(std::string name, const Vector& mean, const Vector& standard_deviation,
                       double period, double offset)
    : Block(std::move(name)), mean_(mean), standard_deviation_(standard_deviation) {
  const std::string label = primitive_checks::label("WhiteNoise", this->name());
  const int size = primitive_checks::checked_size(label, static_cast<int>(mean.size()));
  if (standard_deviation.size() != mean.size()) {
    throw std::invalid_argument(label + ": the standard deviation has size " +
                                std::to_string(standard_deviation.size()) +
                                "; it must have the mean's size, " + std::to_string(mean.size()));
  }
  primitive_checks::check_finite(label, "mean", mean);
  for (Eigen::Index i = 0; i < standard_deviation.size(); ++i) {
    const double sigma = standard_deviation[i];
    if (!std::isfinite(sigma) || sigma < 0.0) {
      throw std::invalid_argument(
          label + ": standard deviation " + format_number(sigma) +
          (standard_deviation.size() > 1 ? " at element " + std::to_string(i) : "") +
          " must be finite and >= 0");
    }
  }
  primitive_checks::check_period(label, period, offset);
  declare_discrete_state("value", mean, StateLifetime::kPerTrial);
  declare_output_port<&WhiteNoise::calc_y>("y", size, {}, "the last draw, mu + sigma z",
                                           OutputSources::kDiscreteState);
  declare_initialization_update<&WhiteNoise::draw>();
  // In place: it writes only
  declare_periodic_update<&WhiteNoise::draw>(period, offset, UpdateWrites::kInPlace);
}

void WhiteNoise::calc_y(const BlockContext& context, VectorRef y) const {
  y = context.discrete_state();
}

EventStatus WhiteNoise::draw(BlockContext& context, VectorRef next) const {
  RandomGenerator& generator = context.random_generator();
  for (Eigen::Index i = 0; i < next.size(); ++i) {
    next[i] = mean_[i] + standard_deviation_[i] * draw_standard_normal(generator);
  }
  return EventStatus::succeeded();
}

}  // namespace cbbg
