#include "cbbg/framework/primitives/ramp_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/primitives/argument_checks.h"

namespace cbbg {

RampSource::RampSource(std::string name, double slope, double start_time, double initial_value)
    : RampSource(std::move(name), Vector::Constant(1, slope), start_time,
                 Vector::Constant(1, initial_value)) {}

RampSource::RampSource(std::string name, const Vector& slope, double start_time,
                       const Vector& initial_value)
    : Block(std::move(name)),
      slope_(slope),
      start_time_(start_time),
      initial_value_(initial_value) {
  const std::string label = primitive_checks::label("RampSource", this->name());
  const int size = primitive_checks::checked_size(label, static_cast<int>(slope.size()));
  if (initial_value.size() != slope.size()) {
    throw std::invalid_argument(label + ": the initial value has size " +
                                std::to_string(initial_value.size()) +
                                "; it must have the slope's size, " + std::to_string(slope.size()));
  }
  primitive_checks::check_finite(label, "slope", slope);
  primitive_checks::check_finite(label, "initial value", initial_value);
  if (!std::isfinite(start_time)) {
    throw std::invalid_argument(label + ": start time " + format_number(start_time) +
                                " must be finite");
  }
  declare_output_port<&RampSource::calc_y>("y", size, {}, "y0 + s max(0, t - t_start)");
}

void RampSource::calc_y(const BlockContext& context, VectorRef y) const {
  y = initial_value_ + std::max(0.0, context.time() - start_time_) * slope_;
}

}  // namespace cbbg
