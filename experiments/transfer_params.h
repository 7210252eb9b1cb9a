#pragma once
// transfer's keys, registered with the protocol (transfer.cc) and read from the run's
// parameters.own.

#include <string>
#include <vector>

#include "cbbg/framework/parameters.h"

namespace cbbg::experiments {

// How transfer trains each arm and seed: as exp3 does, until its actor alone balances, or as
// exp1 does, until its first success.
enum class TransferTraining { kUntilSkill, kUntilSuccess };

// transfer.*: train once, evaluate under many conditions.
struct TransferParams {
  static constexpr const char* kSection = "transfer";
  static constexpr const char* kKeysAfter = "exp3";  // its place in config.yaml

  TransferTraining training = TransferTraining::kUntilSkill;
  std::vector<std::string> conditions{
      "evaluation.body_mass_scale=1", "evaluation.body_mass_scale=1.3",
      "evaluation.com_height_scale=1.3", "evaluation.noise_std=0.05", "evaluation.push_torque=5"};

  template <class Archive>
  void describe(Archive& a) {
    a.choice("training", training,
             "transfer: each arm and seed trains once as exp3 does (until its actor alone "
             "balances) or as exp1 does (until its first success)",
             Choices<TransferTraining>{{"exp3", TransferTraining::kUntilSkill},
                                       {"exp1", TransferTraining::kUntilSuccess}});
    a.settings("conditions", conditions,
               "transfer: what was learnt is evaluated from evaluation.angles under each of these "
               "conditions, a column each; keys of evaluation.*, plant.* (not plant.kind), "
               "sensors.*, push.* or a registered section");
  }
};

}  // namespace cbbg::experiments
