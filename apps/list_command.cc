// cbbg list: the diagrams, the blocks and every config key with its default and meaning.

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "apps/commands.h"
#include "config/config.h"
#include "diagrams/presets.h"

namespace cbbg::app {
namespace {

struct Entry {
  const char* name;
  const char* meaning;
};

constexpr Entry kExperiments[] = {
    {"exp1", "per arm and seed: trials until the first success (paper Fig. 11)"},
    {"exp2", "one cbbg trial, then omega = 1 with the annealing schedule (paper Figs. 12-14)"},
};

constexpr Entry kBlocks[] = {
    {"plant", "SimbodyPlant (plant.kind: simbody) or AnalyticPlant (analytic)"},
    {"controller", "CbbgController: the cerebellum and the basal ganglia, omega, the mixer"},
    {"cerebellum", "the supervisor's target action a_S"},
    {"basal_ganglia", "features, critic, actor, tropism, sampler, entropy"},
    {"sensors", "plant state to measured signals; optional noise and quantisation"},
    {"normaliser", "pitch and pitch rate in grid units, saturated to the RBF grid"},
    {"features", "RbfFeatures: Gaussian radial-basis features on the centres x centres grid"},
    {"critic", "V(s) = w . phi, TD(lambda) with an eligibility trace"},
    {"actor", "a_A = theta . phi, improved or weighted rule"},
    {"supervisor", "PdSupervisor (supervisor.kind: pd) or LqrSupervisor (lqr): the cerebellum"},
    {"tropism", "T = k1 / (1 + exp(k2 V)); k1 annealed between trials"},
    {"sampler", "BoltzmannSampler: a_E ~ N(a_A, K_B T / 2)"},
    {"omega", "OmegaSchedule: omega(t), or fixed 0 or 1"},
    {"mixer", "a = omega a_E + (1 - omega) a_S"},
    {"reward", "sliding-surface reward r = 0 if s^2 shrank, else -1"},
    {"failure", "ends the trial when |theta_b| > trial.failure_angle"},
    {"entropy", "E = 0.5 log2(pi e K_B T), for logging"},
    {"hold, wheel_torques", "zero-order hold of a, fed to both wheels"},
    {"telemetry", "every logged signal in one vector (steps.csv)"},
};

std::string shown(const config::Value& value) {
  std::ostringstream out;
  std::visit(
      [&out](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double> || std::is_same_v<T, long long> ||
                      std::is_same_v<T, std::string>) {
          out << v;
        } else if constexpr (std::is_same_v<T, std::vector<config::AnnealingStep>>) {
          for (const auto& step : v) out << step.from_trial << ":" << step.k1 << " ";
        } else {
          out << "[";
          for (std::size_t i = 0; i < v.size(); ++i) out << (i ? ", " : "") << v[i];
          out << "]";
        }
      },
      value);
  return out.str();
}

}  // namespace

int list_command() {
  std::printf("Experiments (--experiment):\n");
  for (const auto& entry : kExperiments) std::printf("  %-15s %s\n", entry.name, entry.meaning);
  std::printf(
      "\nDiagrams (presets; --experiment NAME runs an arm, arms: [...] compares several, "
      "cbbg graph draws any):\n");
  for (const auto& preset : diagrams::presets()) {
    std::printf("  %-15s %s\n", preset.name.c_str(), preset.description.c_str());
  }
  std::printf("\nBlocks of the diagrams:\n");
  for (const auto& entry : kBlocks) std::printf("  %-20s %s\n", entry.name, entry.meaning);
  std::printf("\nConfig keys (--set key=value, or a YAML file with --config):\n");
  int width = 0;  // the longest key's, so the defaults line up
  for (const auto& spec : config::schema()) {
    width = std::max(width, static_cast<int>(spec.path.size()));
  }
  for (const auto& spec : config::schema()) {
    std::printf("  %-*s %-22s %s\n", width, spec.path.c_str(), shown(spec.default_value).c_str(),
                spec.meaning.c_str());
  }
  return 0;
}

}  // namespace cbbg::app
