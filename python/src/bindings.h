#pragma once
// The parts of the `cbbg` Python module (module.cc calls them in this order), each binding
// one part of the library in Python's idioms: snake_case names as in C++, NumPy arrays for
// vectors, C++ exceptions as Python exceptions with their messages, the GIL released while
// C++ runs.

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace cbbg::python {

namespace py = pybind11;

// The `name` of each entry of a registry (plant kinds, protocols), in its order.
template <class Registry>
std::vector<std::string> names_of(const Registry& entries) {
  std::vector<std::string> names;
  for (const auto& entry : entries) names.push_back(entry.name);
  return names;
}

// Ports, blocks, the builder, diagrams, contexts, the simulator, logs, Graphviz.
void bind_framework(py::module_& m);
// LeafBlock and RobotPlant: blocks and plants written in Python.
void bind_python_blocks(py::module_& m);
// The toolbox (framework/primitives) and the control helpers (framework/control).
void bind_primitives(py::module_& m);
// The library's blocks (supervisors, normaliser, features, ...), their parameters.
void bind_library_blocks(py::module_& m);
// Configs and typed parameters, a user's own sections.
void bind_parameters(py::module_& m);
// Presets, controller options and slots, closed loops, arms, plant kinds.
void bind_controller(py::module_& m);
// The protocols, their results, the command line.
void bind_protocols(py::module_& m);
// The balancing task as a Gymnasium-style environment.
void bind_environment(py::module_& m);

}  // namespace cbbg::python
