#include "cbbg/diagrams/plant_kinds.h"

#include <cmath>
#include <stdexcept>

#include "cbbg/config/declared_keys.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/simbody_plant.h"

namespace cbbg::diagrams {
namespace {

// `value` times `factor`, refused unless it is a finite number > 0.
double scaled(double value, double factor, const char* key, RobotChange change) {
  const double result = value * factor;
  if (!std::isfinite(result) || result <= 0.0) {
    throw config::ConfigError(std::string(change_key(change)) + " (" + format_number(factor) +
                              ") makes " + key + " " + format_number(result) +
                              "; the scaled value must be a finite number > 0");
  }
  return result;
}

// The two-wheeler's plant.*: a denser body of the same shape, or its centre of mass moved.
bool change_two_wheeler(parameters::Parameters& p, RobotChange change, double factor) {
  plant::RobotParams& robot = p.plant.robot;
  if (change == RobotChange::kComHeight) {
    robot.com_height = scaled(robot.com_height, factor, "plant.com_height", change);
    return true;
  }
  robot.body_mass = scaled(robot.body_mass, factor, "plant.body_mass", change);
  robot.body_pitch_inertia =
      scaled(robot.body_pitch_inertia, factor, "plant.body_pitch_inertia", change);
  robot.body_yaw_inertia = scaled(robot.body_yaw_inertia, factor, "plant.body_yaw_inertia", change);
  robot.body_roll_inertia =
      scaled(robot.body_roll_inertia, factor, "plant.body_roll_inertia", change);
  return true;
}

plant::LinearModel linearize_two_wheeler(const parameters::Parameters& p) {
  return plant::linearize_planar_upright(p.plant.robot);
}

// The library plants declare the input "disturbance" when push.* pushes from outside.
plant::DisturbanceInput disturbance_input(const parameters::Parameters& p) {
  return p.push.from_outside() ? plant::DisturbanceInput::kDeclared
                               : plant::DisturbanceInput::kNone;
}

// The robot both library plants model, so each takes the other's weights.
constexpr const char* kTwoWheeler = "two_wheeler";

std::vector<PlantKind>& kinds() {
  static std::vector<PlantKind> all{
      {"simbody", "3-D multibody, reference",
       [](const std::string& name, const parameters::Parameters& p) {
         return std::make_unique<plant::SimbodyPlant>(name, p.plant.robot, p.trial.theta0,
                                                      disturbance_input(p));
       },
       change_two_wheeler, linearize_two_wheeler, kTwoWheeler},
      {"analytic", "fast",
       [](const std::string& name, const parameters::Parameters& p) {
         return std::make_unique<plant::AnalyticPlant>(name, p.plant.robot, p.trial.theta0,
                                                       disturbance_input(p));
       },
       change_two_wheeler, linearize_two_wheeler, kTwoWheeler}};
  return all;
}

// The registered kind named `name`, or null.
const PlantKind* find_kind(std::string_view name) {
  for (const PlantKind& kind : kinds()) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

std::vector<std::string> kind_names() {
  std::vector<std::string> names;
  for (const PlantKind& kind : kinds()) names.push_back(kind.name);
  return names;
}

}  // namespace

const char* change_key(RobotChange change) {
  return change == RobotChange::kBodyMass ? "evaluation.body_mass_scale"
                                          : "evaluation.com_height_scale";
}

void register_plant_kind(PlantKind kind) {
  config::check_new_name("plant kind", kind.name, kind_names());
  if (!kind.make) throw std::invalid_argument("plant kind '" + kind.name + "' has no factory");
  config::register_choice("plant.kind", kind.name, kind.description);
  kinds().push_back(std::move(kind));
}

const std::vector<PlantKind>& plant_kinds() { return kinds(); }

const PlantKind& plant_kind(std::string_view name) {
  if (const PlantKind* kind = find_kind(name)) return *kind;
  throw std::invalid_argument("no plant kind '" + std::string(name) + "' (there are " +
                              config::join(kind_names()) + ")");
}

bool same_robot(std::string_view learnt_on, std::string_view loaded_onto) {
  if (learnt_on == loaded_onto) return true;
  const PlantKind* first = find_kind(learnt_on);
  const PlantKind* second = find_kind(loaded_onto);
  return first != nullptr && second != nullptr && !first->robot.empty() &&
         first->robot == second->robot;
}

plant::LinearModel planar_linearization(const parameters::Parameters& parameters) {
  const PlantKind& kind = plant_kind(parameters.plant.kind);
  if (!kind.linearize) {
    throw std::invalid_argument("plant.kind '" + kind.name +
                                "' offers no linearisation, which a model-based supervisor "
                                "(supervisor.kind: lqr) designs from");
  }
  return kind.linearize(parameters);
}

}  // namespace cbbg::diagrams
