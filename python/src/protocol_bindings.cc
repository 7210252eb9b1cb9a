// The protocols in Python: running them (in memory, or through the command line with its
// results directory), their results as Python objects, a protocol of the user's written with
// the kit, and the learnt weights.
//
// The GIL is released while a protocol runs; its seeds run in C++ threads, and a Python block
// in the loop takes the GIL at each call, so Python calls are serialised and the results are
// the same whatever the thread count.

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "cbbg/apps/cli.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/protocol_kit.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/experiments/transfer.h"
#include "cbbg/store/weights_file.h"
#include "ownership.h"
#include "python_errors.h"
#include "python_factories.h"

namespace cbbg::python {
namespace {

using experiments::ExperimentOptions;
using experiments::ExperimentResults;
using experiments::LearntWeights;

// Throws IndexError unless 0 <= index < count, naming the argument and the range.
void check_index(const char* function, const char* argument, long long index, std::size_t count,
                 const char* of) {
  if (index >= 0 && static_cast<std::size_t>(index) < count) return;
  throw py::index_error(std::string(function) + ": " + argument + " must be in [0, " +
                        std::to_string(count) + ") (an index of " + of + "); got " +
                        std::to_string(index));
}

// A learner's parts as a dict of arrays (copies), in its order.
py::dict parts_of(const experiments::LearntState& state) {
  py::dict parts;
  for (const experiments::LearntPart& part : state.parts) parts[py::str(part.name)] = part.values;
  return parts;
}

ExperimentOptions options_of(int jobs, const LearntWeights* initial_weights) {
  ExperimentOptions options;
  options.jobs = jobs;
  options.initial_weights = initial_weights;
  return options;
}

// `text` as one of `names` (to_string's words); ValueError naming `what` and the words.
template <class Enum>
Enum enum_of(const std::string& text, std::initializer_list<Enum> values, const char* what) {
  std::string words;
  for (const Enum value : values) {
    if (text == experiments::to_string(value)) return value;
    words += std::string(words.empty() ? "" : ", ") + experiments::to_string(value);
  }
  throw py::value_error(std::string(what) + " must be one of " + words + "; got '" + text + "'");
}

experiments::ValueType value_type(const std::string& text) {
  using experiments::ValueType;
  return enum_of(text, {ValueType::kInteger, ValueType::kNumber, ValueType::kFlag}, "type");
}

void bind_schema(py::module_& m) {
  using experiments::Figure;
  using experiments::FigureSummary;
  using experiments::Missing;
  py::class_<experiments::Column>(m, "Column", "One of a protocol's own per-trial columns.")
      .def(py::init([](std::string name, const std::string& type, std::string meaning) {
             return experiments::Column{std::move(name), value_type(type), std::move(meaning)};
           }),
           py::arg("name"), py::arg("type") = "number", py::arg("meaning") = "")
      .def_readonly("name", &experiments::Column::name)
      .def_property_readonly("type", [](const experiments::Column& c) { return to_string(c.type); })
      .def_readonly("meaning", &experiments::Column::meaning);
  py::class_<Figure>(m, "Figure",
                     "A figure a protocol records per seed: its type (integer, number, flag), "
                     "how summary.json shows it (sum, list, none), whether the arms are compared "
                     "on it, how a seed without one counts (not_counted, beyond_max_trials).")
      .def(py::init([](std::string name, const std::string& type, std::string meaning,
                       const std::string& summary, bool paired, const std::string& missing,
                       std::string console) {
             return Figure{
                 .name = std::move(name),
                 .type = value_type(type),
                 .meaning = std::move(meaning),
                 .summary = enum_of(
                     summary, {FigureSummary::kSum, FigureSummary::kList, FigureSummary::kNone},
                     "summary"),
                 .paired = paired,
                 .missing =
                     enum_of(missing, {Missing::kNotCounted, Missing::kBeyondMaxTrials}, "missing"),
                 .console = std::move(console)};
           }),
           py::arg("name"), py::arg("type") = "number", py::arg("meaning") = "",
           py::arg("summary") = "sum", py::arg("paired") = false,
           py::arg("missing") = "not_counted", py::arg("console") = "")
      .def_readonly("name", &Figure::name)
      .def_property_readonly("type", [](const Figure& f) { return to_string(f.type); })
      .def_readonly("meaning", &Figure::meaning)
      .def_property_readonly("summary", [](const Figure& f) { return to_string(f.summary); })
      .def_readonly("paired", &Figure::paired)
      .def_property_readonly("missing", [](const Figure& f) { return to_string(f.missing); });
  py::class_<experiments::ResultsSchema>(m, "ResultsSchema", "What a protocol's results hold.")
      .def_readonly("trial_columns", &experiments::ResultsSchema::trial_columns)
      .def_readonly("evaluates", &experiments::ResultsSchema::evaluates)
      .def_readonly("figures", &experiments::ResultsSchema::figures)
      .def_readonly("pairs_failures", &experiments::ResultsSchema::pairs_failures)
      .def_property_readonly("headline", &experiments::ResultsSchema::headline_name)
      .def_readonly("plots", &experiments::ResultsSchema::plots);
}

void bind_records(py::module_& m) {
  py::class_<experiments::TrialOutcome>(m, "TrialOutcome")
      .def_property_readonly("status",
                             [](const experiments::TrialOutcome& o) {
                               return std::string(experiments::to_string(o.status));
                             })
      .def_readonly("steps", &experiments::TrialOutcome::steps)
      .def_readonly("mean_temperature", &experiments::TrialOutcome::mean_temperature)
      .def_readonly("mean_entropy", &experiments::TrialOutcome::mean_entropy)
      .def_readonly("final_theta", &experiments::TrialOutcome::final_theta)
      .def_readonly("message", &experiments::TrialOutcome::message)
      .def_readonly("pitch_rms", &experiments::TrialOutcome::pitch_rms)
      .def_readonly("pitch_peak_to_peak", &experiments::TrialOutcome::pitch_peak_to_peak)
      .def_readonly("mean_forward_speed", &experiments::TrialOutcome::mean_forward_speed)
      .def_property_readonly("balanced", [](const experiments::TrialOutcome& o) {
        return o.status == experiments::TrialStatus::kSuccess;
      });
  py::class_<experiments::TrialRecord>(m, "TrialRecord")
      .def_readwrite("trial", &experiments::TrialRecord::trial)
      .def_readwrite("k1", &experiments::TrialRecord::k1)
      .def_readwrite("outcome", &experiments::TrialRecord::outcome)
      .def_readwrite("values", &experiments::TrialRecord::values,
                     "The protocol's own columns of this trial (exp3's actor_alone), by name.")
      .def("value", &experiments::TrialRecord::value, py::arg("name"),
           "The value named `name`, or None.")
      .def(
          "set_value",
          [](experiments::TrialRecord& record, std::string name, std::optional<double> value) {
            record.values.push_back({std::move(name), value});
          },
          py::arg("name"), py::arg("value"),
          "Records one of the protocol's own columns (ResultsSchema trial_columns).");
  py::class_<experiments::EvaluationRecord>(m, "EvaluationRecord")
      .def_readonly("theta0", &experiments::EvaluationRecord::theta0)
      .def_readonly("outcome", &experiments::EvaluationRecord::outcome);
  py::class_<experiments::NamedValue>(m, "SeedFigure", "A value recorded by name; None: none.")
      .def(py::init([](std::string name, std::optional<double> value) {
             return experiments::NamedValue{std::move(name), value};
           }),
           py::arg("name"), py::arg("value"))
      .def_readonly("name", &experiments::NamedValue::name)
      .def_readonly("value", &experiments::NamedValue::value);
  py::class_<LearntWeights>(
      m, "LearntWeights",
      "What a learner learnt: the actor's and the critic's parts (the library's: 'weights' "
      "alone), with the feature layout they were learnt on.")
      .def_property_readonly(
          "actor", [](const LearntWeights& w) { return Vector(w.actor.weights("actor")); },
          "The actor's part 'weights' (theta); ValueError if it learnt none.")
      .def_property_readonly(
          "critic", [](const LearntWeights& w) { return Vector(w.critic.weights("critic")); },
          "The critic's part 'weights' (w); ValueError if it learnt none.")
      .def_property_readonly(
          "actor_parts", [](const LearntWeights& w) { return parts_of(w.actor); },
          "Every part the actor learnt, by name, in its order.")
      .def_property_readonly(
          "critic_parts", [](const LearntWeights& w) { return parts_of(w.critic); },
          "Every part the critic learnt, by name, in its order.")
      .def_property_readonly("num_features", &LearntWeights::num_features);
  m.def("load_weights", &store::load_weights, py::arg("path"));
  m.def("save_weights", &store::save_weights, py::arg("path"), py::arg("weights"),
        "Writes a weights file; replaces only a weights file cbbg wrote.");
}

void bind_results(py::module_& m) {
  py::class_<experiments::SeedRun>(m, "SeedRun", "One (arm, seed) of an experiment.")
      .def_readonly("arm", &experiments::SeedRun::arm)
      .def_readonly("seed", &experiments::SeedRun::seed)
      .def_readwrite("trials", &experiments::SeedRun::trials)
      .def_readwrite("failures_before_success", &experiments::SeedRun::failures_before_success)
      .def_readwrite("succeeded", &experiments::SeedRun::succeeded)
      .def_readonly("evaluation", &experiments::SeedRun::evaluation)
      .def_readonly("weights", &experiments::SeedRun::weights)
      .def_readonly("weights_diverged", &experiments::SeedRun::weights_diverged)
      .def_readwrite("figures", &experiments::SeedRun::figures)
      .def("add_trial",
           [](experiments::SeedRun& run, experiments::TrialRecord record) {
             run.trials.push_back(std::move(record));
           })
      .def("figure", &experiments::SeedRun::figure, py::arg("name"),
           "The figure named `name` (exp3's trials_to_skill), or None.")
      .def(
          "add_figure",
          [](experiments::SeedRun& run, std::string name, std::optional<double> value) {
            run.figures.push_back({std::move(name), value});
          },
          py::arg("name"), py::arg("value"),
          "Records a figure of this seed (None: it has none), declared by the protocol.");
  py::class_<ExperimentResults>(m, "ExperimentResults", "Every (arm, seed) run, arm-major.")
      .def_readonly("experiment", &ExperimentResults::experiment)
      .def_readonly("schema", &ExperimentResults::schema)
      .def_readonly("arms", &ExperimentResults::arms)
      .def_readonly("seeds", &ExperimentResults::seeds)
      .def_readonly("runs", &ExperimentResults::runs)
      .def(
          "run",
          [](const ExperimentResults& results, long long arm,
             long long seed_index) -> const experiments::SeedRun& {
            check_index("ExperimentResults.run", "arm", arm, results.arms.size(), "arms");
            check_index("ExperimentResults.run", "seed_index", seed_index, results.seeds.size(),
                        "seeds");
            // runs holds every (arm, seed): C++ makes it so, and Python cannot change it.
            return results.run(static_cast<std::size_t>(arm), static_cast<std::size_t>(seed_index));
          },
          py::arg("arm"), py::arg("seed_index"), py::return_value_policy::reference_internal,
          "The run of arms[arm] and seeds[seed_index] (indices, not a seed itself): "
          "runs[arm * len(seeds) + seed_index]. IndexError outside the lists.");
}

void bind_runs(py::module_& m) {
  m.def(
      "run_experiment",
      [](const parameters::Parameters& p, int jobs, const LearntWeights* initial_weights) {
        return experiments::run_experiment(p, options_of(jobs, initial_weights));
      },
      py::arg("parameters"), py::arg("jobs") = 1, py::arg("initial_weights") = nullptr,
      py::call_guard<py::gil_scoped_release>(),
      "The experiment the parameters name (a protocol, or one arm under exp1's), over its arms.");
  using Runner = ExperimentResults (*)(const parameters::Parameters&,
                                       const std::vector<diagrams::Arm>&, const ExperimentOptions&);
  const auto def_runner = [&m](const char* name, Runner runner, const char* doc) {
    m.def(
        name,
        [runner](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms, int jobs,
                 const LearntWeights* initial_weights) {
          return runner(p, arms, options_of(jobs, initial_weights));
        },
        py::arg("parameters"), py::arg("arms"), py::arg("jobs") = 1,
        py::arg("initial_weights") = nullptr, py::call_guard<py::gil_scoped_release>(), doc);
  };
  def_runner("run_exp1", &experiments::run_exp1, "exp1 over `arms` (Arm objects, a user's too).");
  def_runner("run_exp3", &experiments::run_exp3, "exp3 over `arms`.");
  def_runner("run_evaluation", &experiments::run_evaluation,
             "The weights learning starts from, evaluated as exp1 evaluates what it learnt.");
  def_runner("run_transfer", &experiments::run_transfer,
             "Train once, evaluate under each of transfer.conditions.");
  m.def(
      "run_exp2",
      [](const parameters::Parameters& p, const diagrams::Arm& coordinated,
         const diagrams::Arm& operant, int jobs) {
        return experiments::run_exp2(p, coordinated, operant, options_of(jobs, nullptr));
      },
      py::arg("parameters"), py::arg("coordinated"), py::arg("operant"), py::arg("jobs") = 1,
      py::call_guard<py::gil_scoped_release>());
}

// The SeedLoop a per-seed body in Python is given, usable during its call only: its trials
// write into the task's files, which are closed once the call returns.
struct SeedLoopHandle {
  std::shared_ptr<experiments::SeedLoop> loop;
  std::shared_ptr<bool> live = std::make_shared<bool>(true);

