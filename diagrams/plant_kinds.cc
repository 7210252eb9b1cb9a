#include "cbbg/diagrams/plant_kinds.h"

#include <cmath>
#include <stdexcept>

#include "cbbg/config/declared_keys.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/simbody_plant.h"
#include "cbbg/realtime/remote_params.h"
#include "cbbg/realtime/remote_plant.h"
#ifdef CBBG_WITH_MUJOCO
#include "cbbg/plant/mujoco/mujoco_params.h"
#include "cbbg/plant/mujoco/mujoco_plant.h"
#endif

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

#ifdef CBBG_WITH_MUJOCO
plant::MujocoParams mujoco_params(const parameters::Parameters& p) {
  return config::read_section<plant::MujocoParams>(p.own, "mujoco");
}

// The two-wheeler of plant.* changes as the other two-wheelers do; a model file through the
// scales of mujoco.*, applied to mujoco.body when the plant loads it.
bool change_mujoco(parameters::Parameters& p, RobotChange change, double factor) {
  if (mujoco_params(p).model.empty()) return change_two_wheeler(p, change, factor);
  const char* key =
      change == RobotChange::kBodyMass ? "mujoco.body_mass_scale" : "mujoco.com_height_scale";
  p.own.values[key] = scaled(std::get<double>(p.own.value(key)), factor, key, change);
  return true;
}

PlantKind mujoco_kind() {
  return {"mujoco", "MuJoCo: mujoco.model's MJCF or URDF, or the two-wheeler with ground contact",
          [](const std::string& name, const parameters::Parameters& p) {
            return std::make_unique<plant::MujocoPlant>(name, mujoco_params(p), p.plant.robot,
                                                        p.trial.theta0, disturbance_input(p));
          },
          change_mujoco,
          [](const parameters::Parameters& p) {
            if (!mujoco_params(p).model.empty()) {
              throw std::invalid_argument(
                  "plant.kind 'mujoco' offers a linearisation of its own two-wheeler only; "
                  "mujoco.model names a model file");
            }
            return linearize_two_wheeler(p);
          }};
}
#endif

// remote.* as the link to the robot: its address, this end's, the key, the timeouts.
realtime::LinkOptions link_options(const parameters::Parameters& p) {
  const auto remote = config::read_section<realtime::RemoteParams>(p.own, "remote");
  realtime::LinkOptions link;  // the ports' ranges are their keys' (remote_params.h)
  link.robot = realtime::address_of(remote.host, static_cast<std::uint16_t>(remote.port));
  link.local = realtime::address_of(remote.bind_host, static_cast<std::uint16_t>(remote.bind_port));
  if (!remote.key_file.empty())
    link.key = realtime::read_key_file(remote.key_file, "remote.key_file");
  link.period = p.trial.period;
  link.timeout_periods = static_cast<int>(remote.timeout_periods);
  link.connect_timeout = remote.connect_timeout;
  link.controller = "cbbg " + p.run.experiment + " of";
  for (const std::string& arm : p.run.arms) link.controller += " " + arm;
  link.signals = plant::two_wheeler_signals();
  return link;
}

// A two-wheeler at the other end of a link (cbbg drive), sized as plant.* says.
PlantKind remote_kind() {
  return {.name = "remote",
          .description =
              "a robot over UDP in real time: cbbg robot, or a real one speaking "
              "docs/realtime.md (remote.*)",
          .make =
              [](const std::string& name, const parameters::Parameters& p) {
                return std::make_unique<realtime::RemotePlant>(name, link_options(p),
                                                               p.plant.robot);
              },
          .robot = kTwoWheeler};
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

// How many kinds the library registers (the first ones): unregister_plant_kind leaves them.
std::size_t& library_kind_count() {
  static std::size_t count = 2;  // simbody and analytic, until the others are registered
  return count;
}

}  // namespace

bool register_library_plant_kinds() {
#ifdef CBBG_WITH_MUJOCO
  config::register_section<plant::MujocoParams>("mujoco");
  register_plant_kind(mujoco_kind());
#endif
  config::register_section<realtime::RemoteParams>("remote");
  register_plant_kind(remote_kind());
  library_kind_count() = kinds().size();
  return true;
}

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

void unregister_plant_kind(std::string_view name) {
  const auto library = library_kind_count();
  const auto found =
      std::find_if(kinds().begin() + static_cast<std::ptrdiff_t>(library), kinds().end(),
                   [name](const PlantKind& kind) { return kind.name == name; });
  if (found == kinds().end()) {
    throw std::invalid_argument("no registered plant kind '" + std::string(name) +
                                "' to unregister (the library's kinds stay)");
  }
  config::unregister_choice("plant.kind", found->name);
  kinds().erase(found);
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

double kind_torque_limit(const parameters::Parameters& parameters) {
  const PlantKind& kind = plant_kind(parameters.plant.kind);
  if (!kind.torque_limit) return parameters.plant.robot.torque_limit;
  const double limit = kind.torque_limit(parameters);
  if (!(std::isfinite(limit) && limit > 0.0)) {
    throw std::invalid_argument("plant kind '" + kind.name +
                                "': its torque limit must be a finite number > 0, N m; got " +
                                std::to_string(limit));
  }
  return limit;
}

}  // namespace cbbg::diagrams
