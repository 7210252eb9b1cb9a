#pragma once

#include <string>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config keys normaliser.*.
struct NormaliserParams {
  double scale_theta = 0.05817764;   // normaliser.scale_theta: n_theta, rad (pi/54)
  double scale_dtheta = 0.05817764;  // normaliser.scale_dtheta: n_dtheta, rad/s (pi/54)
  double saturation = 3.0;           // normaliser.saturation: the RBF grid's half-width

  static constexpr const char* kSection = "normaliser";
  template <class Archive>
  void describe(Archive& a) {
    a.number("scale_theta", scale_theta, "n_theta: pitch per grid unit, rad", kPositive);
    a.number("scale_dtheta", scale_dtheta, "n_dtheta: pitch rate per grid unit, rad/s", kPositive);
    a.number("saturation", saturation, "inputs saturate to +-this (the RBF grid)", kPositive);
  }
  // Throws naming the key unless every value is as declared.
  void validate() const;
};

/// Normaliser: pitch and pitch rate in grid units, saturated to the RBF grid (docs/model.md §2.2).
///
/// | port     | dir | size | meaning                                  |
/// |----------|-----|------|------------------------------------------|
/// | measured | in  | 6    | the Sensors output (measured_signals.h)   |
/// | x        | out | 2    | normalised (theta_b, theta_b')            |
///
/// Equations: x = clamp((theta_b / n_theta, theta_b' / n_dtheta), -S, S). Without the clamp
/// the pitch rate leaves the grid and every feature vanishes. Parameters: n_theta =
/// normaliser.scale_theta, n_dtheta = normaliser.scale_dtheta, S = normaliser.saturation.
/// Its layout (feature_layout.h): those three, as normaliser.*.
class Normaliser final : public Block, public DescribesLayout {
 public:
  Normaliser(std::string name, const NormaliserParams& params);

  FeatureLayout layout() const override;

 private:
  NormaliserParams params_;
};

}  // namespace cbbg::blocks
