// Configs and typed parameters in Python, and a user's own sections.
//
//   config = cbbg.Config({"plant": {"kind": "analytic"}, "seeds": 5})   # cbbg/__init__.py
//   parameters = cbbg.validated_parameters(config)
//   parameters["critic.gamma"], parameters["mysup.gain"]

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <limits>
#include <set>

#include "bindings.h"
#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::python {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

config::Config config_of(const parameters::Parameters& parameters) {
  config::Config config;
  parameters::write_parameters(parameters, config);
  return config;
}

bool is_key(const std::string& key) {
  for (const config::KeySpec& spec : config::schema()) {
    if (spec.path == key) return true;
  }
  return false;
}

// The value of any key of a typed tree: built-in, or of a registered section.
config::Value value_of(const parameters::Parameters& parameters, const std::string& key) {
  if (!is_key(key)) {
    const std::string close = config::closest_key(key);
    throw config::ConfigError("unknown key '" + key + "'" +
                              (close.empty() ? std::string() : "; did you mean '" + close + "'?"));
  }
  return config_of(parameters).value(key);
}

// A key of a user's section, from Python; register_section gives it its path.
config::KeySpec key_spec(config::Kind kind, config::Value default_value, std::string meaning,
                         double min, double max, bool min_exclusive, bool max_exclusive,
                         std::vector<std::string> choices, int list_size) {
  return config::KeySpec{.path = "",
                         .kind = kind,
                         .default_value = std::move(default_value),
                         .meaning = std::move(meaning),
                         .choices = std::move(choices),
                         .min = min,
                         .max = max,
                         .min_exclusive = min_exclusive,
                         .max_exclusive = max_exclusive,
                         .list_size = list_size};
}

// The check of section `name` in Python: check({key: value}) raising an Exception refuses
// the values, its message the refusal's (a KeyboardInterrupt stays one).
config::SectionCheck python_check(const std::string& name, const py::object& check) {
  // Kept for the process's life: the registry outlives the interpreter, which must not
  // release it after finalising.
  const auto* held = new py::object(check);
  return [name, held](const config::OwnSections& own) {
    py::gil_scoped_acquire gil;
    py::dict values;
    const std::string prefix = name + ".";
    for (const auto& [key, value] : own.values) {
      if (key.starts_with(prefix)) values[py::str(key.substr(prefix.size()))] = py::cast(value);
    }
    try {
      (*held)(values);
    } catch (py::error_already_set& error) {
      if (!error.matches(PyExc_Exception)) throw;
      throw config::ConfigError(py::str(error.value()).cast<std::string>());
    }
  };
}

// `keys`: {key: KeySpec}, in the order the section lists them; `check`, if not None, is
// called with the section's values at the edge of every run.
// The sections registered from Python: the ones unregister_section may remove.
std::set<std::string>& python_sections() {
  static std::set<std::string> names;
  return names;
}

void unregister_section(const std::string& name) {
  if (python_sections().count(name) == 0) {
    throw std::invalid_argument("no section '" + name +
                                "' registered from Python to unregister (the library's stay)");
  }
  std::vector<std::string> paths;
  for (const config::KeySpec& key : config::schema()) {
    if (key.path.starts_with(name + ".")) paths.push_back(key.path);
  }
  config::unregister_keys(paths);
  config::unregister_section_check(name);
  python_sections().erase(name);
}

void register_section(const std::string& name, const py::dict& keys, const py::object& check,
                      bool replace) {
  if (!config::is_name(name)) {
    throw std::invalid_argument("section '" + name + "': a name is " + config::kNameRule);
  }
  if (replace && python_sections().count(name) != 0) unregister_section(name);
  std::vector<config::KeySpec> specs;
  for (const auto& [key, spec] : keys) {
    specs.push_back(spec.cast<config::KeySpec>());
    specs.back().path = name + "." + key.cast<std::string>();
  }
  config::register_keys(std::move(specs));
  python_sections().insert(name);
  if (!check.is_none()) config::register_section_check(name, python_check(name, check));
}

