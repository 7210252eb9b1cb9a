#pragma once
// Vector types shared by every block: double only, Eigen storage.

#include <Eigen/Core>

namespace cbbg {

using Vector = Eigen::VectorXd;
// A writable view of a slice of the context's contiguous storage.
using VectorRef = Eigen::Ref<Eigen::VectorXd>;
// A read-only view of a slice of the context's contiguous storage.
using ConstVectorView = Eigen::Map<const Eigen::VectorXd>;
using VectorView = Eigen::Map<Eigen::VectorXd>;

}  // namespace cbbg
