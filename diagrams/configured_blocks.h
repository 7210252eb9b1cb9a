#pragma once
// The block each slot gets from the run's parameters when no factory fills it: the one its
// section's `kind` key names (supervisor.kind, critic.kind, exploration.kind, reward.kind,
// tropism.kind), else the paper's. Each is a slot factory (block_factory.h).

#include <memory>

#include "cbbg/diagrams/block_factory.h"

namespace cbbg::diagrams {

// The controller's slots (controller_slots.h).
std::shared_ptr<Block> configured_supervisor(const SlotRequest& request);
std::shared_ptr<Block> configured_normaliser(const SlotRequest& request);
std::shared_ptr<Block> configured_features(const SlotRequest& request);
std::shared_ptr<Block> configured_critic(const SlotRequest& request);
std::shared_ptr<Block> configured_actor(const SlotRequest& request);
std::shared_ptr<Block> configured_exploration(const SlotRequest& request);
std::shared_ptr<Block> configured_tropism(const SlotRequest& request);
std::shared_ptr<Block> configured_entropy(const SlotRequest& request);
std::shared_ptr<Block> configured_mixer(const SlotRequest& request);

// The task's slots around the controller (closed_loop.h).
std::shared_ptr<Block> configured_sensors(const SlotRequest& request);
std::shared_ptr<Block> configured_failure(const SlotRequest& request);
std::shared_ptr<Block> configured_reward(const SlotRequest& request);

// The block of the slot `slot` ("critic"): `user`'s where it is set, else `configured`'s;
// std::invalid_argument naming the slot when a factory returns null.
std::shared_ptr<Block> fill_slot(const char* slot, const BlockFactory& user,
                                 std::shared_ptr<Block> (*configured)(const SlotRequest&),
                                 const SlotRequest& request);

}  // namespace cbbg::diagrams