void bind_key_specs(py::module_& m) {
  py::enum_<config::Kind>(m, "KeyKind")
      .value("NUMBER", config::Kind::kNumber)
      .value("INTEGER", config::Kind::kInteger)
      .value("TEXT", config::Kind::kText)
      .value("NUMBERS", config::Kind::kNumbers)
      .value("NAMES", config::Kind::kNames)
      .value("ANNEALING", config::Kind::kAnnealing)
      .value("SETTINGS", config::Kind::kSettings)
      .value("FILE", config::Kind::kFile);
  py::class_<config::KeySpec>(m, "KeySpec", "One key of the config tree: kind, default, checks.")
      .def_readonly("path", &config::KeySpec::path)
      .def_readonly("kind", &config::KeySpec::kind)
      .def_readonly("default_value", &config::KeySpec::default_value)
      .def_readonly("meaning", &config::KeySpec::meaning)
      .def_readonly("choices", &config::KeySpec::choices)
      .def_readonly("min", &config::KeySpec::min)
      .def_readonly("max", &config::KeySpec::max)
      .def_property_readonly("allowed", &config::allowed_values);
  const auto bounds = [](const char* kind) {
    return std::string("A ") + kind +
           " key of a section of the user's (register_section), checked against [min, max] "
           "(exclusive where asked) as every key is.";
  };
  m.def(
      "number_key",
      [](double default_value, std::string meaning, double min, double max, bool min_exclusive,
         bool max_exclusive) {
        return key_spec(config::Kind::kNumber, default_value, std::move(meaning), min, max,
                        min_exclusive, max_exclusive, {}, 0);
      },
      py::arg("default"), py::arg("meaning"), py::arg("min") = -kInfinity,
      py::arg("max") = kInfinity, py::arg("min_exclusive") = false,
      py::arg("max_exclusive") = false, bounds("number").c_str());
  m.def(
      "integer_key",
      [](long long default_value, std::string meaning, double min, double max) {
        return key_spec(config::Kind::kInteger, default_value, std::move(meaning), min, max, false,
                        false, {}, 0);
      },
      py::arg("default"), py::arg("meaning"), py::arg("min") = -kInfinity,
      py::arg("max") = kInfinity, bounds("integer").c_str());
  m.def(
      "numbers_key",
      [](std::vector<double> default_value, std::string meaning, double min, double max, int size) {
        return key_spec(config::Kind::kNumbers, std::move(default_value), std::move(meaning), min,
                        max, false, false, {}, size);
      },
      py::arg("default"), py::arg("meaning"), py::arg("min") = -kInfinity,
      py::arg("max") = kInfinity, py::arg("size") = 0, bounds("list of numbers").c_str());
  m.def(
      "text_key",
      [](std::string default_value, std::string meaning, std::vector<std::string> choices) {
        return key_spec(config::Kind::kText, std::move(default_value), std::move(meaning),
                        -kInfinity, kInfinity, false, false, std::move(choices), 0);
      },
      py::arg("default"), py::arg("meaning"), py::arg("choices") = std::vector<std::string>{},
      "A text key of a user's section; `choices`, when given, are the words it allows.");
  m.def("unregister_section", &unregister_section, py::arg("name"),
        "Removes a section registered from Python, its keys and its check.");
  m.def("register_section", &register_section, py::arg("name"), py::arg("keys"),
        py::arg("check") = py::none(), py::arg("replace") = false,
        "Adds a section of the user's, {key: number_key(...), ...}, to every config made after: "
        "settable from dicts, files and --set, read from parameters[\"name.key\"]. `check`, "
        "if given, is called with the section's values ({key: value}) before any run and "
        "refuses them by raising an exception, its message the error's.");
  m.def("schema", &config::schema, "Every key of the config tree, built-in and registered.");
}

void bind_config(py::module_& m) {
  py::class_<config::AnnealingStep>(m, "AnnealingStep")
      .def(py::init<long long, double>(), py::arg("from_trial"), py::arg("k1"))
      .def_readwrite("from_trial", &config::AnnealingStep::from_trial)
      .def_readwrite("k1", &config::AnnealingStep::k1);
  py::class_<config::Config>(m, "Config",
                             "The configuration tree: defaults, then YAML files and settings.")
      .def(py::init<>())
      .def(
          "merge_yaml",
          [](config::Config& config, const std::string& text, const std::string& source) {
            config.merge_yaml(text, source);  // a file's path: from the working directory
          },
          py::arg("text"), py::arg("source"))
      .def("merge_file", &config::Config::merge_file, py::arg("path"))
      .def("set_assignment", &config::Config::set, py::arg("assignment"), py::arg("source") = "",
           "Applies one \"key.path=value\" (value in YAML syntax); errors start with `source`.")
      .def("value", &config::Config::value, py::arg("key"))
      .def("__getitem__", &config::Config::value, py::arg("key"))
      .def("to_yaml", &config::Config::to_yaml)
      .def("__eq__", [](const config::Config& a, const config::Config& b) { return a == b; });
}

void bind_typed_parameters(py::module_& m) {
  py::class_<parameters::Parameters>(
      m, "Parameters",
      "The typed parameter tree of a run, checked whole (validated_parameters); what every "
      "factory and protocol is given.")
      .def("value", &value_of, py::arg("key"), "The value of any key, a registered one's too.")
      .def("__getitem__", &value_of, py::arg("key"))
      .def("to_config", &config_of)
      .def("to_yaml", [](const parameters::Parameters& p) { return config_of(p).to_yaml(); })
      .def_property_readonly("seeds", [](const parameters::Parameters& p) { return p.run.seeds; })
      .def_property_readonly("seed", [](const parameters::Parameters& p) { return p.run.seed; })
      .def_property_readonly("experiment",
                             [](const parameters::Parameters& p) { return p.run.experiment; })
      .def_property_readonly("arms", [](const parameters::Parameters& p) { return p.run.arms; });
  m.def("validated_parameters", &diagrams::validated_parameters, py::arg("config"),
        "The typed tree of `config`, every value and rule checked (ConfigError otherwise).");
  m.def(
      "evaluated_parameters",
      [](const parameters::Parameters& training) {
        experiments::check_evaluation_conditions(training);
        return experiments::evaluation_parameters(training);
      },
      py::arg("parameters"),
      "The robot, sensors and push an evaluation sees: `parameters` with its evaluation.* "
      "perturbations applied (body mass and CoM height through plant.kind's kind, pitch noise "
      "into sensors.noise_std, the push into push.*), as the protocols evaluate; an "
      "environment made from them is that evaluation's robot. ConfigError when the kind has "
      "no parameter a scale changes or the result is invalid.");
}

}  // namespace

void bind_parameters(py::module_& m) {
  bind_key_specs(m);
  bind_config(m);
  bind_typed_parameters(m);
}

}  // namespace cbbg::python
