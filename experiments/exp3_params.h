#pragma once
// exp3's keys, registered with the protocol (exp3.cc) and read from the run's
// parameters.own.

#include <vector>

#include "cbbg/framework/parameters.h"

namespace cbbg::experiments {

// exp3.*: the angles of the skill test.
struct Exp3Params {
  static constexpr const char* kSection = "exp3";
  static constexpr const char* kKeysAfter = "evaluation";  // its place in config.yaml

  std::vector<double> angles{0.05, 0.1744, 0.25};

  template <class Archive>
  void describe(Archive& a) {
    a.numbers("angles", angles, "exp3: the learnt actor alone must balance from each of these, rad",
              kFinite);
  }
};

}  // namespace cbbg::experiments
