#pragma once
// The basal ganglia of the CB-BG controller (the paper's Fig. 5): features shared by an
// actor-critic, the tropism that turns the critic's value into a temperature, and exploration
// around the actor's action (the paper's: Boltzmann). It knows nothing of the robot: its state
// input is whatever its feature block maps to features.

#include <memory>
#include <string>

#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/entropy.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/framework/diagram.h"

namespace cbbg {
class DiagramBuilder;
}

namespace cbbg::diagrams {

// The paper's blocks' parameters (the BasalGanglia constructor that builds them).
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

// The blocks of a basal ganglia, each with its slot's contract (controller_slots.h): any
// block that fits fills its place.
struct BasalGangliaBlocks {
  std::shared_ptr<Block> features;  // input "x", output "features" (n)
  std::shared_ptr<Block> critic;    // critic_contract(n)
  std::shared_ptr<Block> actor;     // actor_contract(n)
  // All three, or none (no exploration: a_E = a_A, and T and E are NaN).
  std::shared_ptr<Block> tropism;      // tropism_contract()
  std::shared_ptr<Block> exploration;  // exploration_contract(); named "sampler"
  std::shared_ptr<Block> entropy;      // entropy_contract()
};

/// BasalGanglia: features -> critic (V, delta) and actor (a_A) -> tropism (T) -> exploration
/// (a_E).
///
/// | port               | dir | size | meaning                                          |
/// |--------------------|-----|------|--------------------------------------------------|
/// | state              | in  | k    | the features block's input "x" (k its size)       |
/// | reward             | in  | 1    | r_{t-1}                                           |
/// | failed             | in  | 1    | 1 when s_t is terminal                            |
/// | supervisor_action  | in  | 1    | a_S(t), what the actor learns towards             |
/// | omega              | in  | 1    | omega(t), the mixing factor                       |
/// | actor_action       | out | 1    | a_A(t)                                            |
/// | exploration_action | out | 1    | a_E(t) (the paper's: ~ N(a_A, K_B T / 2))         |
/// | value              | out | 1    | V(s_t)                                            |
/// | td_error           | out | 1    | delta_{t-1}                                       |
/// | temperature        | out | 1    | T(t)                                              |
/// | entropy            | out | 1    | E(t), bits                                        |
///
/// Blocks: "features", "critic", "actor", and with exploration "tropism", "sampler",
/// "entropy" (the names of the blocks given; the slots name them so). Each reads what it
/// needs of what its slot feeds. The paper's blocks' equations: docs/model.md §2.3, §2.5,
/// §2.6, §2.10 to §2.12.
class BasalGanglia final : public Diagram {
 public:
  // Wires `blocks`, after checking each against its slot's contract (std::invalid_argument
  // naming the slot, the block and the port).
  BasalGanglia(std::string name, BasalGangliaBlocks blocks);
  // The paper's blocks around `features` (blocks::RbfFeatures is the paper's): blocks::Critic,
  // blocks::Actor, blocks::Tropism, blocks::BoltzmannSampler and blocks::Entropy of `params`.
  BasalGanglia(std::string name, std::shared_ptr<Block> features, const BasalGangliaParams& params);

  const InputPort& state() const { return *state_; }
  // Null where no block reads it (a user's critic or actor may not).
  const InputPort* reward() const { return reward_; }
  const InputPort* failed() const { return failed_; }
  const InputPort* supervisor_action() const { return supervisor_action_; }
  const InputPort* omega() const { return omega_; }
  const OutputPort& actor_action() const { return *actor_action_; }
  const OutputPort& exploration_action() const { return *exploration_action_; }
  const OutputPort& value() const { return *value_; }
  const OutputPort& td_error() const { return *td_error_; }
  const OutputPort& temperature() const { return *temperature_; }
  const OutputPort& entropy() const { return *entropy_; }

  const Block& critic() const { return *critic_; }
  const Block& actor() const { return *actor_; }
  // Null without exploration.
  const Block* tropism() const { return tropism_; }

 private:
  // The outputs of the exploration's part: a_E, T and E (a_A and NaN without it).
  struct Exploration {
    const OutputPort& action;
    const OutputPort& temperature;
    const OutputPort& entropy;
  };
  // Adds and wires tropism, exploration and entropy.
  Exploration add_exploration(DiagramBuilder& builder, BasalGangliaBlocks& blocks);

  const InputPort* state_ = nullptr;
  const InputPort* reward_ = nullptr;
  const InputPort* failed_ = nullptr;
  const InputPort* supervisor_action_ = nullptr;
  const InputPort* omega_ = nullptr;
  const OutputPort* actor_action_ = nullptr;
  const OutputPort* exploration_action_ = nullptr;
  const OutputPort* value_ = nullptr;
  const OutputPort* td_error_ = nullptr;
  const OutputPort* temperature_ = nullptr;
  const OutputPort* entropy_ = nullptr;
  const Block* critic_ = nullptr;
  const Block* actor_ = nullptr;
  const Block* tropism_ = nullptr;
};

}  // namespace cbbg::diagrams
