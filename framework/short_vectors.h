#pragma once
// Loops over the short vectors ports and states carry, written for their sizes: most are one
// value, where Eigen's general loop (alignment peeling, packets, tail) costs more than the work.

#include <algorithm>
#include <cmath>

#include "cbbg/framework/types.h"

namespace cbbg {

// True when none of x[0, size) is NaN or infinite. A short vector is tested element by element;
// a long one as x * 0 summed, which is 0 for finite values and NaN otherwise, a loop the
// compiler vectorises.
inline bool all_finite(const double* x, Eigen::Index size) {
  constexpr Eigen::Index kShort = 8;
  if (size <= kShort) {
    for (Eigen::Index i = 0; i < size; ++i) {
      if (!std::isfinite(x[i])) return false;
    }
    return true;
  }
  return (ConstVectorView(x, size).array() * 0.0).sum() == 0.0;
}

// to[0, size) = from[0, size): one value without a call, more through std::copy_n.
inline void copy_values(const double* from, Eigen::Index size, double* to) {
  if (size == 1) {
    *to = *from;
  } else {
    std::copy_n(from, size, to);
  }
}

}  // namespace cbbg
