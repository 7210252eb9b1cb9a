#include "cbbg/experiments/parallel_runs.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "cbbg/framework/interrupt.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {
namespace {

// Runs one task, its steps rows (after their header line) into the store's file or into
// run.steps_csv.
void run_task(const parameters::Parameters& parameters, std::size_t task, const TaskBody& body,
              const TaskStorage* store, SeedRun& run) {
  std::ofstream file;
  std::ostringstream memory;
  bool header_pending = true;
  TelemetryOptions telemetry{.keep_in_memory = false,
                             .steps = nullptr,
                             .decimation = parameters.log.decimation,
                             .row_prefix = run.arm + "," + std::to_string(run.seed) + ",",
                             .settle_time = parameters.trial.settle_time,
                             .steps_header_pending = &header_pending};
  if (telemetry.decimation > 0) {
    if (store != nullptr) {
      file.open(store->pending_steps_path(task), std::ios::binary | std::ios::trunc);
      telemetry.steps = &file;
    } else {
      telemetry.steps = &memory;
    }
  }
  body(run, telemetry);
  if (store == nullptr) {
    run.steps_csv = memory.str();
    return;
  }
  if (telemetry.steps != nullptr) {
    file.close();
    if (!file) {
      throw std::runtime_error("cannot write '" + store->pending_steps_path(task).string() +
                               "': " + std::strerror(errno));
    }
  }
  store->save(task, run);
}

ExperimentResults empty_results(const parameters::RunParams& what,
                                const std::vector<std::string>& arms) {
  ExperimentResults results;
  results.experiment = what.experiment;
  results.arms = arms;
  for (long long k = 0; k < what.seeds; ++k) results.seeds.push_back(what.seed + k);
  for (const auto& arm : results.arms) {
    for (const long long seed : results.seeds) {
      SeedRun run;
      run.arm = arm;
      run.seed = seed;
      results.runs.push_back(std::move(run));
    }
  }
  return results;
}

}  // namespace

ExperimentResults run_tasks(const parameters::Parameters& parameters,
                            const std::vector<std::string>& arms, const TaskBody& body,
                            const ExperimentOptions& options) {
  ExperimentResults results = empty_results(parameters.run, arms);
  // Workers take tasks in index order; each writes only its own slot.
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto fail = [&]() {  // in a catch block
    const std::lock_guard<std::mutex> lock(failure_mutex);
    if (!failure) failure = std::current_exception();
    next = results.runs.size();  // stop handing out tasks
  };
  // An interrupt (Ctrl-C in Python, framework/interrupt.h) in one thread stops the others'
  // simulations at their next instant, not only their next tasks.
  InterruptGroup interrupts;
  auto work = [&]() {
    const InterruptGroup::Membership member(interrupts);
    for (std::size_t task = next++; task < results.runs.size(); task = next++) {
      if (options.runs_task && !options.runs_task(task)) continue;
      try {
        SeedRun& run = results.runs[task];
        if (options.store == nullptr || !options.store->load(task, run)) {
          run_task(parameters, task, body, options.store, run);
        }
        if (options.progress) options.progress(run);
      } catch (...) {
        fail();
      }
    }
  };
  std::mutex done_mutex;
  std::condition_variable done;
  int running = std::max(options.jobs, 1) - 1;
  std::vector<std::thread> workers;
  for (int j = 1; j < std::max(options.jobs, 1); ++j) {
    workers.emplace_back([&]() {
      work();
      const std::lock_guard<std::mutex> lock(done_mutex);
      --running;
      done.notify_one();
    });
  }
  work();
  {
    // Its own tasks done, this thread checks for interrupts while the workers finish theirs.
    const InterruptGroup::Membership member(interrupts);
    std::unique_lock<std::mutex> lock(done_mutex);
    while (!done.wait_for(lock, std::chrono::milliseconds(10), [&] { return running == 0; })) {
      lock.unlock();
      try {
        check_interrupt();
      } catch (...) {
        fail();
      }
      lock.lock();
    }
  }
  for (auto& worker : workers) worker.join();
  if (failure) std::rethrow_exception(failure);
  return results;
}

}  // namespace cbbg::experiments
