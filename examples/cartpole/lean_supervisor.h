#pragma once
// A supervisor of the user's own in the cerebellum's slot: a PD law on the pole's lean, with
// its gains as config keys (lean_pd.*).

#include <algorithm>
#include <memory>
#include <string>

#include <cbbg/blocks/measured_signals.h>
#include <cbbg/config/declared_keys.h>
#include <cbbg/framework/block.h>
#include <cbbg/framework/block_context.h>

namespace cartpole {

struct LeanPdParams {
  double k_theta = 40.0;  // N m / rad
  double k_dtheta = 8.0;  // N m s / rad
  double k_phi = 0.2;     // N m / rad of wheel
  double k_dphi = 0.5;    // N m s / rad of wheel
  double limit = 5.0;     // N m, the torque it asks for at most

  template <class Archive>
  void describe(Archive& a) {
    a.number("k_theta", k_theta, "gain on the lean, N m/rad", cbbg::kFinite);
    a.number("k_dtheta", k_dtheta, "gain on the lean rate, N m s/rad", cbbg::kFinite);
    a.number("k_phi", k_phi, "gain on the wheel angle, N m/rad", cbbg::kFinite);
    a.number("k_dphi", k_dphi, "gain on the wheel rate, N m s/rad", cbbg::kFinite);
    a.number("limit", limit, "largest torque asked, N m", cbbg::kPositive);
  }
};

/// LeanPd: a_S = clamp(k_theta theta + k_dtheta theta' + k_phi phi + k_dphi phi', +-limit),
/// phi the mean of the measured wheel angles. Input "measured" (6), output "action" (1).
class LeanPd final : public cbbg::Block {
 public:
  LeanPd(std::string name, const LeanPdParams& k) : Block(std::move(name)), k_(k) {
    measured_ = &declare_input_port("measured", cbbg::blocks::kMeasuredSize);
    declare_output_port<&LeanPd::calc_action>("action", 1, {measured_});
  }

 private:
  // "action": the clamped PD law above.
  void calc_action(const cbbg::BlockContext& context, cbbg::VectorRef action) const {
    using namespace cbbg::blocks;
    const auto y = context.input(*measured_);
    const double phi = (y[kMeasuredPhiLeft] + y[kMeasuredPhiRight]) / 2.0;
    const double dphi = (y[kMeasuredPhiLeftDot] + y[kMeasuredPhiRightDot]) / 2.0;
    const double law = k_.k_theta * y[kMeasuredThetaB] + k_.k_dtheta * y[kMeasuredThetaBDot] +
                       k_.k_phi * phi + k_.k_dphi * dphi;
    action[0] = std::clamp(law, -k_.limit, k_.limit);
  }

  LeanPdParams k_;
  const cbbg::InputPort* measured_;
};

inline void register_lean_pd() { cbbg::config::register_section<LeanPdParams>("lean_pd"); }

inline std::unique_ptr<cbbg::Block> make_lean_pd(const std::string& name,
                                                 const cbbg::parameters::Parameters& p) {
  return std::make_unique<LeanPd>(name, cbbg::config::read_section<LeanPdParams>(p.own, "lean_pd"));
}

}  // namespace cartpole
