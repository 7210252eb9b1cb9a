#pragma once

#include <string>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// What the features see (normaliser.inputs): the paper's pitch and pitch rate, or those with
// the wheels' mean rate, or with the wheels' mean angle and rate.
enum class NormalisedInputs { kPitch, kPitchWheelRate, kPitchWheels };

// Config keys normaliser.*.
struct NormaliserParams {
  double scale_theta = 0.05817764;   // normaliser.scale_theta: n_theta, rad (pi/54)
  double scale_dtheta = 0.05817764;  // normaliser.scale_dtheta: n_dtheta, rad/s (pi/54)
  double saturation = 3.0;           // normaliser.saturation: the RBF grid's half-width
  NormalisedInputs inputs = NormalisedInputs::kPitch;  // normaliser.inputs
  double scale_phi = 2.0;   // normaliser.scale_phi: n_phi, mean wheel angle per unit, rad
  double scale_dphi = 2.0;  // normaliser.scale_dphi: n_dphi, mean wheel rate per unit, rad/s

  static constexpr const char* kSection = "normaliser";
  template <class Archive>
  void describe(Archive& a) {
    a.number("scale_theta", scale_theta, "n_theta: pitch per grid unit, rad", kPositive);
    a.number("scale_dtheta", scale_dtheta, "n_dtheta: pitch rate per grid unit, rad/s", kPositive);
    a.number("saturation", saturation, "inputs saturate to +-this (the RBF grid)", kPositive);
    a.choice("inputs", inputs,
             "what the features see: pitch (theta_b, theta_b', the paper's), pitch_wheel_rate "
             "(and the wheels' mean rate phi'), pitch_wheels (and their mean angle phi and rate)",
             Choices<NormalisedInputs>{{"pitch", NormalisedInputs::kPitch},
                                       {"pitch_wheel_rate", NormalisedInputs::kPitchWheelRate},
                                       {"pitch_wheels", NormalisedInputs::kPitchWheels}});
    a.number("scale_phi", scale_phi,
             "n_phi: mean wheel angle per grid unit, rad (with inputs: pitch_wheels)", kPositive);
    a.number("scale_dphi", scale_dphi,
             "n_dphi: mean wheel rate per grid unit, rad/s (with inputs: pitch_wheel_rate or "
             "pitch_wheels)",
             kPositive);
  }
  // Throws naming the key unless every value is as declared.
  void validate() const;

  // How many values the normaliser outputs: 2, 3 or 4.
  int size() const;
  bool sees_wheel_angle() const { return inputs == NormalisedInputs::kPitchWheels; }
  bool sees_wheel_rate() const { return inputs != NormalisedInputs::kPitch; }
};

/// Normaliser: pitch and pitch rate in grid units, saturated to the RBF grid (docs/model.md §2.2),
/// and, with normaliser.inputs, the wheels' mean angle and rate likewise.
///
/// | port     | dir | size  | meaning                                               |
/// |----------|-----|-------|-------------------------------------------------------|
/// | measured | in  | 6     | the Sensors output (measured_signals.h)               |
/// | x        | out | 2 - 4 | normalised (theta_b, theta_b'[, phi][, phi'])         |
///
/// Equations: x = clamp((theta_b / n_theta, theta_b' / n_dtheta), -S, S), then, as the inputs
/// ask, clamp(phi / n_phi, -S, S) and clamp(phi' / n_dphi, -S, S), with phi = (phi_l + phi_r) / 2
/// and phi' = (phi_l' + phi_r') / 2. Without the clamp the pitch rate leaves the grid and every
/// feature vanishes. Parameters: n_theta = normaliser.scale_theta, n_dtheta =
/// normaliser.scale_dtheta, S = normaliser.saturation, normaliser.inputs, n_phi =
/// normaliser.scale_phi, n_dphi = normaliser.scale_dphi.
/// Its layout (feature_layout.h): the scales of what it sees and S, as normaliser.* (the
/// paper's inputs: n_theta, n_dtheta and S only, so its weights files keep their layout).
class Normaliser final : public Block, public DescribesLayout, public codegen::EmitsC {
 public:
  Normaliser(std::string name, const NormaliserParams& params);

  FeatureLayout layout() const override;
  // "x" as C (cbbg export).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;

 private:
  // "x": the measured signals it sees, each over its scale and saturated to +-S.
  void calc_x(const BlockContext& context, VectorRef x) const;

  NormaliserParams params_;
  const InputPort* measured_;
};

}  // namespace cbbg::blocks
