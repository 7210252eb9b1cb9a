#include "cbbg/blocks/failure_detector.h"

#include <cmath>

#include "cbbg/blocks/measured_signals.h"
#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

void FailureDetectorParams::validate() const {
  check_positive("trial.failure_angle", failure_angle);
}

FailureDetector::FailureDetector(std::string name, const FailureDetectorParams& params,
                                 double period)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  check_period(period);
  measured_ = &declare_input_port("measured", kMeasuredSize, "measured signals");
  declare_output_port<&FailureDetector::calc_failed>(
      "failed", 1, {measured_}, "1 when |theta_b| > trial.failure_angle or a signal is not finite");
  declare_periodic_update<&FailureDetector::check_failure>(period, 0.0);
}

void FailureDetector::calc_failed(const BlockContext& context, VectorRef failed) const {
  const auto y = context.input(*measured_);
  const bool fell = std::abs(y[kMeasuredThetaB]) > params_.failure_angle;
  failed[0] = fell || !y.allFinite() ? 1.0 : 0.0;
}

EventStatus FailureDetector::check_failure(BlockContext& context, VectorRef) const {
  const auto y = context.input(*measured_);
  if (!y.allFinite()) return EventStatus::terminate("a measured signal is not finite");
  if (std::abs(y[kMeasuredThetaB]) > params_.failure_angle) {
    return EventStatus::terminate("|theta_b| exceeded trial.failure_angle");
  }
  return EventStatus::succeeded();
}

namespace {

// C statements setting `finite` to whether every measured signal is (x - x is 0 only then).
std::string all_finite() {
  return "  int i, finite = 1;\n  for (i = 0; i < " + std::to_string(kMeasuredSize) +
         "; ++i) finite = finite && in0[i] - in0[i] == 0;\n";
}

}  // namespace

codegen::CCalculation FailureDetector::c_calculation(int, const Context&) const {
  // in0 measured.
  return {{codegen::c_number("angle", params_.failure_angle)},
          all_finite() + "  out[0] = CBBG_FABS(in0[" + std::to_string(kMeasuredThetaB) +
              "]) > $angle || !finite ? 1 : 0;\n"};
}

codegen::CCalculation FailureDetector::c_update(int, const Context&) const {
  return {{codegen::c_number("angle", params_.failure_angle)},
          all_finite() + "  if (!finite || CBBG_FABS(in0[" + std::to_string(kMeasuredThetaB) +
              "]) > $angle) return 1;\n"};
}

}  // namespace cbbg::blocks
