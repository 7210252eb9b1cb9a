#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config key reward.kind: which block rewards the transitions.
enum class RewardKind {
  kSliding,    // "sliding": the paper's sliding-surface reward, Reward
  kQuadratic,  // "quadratic": QuadraticReward, minus a quadratic cost of the state
};

// "sliding" or "quadratic"; anything else throws naming reward.kind.
RewardKind parse_reward_kind(std::string_view text);
std::string_view to_string(RewardKind kind);

// Config keys reward.*.
struct RewardParams {
  RewardKind kind = RewardKind::kSliding;  // reward.kind
  double a1 = 10.0;                        // reward.a1: weight of theta_b in the surface, 1/rad
  double a2 = 1.0;                         // reward.a2: weight of theta_b', s/rad
  double k_phi = 0.0;  // reward.k_phi: weight of the wheels' mean rate phi', s/rad
  // reward.q: quadratic's weights on theta_b^2, theta_b'^2 and phi'^2, each >= 0.
  std::vector<double> q{1.0, 0.1, 0.0};

  static constexpr const char* kSection = "reward";
  template <class Archive>
  void describe(Archive& a) {
    a.choice("kind", kind, "sliding (the paper's sliding surface) | quadratic",
             Choices<RewardKind>{{"sliding", RewardKind::kSliding},
                                 {"quadratic", RewardKind::kQuadratic}});
    a.number("a1", a1, "sliding surface weight on theta_b, 1/rad", kFinite);
    a.number("a2", a2, "sliding surface weight on theta_b', s/rad", kFinite);
    a.number("k_phi", k_phi,
             "sliding surface weight on the wheels' mean rate phi', s/rad; 0 = the paper's "
             "surface (torque steers s for k_phi < 0.2385 a2 on the default robot: docs/model.md "
             "2.9)",
             kFinite);
    a.numbers("q", q,
              "quadratic: r = -(q0 theta_b^2 + q1 theta_b'^2 + q2 phi'^2), phi' the wheels' mean "
              "rate",
              kNonNegative);
  }

  // Throws naming the key unless every weight is finite, q's are >= 0 and q has 3.
  void validate() const;
};

/// Reward: the sliding-surface reward of docs/model.md §2.9.
///
/// | port     | dir | size | meaning                                              |
/// |----------|-----|------|------------------------------------------------------|
/// | measured | in  | 6    | the Sensors output (measured_signals.h)               |
/// | failed   | in  | 1    | 1 when the trial fails at this tick, else 0           |
/// | reward   | out | 1    | r_{t-1}, the reward of the transition s_{t-1} -> s_t  |
///
/// Equations: s(t) = a1 theta_b + a2 theta_b' + k_phi phi', phi' = (phi_l' + phi_r') / 2 (with
///   k_phi = 0, the paper's surface, computed without the term: the same bits);
///   r_{t-1} = -1 if failed, else 0 if s(t)^2 <= s(t-1)^2, else -1;
/// 0 on the first tick of a trial without failure (there is no transition yet). The
/// periodic update remembers s(t); a new trial forgets it.
/// Parameters: a1 = reward.a1, a2 = reward.a2, k_phi = reward.k_phi, the period trial.period.
/// reward.kind sliding selects it (QuadraticReward is quadratic's).
///
/// Discrete state, per trial: previous_surface s(t-1), has_previous.
class Reward final : public Block, public codegen::EmitsC {
 public:
  Reward(std::string name, const RewardParams& params, double period);

  // Its outputs and updates as C (cbbg export; codegen::EmitsC).
  codegen::CCalculation c_calculation(int output, const Context& context) const override;
  codegen::CCalculation c_update(int update, const Context& context) const override;

 private:
  // "reward": -1 on failure, 0 on the first tick, else 0 if s^2 did not grow and -1 if it did.
  void calc_reward(const BlockContext& context, VectorRef reward) const;
  // Remembers s(t) for the next tick. Reads no state.
  EventStatus remember_surface(BlockContext& context, VectorRef next) const;
  // s(t), the sliding surface of the measured signals.
  double surface(const BlockContext& context) const;
  std::string c_surface(std::vector<codegen::CConstant>& constants) const;
  RewardParams params_;
  const InputPort* measured_;
  const InputPort* failed_;
  StatePart previous_surface_;
  StatePart has_previous_;
};

}  // namespace cbbg::blocks
