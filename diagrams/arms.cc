#include "cbbg/diagrams/arms.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/presets.h"

namespace cbbg::diagrams {
namespace {

struct RegisteredArm {
  ArmName name;
  std::function<Arm(const ClosedLoopOptions&)> make;
};

std::vector<RegisteredArm>& registry() {
  static std::vector<RegisteredArm> arms;
  return arms;
}

void add(std::string name, std::string description,
         std::function<Arm(const ClosedLoopOptions&)> make) {
  config::check_new_name("arm", name, arm_names());
  if (name == kLearntActor) {
    throw std::invalid_argument("arm '" + name + "': the name is the learnt actor's");
  }
  registry().push_back({{std::move(name), std::move(description)}, std::move(make)});
}

// `loop` with the arm's own task slots where the caller's are empty.
ClosedLoopOptions with_task(ClosedLoopOptions loop, const TaskSlots& task) {
  for (auto slot : {&TaskSlots::sensors, &TaskSlots::failure, &TaskSlots::reward}) {
    if (!(loop.slots.*slot)) loop.slots.*slot = task.*slot;
  }
  return loop;
}

}  // namespace

void register_arm(std::string name, std::string description, ControllerOptions options,
                  TaskSlots task) {
  options.validate();
  add(name, std::move(description), [name, options, task](const ClosedLoopOptions& loop) {
    return make_arm(name, options, with_task(loop, task));
  });
}

void register_arm(std::string name, std::string description, ControllerFactory learner,
                  ControllerFactory policy, TaskSlots task) {
  if (!learner) throw std::invalid_argument("arm '" + name + "' has no controller factory");
  add(name, std::move(description), [name, learner, policy, task](const ClosedLoopOptions& loop) {
    return make_arm(name, learner, policy, with_task(loop, task));
  });
}

void unregister_arm(std::string_view name) {
  if (std::erase_if(registry(),
                    [name](const RegisteredArm& arm) { return arm.name.name == name; }) == 0) {
    throw std::invalid_argument("no registered arm '" + std::string(name) +
                                "' to unregister (a preset stays)");
  }
}

std::vector<ArmName> registered_arms() {
  std::vector<ArmName> names;
  for (const RegisteredArm& arm : registry()) names.push_back(arm.name);
  return names;
}

Arm named_arm(std::string_view name, const ClosedLoopOptions& loop) {
  for (const RegisteredArm& arm : registry()) {
    if (arm.name.name == name) return arm.make(loop);
  }
  const std::vector<std::string> arms = arm_names();
  if (std::find(arms.begin(), arms.end(), name) != arms.end()) return preset_arm(name, loop);
  throw std::invalid_argument("unknown arm '" + std::string(name) + "'; the arms are " +
                              config::join(arms));
}

std::vector<Arm> named_arms(const std::vector<std::string>& names) {
  std::vector<Arm> arms;
  for (const auto& name : names) arms.push_back(named_arm(name));
  return arms;
}

}  // namespace cbbg::diagrams
