#pragma once

#include <array>
#include <string>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/parameters.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/plant_signals.h"

namespace cbbg::blocks {

// Config keys sensors.*: per-signal noise and quantisation, in the order of the "measured"
// port (theta_b, theta_b', phi_l, phi_r, phi_l', phi_r'). Zero turns either off (default).
struct SensorsParams {
  std::array<double, kMeasuredSize> noise_std{};     // sensors.noise_std: Gaussian std
  std::array<double, kMeasuredSize> quantisation{};  // sensors.quantisation: step

  static constexpr const char* kSection = "sensors";
  template <class Archive>
  void describe(Archive& a) {
    a.numbers("noise_std", noise_std,
              "Gaussian noise std per measured signal (theta_b, theta_b', phi_l, phi_r, phi_l', "
              "phi_r'); 0 = off",
              kNonNegative);
    a.numbers("quantisation", quantisation, "quantisation step per measured signal; 0 = off",
              kNonNegative);
  }

  // Throws naming the key (e.g. "sensors.noise_std[1]") unless every value is finite, >= 0.
  void validate() const;
};

/// Sensors: the plant state to the signals the controller measures (docs/model.md §2.1).
///
/// | port        | dir | size | meaning                                                  |
/// |-------------|-----|------|----------------------------------------------------------|
/// | plant_state | in  | n    | the plant's signals (plant/plant_signals.h)              |
/// | measured    | out | 6    | theta_b, theta_b', phi_l, phi_r, phi_l', phi_r' (rad, s) |
///
/// Equations, per signal i taken from the plant state x by name (`signals`: where each sits in
/// the n = `state_size` signals; a plant of one wheel gives it for both sides):
///   y_i = Q_i(x_i + sigma_i n_i),   Q_i(v) = q_i round(v / q_i) if q_i > 0, else v,
/// with n_i a standard normal held in the discrete state: drawn by the initialization update
/// for the first tick and by each periodic update for the next, from the block's own
/// generator (only for signals with sigma_i > 0). The initialization update runs at the start
/// of every trial, so a trial never reuses the previous one's last draw. Parameters: sigma =
/// sensors.noise_std, q = sensors.quantisation (both off by default), the period trial.period.
/// Context parameter "noise_scale" (6, ones): sigma_i is used times its entry, so a trial can
/// have less noise than the block was built for (training.* grows it trial by trial) without
/// changing which signals draw.
class Sensors final : public Block {
 public:
  Sensors(std::string name, const SensorsParams& params, double period,
          const plant::SignalIndex& signals = plant::two_wheeler_index(),
          int state_size = plant::kStateSize);

 private:
  // "measured": y_i = Q_i(x_i + sigma_i n_i), sigma_i times its "noise_scale" entry.
  void calc_measured(const BlockContext& context, VectorRef measured) const;
  // Draws n for the next tick (the initialization update and each periodic update).
  EventStatus draw(BlockContext& context, VectorRef next) const;
  // Writes fresh noise samples n_i into `noise` (size 6).
  void draw_noise(RandomGenerator& generator, VectorRef noise) const;

  SensorsParams params_;
  int noise_scale_;                             // the context parameter's index
  std::array<int, kMeasuredSize> plant_index_;  // the plant state's index of each measured signal
  const InputPort* plant_state_;
};

}  // namespace cbbg::blocks
