#include "python_factories.h"

#include <pybind11/functional.h>

#include "python_errors.h"

namespace cbbg::python {
namespace {

// A factory C++ made (a preset's slot, a registered kind's plant), carried through Python.
template <class Factory>
struct NativeFactory {
  Factory factory;
};

template <class Factory>
void bind_native_factory(py::module_& m, const char* name) {
  py::class_<NativeFactory<Factory>>(m, name, "A factory made in C++; assign it to a slot again.")
      .def("__repr__",
           [name](const NativeFactory<Factory>&) { return std::string("<cbbg.") + name + ">"; });
}

template <class Python, class Factory>
Factory factory_from(py::handle value, const char* what) {
  if (value.is_none()) return {};
  if (py::isinstance<NativeFactory<Factory>>(value)) {
    return value.cast<const NativeFactory<Factory>&>().factory;
  }
  if (!PyCallable_Check(value.ptr())) {
    throw std::invalid_argument(std::string(what) + ": expected a callable or None, got " +
                                std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  return Python{SharedPythonObject(py::reinterpret_borrow<py::object>(value))};
}

template <class Python, class Factory>
py::object callable_from(const Factory& factory) {
  if (!factory) return py::none();
  if (const Python* python = factory.template target<Python>()) {
    return py::reinterpret_borrow<py::object>(python->callable.get());
  }
  return py::cast(NativeFactory<Factory>{factory});
}

}  // namespace

py::object copy_of(const parameters::Parameters& parameters) {
  return py::cast(parameters, py::return_value_policy::copy);
}

std::shared_ptr<Block> PythonBlockFactory::operator()(const diagrams::SlotRequest& request) const {
  py::gil_scoped_acquire gil;
  py::object block = calling_python([&] {
    const py::object factory = py::reinterpret_borrow<py::object>(callable.get());
    py::object parameters = copy_of(request.parameters);
    if (request.num_features > 0) {  // a learner: it needs the features' size
      return factory(request.name, parameters, request.num_features, request.learns);
    }
    return factory(request.name, parameters);
  });
  return shared_from_python<Block>(block, "the factory of slot '" + request.name + "'");
}

std::shared_ptr<plant::RobotPlant> PythonPlantFactory::operator()(
    const std::string& name, const parameters::Parameters& p) const {
  py::gil_scoped_acquire gil;
  py::object plant = calling_python(
      [&] { return py::reinterpret_borrow<py::object>(callable.get())(name, copy_of(p)); });
  return shared_from_python<plant::RobotPlant>(plant, "the plant factory");
}

std::shared_ptr<Diagram> PythonControllerFactory::operator()(
    const parameters::Parameters& p) const {
  py::gil_scoped_acquire gil;
  py::object controller = calling_python(
      [&] { return py::reinterpret_borrow<py::object>(callable.get())(copy_of(p)); });
  return shared_from_python<Diagram>(controller, "the controller factory");
}

diagrams::BlockFactory block_factory_from(py::handle value) {
  return factory_from<PythonBlockFactory, diagrams::BlockFactory>(value, "a slot");
}
diagrams::PlantFactory plant_factory_from(py::handle value) {
  return factory_from<PythonPlantFactory, diagrams::PlantFactory>(value, "a plant factory");
}
diagrams::ControllerFactory controller_factory_from(py::handle value) {
  return factory_from<PythonControllerFactory, diagrams::ControllerFactory>(value,
                                                                            "a controller factory");
}
py::object callable_of(const diagrams::BlockFactory& factory) {
  return callable_from<PythonBlockFactory>(factory);
}
py::object callable_of(const diagrams::PlantFactory& factory) {
  return callable_from<PythonPlantFactory>(factory);
}

void bind_native_factories(py::module_& m) {
  bind_native_factory<diagrams::BlockFactory>(m, "NativeBlockFactory");
  bind_native_factory<diagrams::PlantFactory>(m, "NativePlantFactory");
}

}  // namespace cbbg::python
