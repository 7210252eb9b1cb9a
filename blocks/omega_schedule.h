#pragma once

#include <string>
#include <string_view>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Where omega comes from (a controller option, diagrams::ControllerOptions::omega).
enum class OmegaMode {
  kSchedule,  // "schedule": docs/model.md §2.7's exponential rise (the CB-BG arms)
  kZero,      // "zero": omega = 0, the supervisor alone drives (cb_only)
  kOne,       // "one": omega = 1, exploration alone drives (bg_only)
  kConstant,  // "constant": omega = OmegaParams::constant throughout (an ablation)
};

// "schedule", "zero", "one" or "constant"; anything else throws naming omega.mode.
OmegaMode parse_omega_mode(std::string_view text);
std::string_view to_string(OmegaMode mode);

// Config keys omega.*.
struct OmegaParams {
  double n2 = 500.0;  // omega.n2: ticks of pure supervision before omega rises, >= 0
  double n3 = 200.0;  // omega.n3: the rise's time constant in ticks, > 0
  OmegaMode mode = OmegaMode::kSchedule;  // not a config key: the controller's option
  double constant = 0.5;                  // mode constant's omega, in [0, 1]; the same

  static constexpr const char* kSection = "omega";
  template <class Archive>
  void describe(Archive& a) {
    a.number("n2", n2, "ticks of supervision before omega rises", kNonNegative);
    a.number("n3", n3, "time constant of omega's rise, ticks", kPositive);
  }

  // Throws naming the key unless n2 is finite and >= 0, n3 finite and > 0, mode valid, and
  // (mode constant) the constant in [0, 1].
  void validate() const;
};

/// OmegaSchedule: the coordination factor between cerebellum and basal ganglia (docs/model.md
/// §2.7).
///
/// | port  | dir | size | meaning               |
/// |-------|-----|------|-----------------------|
/// | omega | out | 1    | omega(t), in [0, 1]   |
///
/// Equation (mode schedule): omega(t) = max(0, 1 - exp(-(t - n2) / n3)), t the ticks since
/// learning began: a counter in the discrete state, advanced by each periodic update and
/// NOT reset between trials. Modes zero and one output that constant, mode constant its
/// `constant`.
/// Parameters: n2 = omega.n2, n3 = omega.n3, mode = omega.mode, the period trial.period.
class OmegaSchedule final : public Block, public codegen::EmitsC {
 public:
  OmegaSchedule(std::string name, const OmegaParams& params, double period);

  // Its outputs and updates as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;

  // omega after `ticks` ticks of learning.
  double omega_at(double ticks) const;
  // Ticks of learning so far in `context`.
  double ticks(const Context& context) const;

 private:
  // "omega": omega_at the ticks counted so far.
  void calc_omega(const BlockContext& context, VectorRef omega) const;
  // Advances the tick count by one.
  EventStatus count_tick(BlockContext& context, VectorRef next) const;

  OmegaParams params_;
};

}  // namespace cbbg::blocks
