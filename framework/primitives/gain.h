#pragma once

#include <Eigen/Core>

#include "cbbg/framework/block.h"

namespace cbbg {

/// Gain: y = k u, elementwise with a scalar k, or y = K u with a matrix K of m rows and n
/// columns (for a scalar gain, m = n = its size).
///
/// | port | dir | size | meaning    |
/// |------|-----|------|------------|
/// | u    | in  | n    | input      |
/// | y    | out | m    | k u or K u |
///
/// y reads u directly (direct feedthrough).
class Gain final : public Block {
 public:
  Gain(std::string name, double gain, int size);
  // Throws std::invalid_argument naming the block unless K has at least one row and one
  // column and every element is finite.
  Gain(std::string name, Eigen::MatrixXd matrix);

 private:
  // "y" of a scalar gain: k u.
  void calc_y_scalar(const BlockContext& context, VectorRef y) const;
  // "y" of a matrix gain: K u.
  void calc_y_matrix(const BlockContext& context, VectorRef y) const;

  double gain_ = 0.0;
  Eigen::MatrixXd matrix_;  // empty for a scalar gain
  const InputPort* u_;
};

}  // namespace cbbg
