// CPU time per trial tick of the cbbg diagram on the analytic plant, run by the TrialRunner
// on either of the simulator's schedules, against docs/model.md §2 as one plain loop
// (tests/diagrams/plain_loop.h) that tests/diagrams proves bit-identical to it. Each iteration is
// the first trial of a fresh learner from the default theta0 and root seed 1, so both sides do
// exactly the same arithmetic and tick count; building the learner is left out of the timing.

#include <benchmark/benchmark.h>

#include <ostream>  // before bench/ratio_reporter.h, which streams without including it
#include <string>

#include "bench/ratio_reporter.h"
#include "cbbg/config/config.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/trial_runner.h"
#include "tests/diagrams/plain_loop.h"

namespace cbbg::bench {
namespace {

constexpr std::uint64_t kSeed = 1;

config::Config analytic_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  return config;
}

// Reports the trial's ticks and the CPU time per tick.
void count_ticks(benchmark::State& state, long long ticks) {
  state.counters["ticks"] = static_cast<double>(ticks);
  state.counters["cpu_per_tick"] =
      benchmark::Counter(static_cast<double>(ticks), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

void run_diagram_trial(benchmark::State& state, Schedule schedule) {
  const parameters::Parameters parameters = parameters::read_parameters(analytic_config());
  diagrams::ClosedLoop controller = diagrams::build_preset("cbbg", parameters);
  controller.schedule = schedule;
  const double theta0 = parameters.trial.theta0;
  const double duration = parameters.trial.duration;
  long long ticks = 0;
  for (auto _ : state) {
    state.PauseTiming();
    experiments::TrialRunner runner(controller, kSeed, parameters.trial.period);
    state.ResumeTiming();
    const experiments::TrialOutcome outcome = runner.run_trial(theta0, duration);
    ticks = outcome.steps;
    benchmark::DoNotOptimize(outcome.final_theta);
  }
  count_ticks(state, ticks);
}

void BM_DiagramTrial(benchmark::State& state) { run_diagram_trial(state, Schedule::kCompiled); }
// The schedule before the compiled one, measured in the same run.
void BM_DiagramTrialInterpreted(benchmark::State& state) {
  run_diagram_trial(state, Schedule::kInterpreted);
}

void BM_PlainLoopTrial(benchmark::State& state) {
  const config::Config config = analytic_config();
  const double theta0 = config.number("trial.theta0");
  const double duration = config.number("trial.duration");
  long long ticks = 0;
  for (auto _ : state) {
    state.PauseTiming();
    tests::PlainLoop loop(config, kSeed, "cbbg");
    state.ResumeTiming();
    const tests::PlainLoopOutcome outcome = loop.run_trial(theta0, duration);
    ticks = outcome.steps;
    benchmark::DoNotOptimize(outcome.final_theta);
  }
  count_ticks(state, ticks);
}

BENCHMARK(BM_DiagramTrial)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiagramTrialInterpreted)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlainLoopTrial)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cbbg::bench

int main(int argc, char** argv) {
  return cbbg::bench::run_benchmarks_with_ratios(argc, argv, [](const std::string& name) {
    return name.rfind("BM_DiagramTrial", 0) == 0 ? std::string("BM_PlainLoopTrial") : std::string();
  });
}
