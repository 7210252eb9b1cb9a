#pragma once
// The kinds of plant `plant.kind` may name: the Simbody and the analytic two-wheeler, and any
// a user registers. A kind says how to build its plant from the run's parameters, how an
// evaluation's changed robot (evaluation.body_mass_scale, evaluation.com_height_scale) reaches
// its parameters, if it can, its linearisation for model-based supervisors (LQR), and which
// robot it models: weights learnt on one kind load only onto a kind of the same robot.
//
//   diagrams::register_plant_kind({
//       .name = "cartpole", .description = "a pole on a cart driven through its wheel",
//       .make = [](const std::string& name, const parameters::Parameters& p) {
//         return std::make_unique<CartPole>(name, config::read_section<CartPoleParams>(p.own,
//         "cartpole"));
//       },
//       .change = ...,     // scales cartpole.pole_mass for kBodyMass; false for the rest
//       .linearize = ...,  // optional
//   });                    // before any Config is made: plant.kind=cartpole is then allowed

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/parameters/parameters.h"
#include "cbbg/plant/linearization.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::diagrams {

// Makes the plant block named `name` from the run's typed parameters (a factory may return a
// std::unique_ptr: it converts).
using PlantFactory = std::function<std::shared_ptr<plant::RobotPlant>(
    const std::string& name, const parameters::Parameters& parameters)>;

// A change of the robot an evaluation asks for, by the factor of its key.
enum class RobotChange {
  kBodyMass,   // evaluation.body_mass_scale: a denser body of the same shape
  kComHeight,  // evaluation.com_height_scale: the load moved up or down
};
// "evaluation.body_mass_scale", "evaluation.com_height_scale".
const char* change_key(RobotChange change);

struct PlantKind {
  std::string name{};         // plant.kind's word
  std::string description{};  // for `cbbg list`
  PlantFactory make{};
  // Applies `change` by `factor` to the kind's own parameters in `parameters`; false when the
  // plant has no such parameter (the evaluation is then refused, never silently unchanged).
  // Throws config::ConfigError for a factor that makes a parameter invalid. Empty: no change.
  std::function<bool(parameters::Parameters& parameters, RobotChange change, double factor)>
      change{};
  // The plant linearised upright at rest with both wheels driven alike: x = (theta_b, phi,
  // theta_b', phi'), phi the mean wheel angle, u = the wheel torque. Empty: not offered.
  std::function<plant::LinearModel(const parameters::Parameters& parameters)> linearize{};
  // The robot it models, where other kinds model the same one (simbody and analytic:
  // "two_wheeler"): weights learnt on one load onto the others. Empty: a robot of its own.
  std::string robot{};
  // The torque, N m, at which the plant saturates each wheel's command: the action space of an
  // agent driving it (environment/). Empty: plant.torque_limit, where the library's plants
  // saturate.
  std::function<double(const parameters::Parameters& parameters)> torque_limit{};
};

// Adds `kind` (its name a config::is_name word, new). Register before making any Config, as
// for a section: plant.kind allows its name from then on. Throws std::invalid_argument.
void register_plant_kind(PlantKind kind);
// Removes a kind register_plant_kind added after the library's (a notebook registering it
// again); plant.kind no longer allows it. Throws std::invalid_argument for another name.
void unregister_plant_kind(std::string_view name);

// The library's kinds beyond simbody and analytic: mujoco, in a build with MuJoCo (its section
// mujoco.* with it), and remote, a robot over the real-time link (remote.*; cbbg drive). Run
// once before main by kLibraryPlantKindsRegistered.
bool register_library_plant_kinds();
[[maybe_unused]] inline const bool kLibraryPlantKindsRegistered = register_library_plant_kinds();

// simbody, analytic, then the registered kinds.
const std::vector<PlantKind>& plant_kinds();
// The kind named `name`; std::invalid_argument listing the kinds for another name.
const PlantKind& plant_kind(std::string_view name);

// Whether weights learnt on plant kind `learnt_on` may be loaded onto plant kind `loaded_onto`:
// the same kind, or two registered kinds of one robot (PlantKind::robot). A kind this program
// has not registered is a robot of its own.
bool same_robot(std::string_view learnt_on, std::string_view loaded_onto);

// The linearisation plant.kind's kind offers (PlantKind::linearize) for the run's parameters.
// Throws std::invalid_argument naming the kind when it offers none.
plant::LinearModel planar_linearization(const parameters::Parameters& parameters);
// The torque limit of plant.kind's kind (PlantKind::torque_limit, else plant.torque_limit).
// Throws std::invalid_argument for a limit that is not finite and > 0, naming the kind.
double kind_torque_limit(const parameters::Parameters& parameters);

}  // namespace cbbg::diagrams