  experiments::SeedLoop& checked() const {
    if (!*live) {
      throw std::runtime_error(
          "SeedLoop: its per-seed call has returned; keep the records its trials gave, not "
          "the loop");
    }
    return *loop;
  }
};

// A per-seed body written in Python: per_seed(parameters, arm, seed_run, kit) fills seed_run.
experiments::PerSeed per_seed_from(py::object per_seed) {
  SharedPythonObject callable(std::move(per_seed));
  return [callable](const parameters::Parameters& p, const diagrams::Arm& arm,
                    const experiments::TelemetryOptions& telemetry,
                    const LearntWeights* initial_weights, experiments::SeedRun& run) {
    // Python gets its own copies of the arm and the run (copied back when the call returns)
    // and a handle of the loop that refuses use after it: nothing it keeps dangles.
    const SeedLoopHandle kit{
        std::make_shared<experiments::SeedLoop>(p, arm, telemetry, initial_weights, run.seed)};
    {
      py::gil_scoped_acquire gil;
      const py::object run_object = py::cast(run);
      const py::object kit_object = py::cast(kit);
      struct Expiry {
        const SeedLoopHandle& kit;
        ~Expiry() { *kit.live = false; }
      } expiry{kit};
      calling_python([&] {
        return py::reinterpret_borrow<py::object>(callable.get())(copy_of(p), py::cast(arm),
                                                                  run_object, kit_object);
      });
      run = run_object.cast<experiments::SeedRun>();
    }
    experiments::finish_run(p, arm, kit.loop->loop, kit.loop->runner.context(), run);
  };
}

void bind_kit(py::module_& m) {
  py::class_<SeedLoopHandle>(
      m, "SeedLoop",
      "One seed of an arm: its learning closed loop and the runner of its trials. Valid during "
      "the per-seed call only: after it, its methods raise RuntimeError.")
      .def(
          "trial",
          [](const SeedLoopHandle& kit, const parameters::Parameters& p, int trial,
             std::optional<double> theta0) {
            experiments::SeedLoop& loop = kit.checked();
            return theta0 ? experiments::next_trial(p, loop, trial, *theta0)
                          : experiments::next_trial(p, loop, trial);
          },
          py::arg("parameters"), py::arg("trial"), py::arg("theta0") = std::nullopt,
          py::call_guard<py::gil_scoped_release>(),
          "Runs trial number `trial` from trial.theta0 (or theta0) and returns its record.")
      .def_property_readonly(
          "context",
          [](const SeedLoopHandle& kit) -> Context& { return kit.checked().runner.context(); },
          py::return_value_policy::reference_internal);
  m.def(
      "register_protocol",
      [](std::string name, std::string meaning, py::object per_seed, bool evaluates, bool paired,
         std::vector<experiments::Figure> figures, std::vector<experiments::Column> trial_columns,
         std::string headline, const std::vector<std::string>& paired_figures, bool replace) {
        const experiments::PerSeed body = per_seed_from(std::move(per_seed));
        experiments::ResultsSchema schema{.trial_columns = std::move(trial_columns),
                                          .evaluates = evaluates,
                                          .figures = std::move(figures),
                                          .pairs_failures = paired,
                                          .headline = std::move(headline)};
        for (const std::string& figure : paired_figures) {
          if (schema.figure(figure) == nullptr) schema.figures.push_back({.name = figure});
          for (auto& declared : schema.figures) declared.paired |= declared.name == figure;
        }
        if (!schema.figures.empty()) schema.plots.push_back("figures");
        experiments::check_schema(schema, name);
        if (replace && std::ranges::any_of(experiments::protocols(),
                                           [&name](const auto& p) { return p.name == name; })) {
          experiments::unregister_protocol(name);
        }
        experiments::register_protocol(
            {.name = name,
             .meaning = std::move(meaning),
             .run =
                 [name, body](const parameters::Parameters& p,
                              const std::vector<diagrams::Arm>& arms,
                              const ExperimentOptions& options) {
                   return experiments::run_per_arm(name, body, p, arms, options);
                 },
             .schema = [schema](const parameters::Parameters&) { return schema; }});
      },
      py::arg("name"), py::arg("meaning"), py::arg("per_seed"), py::arg("evaluates") = true,
      py::arg("paired") = true, py::arg("figures") = std::vector<experiments::Figure>{},
      py::arg("trial_columns") = std::vector<experiments::Column>{}, py::arg("headline") = "",
      py::arg("paired_figures") = std::vector<std::string>{}, py::arg("replace") = false,
      "Adds a protocol `experiment` may name (replace=True: in place of one registered under "
      "that name). per_seed(parameters, arm, run, loop) runs one "
      "seed of one arm: loop.trial(parameters, k) runs trials, run.add_trial(record) and "
      "run.add_figure(name, value) record them; the run is then finished as exp1's (weights "
      "kept, evaluated when `evaluates`). Its results: the figures it records (cbbg.Figure, "
      "or names in paired_figures: summed and compared between arms), its own per-trial "
      "columns (cbbg.Column, recorded with record.set_value), `paired`: whether the arms' "
      "failures before the first success are compared, `headline`: sweep.csv's figure.");
  m.def("unregister_protocol", &experiments::unregister_protocol, py::arg("name"),
        "Removes a registered protocol and its keys (the library's stay).");
  m.def("protocol_names", [] { return names_of(experiments::protocols()); });
}

// The command line reads C strings, which a NUL ends: an argument holding one would be read
// cut short (results written to "x" for "x\0y"). Throws ValueError naming it.
void check_no_nul(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i].find('\0') == std::string::npos) continue;
    std::string shown;
    for (const char c : args[i]) shown += c == '\0' ? std::string("\\0") : std::string(1, c);
    throw std::invalid_argument("cbbg.main: args[" + std::to_string(i) + "] '" + shown +
                                "' contains a NUL character; an argument is text without NUL");
  }
}

}  // namespace

void bind_protocols(py::module_& m) {
  bind_schema(m);
  bind_records(m);
  bind_results(m);
  bind_runs(m);
  bind_kit(m);
  m.def(
      "cli",
      [](std::vector<std::string> args, const std::filesystem::path& share) {
        check_no_nul(args);
        args.insert(args.begin(), "cbbg");
        std::vector<char*> argv;
        for (std::string& arg : args) argv.push_back(arg.data());
        return app::run_cli(static_cast<int>(argv.size()), argv.data(), share);
      },
      py::arg("args"), py::arg("share"), py::call_guard<py::gil_scoped_release>(),
      "Runs the cbbg command line (run, eval, graph, plot, merge, ...) with this process's "
      "registrations; returns its exit code. cbbg.main(args) supplies `share`.");
}

}  // namespace cbbg::python
