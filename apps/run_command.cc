// cbbg run: resolve the config, run the experiment, write the results directory.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include <spdlog/spdlog.h>
#include <unistd.h>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/errors.h"
#include "cbbg/apps/figures.h"
#include "cbbg/apps/progress.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/arm_checks.h"
#include "cbbg/experiments/evaluation_conditions.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/run_names.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"
#include "cbbg/store/results_writer.h"
#include "cbbg/store/run_directory.h"
#include "cbbg/store/seed_figures.h"
#include "cbbg/store/task_store.h"
#include "cbbg/store/weights_file.h"

namespace cbbg::app {
namespace {

// Applies the file, the overrides and the run flags, in that order.
// What a sweep runs with unless its config file or a --set says otherwise: no per-tick logs,
// whose steps.csv would be most of a sweep's bytes and of its merge's work.
constexpr const char* kSweepDefault = "log.decimation=0";

config::Config resolve(const RunOptions& options, bool sweep = false) {
  config::Config config;
  if (sweep) config.set(kSweepDefault, "a sweep's default");
  if (!options.config_file.empty()) config.merge_file(options.config_file);
  for (const auto& assignment : options.sets) config.set(assignment);
  if (options.experiment) {
    const std::string flag = "--experiment " + *options.experiment;
    if (options.experiment->empty()) {
      throw config::ConfigError("--experiment needs a name: a protocol or a diagram (cbbg list)");
    }
    config.set("experiment=" + *options.experiment, flag);
    try {
      experiments::check_experiment_name(*options.experiment);
    } catch (const config::ConfigError& error) {
      throw config::ConfigError(flag + ": " + error.what());
    }
  }
  if (options.seeds) config.set("seeds=" + *options.seeds, "--seeds " + *options.seeds);
  if (options.seed) config.set("seed=" + *options.seed, "--seed " + *options.seed);
  return config;
}

// Per trial, over the seeds: k1, mean temperature and entropy, and the runs that balanced.
void print_trials_summary(const experiments::ExperimentResults& results) {
  const auto& first_run = results.runs.front();
  std::printf("%-6s %6s %12s %12s %10s\n", "trial", "k1", "mean T", "mean E", "balanced");
  for (std::size_t t = 0; t < first_run.trials.size(); ++t) {
    double temperature = 0.0;
    double entropy = 0.0;
    int balanced = 0;
    for (const auto& run : results.runs) {
      temperature += run.trials[t].outcome.mean_temperature;
      entropy += run.trials[t].outcome.mean_entropy;
      balanced += run.trials[t].outcome.status == experiments::TrialStatus::kSuccess ? 1 : 0;
    }
    const double n = static_cast<double>(results.runs.size());
    std::printf("%-6d %6g %12.4f %12.4f %6d/%zu\n", first_run.trials[t].trial,
                first_run.trials[t].k1, temperature / n, entropy / n, balanced,
                results.runs.size());
  }
}

// The width of the tables' arm column: 14, or the longest arm name.
int arm_width(const experiments::ExperimentResults& results) {
  std::size_t width = 14;
  for (const std::string& arm : results.arms) width = std::max(width, arm.size());
  return static_cast<int>(width);
}

// A figure the schema shows on the console: per arm, the seeds with a value, their median and
// range.
void print_reached(const experiments::ExperimentResults& results,
                   const experiments::Figure& figure) {
  const int width = arm_width(results);
  std::printf("%-*s %8s %10s %8s %s\n", width, "arm", "seeds", "reached", "median", "range");
  for (std::size_t a = 0; a < results.arms.size(); ++a) {
    const std::vector<double> values =
        store::ranked(store::seed_values(results, a, figure), experiments::Missing::kNotCounted);
    if (values.empty()) {
      std::printf("%-*s %8zu %10d %8s (%s: no seed has it)\n", width, results.arms[a].c_str(),
                  results.seeds.size(), 0, "-", figure.name.c_str());
      continue;
    }
    std::printf("%-*s %8zu %10zu %8.1f [%g, %g]  (%s)\n", width, results.arms[a].c_str(),
                results.seeds.size(), values.size(), store::middle(values), values.front(),
                values.back(), figure.console.c_str());
  }
}

// Per arm, the median and range over seeds of the schema's headline figure; the seeds that
// succeeded beside the failures before the first success.
void print_headline_summary(const experiments::ExperimentResults& results) {
  const bool failures = results.schema.headline.empty();
  const experiments::Figure& headline =
      *store::find_figure(results, results.schema.headline_name());
  const int width = arm_width(results);
  std::printf("%-*s %8s %10s %8s %s\n", width, "arm", "seeds", failures ? "succeeded" : "",
              "median", "range");
  for (std::size_t a = 0; a < results.arms.size(); ++a) {
    int succeeded = 0;
    for (std::size_t s = 0; s < results.seeds.size(); ++s) {
      succeeded += results.run(a, s).succeeded ? 1 : 0;
    }
    const std::vector<double> values =
        store::ranked(store::seed_values(results, a, headline), headline.missing);
    const std::string what = failures ? "failures before the first success" : headline.name;
    std::printf("%-*s %8zu %10s %8.1f [%g, %g]  (%s)\n", width, results.arms[a].c_str(),
                results.seeds.size(), failures ? std::to_string(succeeded).c_str() : "",
                store::middle(values), values.empty() ? NAN : values.front(),
                values.empty() ? NAN : values.back(), what.c_str());
  }
}

// The figures the schema sums, each over the seeds, an arm a column.
void print_figures_summary(const experiments::ExperimentResults& results) {
  std::vector<const experiments::Figure*> summed;
  std::size_t width = 6;
  for (const auto& figure : results.schema.figures) {
    if (figure.summary != experiments::FigureSummary::kSum) continue;
    summed.push_back(&figure);
    width = std::max(width, figure.name.size());
  }
  if (summed.empty()) return;
  std::printf("\n%-*s", static_cast<int>(width), "figure");
  for (const auto& arm : results.arms) std::printf(" %10s", arm.c_str());
  std::printf("  (sums over %zu seeds)\n", results.seeds.size());
  for (const experiments::Figure* figure : summed) {
    std::printf("%-*s", static_cast<int>(width), figure->name.c_str());
    for (std::size_t a = 0; a < results.arms.size(); ++a) {
      double total = 0.0;
      for (const auto& value : store::seed_values(results, a, *figure)) total += value.value_or(0);
      std::printf(" %10g", total);
    }
    std::printf("\n");
  }
}

void print_summary(const experiments::ExperimentResults& results) {
  if (results.schema.console == experiments::ConsoleTable::kTrials) {
    print_trials_summary(results);
    return;
  }
  print_headline_summary(results);
  for (const auto& figure : results.schema.figures) {
    if (!figure.console.empty()) print_reached(results, figure);
  }
  print_figures_summary(results);
}

// Learning runs of the experiment: every (arm, seed) of an arm with basal ganglia, under a
// protocol that learns.
long long learning_runs(const parameters::RunParams& run, const std::vector<std::string>& arms) {
  const experiments::Protocol* protocol = experiments::find_protocol(run.experiment);
  if (protocol != nullptr && !protocol->learns) return 0;
  const auto learning = std::count_if(arms.begin(), arms.end(), [](const std::string& arm) {
    return static_cast<bool>(diagrams::named_arm(arm).policy);
  });
  return learning * run.seeds;
}

// Learning starts from the file's weights in every arm that learns: each must have the
// layout they were made for.
void check_initial_weights(const experiments::LearntWeights& weights,
                           const parameters::Parameters& parameters,
                           const std::vector<std::string>& arms,
                           const std::filesystem::path& file) {
  for (const std::string& name : arms) {
    const diagrams::ClosedLoop loop = diagrams::named_arm(name).learner(parameters);
    if (loop.learner.learns()) {
      experiments::check_weights(weights, parameters.plant.kind, loop, file);
    }
  }
}

// What a run needs before it starts: everything checked, the work directory made.
struct PreparedRun {
  config::Config config;  // what the results directory records
  parameters::Parameters parameters;
  std::vector<std::string> arms;  // the arms the experiment runs
  std::optional<store::RunDirectory> directory;
  std::optional<experiments::LearntWeights> initial_weights;
};

void check_resume_alone(const RunOptions& options) {
  if (!options.config_file.empty() || !options.sets.empty() || options.experiment ||
      options.seeds || options.seed || !options.load_weights.empty() || options.replace ||
      !options.figures || !options.replays || !options.grid.empty() || options.shard ||
      options.check) {
    throw config::ConfigError(
        "--resume continues with the config, weights and options of the interrupted run; drop "
        "--config, --set, --experiment, --seeds, --seed, --load-weights, --replace, "
        "--no-figures, --no-replay, --grid, --shard and --check (a sweep continues by running "
        "its command again)");
  }
}

PreparedRun prepare(const RunOptions& options) {
  PreparedRun run;
  if (options.resume) {
    check_resume_alone(options);
    run.directory = store::RunDirectory::resume(*options.resume);
    run.config = run.directory->config();
    if (run.directory->published()) return run;
  } else {
    run.config = resolve(options);
  }
  run.parameters = checked_parameters(run.config);
  run.arms = experiments::experiment_arms(run.parameters.run);
  check_arms_and_memory(run.parameters, run.arms.size(), options.jobs);
  if (!options.save_weights.empty()) {
    const long long learning = learning_runs(run.parameters.run, run.arms);
    if (learning == 0) {
      throw config::ConfigError("--save-weights keeps the weights a run learns; --experiment " +
                                run.parameters.run.experiment +
                                " learns none (the weights it uses are those of --load-weights)");
    }
    if (learning != 1) {
      throw config::ConfigError(
          "--save-weights keeps the weights of one learning run; this run has " +
          std::to_string(learning) +
          " (use --experiment ARM --seeds 1; every run's weights are in DIR/weights/)");
    }
    check_output_file(options.save_weights, "--save-weights");
    store::check_replaceable_file(options.save_weights, "--save-weights", store::kWeightsFormat);
  }
  if (!options.load_weights.empty()) {
    run.initial_weights = store::load_weights(options.load_weights);
    check_initial_weights(*run.initial_weights, run.parameters, run.arms, options.load_weights);
  }
  if (!options.resume) {  // a resumed run passed it when it started
    experiments::check_protocol(run.parameters,
                                run.initial_weights ? &*run.initial_weights : nullptr);
  }
  if (options.check) return run;
  if (!run.directory) {
    run.directory = store::RunDirectory::create(
        options.out, run.config,
        {.figures = options.figures, .replays = options.replays, .replace = options.replace});
    if (run.initial_weights) {
      store::save_weights(run.directory->initial_weights(), *run.initial_weights);
    }
  } else if (std::filesystem::exists(run.directory->initial_weights())) {
    run.initial_weights = store::load_weights(run.directory->initial_weights());
  }
  return run;
}

// --save-weights: the one learning run's weights. Throws std::runtime_error when it has none
// (they stopped being finite), so no file is claimed that was not written.
void save_learnt_weights(const experiments::ExperimentResults& results,
                         const std::filesystem::path& file) {
  for (const auto& seed : results.runs) {
    if (!seed.weights) continue;
    store::save_weights(file, *seed.weights);
    spdlog::info("weights in {}", file.string());
    return;
  }
  throw std::runtime_error(
      "--save-weights: the run learnt no finite weights (see "
      "weights_diverged in summary.json); nothing was written to " +
      store::quoted_path(file));
}

void execute(const RunOptions& options, PreparedRun& run) {
  const config::Config& config = run.config;
  const parameters::RunParams& what = run.parameters.run;
  store::RunDirectory& directory = *run.directory;
  const std::size_t arms = run.arms.size();
  const std::size_t tasks = arms * static_cast<std::size_t>(what.seeds);
  spdlog::info("{}: {} seed(s) x {} arm(s) on the {} plant, {} thread(s){}", what.experiment,
               what.seeds, arms, run.parameters.plant.kind, options.jobs,
               options.resume ? ", resumed" : "");
  const store::TaskStore store(directory.tasks());
  Progress progress(tasks, ::isatty(STDERR_FILENO) == 1);
  experiments::ExperimentOptions experiment;
  experiment.jobs = options.jobs;
  experiment.progress = [&progress](const experiments::SeedRun& seed) { progress.finished(seed); };
  experiment.store = &store;
  if (run.initial_weights) experiment.initial_weights = &*run.initial_weights;
  const experiments::ExperimentResults results =
      experiments::run_experiment(run.parameters, experiment);
  progress.close();
  store::write_result_files(results, config, store::run_facts(run.parameters), directory.work(),
                            &store);
  if (directory.shape().figures) {
    draw_figures(directory.work(), run.parameters,
                 {.quiet = true,
                  .replays = directory.shape().replays,
                  .run_name = directory.target().filename().string()});
  }
  directory.commit();
  print_summary(results);
  if (!options.save_weights.empty()) save_learnt_weights(results, options.save_weights);
  spdlog::info("results in {}", directory.target().string());
}

// After a failed run, what to do next: --resume, unless the last try failed the same way.
std::string way_forward(const store::RunDirectory& directory, const std::exception& error) {
  std::error_code ignored;
  if (!std::filesystem::exists(directory.work(), ignored)) return "";
  if (dynamic_cast<const store::EarlierTaskRecord*>(&error) != nullptr) return "";
  const std::string work = store::quoted_path(directory.work());
  if (directory.record_failure(describe(error))) {
    return "; the run failed the same way when it was resumed before, so --resume will not "
           "finish it: mend what the message names, or remove " +
           work + " to start anew";
  }
  return "; the finished seeds are kept in " + work + ": continue with " + program_name() +
         " run --resume " + directory.target().string();
}

}  // namespace

void check_arms_and_memory(const parameters::Parameters& parameters, std::size_t arms, int jobs) {
  const std::size_t tasks = arms * static_cast<std::size_t>(parameters.run.seeds);
  experiments::check_run_memory(experiments::check_arms_build(parameters),
                                std::min(tasks, static_cast<std::size_t>(jobs)));
}

parameters::Parameters checked_parameters(const config::Config& config) {
  parameters::Parameters parameters = diagrams::validated_parameters(config);
  experiments::check_run_names(parameters.run);
  experiments::check_evaluation_conditions(parameters);
  return parameters;
}

int run_command(const RunOptions& options) {
  if (!options.resume) {
    config::Sweep sweep;
    config::Config base;
    try {
      if (!options.config_file.empty()) {
        base = resolve(options);  // checks the file before its sweep: section is read
        checked_parameters(base);
        sweep.add_file(options.config_file);
      }
      for (const std::string& axis : options.grid) sweep.add_flag(axis);
      if (!sweep.empty() || options.shard) {
        return sweep_command(options, resolve(options, true), sweep);
      }
    } catch (const config::ConfigError& error) {
      return report_error(kUserError, error.what());
    }
  }
  PreparedRun run;
  try {
    run = prepare(options);
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  if (options.check) {
    std::cout << "the run checks out; nothing was written\n";
    return 0;
  }
  try {
    if (run.directory->published()) {
      run.directory->commit();
      spdlog::info("results in {} (the interrupted commit is finished)",
                   run.directory->target().string());
      return 0;
    }
    execute(options, run);
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error) + way_forward(*run.directory, error));
  }
  return 0;
}

}  // namespace cbbg::app
