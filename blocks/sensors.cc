#include "cbbg/blocks/sensors.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/random.h"

namespace cbbg::blocks {

void SensorsParams::validate() const { check_declared(*this, kSection); }

Sensors::Sensors(std::string name, const SensorsParams& params, double period,
                 const plant::SignalIndex& signals, int state_size)
    : Block(std::move(name)),
      params_(params),
      plant_index_{signals.pitch,       signals.pitch_rate,      signals.wheel_left,
                   signals.wheel_right, signals.wheel_left_rate, signals.wheel_right_rate} {
  params_.validate();
  check_period(period);
  for (const int index : plant_index_) {
    if (index < 0 || index >= state_size) {
      throw std::invalid_argument("block '" + this->name() + "': a measured signal's index (" +
                                  std::to_string(index) + ") lies outside the plant's " +
                                  std::to_string(state_size) + " signals");
    }
  }
  plant_state_ =
      &declare_input_port("plant_state", state_size, "the plant's signals (plant/plant_signals.h)");
  declare_discrete_state("noise", Vector::Zero(kMeasuredSize), StateLifetime::kPerTrial);
  noise_scale_ = declare_parameter("noise_scale", Vector::Ones(kMeasuredSize));
  declare_output_port<&Sensors::calc_measured>("measured", kMeasuredSize, {plant_state_},
                                               "theta_b, theta_b', phi_l, phi_r, phi_l', phi_r'");
  declare_initialization_update<&Sensors::draw>();
  declare_periodic_update<&Sensors::draw>(period, 0.0, UpdateWrites::kInPlace);  // writes only
}

void Sensors::calc_measured(const BlockContext& context, VectorRef measured) const {
  const auto state = context.input(*plant_state_);
  const auto noise = context.discrete_state();
  const auto scale = context.parameter(noise_scale_);
  for (int i = 0; i < kMeasuredSize; ++i) {
    const auto index = static_cast<size_t>(i);
    double value = state[plant_index_[index]] + params_.noise_std[index] * scale[i] * noise[i];
    const double step = params_.quantisation[index];
    if (step > 0.0) value = step * std::round(value / step);
    measured[i] = value;
  }
}

EventStatus Sensors::draw(BlockContext& context, VectorRef next) const {
  draw_noise(context.random_generator(), next);
  return EventStatus::succeeded();
}

void Sensors::draw_noise(RandomGenerator& generator, VectorRef noise) const {
  for (int i = 0; i < kMeasuredSize; ++i) {
    noise[i] =
        params_.noise_std[static_cast<size_t>(i)] > 0.0 ? draw_standard_normal(generator) : 0.0;
  }
}

}  // namespace cbbg::blocks
