// cbbg run --grid / --shard, cbbg merge and cbbg status: a sweep split into tasks (grid
// point, arm, seed), run by any engine as shards into one shared work directory, and merged
// into one results directory. A single-process sweep is shard 1 of 1 followed by the merge,
// so its results are the same bytes as any sharded run of the same sweep.

#include <iostream>
#include <optional>
#include <tuple>

#include <spdlog/spdlog.h>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/errors.h"
#include "cbbg/apps/figures.h"
#include "cbbg/config/sweep.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/store/files.h"
#include "cbbg/store/results_writer.h"
#include "cbbg/store/run_directory.h"
#include "cbbg/store/sweep_directory.h"
#include "cbbg/store/sweep_results.h"
#include "cbbg/store/task_store.h"

namespace cbbg::app {
namespace {

// The sweep's grid points, each a full config, and where each point's tasks start in the
// sweep's numbering (point-major, then arm, then seed).
struct SweepPlan {
  config::Config base;
  config::Sweep sweep;
  std::vector<config::Config> points;
  std::vector<parameters::Parameters> parameters;  // each point's, checked
  std::vector<std::size_t> first_task;
  std::size_t tasks = 0;
};

std::size_t point_tasks(const parameters::RunParams& point) {
  return experiments::experiment_arms(point).size() * static_cast<std::size_t>(point.seeds);
}

// Checks every grid point's config before anything runs; with `jobs` (a shard about to
// run), builds each point's arms once and checks `jobs` tasks at once fit in memory.
SweepPlan plan(config::Config base, config::Sweep sweep, std::optional<int> jobs = {}) {
  SweepPlan result{std::move(base), std::move(sweep), {}, {}, {}, 0};
  result.sweep.check(result.base);
  for (std::size_t p = 0; p < result.sweep.points(); ++p) {
    result.points.push_back(result.sweep.config(result.base, p));
    try {
      result.parameters.push_back(checked_parameters(result.points.back()));
      experiments::check_protocol(result.parameters.back(), nullptr);  // sweeps start from zero
      if (jobs) {
        const parameters::Parameters& point = result.parameters.back();
        check_arms_and_memory(point, experiments::experiment_arms(point.run).size(), *jobs);
      }
    } catch (const config::ConfigError& error) {
      throw config::ConfigError("grid point " + store::point_name(p, result.sweep.points()) + ": " +
                                error.what());
    }
    result.first_task.push_back(result.tasks);
    result.tasks += point_tasks(result.parameters.back().run);
  }
  return result;
}

std::string sweep_yaml(const SweepPlan& plan) { return plan.base.to_yaml() + plan.sweep.to_yaml(); }

SweepPlan plan_of(const store::SweepDirectory& directory) {
  const std::string yaml = directory.config_yaml();
  const std::string source = (directory.work() / "config.yaml").string();
  config::Config base;
  base.merge_yaml(yaml, source);
  config::Sweep sweep;
  sweep.add_yaml(yaml, source);
  return plan(std::move(base), std::move(sweep));
}

// "K/N" with 1 <= K <= N <= 100000.
std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  int k = 0;
  int n = 0;
  std::size_t used_k = 0;
  std::size_t used_n = 0;
  try {
    if (slash != std::string::npos) {
      k = std::stoi(text.substr(0, slash), &used_k);
      n = std::stoi(text.substr(slash + 1), &used_n);
    }
  } catch (const std::exception&) {
    k = 0;
  }
  if (slash == std::string::npos || used_k != slash || used_n != text.size() - slash - 1 || k < 1 ||
      n < k || n > 100000) {
    throw config::ConfigError("--shard must be K/N with 1 <= K <= N <= 100000; got '" + text + "'");
  }
  return {k, n};
}

// Runs shard k of n: the tasks whose sweep number is k - 1 modulo n.
void run_shard(const SweepPlan& plan, const store::SweepDirectory& directory, int k, int n,
               int jobs) {
  for (std::size_t p = 0; p < plan.points.size(); ++p) {
    const store::TaskStore store(directory.tasks(p, plan.points.size()));
    experiments::ExperimentOptions options;
    options.jobs = jobs;
    options.store = &store;
    const std::size_t first = plan.first_task[p];
    options.runs_task = [first, k, n](std::size_t task) {
      return (first + task) % static_cast<std::size_t>(n) == static_cast<std::size_t>(k - 1);
    };
    experiments::run_experiment(plan.parameters[p], options);
  }
}

// The tasks without a record, as "point 002 (actor.alpha=0.2) bg_only seed 4".
std::vector<std::string> missing_tasks(const SweepPlan& plan,
                                       const store::SweepDirectory& directory) {
  std::vector<std::string> missing;
  for (std::size_t p = 0; p < plan.points.size(); ++p) {
    const store::TaskStore store(directory.tasks(p, plan.points.size()));
    const parameters::RunParams& point = plan.parameters[p].run;
    const auto arms = experiments::experiment_arms(point);
    const auto seeds = static_cast<std::size_t>(point.seeds);
    for (std::size_t t = 0; t < arms.size() * seeds; ++t) {
      if (store.has(t)) continue;
      std::string name = "point " + store::point_name(p, plan.points.size()) + " (";
      const auto values = plan.sweep.values(p);
      for (std::size_t a = 0; a < values.size(); ++a) {
        name += (a == 0 ? "" : ", ") + plan.sweep.axes()[a].key + "=" + values[a];
      }
      name += ") " + arms[t / seeds] + " seed " +
              std::to_string(point.seed + static_cast<long long>(t % seeds));
      missing.push_back(name);
    }
  }
  return missing;
}

// Writes every point's results and sweep.csv from the tasks, then commits.
void merge(const SweepPlan& plan, store::SweepDirectory& directory) {
  if (!directory.published()) {
    const std::vector<std::string> missing = missing_tasks(plan, directory);
    if (!missing.empty()) {
      std::string list;
      for (std::size_t i = 0; i < missing.size() && i < 5; ++i) {
        list += (i == 0 ? "" : "; ") + missing[i];
      }
      throw std::runtime_error(std::to_string(missing.size()) + " of " +
                               std::to_string(plan.tasks) + " tasks are missing (" + list +
                               (missing.size() > 5 ? "; ..." : "") +
                               "); run their shards again, then merge");
    }
    std::vector<experiments::ExperimentResults> results;
    for (std::size_t p = 0; p < plan.points.size(); ++p) {
      const store::TaskStore store(directory.tasks(p, plan.points.size()));
      experiments::ExperimentOptions options;
      options.store = &store;  // every task is there: loaded, none run
      results.push_back(experiments::run_experiment(plan.parameters[p], options));
      const std::filesystem::path out = directory.point_results(p, plan.points.size());
      std::filesystem::create_directories(out);
      store::write_result_files(results.back(), plan.points[p],
                                store::run_facts(plan.parameters[p]), out, &store);
    }
    store::write_atomically(directory.work() / "sweep.csv", store::sweep_csv(plan.sweep, results));
    if (directory.figures() && run_plot_script(directory.work(), /*quiet=*/true) != 0) {
      spdlog::warn("the sweep's figures could not be drawn (see the message above)");
    }
  }
  directory.commit();
}

// What `cbbg status` says of a sweep's per-tick logs.
std::string per_tick_logs(long long decimation) {
  if (decimation == 0) return "off (log.decimation 0, a sweep's default)";
  if (decimation == 1) return "steps.csv, every tick (log.decimation 1)";
  std::string text = "steps.csv, every ";
  text += std::to_string(decimation);
  text += "th tick (log.decimation)";
  return text;
}

}  // namespace

