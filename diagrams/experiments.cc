#include "diagrams/experiments.h"

#include "diagrams/policy_evaluation.h"
#include "diagrams/task_store.h"

#include <atomic>
#include <charconv>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

namespace cbbg::diagrams {
namespace {

// k1 of `trial` under the annealing schedule (steps sorted by from_trial, the first at 1).
double annealed_k1(const std::vector<config::AnnealingStep>& schedule, int trial) {
  double k1 = schedule.front().k1;
  for (const auto& step : schedule) {
    if (step.from_trial <= trial) k1 = step.k1;
  }
  return k1;
}

// The policy learnt so far alone (no exploration, no supervisor, frozen) from each
// evaluation angle, as `cbbg eval` runs it with this run's seed.
void evaluate_learnt_actor(config::Config config, SeedRun& run) {
  config.set("seed=" + std::to_string(run.seed));
  EvaluationSettings settings;
  settings.angles = config.numbers("evaluation.angles");
  const PolicyEvaluation evaluation = evaluate_policy(config, *run.weights, settings);
  for (const AngleEvaluation& angle : evaluation.angles) {
    run.evaluation.push_back({angle.theta0, angle.runs.front()});
  }
}

WeightsProvenance provenance(const config::Config& config, const SeedRun& run) {
  return {run.arm, run.seed, static_cast<long long>(run.trials.size()), config.text("plant.kind")};
}

void run_until_success(const config::Config& config, const TelemetryOptions& telemetry,
                       const LearntWeights* initial_weights, SeedRun& run) {
  const ControllerDiagram controller = build_controller_diagram(run.arm, config);
  const double period = config.number("trial.period");
  TrialRunner runner(controller, static_cast<std::uint64_t>(run.seed), period, telemetry);
  if (initial_weights != nullptr && controller.learns()) {
    load_learnt_weights(controller, runner.context(), *initial_weights);
  }
  const long long max_trials = config.integer("max_trials");
  const double k1 = config.number("tropism.k1");
  for (int trial = 1; trial <= max_trials; ++trial) {
    const TrialRecord record{
        trial, k1,
        runner.run_trial(config.number("trial.theta0"), config.number("trial.duration"), trial)};
    run.trials.push_back(record);
    if (record.outcome.status == TrialStatus::kSuccess) {
      run.succeeded = true;
      break;
    }
    ++run.failures_before_success;
  }
  if (controller.learns()) {
    run.weights = learnt_weights(controller, runner.context(), config, provenance(config, run));
    evaluate_learnt_actor(config, run);
  }
}

// exp2: trial 1 coordinated by the cerebellum, then operant learning alone with annealing.
void run_annealing(const config::Config& config, const TelemetryOptions& telemetry,
                   const LearntWeights* initial_weights, SeedRun& run) {
  const double period = config.number("trial.period");
  const double theta0 = config.number("trial.theta0");
  const double duration = config.number("trial.duration");
  const auto& schedule = config.annealing("annealing");
  const ControllerDiagram coordinated = build_controller_diagram("cbbg", config);
  const ControllerDiagram operant = build_controller_diagram("bg_only", config);
  TrialRunner first(coordinated, static_cast<std::uint64_t>(run.seed), period, telemetry);
  if (initial_weights != nullptr) {
    load_learnt_weights(coordinated, first.context(), *initial_weights);
  }
  coordinated.tropism->set_k1(first.context(), annealed_k1(schedule, 1));
  run.trials.push_back({1, annealed_k1(schedule, 1), first.run_trial(theta0, duration, 1)});

  // Same seed, other diagram: the block paths differ, so the random streams do too.
  TrialRunner later(operant, static_cast<std::uint64_t>(run.seed), period, telemetry);
  operant.critic->mutable_weights(later.context()) = coordinated.critic->weights(first.context());
  operant.actor->mutable_weights(later.context()) = coordinated.actor->weights(first.context());
  for (int trial = 2; trial <= config.integer("exp2.trials"); ++trial) {
    const double k1 = annealed_k1(schedule, trial);
    operant.tropism->set_k1(later.context(), k1);
    run.trials.push_back({trial, k1, later.run_trial(theta0, duration, trial)});
  }
  for (const auto& trial : run.trials) {
    if (trial.outcome.status == TrialStatus::kSuccess && !run.succeeded) {
      run.succeeded = true;
      run.failures_before_success = trial.trial - 1;
    }
  }
  if (!run.succeeded) run.failures_before_success = static_cast<int>(run.trials.size());
  run.weights = learnt_weights(operant, later.context(), config, provenance(config, run));
}

// Runs one (arm, seed) task, its steps rows into the store's file or into run.steps_csv.
void run_task(const config::Config& config, std::size_t task, const ExperimentOptions& options,
              SeedRun& run) {
  const TaskStore* store = options.store;
  std::ofstream file;
  std::ostringstream memory;
  TelemetryOptions telemetry{.keep_in_memory = false,
                             .steps = nullptr,
                             .decimation = config.integer("log.decimation"),
                             .row_prefix = run.arm + "," + std::to_string(run.seed) + ","};
  if (telemetry.decimation > 0) {
    if (store != nullptr) {
      file.open(store->pending_steps_path(task), std::ios::binary | std::ios::trunc);
      telemetry.steps = &file;
    } else {
      telemetry.steps = &memory;
    }
  }
  if (config.text("experiment") == "exp2") {
    run_annealing(config, telemetry, options.initial_weights, run);
  } else {
    run_until_success(config, telemetry, options.initial_weights, run);
  }
  if (store == nullptr) {
    run.steps_csv = memory.str();
    return;
  }
  file.close();
  if (!file)
    throw std::runtime_error("cannot write '" + store->pending_steps_path(task).string() + "'");
  store->save(task, run);
}

}  // namespace

std::vector<std::string> experiment_arms(const config::Config& config) {
  const std::string& experiment = config.text("experiment");
  if (experiment == "exp1") return config.names("arms");
  if (experiment == "exp2") return {"cbbg"};
  return {experiment};
}

ExperimentResults run_experiment(const config::Config& config, const ExperimentOptions& options) {
  ExperimentResults results;
  results.experiment = config.text("experiment");
  results.arms = experiment_arms(config);
  for (long long k = 0; k < config.integer("seeds"); ++k) {
    results.seeds.push_back(config.integer("seed") + k);
  }
  for (const auto& arm : results.arms) {
    for (const long long seed : results.seeds) {
      SeedRun run;
      run.arm = arm;
      run.seed = seed;
      results.runs.push_back(std::move(run));
    }
  }

  // Workers take tasks in index order; each writes only its own slot.
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&]() {
    for (std::size_t task = next++; task < results.runs.size(); task = next++) {
      try {
        SeedRun& run = results.runs[task];
        if (options.store == nullptr || !options.store->load(task, run)) {
          run_task(config, task, options, run);
        }
        if (options.progress) options.progress(run);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = results.runs.size();  // stop handing out tasks
      }
    }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < std::max(options.jobs, 1); ++j) workers.emplace_back(work);
  work();
  for (auto& worker : workers) worker.join();
  if (failure) std::rethrow_exception(failure);
  return results;
}

}  // namespace cbbg::diagrams
