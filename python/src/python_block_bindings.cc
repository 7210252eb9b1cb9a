// LeafBlock and RobotPlant: blocks and plants a Python class declares (python_block.h).

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "python_block.h"

namespace cbbg::python {
namespace {

constexpr const char* kLeafBlockDoc = R"(A block written in Python.

Subclass it, call super().__init__(name), then declare what the block has:

    class Lean(cbbg.LeafBlock):
        def __init__(self, name, gain):
            super().__init__(name)
            self.gain = gain
            self.measured = self.declare_input_port("measured", 6)
            self.declare_output_port("action", 1, self.calc_action, reads=[self.measured])

        def calc_action(self, context, action):
            action[0] = self.gain * context.input(self.measured)[0]

A callable gets a CallContext (valid during the call only) and an array to write into
(out[:] = ...; it holds the current values). Updates return None, or
cbbg.EventStatus.terminate(reason) to end the simulation.)";

// The declarations, on LeafBlock (Impl = PythonLeafBlock) and RobotPlant (Impl =
// PythonRobotPlant, reached from the bound base class).
template <class Impl, class Bound>
Impl& implementation(Bound& block) {
  if (auto* python = dynamic_cast<Impl*>(&block)) return *python;
  throw std::logic_error("block '" + block.path() +
                         "' was not written in Python: only a Python subclass declares ports");
}

template <class Impl, class Class>
void add_declarations(Class& cls) {
  using Bound = typename Class::type;
  cls.def(
         "declare_input_port",
         [](Bound& self, std::string name, int size, std::string description) -> const InputPort& {
           return implementation<Impl>(self).python_input_port(std::move(name), size,
                                                               std::move(description));
         },
         py::arg("name"), py::arg("size"), py::arg("description") = "",
         py::return_value_policy::reference_internal)
      .def(
          "declare_output_port",
          [](Bound& self, std::string name, int size, py::object calc,
             const std::vector<const InputPort*>& reads, std::string description,
             bool holds_between_events) -> const OutputPort& {
            return implementation<Impl>(self).python_output_port(
                std::move(name), size, std::move(calc), reads, std::move(description),
                holds_between_events);
          },
          py::arg("name"), py::arg("size"), py::arg("calc"),
          py::arg("reads") = std::vector<const InputPort*>{}, py::arg("description") = "",
          py::arg("holds_between_events") = false, py::return_value_policy::reference_internal,
          "calc(context, out) writes the output. `reads`: the inputs it reads directly (none "
          "breaks a feedback loop). holds_between_events: it reads only discrete state and "
          "parameters, so the simulator computes it once per interval.")
      .def(
          "declare_discrete_state",
          [](Bound& self, std::string name, const Vector& initial, bool per_trial) {
            return implementation<Impl>(self).python_discrete_state(std::move(name), initial,
                                                                    per_trial);
          },
          py::arg("name"), py::arg("initial"), py::arg("per_trial") = false,
          "Appends a named part to the discrete state; per_trial parts restart at each trial.")
      .def(
          "declare_parameter",
          [](Bound& self, std::string name, const Vector& default_value) {
            return implementation<Impl>(self).python_parameter(std::move(name), default_value);
          },
          py::arg("name"), py::arg("default_value"))
      .def(
          "declare_periodic_update",
          [](Bound& self, double period, double offset, py::object update) {
            implementation<Impl>(self).python_periodic_update(period, offset, std::move(update));
          },
          py::arg("period"), py::arg("offset"), py::arg("update"),
          "update(context, next_state) writes the next discrete state (it holds the current).")
      .def(
          "declare_initialization_update",
          [](Bound& self, py::object update) {
            implementation<Impl>(self).python_initialization_update(std::move(update));
          },
          py::arg("update"))
      .def(
          "declare_continuous_state",
          [](Bound& self, const Vector& initial, py::object derivatives) {
            implementation<Impl>(self).python_continuous_state(initial, std::move(derivatives));
          },
          py::arg("initial"), py::arg("derivatives"),
          "derivatives(context, out) writes the time derivatives of the continuous state.");
}

void bind_call_context(py::module_& m) {
  py::class_<CallContext, std::shared_ptr<CallContext>>(
      m, "CallContext", "A block's view of the context during one call of its callables.")
      .def_property_readonly("time", &CallContext::time)
      .def("input", &CallContext::input, py::arg("port"), "A copy of the input's value.")
      .def("input", &CallContext::input_named, py::arg("name"))
      .def("output", &CallContext::output, py::arg("port"),
           "In an update: the block's own output as evaluated at this instant.")
      .def_property_readonly("discrete_state", &CallContext::discrete_state)
      .def("state", &CallContext::state_part, py::arg("name"),
           "A named part of the discrete state.")
      .def_property_readonly("continuous_state", &CallContext::continuous_state)
      .def("parameter", &CallContext::parameter, py::arg("name"))
      .def("random_normal", &CallContext::random_normal,
           "A standard normal draw from the block's own stream (updates only).")
      .def("random_uniform", &CallContext::random_uniform, "A draw on [0, 1) (updates only).");
}

}  // namespace

void bind_python_blocks(py::module_& m) {
  bind_call_context(m);
  py::class_<PythonLeafBlock, Block> leaf(m, "LeafBlock", kLeafBlockDoc);
  leaf.def(py::init<std::string>(), py::arg("name"));
  add_declarations<PythonLeafBlock>(leaf);

  py::class_<plant::RobotPlant, PythonRobotPlant, Block> robot(
      m, "RobotPlant",
      "A robot balanced through wheel torque: input \"torque\" (2), output \"state\" (its "
      "signals). A Python plant declares both ports and overrides reset(context, "
      "initial_pitch); signals(), logged_signals() and wheel_radius() as needed.");
  robot.def(py::init<std::string>(), py::arg("name"))
      .def("reset", &plant::RobotPlant::reset, py::arg("context"), py::arg("initial_pitch"))
      .def("signals", &plant::RobotPlant::signals)
      .def("logged_signals", &plant::RobotPlant::logged_signals,
           "The signals of signals() steps.csv records, after its own columns: none by default.")
      .def("wheel_radius", &plant::RobotPlant::wheel_radius)
      .def_property_readonly("torque_input", &plant::RobotPlant::torque_input,
                             py::return_value_policy::reference_internal)
      .def_property_readonly("state_output", &plant::RobotPlant::state_output,
                             py::return_value_policy::reference_internal);
  add_declarations<PythonRobotPlant>(robot);
}

}  // namespace cbbg::python
