#pragma once

#include <string>
#include <vector>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Where the units sit: on the grid of centres over every axis (the paper's), or along each
// axis alone, so what is learnt is a sum of one function per input.
enum class RbfUnits { kGrid, kPerAxis };

// Config keys rbf.*.
struct RbfParams {
  // rbf.centres: the grid's coordinates along each axis; the units sit on centres x centres.
  std::vector<double> centres{-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0};
  double width = 0.5;  // rbf.width: b, the Gaussian width of every unit, in grid units
  RbfUnits units = RbfUnits::kGrid;  // rbf.units

  static constexpr const char* kSection = "rbf";
  template <class Archive>
  void describe(Archive& a) {
    a.numbers("centres", centres, "grid coordinates per axis (n x n units)", kFinite);
    a.number("width", width, "b: Gaussian width of every unit, grid units", kPositive);
    a.choice("units", units,
             "where the units sit: grid (m^d of them, on the centres of every axis at once, the "
             "paper's) or per_axis (m on each of the d axes alone, d m in all: the critic's value "
             "and the actor's action become a sum of one function per input)",
             Choices<RbfUnits>{{"grid", RbfUnits::kGrid}, {"per_axis", RbfUnits::kPerAxis}});
  }

  // Throws naming the key unless centres is non-empty, finite and strictly increasing and
  // width is finite and > 0.
  void validate() const;
};

/// RbfFeatures: the Gaussian radial-basis features of the critic and the actor (docs/model.md
/// §2.3).
///
/// | port     | dir | size | meaning                                  |
/// |----------|-----|------|------------------------------------------|
/// | x        | in  | d    | normalised (theta_b, theta_b'), d = 2     |
/// | features | out | m^d  | phi(x), unit k = i m + j at (c_i, c_j)    |
/// |          |     | (d m)| (rbf.units per_axis: unit k = a m + i)    |
///
/// Equations: phi_k(x) = exp(-((x_0 - c_i)^2 + (x_1 - c_j)^2) / (2 b^2)), k = i m + j, for
/// i, j in [0, m): pitch picks the row i, pitch rate the column j. Since V = w . phi and
/// a_A = theta . phi, phi is also the gradient of both with respect to their weights.
/// With d = 3 or 4 inputs (normaliser.inputs) the grid has an axis per input, the first the
/// slowest: phi_k(x) = exp(-sum_a (x_a - c_{k_a})^2 / (2 b^2)), k = sum_a k_a m^(d-1-a).
/// With rbf.units per_axis the units sit on each axis alone: phi_k(x) = exp(-(x_a - c_i)^2 /
/// (2 b^2)), k = a m + i, d m of them; what a learner sums over them is a sum of one function
/// per input (the PD law's shape), with far fewer weights than the grid's m^d.
/// Parameters: c = rbf.centres (m of them), b = rbf.width. Its layout (feature_layout.h):
/// rbf.centres and rbf.width, and rbf.per_axis 1 with rbf.units per_axis.
class RbfFeatures final : public Block, public DescribesLayout, public codegen::EmitsC {
 public:
  // `dimensions`, d: the size of x, from 1 to kMaxDimensions (NormaliserParams::size()).
  RbfFeatures(std::string name, const RbfParams& params, int dimensions = 2);

  static constexpr int kMaxDimensions = 4;

  // m^d (d m per axis), the size of the "features" port.
  int num_features() const;

  FeatureLayout layout() const override;
  std::string layout_note() const override;
  // "features" as C (cbbg export): the same sums in the same order.
  codegen::CCalculation c_calculation(int output, const Context& context) const override;

 private:
  // "features": phi(x), the grid of two axes here, the others by the functions below.
  void calc_features(const BlockContext& context, VectorRef features) const;
  // The grid of d > 2 axes, an odometer over the units that keeps each axis's partial sum.
  void grid_features(const ConstVectorView& point, VectorRef features) const;
  // rbf.units per_axis: m units along each axis alone.
  void per_axis_features(const ConstVectorView& point, VectorRef features) const;
  std::string per_axis_c_body() const;

  RbfParams params_;
  int dimensions_;
  double inverse_two_width_squared_;
  const InputPort* x_;
};

}  // namespace cbbg::blocks
