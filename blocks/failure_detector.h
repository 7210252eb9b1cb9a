#pragma once

#include <string>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"

namespace cbbg::blocks {

// Config key trial.failure_angle.
struct FailureDetectorParams {
  double failure_angle = 0.5236;  // trial.failure_angle: |theta_b| beyond it fails, rad

  // Throws naming trial.failure_angle unless it is finite and > 0.
  void validate() const;
};

/// FailureDetector: ends the trial when the robot falls (docs/model.md §3).
///
/// | port     | dir | size | meaning                                  |
/// |----------|-----|------|------------------------------------------|
/// | measured | in  | 6    | the Sensors output (measured_signals.h)   |
/// | failed   | out | 1    | 1 when the trial fails at this tick, else 0 |
///
/// Equation: failed = 1 if |theta_b| > failure_angle (strictly: at the angle it still
/// stands) or any measured signal is not finite, else 0. The periodic update returns
/// EventStatus::terminate when failed, so the simulation stops after this tick's updates
/// (the learning blocks still learn from the failing transition).
/// Parameters: failure_angle = trial.failure_angle, the period trial.period.
class FailureDetector final : public Block, public codegen::EmitsC {
 public:
  FailureDetector(std::string name, const FailureDetectorParams& params, double period);

  // Its outputs and updates as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;

 private:
  // "failed": 1 if |theta_b| > failure_angle or a measured signal is not finite, else 0.
  void calc_failed(const BlockContext& context, VectorRef failed) const;
  // Ends the simulation when the trial fails; writes no state.
  EventStatus check_failure(BlockContext& context, VectorRef next) const;

  FailureDetectorParams params_;
  const InputPort* measured_;
};

}  // namespace cbbg::blocks
