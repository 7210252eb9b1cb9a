#include "cbbg/blocks/push_params.h"

#include <algorithm>
#include <cmath>

#include "cbbg/blocks/parameter_checks.h"

namespace cbbg::blocks {

void PushParams::validate() const { check_declared(*this, kSection); }

bool PushParams::on_at(double t) const {
  const double tolerance = 1e-9 * std::max(1.0, std::abs(t));
  return t >= start - tolerance && t < start + duration - tolerance;
}

}  // namespace cbbg::blocks
