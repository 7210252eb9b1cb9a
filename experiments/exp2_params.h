#pragma once
// exp2's keys: the annealing schedule (a key of its own, before the exp2 section) and the
// trials, registered with the protocol (exp2.cc) and read from the run's parameters.own.

#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::experiments {

struct Exp2Trials {
  long long trials = 30;

  template <class Archive>
  void describe(Archive& a) {
    a.integer("trials", trials, "exp2: trials in all, the CB-coordinated one included",
              interval(2, config::kMaxTrials));
  }
};

// exp2's keys: the annealing schedule (a key of its own, before the exp2 section).
struct Exp2Params {
  // Keys of its own at the top level (annealing, exp2.*), in config.yaml after push.*.
  static constexpr const char* kSection = "";
  static constexpr const char* kKeysAfter = "push";

  std::vector<config::AnnealingStep> annealing{{1, 10}, {11, 5}, {16, 1}, {21, 0.5}, {23, 0.1}};
  Exp2Trials exp2;

  template <class Archive>
  void describe(Archive& a) {
    a.annealing("annealing", annealing,
                "exp2: k1 from a trial on (trial 1 is the CB-coordinated one)");
    a.section("exp2", exp2);
  }
};

}  // namespace cbbg::experiments
