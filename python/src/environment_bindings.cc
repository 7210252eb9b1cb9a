// The balancing task as a Gymnasium-style environment in Python (environment/): reset and
// step return Gymnasium's tuples, info as a dict; python/cbbg/environment.py adds the spaces.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cbbg/blocks/measured_signals.h"
#include "cbbg/environment/balance_environment.h"
#include "cbbg/environment/vec_balance_environment.h"
#include "python_factories.h"

namespace cbbg::python {
namespace {

using environment::BalanceEnvironment;

py::dict info_dict(const environment::Info& info) {
  py::dict dict;
  dict["time"] = info.time;
  dict["supervisor_action"] = info.supervisor_action;
  dict["unsaturated_supervisor_action"] = info.unsaturated_supervisor_action;
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

// The reset distribution from Python: None (trial.theta0), or a pair (low, high) of radians.
std::optional<environment::InitialPitch> initial_pitch_of(py::handle range) {
  if (range.is_none()) return std::nullopt;
  const auto pair = range.cast<std::pair<double, double>>();
  return environment::InitialPitch{pair.first, pair.second};
}

// N actions as Gymnasium's vector envs take them: an array of N real numbers, (N,) or (N, 1).
std::vector<double> actions_of(py::handle actions, int n) {
  const auto array = py::array::ensure(actions);
  const char kind = array ? array.dtype().kind() : '\0';
  if (!array || (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f')) {
    throw py::type_error("step: the actions are " + std::to_string(n) +
                         " torques, N m: an array of real numbers; got " +
                         std::string(py::str(py::repr(actions))));
  }
  const bool fits = (array.ndim() == 1 && array.shape(0) == n) ||
                    (array.ndim() == 2 && array.shape(0) == n && array.shape(1) == 1);
  if (!fits) {
    throw std::invalid_argument("step: the actions must have shape (" + std::to_string(n) +
                                ",) or (" + std::to_string(n) + ", 1); got " +
                                std::string(py::str(array.attr("shape"))));
  }
  const auto doubles =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  return std::vector<double>(doubles.data(), doubles.data() + n);
}

template <typename T>
py::array_t<T> copy_of(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::array_t<bool> flags_of(const std::vector<std::uint8_t>& values) {
  py::array_t<bool> flags(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), flags.mutable_data());
  return flags;
}

py::dict vec_info(const environment::VecBalanceEnvironment& env) {
  py::dict info;
  info["time"] = copy_of(env.times());
  info["supervisor_action"] = copy_of(env.supervisor_actions());
  info["autoreset"] = flags_of(env.autoreset());
  return info;
}

py::array_t<double> observations_of(const environment::VecBalanceEnvironment& env) {
  py::array_t<double> observations(
      {static_cast<py::ssize_t>(env.num_envs()), static_cast<py::ssize_t>(blocks::kMeasuredSize)});
  std::copy(env.observations().begin(), env.observations().end(), observations.mutable_data());
  return observations;
}

void bind_vec_environment(py::module_& m) {
  using environment::VecBalanceEnvironment;
  py::class_<VecBalanceEnvironment>(
      m, "VecBalanceEnvironment",
      "N balancing environments stepped in C++ threads, Gymnasium 1.x's vector semantics "
      "(autoreset on the next step); cbbg.VecBalanceEnv adds the spaces.")
      .def(py::init([](const parameters::Parameters& p, int num_envs, py::object plant, int threads,
                       py::object initial_pitch) {
             environment::VecOptions options;
             options.environment.plant = plant_factory_from(plant);
             options.environment.initial_pitch = initial_pitch_of(initial_pitch);
             options.threads = threads;
             return std::make_unique<VecBalanceEnvironment>(p, num_envs, std::move(options));
           }),
           py::arg("parameters"), py::arg("num_envs"), py::arg("plant") = py::none(),
           py::arg("threads") = 0, py::arg("initial_pitch") = py::none())
      .def(
          "reset",
          [](VecBalanceEnvironment& env, std::optional<std::uint64_t> seed,
             std::optional<std::vector<double>> pitches) {
            {
              py::gil_scoped_release release;
              env.reset(seed, pitches ? &*pitches : nullptr);
            }
            return py::make_tuple(observations_of(env), vec_info(env));
          },
          py::arg("seed") = std::nullopt, py::arg("initial_pitches") = std::nullopt)
      .def(
          "step",
          [](VecBalanceEnvironment& env, py::handle actions) {
            const std::vector<double> torques = actions_of(actions, env.num_envs());
            {
              py::gil_scoped_release release;
              env.step(torques.data());
            }
            return py::make_tuple(observations_of(env), copy_of(env.rewards()),
                                  flags_of(env.terminated()), flags_of(env.truncated()),
                                  vec_info(env));
          },
          py::arg("actions"))
      .def_property_readonly("num_envs", &VecBalanceEnvironment::num_envs)
      .def_property_readonly("threads", &VecBalanceEnvironment::threads)
      .def(
          "environment",
          [](const VecBalanceEnvironment& env, int index)
              -> const environment::BalanceEnvironment& { return env.environment(index); },
          py::arg("index"), py::return_value_policy::reference_internal);
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
      .def(
          py::init([](const parameters::Parameters& p, py::object plant, py::object initial_pitch) {
            return std::make_unique<BalanceEnvironment>(
                p,
                environment::EnvironmentOptions{.plant = plant_factory_from(plant),
                                                .initial_pitch = initial_pitch_of(initial_pitch)});
          }),
          py::arg("parameters"), py::arg("plant") = py::none(),
          py::arg("initial_pitch") = py::none())
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
      .def_property_readonly("failure_angle", &BalanceEnvironment::failure_angle)
      .def_property_readonly("period", &BalanceEnvironment::period)
      .def_property_readonly("duration", &BalanceEnvironment::duration)
      .def_property_readonly("signal_names", &BalanceEnvironment::signal_names)
      .def_property_readonly("closed_loop", &BalanceEnvironment::closed_loop,
                             py::return_value_policy::reference_internal);
  bind_vec_environment(m);
}

}  // namespace cbbg::python
