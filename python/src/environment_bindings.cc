// The balancing task as a Gymnasium-style environment in Python (environment/): reset and
// step return Gymnasium's tuples, info as a dict; python/cbbg/environment.py adds the spaces.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cbbg/environment/balance_environment.h"
#include "python_factories.h"

namespace cbbg::python {
namespace {

using environment::BalanceEnvironment;

py::dict info_dict(const environment::Info& info) {
  py::dict dict;
  dict["time"] = info.time;
  dict["supervisor_action"] = info.supervisor_action;
  dict["state"] = info.state;
  dict["signal_names"] = info.signal_names;
  if (!info.failure_reason.empty()) dict["failure_reason"] = info.failure_reason;
  return dict;
}

// An action as Gymnasium gives it: a real number, or an array of one. A complex number, a
// text or an object is refused (TypeError), not converted: NumPy would drop an imaginary part
// and parse a text.
double action_of(py::handle action) {
  if (py::isinstance<py::float_>(action) || py::isinstance<py::int_>(action)) {
    return action.cast<double>();
  }
  const bool is_array = py::isinstance<py::array>(action);
  if (!is_array && py::isinstance(action, py::module_::import("numbers").attr("Real"))) {
    return action.cast<double>();  // NumPy's real scalars, Fraction: through __float__
  }
  const auto refused = [&action, is_array](const py::handle& dtype) {
    const std::string what = is_array ? "an array of " + std::string(py::str(dtype))
                                      : std::string(py::str(py::type::of(action).attr("__name__")));
    return py::type_error(
        "step: the action is one torque, N m: a real number or an array of one real number; "
        "got " +
        what + " " + std::string(py::str(py::repr(action))));
  };
  const auto array = py::array::ensure(action);
  if (!array) throw refused(py::none());
  const char kind = array.dtype().kind();  // b: bool, i and u: integers, f: floats
  if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f') throw refused(array.dtype());
  if (array.size() != 1) {
    throw std::invalid_argument(
        "step: the action is one torque, N m: a number or an array of "
        "one element; got " +
        std::string(py::str(py::repr(action))));
  }
  return *py::array_t<double, py::array::forcecast>::ensure(array).data();
}

}  // namespace

void bind_environment(py::module_& m) {
  py::class_<BalanceEnvironment>(
      m, "BalanceEnvironment",
      "The balancing task with the shape of Gymnasium's API (cbbg.BalanceEnv adds the spaces): "
      "reset(seed, initial_pitch) -> (observation, info); step(action) -> (observation, reward, "
      "terminated, truncated, info). The action, N m on both wheels, is held for trial.period; "
      "the observation is the 6 measured signals; info holds time, supervisor_action (the "
      "configured supervisor's action on this observation), state and signal_names.")
      .def(py::init([](const parameters::Parameters& p, py::object plant) {
             return std::make_unique<BalanceEnvironment>(
                 p, environment::EnvironmentOptions{.plant = plant_factory_from(plant)});
           }),
           py::arg("parameters"), py::arg("plant") = py::none())
      .def(
          "reset",
          [](BalanceEnvironment& env, std::optional<std::uint64_t> seed,
             std::optional<double> initial_pitch) {
            environment::ResetResult result;
            {
              py::gil_scoped_release release;
              result = env.reset(seed, initial_pitch);
            }
            return py::make_tuple(result.observation, info_dict(result.info));
          },
          py::arg("seed") = std::nullopt, py::arg("initial_pitch") = std::nullopt)
      .def(
          "step",
          [](BalanceEnvironment& env, py::handle action) {
            const double torque = action_of(action);
            environment::StepResult result;
            {
              py::gil_scoped_release release;
              result = env.step(torque);
            }
            return py::make_tuple(result.observation, result.reward, result.terminated,
                                  result.truncated, info_dict(result.info));
          },
          py::arg("action"))
      .def_property_readonly("observation_low", &BalanceEnvironment::observation_low)
      .def_property_readonly("observation_high", &BalanceEnvironment::observation_high)
      .def_property_readonly("action_low", &BalanceEnvironment::action_low)
      .def_property_readonly("action_high", &BalanceEnvironment::action_high)
      .def_property_readonly("period", &BalanceEnvironment::period)
      .def_property_readonly("duration", &BalanceEnvironment::duration)
      .def_property_readonly("signal_names", &BalanceEnvironment::signal_names)
      .def_property_readonly("closed_loop", &BalanceEnvironment::closed_loop,
                             py::return_value_policy::reference_internal);
}

}  // namespace cbbg::python
