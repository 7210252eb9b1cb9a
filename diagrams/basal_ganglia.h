#pragma once
// The basal ganglia of the CB-BG controller (the paper's Fig. 5): features shared by an
// actor-critic, the tropism that turns the critic's value into a temperature, and Boltzmann
// exploration around the actor's action. It knows nothing of the robot: its state input is
// whatever its feature block maps to features.

#include <memory>
#include <string>

#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/entropy.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/framework/diagram.h"

namespace cbbg::diagrams {

struct BasalGangliaParams {
  blocks::CriticParams critic;
  blocks::ActorParams actor;
  blocks::TropismParams tropism;
  blocks::SamplerParams sampler;
  blocks::EntropyParams entropy;
  double period = 0.01;  // trial.period, s
  // False: no tropism, sampler or entropy; the exploration action is the actor's own and
  // the temperature and entropy outputs are NaN (the learnt actor evaluated alone).
  bool exploration = true;
};

/// BasalGanglia: features -> critic (V, delta) and actor (a_A) -> tropism (T) -> sampler (a_E).
///
/// | port               | dir | size | meaning                                          |
/// |--------------------|-----|------|--------------------------------------------------|
/// | state              | in  | k    | the features block's input "x" (k its size)       |
/// | reward             | in  | 1    | r_{t-1}                                           |
/// | failed             | in  | 1    | 1 when s_t is terminal                            |
/// | supervisor_action  | in  | 1    | a_S(t), what the actor learns towards             |
/// | omega              | in  | 1    | omega(t), the mixing factor                       |
/// | actor_action       | out | 1    | a_A(t) = theta . phi(s_t)                         |
/// | exploration_action | out | 1    | a_E(t) ~ N(a_A, K_B T / 2)                        |
/// | value              | out | 1    | V(s_t)                                            |
/// | td_error           | out | 1    | delta_{t-1}                                       |
/// | temperature        | out | 1    | T(t)                                              |
/// | entropy            | out | 1    | E(t), bits                                        |
///
/// Blocks: "features" (the slot: any block with input "x" and output "features"), "critic",
/// "actor", and with exploration "tropism", "sampler", "entropy". Equations: those of each
/// block (docs/model.md §2.3, §2.5, §2.6, §2.10 to §2.12).
class BasalGanglia final : public Diagram {
 public:
  // `features` maps the state (its input "x") to the features (its output "features") that
  // the critic and the actor share; blocks::RbfFeatures is the paper's.
  BasalGanglia(std::string name, std::shared_ptr<Block> features, const BasalGangliaParams& params);

  const InputPort& state() const { return *state_; }
  const InputPort& reward() const { return *reward_; }
  const InputPort& failed() const { return *failed_; }
  const InputPort& supervisor_action() const { return *supervisor_action_; }
  const InputPort& omega() const { return *omega_; }
  const OutputPort& actor_action() const { return *actor_action_; }
  const OutputPort& exploration_action() const { return *exploration_action_; }
  const OutputPort& value() const { return *value_; }
  const OutputPort& td_error() const { return *td_error_; }
  const OutputPort& temperature() const { return *temperature_; }
  const OutputPort& entropy() const { return *entropy_; }

  const blocks::Critic& critic() const { return *critic_; }
  const blocks::Actor& actor() const { return *actor_; }
  // Null without exploration.
  const blocks::Tropism* tropism() const { return tropism_; }

 private:
  const InputPort* state_;
  const InputPort* reward_;
  const InputPort* failed_;
  const InputPort* supervisor_action_;
  const InputPort* omega_;
  const OutputPort* actor_action_;
  const OutputPort* exploration_action_;
  const OutputPort* value_;
  const OutputPort* td_error_;
  const OutputPort* temperature_;
  const OutputPort* entropy_;
  const blocks::Critic* critic_;
  const blocks::Actor* actor_;
  const blocks::Tropism* tropism_ = nullptr;
};

}  // namespace cbbg::diagrams