int sweep_command(const RunOptions& options, const config::Config& base,
                  const config::Sweep& sweep) {
  SweepPlan sweep_plan;
  int k = 1;
  int n = 1;
  std::optional<store::SweepDirectory> directory;
  try {
    if (options.resume || !options.load_weights.empty() || !options.save_weights.empty() ||
        options.replace) {
      throw config::ConfigError(
          "a sweep (--grid, --shard or a config's sweep:) takes no --resume, --load-weights, "
          "--save-weights or --replace; run the same command again to continue it");
    }
    if (options.shard) std::tie(k, n) = parse_shard(*options.shard);
    sweep_plan = plan(base, sweep, options.jobs);
    if (options.check) {
      std::cout << "the sweep checks out (" << sweep_plan.points.size() << " grid point(s), "
                << sweep_plan.tasks << " task(s)); nothing was written\n";
      return 0;
    }
    directory.emplace(store::SweepDirectory::open_shard(options.out, sweep_yaml(sweep_plan),
                                                        options.figures, k, n));
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  try {
    spdlog::info("sweep: {} grid point(s), {} task(s); shard {}/{}, {} thread(s)",
                 sweep_plan.points.size(), sweep_plan.tasks, k, n, options.jobs);
    directory->clear_failure();
    run_shard(sweep_plan, *directory, k, n, options.jobs);
  } catch (const std::exception& error) {
    directory->record_failure(describe(error));
    return report_error(kMachineError, describe(error) + "; the finished tasks are kept in " +
                                           store::quoted_path(directory->work()) +
                                           ": run the same command again to continue");
  }
  if (options.shard) {
    spdlog::info("shard {}/{} done; when every shard is, run: {} merge {}", k, n, program_name(),
                 options.out.string());
    return 0;
  }
  directory.reset();  // the shard's lock, before the merge takes the directory's
  try {
    store::SweepDirectory merging = store::SweepDirectory::open_existing(options.out, true);
    merge(sweep_plan, merging);
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  spdlog::info("results in {}", options.out.string());
  return 0;
}

int merge_command(const std::filesystem::path& target) {
  try {
    store::SweepDirectory directory = store::SweepDirectory::open_existing(target, true);
    if (directory.published()) {
      directory.commit();
      spdlog::info("results in {} (the interrupted merge is finished)", target.string());
      return 0;
    }
    const SweepPlan sweep_plan = plan_of(directory);
    merge(sweep_plan, directory);
    spdlog::info("merged {} task(s) of {} grid point(s) into {}", sweep_plan.tasks,
                 sweep_plan.points.size(), target.string());
    return 0;
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
}

// cbbg status of a run (not a sweep): how far it got, and what continues it.
void print_run_status(const std::filesystem::path& target, const store::RunState& state) {
  const std::string name = target.string();
  using Phase = store::RunState::Phase;
  if (state.phase == Phase::kFinished || state.phase == Phase::kPublished) {
    std::cout << name << ": finished results of " << program_name() << " run"
              << (state.phase == Phase::kPublished
                      ? " (the commit's cleanup is unfinished: " + program_name() +
                            " run --resume " + name + " finishes it)"
                      : "")
              << "\n";
    return;
  }
  const parameters::Parameters parameters = checked_parameters(state.config);
  const std::size_t tasks = point_tasks(parameters.run);
  std::cout << name << ": " << (state.phase == Phase::kRunning ? "running" : "interrupted") << ", "
            << store::finished_tasks(state.tasks, tasks) << " of " << tasks << " task(s) done"
            << (state.phase == Phase::kInterrupted
                    ? "; continue it with " + program_name() + " run --resume " + name
                    : "")
            << "\n";
}

int status_command(const std::filesystem::path& target) {
  try {
    if (const auto run = store::RunDirectory::inspect(target)) {
      print_run_status(target, *run);
      return 0;
    }
    std::filesystem::path work = target;
    work += ".partial";
    std::error_code error;
    if (std::filesystem::exists(target / store::kResultsMarker, error) &&
        std::filesystem::exists(target / "sweep.csv", error) &&
        !std::filesystem::exists(work, error)) {
      std::cout << target.string() << ": merged\n";
      return 0;
    }
    const store::SweepDirectory directory = store::SweepDirectory::open_existing(target, false);
    if (directory.published()) {
      std::cout << target.string()
                << ": merged (the merge's cleanup is unfinished: " << program_name() << " merge "
                << target.string() << " finishes it)\n";
      return 0;
    }
    const SweepPlan sweep_plan = plan_of(directory);
    const std::vector<std::string> missing = missing_tasks(sweep_plan, directory);
    std::cout << target.string() << ": " << sweep_plan.points.size() << " grid point(s), "
              << sweep_plan.tasks << " task(s): " << sweep_plan.tasks - missing.size() << " done, "
              << missing.size() << " missing\n";
    for (std::size_t i = 0; i < missing.size() && i < 10; ++i) {
      std::cout << "  missing: " << missing[i] << "\n";
    }
    if (missing.size() > 10) std::cout << "  ... and " << missing.size() - 10 << " more\n";
    for (const auto& [shard, message] : directory.failures()) {
      std::cout << "  failed: shard " << shard << ": " << message << "\n";
    }
    std::cout << "  per-tick logs: " << per_tick_logs(sweep_plan.base.integer("log.decimation"))
              << "\n";
    return 0;
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
}

}  // namespace cbbg::app
