#pragma once

#include <string>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config keys supervisor.* of the PD supervisor (supervisor.kind: pd).
struct PdSupervisorParams {
  double k_theta = 50.0;   // supervisor.k_theta: N m / rad
  double k_dtheta = 10.0;  // supervisor.k_dtheta: N m s / rad
  double k_phi = 1.0;      // supervisor.k_phi: N m / rad
  double k_dphi = 1.0;     // supervisor.k_dphi: N m s / rad

  static constexpr const char* kSection = "supervisor";
  template <class Archive>
  void describe(Archive& a) {
    a.number("k_theta", k_theta, "PD gain on theta_b, N m/rad", kFinite);
    a.number("k_dtheta", k_dtheta, "PD gain on theta_b', N m s/rad", kFinite);
    a.number("k_phi", k_phi, "PD gain on (phi_l + phi_r)/2, N m/rad", kFinite);
    a.number("k_dphi", k_dphi, "PD gain on (phi_l' + phi_r')/2, N m s/rad", kFinite);
  }
  // Throws naming the key unless every gain is finite.
  void validate() const;
};

/// PdSupervisor: the cerebellum's target action, a PD law on pitch and wheel angle (docs/model.md
/// §2.4).
///
/// | port     | dir | size | meaning                                 |
/// |----------|-----|------|-----------------------------------------|
/// | measured | in  | 6    | the Sensors output (measured_signals.h)  |
/// | action   | out | 1    | a_S, N m (the plant saturates it)        |
///
/// Equation: a_S = k_theta theta_b + k_dtheta theta_b' + k_phi (phi_l + phi_r) / 2
///                 + k_dphi (phi_l' + phi_r') / 2.
/// Parameters: supervisor.k_theta, supervisor.k_dtheta, supervisor.k_phi, supervisor.k_dphi.
class PdSupervisor final : public Block, public codegen::EmitsC {
 public:
  PdSupervisor(std::string name, const PdSupervisorParams& params);

  // "action" as C (cbbg export --omega).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;

 private:
  // "action": a_S, the PD law of the class comment.
  void calc_action(const BlockContext& context, VectorRef action) const;

  PdSupervisorParams params_;
  const InputPort* measured_;
};

}  // namespace cbbg::blocks
