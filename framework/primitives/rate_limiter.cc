#include "cbbg/framework/primitives/rate_limiter.h"

#include <cmath>
#include <stdexcept>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

using primitive_checks::label;

namespace {

void check_rate(const std::string& block, const char* what, double rate) {
  if (std::isnan(rate) || rate < 0.0) {
    throw std::invalid_argument(block + ": " + what + " " + format_number(rate) +
                                " must be >= 0 (inf for no limit)");
  }
}

}  // namespace

RateLimiter::RateLimiter(std::string name, int size, double rising_rate, double falling_rate,
                         double period, double offset)
    // `name` copied, not moved: the size's check reads it too.
    : RateLimiter(name,
                  Vector::Zero(primitive_checks::checked_size(label("RateLimiter", name), size)),
                  rising_rate, falling_rate, period, offset) {}

RateLimiter::RateLimiter(std::string name, const Vector& initial_value, double rising_rate,
                         double falling_rate, double period, double offset)
    : Block(std::move(name)), max_rise_(rising_rate * period), max_fall_(falling_rate * period) {
  const std::string block = label("RateLimiter", this->name());
  const int size = primitive_checks::checked_size(block, static_cast<int>(initial_value.size()));
  primitive_checks::check_finite(block, "initial value", initial_value);
  check_rate(block, "rising rate", rising_rate);
  check_rate(block, "falling rate", falling_rate);
  primitive_checks::check_period(block, period, offset);
  u_ = &declare_input_port("u", size, "the signal to limit");
  declare_discrete_state("output", initial_value, StateLifetime::kPerTrial);
  declare_output_port<&RateLimiter::calc_y>("y", size, {}, "the rate-limited signal",
                                            OutputSources::kDiscreteState);
  // In place: it reads and writes its state through `next` alone
  declare_periodic_update<&RateLimiter::limit>(period, offset, UpdateWrites::kInPlace);
}

void RateLimiter::calc_y(const BlockContext& context, VectorRef y) const {
  y = context.discrete_state();
}

EventStatus RateLimiter::limit(BlockContext& context, VectorRef next) const {
  // `next` holds y_{k-1} on entry.
  const ConstVectorView input = context.input(*u_);
  for (Eigen::Index i = 0; i < input.size(); ++i) {
    const double step = input[i] - next[i];
    if (step > max_rise_) {
      next[i] += max_rise_;
    } else if (step < -max_fall_) {
      next[i] -= max_fall_;
    } else {
      next[i] = input[i];  // within the limits (or NaN, which the simulator reports)
    }
  }
  return EventStatus::succeeded();
}

}  // namespace cbbg
