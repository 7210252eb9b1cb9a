#pragma once

#include <limits>
#include <string>

#include "cbbg/framework/block.h"

namespace cbbg {

/// PidController: a discrete PID controller with output limits and anti-windup by conditional
/// integration, elementwise on n error signals, sampled every `period` h from `offset` t_0
/// (t_k = t_0 + k h). Its input is the error e = reference - measurement (an Adder with signs
/// +1, -1 forms it), so one block serves any sign convention and set-point weighting stays
/// outside.
///
/// | port | dir | size | meaning                                 |
/// |------|-----|------|-----------------------------------------|
/// | e    | in  | n    | the error, reference - measurement      |
/// | u    | out | n    | the command u_k, held until t_{k+1}     |
///
/// At each sample t_k, in this order, for each element:
///  1. e_k = e(t_k), the error every update at t_k reads (simulator.h step 2);
///  2. D_k = (e_k - e_{k-1}) / h, the backward difference; D_0 = 0 (e_{-1} is taken as e_0,
///     so the first sample gives no derivative kick);
///  3. v_k = kp e_k + ki I_k + kd D_k, the unsaturated command, with I_0 = 0;
///  4. u_k = sat(v_k) = min(max(v_k, u_min), u_max), held on u from t_k until t_{k+1};
///  5. anti-windup by conditional integration: I_{k+1} = I_k when the command saturates and
///     e_k would drive it further (v_k > u_max and e_k > 0, or v_k < u_min and e_k < 0);
///     otherwise I_{k+1} = I_k + h e_k (the forward rectangle rule: I_k sums the errors before
///     t_k, times h);
///  6. e_k is kept as the next sample's e_{k-1}.
///
/// Conditional integration rather than back-calculation: it needs no tracking gain to tune,
/// and the integral never moves further into a limit it is already past.
///
/// u reads the block's state alone (no direct feedthrough): the controller closes a loop with
/// a plant that feeds through, and a continuous plant sees u_k over [t_k, t_{k+1}) (a zero-
/// order hold with no computational delay); a discrete block that samples u at t_{k+1}
/// reads u_k. Before the first sample u is sat(0). The state parts "integral" (I),
/// "previous_error" (e_{k-1}), "command" (u) and "started" (1 after the first sample) are all
/// StateLifetime::kPerTrial: each trial starts afresh.
class PidController final : public Block {
 public:
  struct Params {
    double kp = 0.0;  // proportional gain, finite, >= 0
    double ki = 0.0;  // integral gain, per second, finite, >= 0
    double kd = 0.0;  // derivative gain, in seconds, finite, >= 0
    double u_min = -std::numeric_limits<double>::infinity();  // -inf: no lower limit
    double u_max = std::numeric_limits<double>::infinity();   // inf: no upper limit
  };

  // Throws std::invalid_argument naming the block and the argument unless every gain is
  // finite and >= 0, u_min <= u_max (neither NaN, u_min below inf, u_max above -inf), the
  // period is positive and finite, the offset finite and >= 0, and size >= 1.
  PidController(std::string name, const Params& params, double period, int size = 1,
                double offset = 0.0);

  const Params& params() const { return params_; }
  double period() const { return period_; }

 private:
  // "u": the command u_k held in the state.
  void calc_u(const BlockContext& context, VectorRef u) const;
  // Steps 1 to 6 of the class comment at a sample t_k.
  EventStatus sample(BlockContext& context, VectorRef next) const;

  Params params_;
  double period_;
  const InputPort* e_;
  StatePart integral_;
  StatePart previous_error_;
  StatePart command_;
  StatePart started_;
};

}  // namespace cbbg
