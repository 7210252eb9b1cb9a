// The controller and its closed loop in Python: presets, options and slots, closed loops,
// arms, plant kinds. Every factory may be a Python callable (python_factories.h).
//
//   options = cbbg.preset("cbbg").options
//   options.slots.supervisor = lambda name, parameters: MySupervisor(name)
//   cbbg.register_arm("cbbg_mine", "cbbg with my supervisor", options)

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "python_errors.h"
#include "python_factories.h"

namespace cbbg::python {
namespace {

using diagrams::ControllerOptions;
using diagrams::ControllerSlots;

template <diagrams::BlockFactory ControllerSlots::*slot>
void def_slot(py::class_<ControllerSlots>& cls, const char* name, const char* doc) {
  cls.def_property(
      name, [](const ControllerSlots& slots) { return callable_of(slots.*slot); },
      [](ControllerSlots& slots, py::object value) { slots.*slot = block_factory_from(value); },
      doc);
}

void bind_slots(py::module_& m) {
  py::class_<ControllerSlots> slots(
      m, "ControllerSlots",
      "The blocks that fill the controller's slots: each a callable(name, parameters) -> Block, "
      "or None for the parameters' own.");
  slots.def(py::init<>());
  def_slot<&ControllerSlots::supervisor>(slots, "supervisor",
                                         "input \"measured\" (6), output \"action\" (1): a_S");
  def_slot<&ControllerSlots::normaliser>(
      slots, "normaliser", "input \"measured\" (6), output \"x\": what the features expect");
  def_slot<&ControllerSlots::features>(
      slots, "features", "input \"x\", output \"features\": what critic and actor share");
  def_slot<&ControllerSlots::critic>(
      slots, "critic",
      "callable(name, parameters, num_features, learns): reads any of \"features\" (n), "
      "\"reward\", \"failed\"; outputs \"value\", \"td_error\" (1 each)");
  def_slot<&ControllerSlots::actor>(
      slots, "actor",
      "callable(name, parameters, num_features, learns): reads any of \"features\" (n), "
      "\"td_error\", \"supervisor_action\", \"omega\", \"exploration_action\"; outputs "
      "\"actor_action\" (1)");
  def_slot<&ControllerSlots::exploration>(
      slots, "exploration",
      "reads any of \"actor_action\", \"temperature\"; outputs \"exploration_action\" (1); "
      "named \"sampler\": draw from context.random_generator() for common random numbers");
  def_slot<&ControllerSlots::tropism>(slots, "tropism",
                                      "reads \"value\" (1); outputs \"temperature\" (1)");
  def_slot<&ControllerSlots::entropy>(slots, "entropy",
                                      "reads \"temperature\" (1); outputs \"entropy\" (1)");
  def_slot<&ControllerSlots::mixer>(
      slots, "mixer",
      "reads any of \"exploration_action\", \"supervisor_action\", \"omega\"; outputs "
      "\"action\" (1)");
  def_slot<&ControllerSlots::omega>(slots, "omega", "no input, output \"omega\" (1), in [0, 1]");
}

template <diagrams::BlockFactory diagrams::TaskSlots::*slot>
void def_task_slot(py::class_<diagrams::TaskSlots>& cls, const char* name, const char* doc) {
  cls.def_property(
      name, [](const diagrams::TaskSlots& slots) { return callable_of(slots.*slot); },
      [](diagrams::TaskSlots& slots, py::object value) { slots.*slot = block_factory_from(value); },
      doc);
}

void bind_task_slots(py::module_& m) {
  py::class_<diagrams::TaskSlots> slots(
      m, "TaskSlots",
      "The task's slots around the controller: each a callable(name, parameters) -> Block, or "
      "None for the parameters' own. The reward the loop records is the one the controller "
      "learns from.");
  slots.def(py::init<>());
  def_task_slot<&diagrams::TaskSlots::sensors>(slots, "sensors",
                                               "reads \"plant_state\"; outputs \"measured\" (6)");
  def_task_slot<&diagrams::TaskSlots::failure>(slots, "failure",
                                               "reads \"measured\" (6); outputs \"failed\" (1)");
  def_task_slot<&diagrams::TaskSlots::reward>(
      slots, "reward", "reads any of \"measured\" (6), \"failed\" (1); outputs \"reward\" (1)");
}

void bind_options(py::module_& m) {
  py::class_<ControllerOptions>(
      m, "ControllerOptions",
      "Independent choices of the CB-BG controller; each preset is one set.")
      .def(py::init<>())
      .def_readwrite("supervisor", &ControllerOptions::supervisor)
      .def_readwrite("basal_ganglia", &ControllerOptions::basal_ganglia)
      .def_property(
          "omega",
          [](const ControllerOptions& o) { return std::string(blocks::to_string(o.omega)); },
          [](ControllerOptions& o, const std::string& word) {
            o.omega = blocks::parse_omega_mode(word);
          },
          "schedule, zero, one or constant (omega_constant throughout)")
      .def_readwrite("omega_constant", &ControllerOptions::omega_constant)
      .def_property(
          "actor_rule",
          [](const ControllerOptions& o) -> py::object {
            if (!o.actor_rule) return py::none();
            return py::str(std::string(blocks::to_string(*o.actor_rule)));
          },
          [](ControllerOptions& o, py::object word) {
            if (word.is_none()) {
              o.actor_rule.reset();
            } else {
              o.actor_rule = blocks::parse_actor_rule(word.cast<std::string>());
            }
          },
          "improved, weighted, or None for actor.rule")
      .def_readwrite("critic_learns", &ControllerOptions::critic_learns)
      .def_readwrite("actor_learns", &ControllerOptions::actor_learns)
      .def_readwrite("exploration", &ControllerOptions::exploration)
      .def_readwrite("slots", &ControllerOptions::slots)
      .def("validate", &ControllerOptions::validate);
  py::class_<diagrams::Preset>(m, "Preset")
      .def_readonly("name", &diagrams::Preset::name)
      .def_readonly("description", &diagrams::Preset::description)
      .def_readonly("options", &diagrams::Preset::options);
  m.def("presets", &diagrams::presets, py::return_value_policy::copy);
  m.def("preset", &diagrams::preset, py::arg("name"), py::return_value_policy::copy);
  m.def("arm_names", &diagrams::arm_names);
  m.def("diagram_names", &diagrams::diagram_names);
  m.def("learnt_actor", &diagrams::learnt_actor, py::arg("options"));
}

diagrams::ClosedLoopOptions loop_options(py::handle plant, std::optional<blocks::PushParams> push,
                                         const std::optional<diagrams::TaskSlots>& task = {}) {
  return diagrams::ClosedLoopOptions{.plant = plant_factory_from(plant),
                                     .push = std::move(push),
                                     .slots = task.value_or(diagrams::TaskSlots{})};
}

void bind_closed_loop(py::module_& m) {
  py::class_<diagrams::ClosedLoop>(m, "ClosedLoop",
                                   "A trial's closed loop: plant, sensors, task, controller, hold.")
      .def_property_readonly(
          "diagram",
          [](const diagrams::ClosedLoop& loop) -> const Diagram& { return *loop.diagram; },
          py::return_value_policy::reference_internal)
      .def_property_readonly(
          "plant", [](const diagrams::ClosedLoop& loop) { return loop.plant; },
          py::return_value_policy::reference_internal)
      .def_property_readonly(
          "controller", [](const diagrams::ClosedLoop& loop) { return loop.controller; },
          py::return_value_policy::reference_internal)
      .def_property_readonly(
          "telemetry", [](const diagrams::ClosedLoop& loop) { return loop.telemetry; },
          py::return_value_policy::reference_internal,
          "The output of what each tick records (telemetry_names() names its signals).")
      .def_readonly("accuracy", &diagrams::ClosedLoop::accuracy)
      .def_readwrite("schedule", &diagrams::ClosedLoop::schedule)
      .def("start_trial", &diagrams::ClosedLoop::start_trial, py::arg("context"), py::arg("theta0"),
           "Time 0, per-trial state reset, the robot at theta0 at rest; learning carries on.");
  m.def(
      "build_closed_loop",
      [](std::string name, const parameters::Parameters& p, py::object controller, py::object plant,
         std::optional<blocks::PushParams> push, std::optional<diagrams::TaskSlots> task) {
        return diagrams::build_closed_loop(
            std::move(name), p, shared_from_python<Diagram>(controller, "build_closed_loop"),
            loop_options(plant, std::move(push), task));
      },
      py::arg("name"), py::arg("parameters"), py::arg("controller"), py::arg("plant") = py::none(),
      py::arg("push") = std::nullopt, py::arg("task") = std::nullopt,
      "Wires `controller` (a diagram with a controller's ports) into a closed loop; `plant`: a "
      "callable(name, parameters) -> RobotPlant, or None for plant.kind's.");
  m.def(
      "build_preset",
      [](std::string_view name, const parameters::Parameters& p, py::object plant,
         std::optional<blocks::PushParams> push, std::optional<diagrams::TaskSlots> task) {
        return diagrams::build_preset(name, p, loop_options(plant, std::move(push), task));
      },
      py::arg("name"), py::arg("parameters"), py::arg("plant") = py::none(),
      py::arg("push") = std::nullopt, py::arg("task") = std::nullopt);
}

// Removes the registered arm `name` if there is one (register_arm's replace=True).
void forget_arm(const std::string& name) {
  for (const diagrams::ArmName& arm : diagrams::registered_arms()) {
    if (arm.name == name) return diagrams::unregister_arm(name);
  }
}

void bind_arms(py::module_& m) {
  py::class_<diagrams::Arm>(m, "Arm",
                            "What an experiment compares: a name, the closed loop that learns "
                            "and that of its learnt actor alone.")
      .def_readonly("name", &diagrams::Arm::name)
      .def(
          "learner",
          [](const diagrams::Arm& arm, const parameters::Parameters& p) { return arm.learner(p); },
          py::arg("parameters"), py::call_guard<py::gil_scoped_release>())
      .def_property_readonly(
          "learns", [](const diagrams::Arm& arm) { return static_cast<bool>(arm.policy); });
  m.def(
      "make_arm",
      [](std::string name, const ControllerOptions& options, py::object plant,
         std::optional<diagrams::TaskSlots> task) {
        return diagrams::make_arm(std::move(name), options,
                                  loop_options(plant, std::nullopt, task));
      },
      py::arg("name"), py::arg("options"), py::arg("plant") = py::none(),
      py::arg("task") = std::nullopt);
  m.def(
      "make_arm_of",
      [](std::string name, py::object learner, py::object policy, py::object plant) {
        return diagrams::make_arm(std::move(name), controller_factory_from(learner),
                                  controller_factory_from(policy),
                                  loop_options(plant, std::nullopt));
      },
      py::arg("name"), py::arg("learner"), py::arg("policy") = py::none(),
      py::arg("plant") = py::none(),
      "The arm of a controller of the user's: learner(parameters) -> Diagram, and policy, its "
      "learnt actor alone.");
  m.def(
      "preset_arm", [](std::string_view name) { return diagrams::preset_arm(name); },
      py::arg("name"));
  m.def(
      "named_arm", [](std::string_view name) { return diagrams::named_arm(name); }, py::arg("name"),
      "A preset's or a registered arm, by name.");
  m.def(
      "register_arm",
      [](std::string name, std::string description, const ControllerOptions& options,
         std::optional<diagrams::TaskSlots> task, bool replace) {
        if (replace) forget_arm(name);
        diagrams::register_arm(std::move(name), std::move(description), options,
                               task.value_or(diagrams::TaskSlots{}));
      },
      py::arg("name"), py::arg("description"), py::arg("options"), py::arg("task") = std::nullopt,
      py::arg("replace") = false,
      "Registers an arm of a CB-BG controller with `options`, in a task whose slots `task` "
      "(TaskSlots) fills; replace=True replaces an arm registered under that name.");
  m.def(
      "register_arm_of",
      [](std::string name, std::string description, py::object learner, py::object policy,
         bool replace) {
        if (replace) forget_arm(name);
        diagrams::register_arm(std::move(name), std::move(description),
                               controller_factory_from(learner), controller_factory_from(policy));
      },
      py::arg("name"), py::arg("description"), py::arg("learner"), py::arg("policy") = py::none(),
      py::arg("replace") = false);
  m.def("unregister_arm", &diagrams::unregister_arm, py::arg("name"),
        "Removes a registered arm (a preset stays).");
}

// A change of the robot, asked of a Python plant kind as a dict of settings.
using PythonChange = std::function<bool(parameters::Parameters&, diagrams::RobotChange, double)>;
PythonChange change_from(py::object change) {
  if (change.is_none()) return {};
  SharedPythonObject callable(std::move(change));
  return [callable](parameters::Parameters& p, diagrams::RobotChange what, double factor) {
    py::gil_scoped_acquire gil;
    py::object settings = calling_python([&] {
      return py::reinterpret_borrow<py::object>(callable.get())(copy_of(p),
                                                                diagrams::change_key(what), factor);
    });
    if (settings.is_none()) return false;
    config::Config config;
    parameters::write_parameters(p, config);
    for (const auto& [key, value] : settings.cast<py::dict>()) {
      const std::string assignment =
          key.cast<std::string>() + "=" +
          py::module_::import("json").attr("dumps")(value).cast<std::string>();
      config.set(assignment,
                 std::string("the plant kind's change of ") + diagrams::change_key(what));
    }
    p = parameters::read_parameters(config);
    return true;
  };
}

// A Python plant kind's linearisation: linearize(parameters) -> LinearModel (or (A, B)), the
// model PlantKind::linearize describes (x = (theta_b, phi, theta_b', phi'), u the torque).
using PythonLinearize = std::function<plant::LinearModel(const parameters::Parameters&)>;
PythonLinearize linearize_from(py::object linearize, const std::string& kind) {
  if (linearize.is_none()) return {};
  SharedPythonObject callable(std::move(linearize));
  return [callable, kind](const parameters::Parameters& p) {
    py::gil_scoped_acquire gil;
    const py::object model = calling_python(
        [&] { return py::reinterpret_borrow<py::object>(callable.get())(copy_of(p)); });
    plant::LinearModel linear;
    if (py::isinstance<plant::LinearModel>(model)) {
      linear = model.cast<plant::LinearModel>();
    } else {
      const auto pair = model.cast<std::pair<Eigen::MatrixXd, Eigen::MatrixXd>>();
      linear = {pair.first, pair.second};
    }
    if (linear.A.rows() != 4 || linear.A.cols() != 4 || linear.B.rows() != 4 ||
        linear.B.cols() != 1 || !linear.A.allFinite() || !linear.B.allFinite()) {
      throw std::invalid_argument(
          "plant kind '" + kind +
          "': linearize must return finite A (4 x 4) and B (4 x 1) for "
          "x = (theta_b, phi, theta_b', phi'); got A " +
          std::to_string(linear.A.rows()) + " x " + std::to_string(linear.A.cols()) + ", B " +
          std::to_string(linear.B.rows()) + " x " + std::to_string(linear.B.cols()));
    }
    return linear;
  };
}

// A Python plant kind's torque limit: torque_limit(parameters) -> N m.
std::function<double(const parameters::Parameters&)> torque_limit_from(py::object limit) {
  if (limit.is_none()) return {};
  SharedPythonObject callable(std::move(limit));
  return [callable](const parameters::Parameters& p) {
    py::gil_scoped_acquire gil;
    return calling_python([&] {
      return py::reinterpret_borrow<py::object>(callable.get())(copy_of(p)).cast<double>();
    });
  };
}

void bind_plant_kinds(py::module_& m) {
  bind_native_factories(m);
  m.def(
      "register_plant_kind",
      [](std::string name, std::string description, py::object make, py::object change,
         py::object linearize, py::object torque_limit, bool replace) {
        if (replace && std::ranges::any_of(diagrams::plant_kinds(), [&name](const auto& kind) {
              return kind.name == name;
            })) {
          diagrams::unregister_plant_kind(name);
        }
        auto linear = linearize_from(std::move(linearize), name);
        diagrams::register_plant_kind({.name = std::move(name),
                                       .description = std::move(description),
                                       .make = plant_factory_from(make),
                                       .change = change_from(std::move(change)),
                                       .linearize = std::move(linear),
                                       .torque_limit = torque_limit_from(std::move(torque_limit))});
      },
      py::arg("name"), py::arg("description"), py::arg("make"), py::arg("change") = py::none(),
      py::arg("linearize") = py::none(), py::arg("torque_limit") = py::none(),
      py::arg("replace") = false,
      "Adds a plant kind plant.kind may name (replace=True: in place of a kind registered under "
      "that name): make(name, parameters) -> RobotPlant; change("
      "parameters, key, factor) -> {key: value} applying an evaluation's changed robot "
      "(key: evaluation.body_mass_scale or evaluation.com_height_scale), or None when it has "
      "no such parameter; linearize(parameters) -> LinearModel or (A, B), the robot linearised "
      "upright at rest (x = (theta_b, phi, theta_b', phi'), u the wheel torque: what "
      "supervisor.kind: lqr designs from), or None; torque_limit(parameters) -> N m, where the "
      "plant saturates each wheel (the environments' action space), or None for "
      "plant.torque_limit. Register before making any Config.");
  m.def("unregister_plant_kind", &diagrams::unregister_plant_kind, py::arg("name"),
        "Removes a registered plant kind (the library's stay).");
  m.def("plant_kinds", [] { return names_of(diagrams::plant_kinds()); });
  m.def(
      "plant_factory",
      [](std::string_view kind) { return callable_of(diagrams::plant_kind(kind).make); },
      py::arg("kind"), "The factory of a plant kind, for ClosedLoop options or the environment.");
}

}  // namespace

void bind_controller(py::module_& m) {
  bind_slots(m);
  bind_task_slots(m);
  bind_options(m);
  bind_closed_loop(m);
  bind_arms(m);
  bind_plant_kinds(m);
}

}  // namespace cbbg::python
