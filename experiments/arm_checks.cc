#include "cbbg/experiments/arm_checks.h"

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cbbg/blocks/learner.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::experiments {
namespace {

// The loop of arm `name`, its factory's refusal as the user's.
diagrams::ClosedLoop build_arm(const std::string& name, const parameters::Parameters& parameters) {
  try {
    return diagrams::named_arm(name).learner(parameters);
  } catch (const config::ConfigError&) {
    throw;
  } catch (const std::exception& error) {
    throw config::ConfigError("arm '" + name +
                              "' cannot be built from this config: " + error.what());
  }
}

// A user's learner may learn parts larger than its features: each is a file's section too.
void check_learnt_parts(const std::string& name, const blocks::Learner* learner) {
  if (learner == nullptr) return;
  const std::string who = "arm '" + name + "': its " + blocks::role_name(learner->learner_role()) +
                          " '" + learner->learner_block().path() + "' learns a part '";
  for (const StatePart& part : learner->learnt_parts()) {
    if (!blocks::is_part_name(part.name)) {
      throw config::ConfigError(who + part.name +
                                "'; a weights file names parts with letters, digits and '_' only");
    }
    if (part.size > blocks::kMaxFeatures) {
      throw config::ConfigError(who + part.name + "' of " + std::to_string(part.size) +
                                " numbers; a weights file stores at most " +
                                std::to_string(blocks::kMaxFeatures) + " per part");
    }
  }
}

void check_features(const std::string& name, const diagrams::ClosedLoop& loop) {
  if (!loop.learner.learns()) return;
  const int features = loop.learner.actor->num_features();
  if (features <= blocks::kMaxFeatures) {
    check_learnt_parts(name, loop.learner.actor);
    check_learnt_parts(name, loop.learner.critic);
    return;
  }
  std::vector<std::string> keys;
  for (const blocks::LayoutEntry& entry : loop.layout) keys.push_back(entry.key);
  throw config::ConfigError("arm '" + name + "' has " + std::to_string(features) +
                            " features per learner; a learner holds at most " +
                            std::to_string(blocks::kMaxFeatures) +
                            ", what a weights file stores: make its features smaller (its " +
                            "layout: " + (keys.empty() ? "none" : config::join(keys)) + ")");
}

// The bytes the C library's heap holds now (glibc's mallinfo2).
std::size_t heap_in_use() { return ::mallinfo2().uordblks; }

// "1.2 GB", "350 MB": a size in messages.
std::string size_text(double bytes) {
  const bool gigabytes = bytes >= 1e9;
  return format_number(std::round(bytes / (gigabytes ? 1e8 : 1e5)) / 10.0) +
         (gigabytes ? " GB" : " MB");
}

// MemAvailable of /proc/meminfo, in bytes; 0 when it cannot be read.
double available_memory() {
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    std::istringstream fields(line);
    std::string key;
    double kilobytes = 0.0;
    if (fields >> key >> kilobytes && key == "MemAvailable:") return kilobytes * 1024.0;
  }
  return 0.0;
}

}  // namespace

std::size_t check_arms_build(const parameters::Parameters& parameters) {
  std::size_t largest = 0;
  for (const std::string& name : experiment_arms(parameters.run)) {
    const std::size_t before = heap_in_use();
    const diagrams::ClosedLoop loop = build_arm(name, parameters);
    check_features(name, loop);
    const TrialRunner runner(loop, 0, parameters.trial.period);
    const std::size_t after = heap_in_use();
    largest = std::max(largest, after > before ? after - before : 0);
  }
  return largest;
}

void check_run_memory(std::size_t task_bytes, std::size_t threads) {
  const double needed = static_cast<double>(task_bytes) * static_cast<double>(threads);
  const double available = available_memory();
  if (available <= 0.0 || needed <= available) return;
  throw config::ConfigError("this run would hold about " + size_text(needed) + " (" +
                            size_text(static_cast<double>(task_bytes)) + " per task, " +
                            std::to_string(threads) + " at once) and the machine has " +
                            size_text(available) +
                            " available: lower --jobs, or the features (rbf.centres, "
                            "normaliser.inputs, a layout of your own)");
}

}  // namespace cbbg::experiments
