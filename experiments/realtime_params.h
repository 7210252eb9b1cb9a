#pragma once
// realtime.*: the keys of the protocol realtime (realtime.cc), which `cbbg drive` runs: per arm
// and seed, realtime.trials trials of trial.duration against the robot of plant.kind remote
// (realtime/remote_plant.h), learning on from trial to trial where the arm learns; no
// evaluation. Each trial's link figures are columns of trials.csv, the run's in summary.json.
// A trial the link stops (lost, SIGINT, the robot's stop) is recorded as stopped, and is the
// run's last.

#include "cbbg/framework/parameters.h"

namespace cbbg::experiments {

// The protocol's name (`cbbg drive` runs it by this name).
inline constexpr const char* kRealtimeProtocol = "realtime";

// realtime.loop: what drives the robot.
enum class DrivenLoop {
  kLearner,  // the arm's closed loop as it learns (cbbg: supervisor, actor, critic)
  kPolicy,   // the arm's learnt actor alone, frozen: the weights of --load-weights
};

// realtime.*
struct RealtimeParams {
  static constexpr const char* kSection = "realtime";
  static constexpr const char* kKeysAfter = "exp3";

  long long trials = 1;
  DrivenLoop loop = DrivenLoop::kLearner;

  template <class Archive>
  void describe(Archive& a) {
    a.integer("trials", trials,
              "realtime: trials against the robot (plant.kind remote), learning carried on",
              interval(1.0, 1e6));
    a.choice(
        "loop", loop,
        "realtime: learner (the arm's closed loop, learning on) | policy (its learnt actor "
        "alone, frozen: the weights of --load-weights)",
        Choices<DrivenLoop>{{"learner", DrivenLoop::kLearner}, {"policy", DrivenLoop::kPolicy}});
  }
};

}  // namespace cbbg::experiments
