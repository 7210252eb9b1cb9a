#pragma once
// Python callables as the library's factories (a slot's block, a plant, a controller, a closed
// loop): each call takes the GIL, hands Python a copy of the parameters (nothing it keeps
// reaches the caller's), and shares the block Python returns (ownership.h). A Python exception
// crosses back unchanged; KeyboardInterrupt and SystemExit as PythonInterrupt (python_errors.h).

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "cbbg/diagrams/cbbg_controller.h"
#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "ownership.h"

namespace cbbg::python {

// A slot's factory: callable(name, parameters) -> Block, and for the critic and actor slots
// callable(name, parameters, num_features, learns) (diagrams::SlotRequest).
struct PythonBlockFactory {
  SharedPythonObject callable;
  std::shared_ptr<Block> operator()(const diagrams::SlotRequest& request) const;
};

// A plant's factory: callable(name, parameters) -> RobotPlant.
struct PythonPlantFactory {
  SharedPythonObject callable;
  std::shared_ptr<plant::RobotPlant> operator()(const std::string& name,
                                                const parameters::Parameters& p) const;
};

// A controller's factory: callable(parameters) -> Diagram.
struct PythonControllerFactory {
  SharedPythonObject callable;
  std::shared_ptr<Diagram> operator()(const parameters::Parameters& p) const;
};

// A copy of `parameters` for Python to keep.
py::object copy_of(const parameters::Parameters& parameters);

// `value` as a factory: None (empty), a callable, or what callable_of returned.
diagrams::BlockFactory block_factory_from(py::handle value);
diagrams::PlantFactory plant_factory_from(py::handle value);
diagrams::ControllerFactory controller_factory_from(py::handle value);
// The Python callable behind `factory` if Python gave it; None when it is empty; else an
// opaque object (NativeBlockFactory, NativePlantFactory) that gives the C++ factory back
// when assigned.
py::object callable_of(const diagrams::BlockFactory& factory);
py::object callable_of(const diagrams::PlantFactory& factory);

// The opaque factories' classes.
void bind_native_factories(py::module_& m);

}  // namespace cbbg::python
