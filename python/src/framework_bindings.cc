// The framework in Python: ports, blocks, the builder, diagrams, contexts, the simulator,
// logs and Graphviz.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <type_traits>

#include "bindings.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/graphviz.h"
#include "cbbg/framework/signal_log.h"
#include "cbbg/framework/simulator.h"
#include "event_reasons.h"
#include "ownership.h"

namespace cbbg::python {
namespace {

Vector copy_of(ConstVectorView view) { return view; }

// A child of a diagram as Python sees it: the very object Python made, or a reference that
// keeps its diagram alive.
py::object child_object(const Block& child, py::handle diagram) {
  return py::cast(&child, py::return_value_policy::reference_internal, diagram);
}

py::list children(const Diagram& diagram, py::handle self) {
  py::list list;
  for (const auto& child : diagram.blocks()) list.append(child_object(*child, self));
  return list;
}

// A block's input or output ports, each keeping the block alive.
template <class PortType>
py::list ports_of(py::object self) {
  const Block& block = self.cast<const Block&>();
  constexpr bool inputs = std::is_same_v<PortType, InputPort>;
  const int count = inputs ? block.num_input_ports() : block.num_output_ports();
  py::list ports;
  for (int i = 0; i < count; ++i) {
    const Port& port = inputs ? static_cast<const Port&>(block.input_port(i))
                              : static_cast<const Port&>(block.output_port(i));
    ports.append(py::cast(&static_cast<const PortType&>(port),
                          py::return_value_policy::reference_internal, self));
  }
  return ports;
}

template <class PortType>
std::string port_repr(const PortType& port, const char* kind) {
  return "<cbbg." + std::string(kind) + " '" + port.path() + "' size " +
         std::to_string(port.size()) + ">";
}

void bind_ports(py::module_& m) {
  py::class_<Port>(m, "Port", "A named, fixed-size port of a block.")
      .def_property_readonly("block", &Port::block, py::return_value_policy::reference)
      .def_property_readonly("index", &Port::index)
      .def_property_readonly("name", &Port::name)
      .def_property_readonly("size", &Port::size)
      .def_property_readonly("description", &Port::description)
      .def_property_readonly("path", &Port::path, "\"diagram/block.port\"");
  py::class_<InputPort, Port>(m, "InputPort", "A vector a block reads.")
      .def("__repr__", [](const InputPort& port) { return port_repr(port, "InputPort"); });
  py::class_<OutputPort, Port>(m, "OutputPort", "A vector a block computes.")
      .def("__repr__", [](const OutputPort& port) { return port_repr(port, "OutputPort"); });
}

void bind_block_parts(py::module_& m) {
  py::class_<EventStatus>(m, "EventStatus",
                          "What an update tells the simulator: carry on, or end the simulation.")
      .def_static("succeeded", &EventStatus::succeeded)
      .def_static(
          "terminate",
          [](const std::string& reason) { return EventStatus::terminate(lasting_reason(reason)); },
          py::arg("reason"))
      .def_property_readonly("terminates", &EventStatus::terminates)
      .def_property_readonly("reason", &EventStatus::reason);
  py::class_<StatePart>(m, "StatePart", "A named part of a block's discrete state.")
      .def_readonly("name", &StatePart::name)
      .def_readonly("offset", &StatePart::offset)
      .def_readonly("size", &StatePart::size)
      .def_property_readonly(
          "per_trial",
          [](const StatePart& part) { return part.lifetime == StateLifetime::kPerTrial; })
      .def(
          "of",
          [](const StatePart& part, py::array_t<double> state) {
            return state[py::slice(part.offset, part.offset + part.size, 1)];
          },
          py::arg("state"), "The part inside the block's whole state array (a view of it).");
  py::class_<Parameter>(m, "Parameter")
      .def_readonly("name", &Parameter::name)
      .def_readonly("default_value", &Parameter::default_value);
}

void bind_block(py::module_& m) {
  py::class_<Block>(m, "Block", "The unit of composition: named ports, state, parameters, events.")
      .def_property_readonly("name", &Block::name)
      .def_property_readonly("type_name", &Block::type_name)
      .def_property_readonly("path", &Block::path,
                             "Names from the root diagram down, joined by '/'.")
      .def_property_readonly("is_diagram", &Block::is_diagram)
      .def_property_readonly("num_input_ports", &Block::num_input_ports)
      .def_property_readonly("num_output_ports", &Block::num_output_ports)
      .def("input_port", py::overload_cast<std::string_view>(&Block::input_port, py::const_),
           py::arg("name"), py::return_value_policy::reference_internal)
      .def("input_port", py::overload_cast<int>(&Block::input_port, py::const_), py::arg("index"),
           py::return_value_policy::reference_internal)
      .def("output_port", py::overload_cast<std::string_view>(&Block::output_port, py::const_),
           py::arg("name"), py::return_value_policy::reference_internal)
      .def("output_port", py::overload_cast<int>(&Block::output_port, py::const_), py::arg("index"),
           py::return_value_policy::reference_internal)
      .def_property_readonly("input_ports", &ports_of<InputPort>)
      .def_property_readonly("output_ports", &ports_of<OutputPort>)
      .def_property_readonly("discrete_state_parts", &Block::discrete_state_parts)
      .def("discrete_state_part", &Block::discrete_state_part, py::arg("name"))
      .def_property_readonly("initial_discrete_state", &Block::initial_discrete_state)
      .def_property_readonly("initial_continuous_state", &Block::initial_continuous_state)
      .def_property_readonly("parameters", &Block::parameters)
      .def("__repr__", [](const Block& block) {
        return "<cbbg." + block.type_name() + " '" + block.path() + "'>";
      });
}

void bind_diagram(py::module_& m) {
  py::class_<Diagram, Block>(m, "Diagram", "Blocks wired port to port; made by DiagramBuilder.")
      .def_property_readonly(
          "blocks", [](py::object self) { return children(self.cast<const Diagram&>(), self); })
      .def(
          "block",
          [](py::object self, const std::string& name) {
            return child_object(self.cast<const Diagram&>().block(name), self);
          },
          py::arg("name"), "A direct child by name.")
      .def("create_context", &Diagram::create_context, py::arg("seed") = 0, py::keep_alive<0, 1>(),
           "A fresh context: initial state, default parameters, generators seeded from `seed`.")
      .def(
          "eval_output",
          [](const Diagram& diagram, Context& context, const OutputPort& port) {
            return copy_of(diagram.eval_output(context, port));
          },
          py::arg("context"), py::arg("port"),
          "Evaluates every output and returns the value of `port` (an output of any block inside).")
      .def(
          "to_dot",
          [](const Diagram& diagram, int max_depth, std::vector<std::string> hidden) {
            return to_dot(diagram, {.max_depth = max_depth, .hidden_blocks = std::move(hidden)});
          },
          py::arg("max_depth") = -1, py::arg("hidden_blocks") = std::vector<std::string>{},
          "The Graphviz DOT text of the diagram.");
}

void bind_builder(py::module_& m) {
  py::class_<DiagramBuilder>(
      m, "DiagramBuilder",
      "Add blocks, connect ports, export or fix what stays open, then build().")
      .def(py::init<std::string>(), py::arg("name"))
      .def(
          "add",
          [](DiagramBuilder& builder, py::object block) {
            builder.add(shared_from_python<Block>(block, "DiagramBuilder.add"));
            return block;
          },
          py::arg("block"), "Adds a block (leaf or diagram) and returns it.")
      .def("connect",
           py::overload_cast<const OutputPort&, const InputPort&>(&DiagramBuilder::connect),
           py::arg("source"), py::arg("destination"))
      .def("connect",
           py::overload_cast<const Block&, std::string_view, const Block&, std::string_view>(
               &DiagramBuilder::connect),
           py::arg("source"), py::arg("output"), py::arg("destination"), py::arg("input"))
      .def("export_input", &DiagramBuilder::export_input, py::arg("inner"), py::arg("name") = "",
           py::return_value_policy::reference_internal)
      .def("export_output", &DiagramBuilder::export_output, py::arg("inner"), py::arg("name") = "",
           py::return_value_policy::reference_internal)
      .def("fix_input", &DiagramBuilder::fix_input, py::arg("inner"), py::arg("value"))
      .def("build", &DiagramBuilder::build,
           "Checks the wiring and returns the Diagram; the builder is spent afterwards.");
}

void bind_context(py::module_& m) {
  py::class_<Context>(m, "Context", "Everything that changes during a simulation.")
      .def_property("time", &Context::time, &Context::set_time)
      .def_property_readonly("root_seed", &Context::root_seed)
      .def("clone", &Context::clone, py::keep_alive<0, 1>())
      .def(
          "discrete_state",
          [](const Context& c, const Block& b) { return copy_of(c.discrete_state(b)); },
          py::arg("block"), "A copy of the block's discrete state.")
      .def(
          "set_discrete_state",
          [](Context& c, const Block& b, const Vector& value) {
            VectorView state = c.discrete_state(b);
            if (value.size() != state.size()) {
              throw std::invalid_argument("set_discrete_state: block '" + b.path() + "' has " +
                                          std::to_string(state.size()) + " discrete states, got " +
                                          std::to_string(value.size()));
            }
            state = value;
          },
          py::arg("block"), py::arg("value"))
      .def(
          "continuous_state",
          [](const Context& c, const Block& b) { return copy_of(c.continuous_state(b)); },
          py::arg("block"))
      .def(
          "set_continuous_state",
          [](Context& c, const Block& b, const Vector& value) {
            VectorView state = c.continuous_state(b);
            if (value.size() != state.size()) {
              throw std::invalid_argument("set_continuous_state: block '" + b.path() + "' has " +
                                          std::to_string(state.size()) +
                                          " continuous states, got " +
                                          std::to_string(value.size()));
            }
            state = value;
          },
          py::arg("block"), py::arg("value"))
      .def(
          "parameter",
          [](const Context& c, const Block& b, std::string_view name) {
            return copy_of(c.parameter(b, name));
          },
          py::arg("block"), py::arg("name"))
      .def("set_parameter", &Context::set_parameter, py::arg("block"), py::arg("name"),
           py::arg("value"))
      .def("fix_input", &Context::fix_input, py::arg("port"), py::arg("value"),
           "Sets an input port the root diagram exports.")
      .def(
          "signal",
          [](const Context& c, const OutputPort& port) { return copy_of(c.signal(port)); },
          py::arg("port"), "The last evaluated value of an output port.")
      .def("reset_state", &Context::reset_state, py::arg("block"))
      .def("reset_all_state", &Context::reset_all_state)
      .def("reset_trial_state", &Context::reset_trial_state)
      .def("continue_from", &Context::continue_from, py::arg("other"))
      .def("reseed", &Context::reseed, py::arg("seed"));
}

void bind_simulator(py::module_& m) {
  py::enum_<Schedule>(m, "Schedule")
      .value("COMPILED", Schedule::kCompiled)
      .value("INTERPRETED", Schedule::kInterpreted);
  py::class_<SimulatorOptions>(m, "SimulatorOptions")
      .def(py::init([](double accuracy, double min_step, Schedule schedule) {
             return SimulatorOptions{accuracy, min_step, schedule};
           }),
           py::arg("accuracy") = 1e-6, py::arg("min_step") = 1e-12,
           py::arg("schedule") = Schedule::kCompiled)
      .def_readwrite("accuracy", &SimulatorOptions::accuracy)
      .def_readwrite("min_step", &SimulatorOptions::min_step)
      .def_readwrite("schedule", &SimulatorOptions::schedule);
  py::class_<SimulationStatus>(m, "SimulationStatus")
      .def_readonly("terminated", &SimulationStatus::terminated)
      .def_readonly("time", &SimulationStatus::time)
      .def_property_readonly("terminated_by",
                             [](const SimulationStatus& s) {
                               return s.terminated_by == nullptr ? std::string()
                                                                 : s.terminated_by->path();
                             })
      .def_property_readonly("reason",
                             [](const SimulationStatus& s) { return std::string(s.reason); });
  py::class_<SignalLog>(m, "SignalLog", "One output port recorded at its own period.")
      .def_property_readonly("port", &SignalLog::port, py::return_value_policy::reference)
      .def_property_readonly("period", &SignalLog::period)
      .def_property_readonly("offset", &SignalLog::offset)
      .def_property_readonly("size", &SignalLog::size)
      .def_property_readonly("num_samples", &SignalLog::num_samples)
      .def_property_readonly("times",
                             [](const SignalLog& log) {
                               return py::array_t<double>(
                                   static_cast<py::ssize_t>(log.times().size()),
                                   log.times().data());
                             })
      .def_property_readonly(
          "values", [](const SignalLog& log) { return Eigen::MatrixXd(log.values()); },
          "Every sample as a column: size rows, num_samples columns.")
      .def_property_readonly("column_names", &SignalLog::column_names);
  py::class_<Simulator>(m, "Simulator", "Advances a context of a root diagram through time.")
      .def(py::init<const Diagram&, SimulatorOptions, std::uint64_t>(), py::arg("diagram"),
           py::arg("options") = SimulatorOptions{}, py::arg("seed") = 0, py::keep_alive<1, 2>())
      .def(py::init([](const Diagram& diagram, const Context& context, SimulatorOptions options) {
             return std::make_unique<Simulator>(diagram, context.clone(), options);
           }),
           py::arg("diagram"), py::arg("context"), py::arg("options") = SimulatorOptions{},
           py::keep_alive<1, 2>(), "Simulates a copy of `context`.")
      .def_property_readonly("context", py::overload_cast<>(&Simulator::context),
                             py::return_value_policy::reference_internal)
      .def("initialize", &Simulator::initialize, py::call_guard<py::gil_scoped_release>())
      .def("advance_to", &Simulator::advance_to, py::arg("time"),
           py::call_guard<py::gil_scoped_release>())
      .def("add_log", &Simulator::add_log, py::arg("port"), py::arg("period"),
           py::arg("offset") = 0.0, py::return_value_policy::reference_internal)
      .def_property_readonly("num_event_instants", &Simulator::num_event_instants);
}

}  // namespace

void bind_framework(py::module_& m) {
  bind_ports(m);
  bind_block_parts(m);
  bind_block(m);
  bind_diagram(m);
  bind_builder(m);
  bind_context(m);
  bind_simulator(m);
  m.def(
      "to_dot",
      [](const Diagram& diagram, int max_depth, std::vector<std::string> hidden) {
        return to_dot(diagram, {.max_depth = max_depth, .hidden_blocks = std::move(hidden)});
      },
      py::arg("diagram"), py::arg("max_depth") = -1,
      py::arg("hidden_blocks") = std::vector<std::string>{});
  m.def("render_dot", &render_dot, py::arg("dot"), py::arg("output"),
        "Writes DOT text to a .dot, .svg or .png file (through Graphviz's dot).");
}

}  // namespace cbbg::python
