#include "cbbg/plant/plant_signals.h"

#include <algorithm>
#include <stdexcept>

namespace cbbg::plant {
namespace {

// The index of `name` in `signals`, or -1.
int find(const std::vector<std::string>& signals, const std::string& name) {
  const auto at = std::find(signals.begin(), signals.end(), name);
  return at == signals.end() ? -1 : static_cast<int>(at - signals.begin());
}

// Where each of `logged` sits in `signals`.
std::vector<LoggedSignal> index_logged(const std::string& plant,
                                       const std::vector<std::string>& signals,
                                       const std::vector<std::string>& logged) {
  std::vector<LoggedSignal> result;
  for (const std::string& name : logged) {
    const int index = find(signals, name);
    if (index < 0) {
      std::string names;
      for (const std::string& signal : signals) names += (names.empty() ? "" : ", ") + signal;
      throw std::invalid_argument("plant '" + plant + "' logs '" + name +
                                  "', which is not one of its signals (" + names + ")");
    }
    if (name == "x" || name == "y" || name == "yaw") {
      throw std::invalid_argument("plant '" + plant + "' logs '" + name +
                                  "', its pose, which steps.csv records anyway; log only "
                                  "its other signals");
    }
    for (const LoggedSignal& earlier : result) {
      if (earlier.name == name) {
        throw std::invalid_argument("plant '" + plant + "' logs '" + name + "' twice");
      }
    }
    result.push_back({name, index});
  }
  return result;
}

}  // namespace

const std::vector<std::string>& two_wheeler_signals() {
  static const std::vector<std::string> names{
      "pitch", "pitch_rate", "wheel_left", "wheel_right", "wheel_left_rate", "wheel_right_rate",
      "x",     "y",          "yaw",        "yaw_rate"};
  return names;
}

SignalIndex index_signals(const std::string& plant, const std::vector<std::string>& signals,
                          const std::vector<std::string>& logged) {
  for (std::size_t i = 0; i < signals.size(); ++i) {
    if (find(signals, signals[i]) != static_cast<int>(i)) {
      throw std::invalid_argument("plant '" + plant + "' names its signal '" + signals[i] +
                                  "' twice");
    }
  }
  auto required = [&](const std::string& name, const std::string& single) {
    int index = find(signals, name);
    if (index < 0 && !single.empty()) index = find(signals, single);
    if (index < 0) {
      throw std::invalid_argument(
          "plant '" + plant + "' has no signal '" + name + "'" +
          (single.empty() ? "" : " (or '" + single + "')") +
          " in its state output; a plant names pitch, pitch_rate, wheel_left, wheel_right, "
          "wheel_left_rate and wheel_right_rate (or wheel and wheel_rate) "
          "(plant/plant_signals.h)");
    }
    return index;
  };
  SignalIndex index;
  index.pitch = required("pitch", "");
  index.pitch_rate = required("pitch_rate", "");
  index.wheel_left = required("wheel_left", "wheel");
  index.wheel_right = required("wheel_right", "wheel");
  index.wheel_left_rate = required("wheel_left_rate", "wheel_rate");
  index.wheel_right_rate = required("wheel_right_rate", "wheel_rate");
  index.x = find(signals, "x");
  index.y = find(signals, "y");
  index.yaw = find(signals, "yaw");
  index.logged = index_logged(plant, signals, logged);
  return index;
}

const SignalIndex& two_wheeler_index() {
  static const SignalIndex index = index_signals("two-wheeler", two_wheeler_signals());
  return index;
}

}  // namespace cbbg::plant
