// The protocol realtime: trials against a robot over the link of plant.kind remote, each
// trial's link figures recorded beside it.

#include <spdlog/spdlog.h>

#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/experiments/builtin_protocols.h"
#include "cbbg/experiments/protocol_kit.h"
#include "cbbg/experiments/realtime_params.h"
#include "cbbg/realtime/remote_plant.h"

namespace cbbg::experiments {
namespace {

using realtime::LinkFigures;
using realtime::RemotePlant;

// The link's figures of a trial, as its columns.
std::vector<NamedValue> trial_values(const LinkFigures& figures) {
  return {{"deadline_misses", static_cast<double>(figures.deadline_misses)},
          {"latency_p50", figures.latency_quantile(0.5)},
          {"latency_p99", figures.latency_quantile(0.99)},
          {"latency_max", figures.latency_quantile(1.0)},
          {"lost", static_cast<double>(figures.lost)},
          {"refused", static_cast<double>(figures.refused_total())}};
}

RealtimeParams realtime_params(const parameters::Parameters& p) {
  return config::read_section<RealtimeParams>(p.own, RealtimeParams::kSection);
}

void drive(const parameters::Parameters& p, const diagrams::Arm& arm,
           const TelemetryOptions& telemetry, const LearntWeights* initial_weights, SeedRun& run) {
  const RealtimeParams own = realtime_params(p);
  const bool policy = own.loop == DrivenLoop::kPolicy;
  const diagrams::ClosedLoop loop = policy ? arm.policy(p) : arm.learner(p);
  TrialRunner runner(loop, static_cast<std::uint64_t>(run.seed), p.trial.period, telemetry);
  if (initial_weights != nullptr && (policy || loop.learner.learns())) {
    load_learnt_weights(loop, runner.context(), *initial_weights);
  }
  const auto& plant = dynamic_cast<const RemotePlant&>(*loop.plant);
  LinkFigures whole;
  for (int trial = 1; trial <= own.trials; ++trial) {
    TrialRecord record = next_trial(p, runner, trial);
    const LinkFigures figures = plant.link().take_figures();
    spdlog::info("{} seed {} trial {}: {} after {} ticks; {}", run.arm, run.seed, trial,
                 to_string(record.outcome.status), record.outcome.steps, figures.line());
    whole.add(figures);
    record.values = trial_values(figures);
    run.trials.push_back(record);
    const TrialStatus status = record.outcome.status;
    if (status == TrialStatus::kStopped) break;
    if (status == TrialStatus::kSuccess) run.succeeded = true;
    if (!run.succeeded) ++run.failures_before_success;
  }
  plant.link().stop("the run is over");
  for (auto& value : trial_values(whole)) run.figures.push_back(std::move(value));
  keep_learnt(p, loop, runner.context(), run);
}

Figure run_figure(std::string name, std::string meaning) {
  return {.name = std::move(name),
          .meaning = std::move(meaning),
          .summary = FigureSummary::kList,
          .statistics = {}};
}

ResultsSchema realtime_schema(const parameters::Parameters&) {
  const auto column = [](const char* name, ValueType type, const char* meaning) {
    return Column{name, type, meaning};
  };
  return ResultsSchema{
      .trial_columns =
          {column("deadline_misses", ValueType::kInteger,
                  "torques the robot did not have by its deadline (it held the last)"),
           column("latency_p50", ValueType::kNumber,
                  "median round trip, measurement sent to torque received (robot's clock), s"),
           column("latency_p99", ValueType::kNumber, "99th percentile of the round trip, s"),
           column("latency_max", ValueType::kNumber, "largest round trip, s"),
           column("lost", ValueType::kInteger,
                  "measurements not applied: never arrived, or passed over for a newer one"),
           column("refused", ValueType::kInteger,
                  "datagrams dropped: malformed, forged, non-finite, from elsewhere, out of "
                  "sequence")},
      .evaluates = false,
      .figures = {run_figure("deadline_misses", "the run's deadline misses"),
                  run_figure("latency_p50", "the run's median round trip, s"),
                  run_figure("latency_p99", "the run's 99th-percentile round trip, s"),
                  run_figure("latency_max", "the run's largest round trip, s"),
                  run_figure("lost", "the run's lost measurements"),
                  run_figure("refused", "the run's refused datagrams")},
      .pairs_failures = false,
      .plots = {"pitch"}};
}

void check_realtime(const parameters::Parameters& p, const LearntWeights* weights) {
  if (p.plant.kind != "remote") {
    throw config::ConfigError(
        "experiment realtime drives a robot in real time: plant.kind must be remote; got '" +
        p.plant.kind + "'");
  }
  if (realtime_params(p).loop != DrivenLoop::kPolicy) return;
  if (weights == nullptr) {
    throw config::ConfigError(
        "realtime.loop policy (cbbg drive --policy) runs learnt weights: give --load-weights");
  }
  for (const std::string& arm : p.run.arms) {
    if (!diagrams::named_arm(arm).policy) {
      throw config::ConfigError("realtime.loop policy: arm '" + arm +
                                "' has no learnt actor to run alone");
    }
  }
}

}  // namespace

Protocol realtime_protocol() {
  return {.name = kRealtimeProtocol,
          .meaning =
              "per arm and seed: realtime.trials trials against a robot in real time "
              "(plant.kind remote; `cbbg drive`), the link's figures per trial",
          .run =
              [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
                 const ExperimentOptions& options) {
                return run_per_arm(kRealtimeProtocol, drive, p, arms, options);
              },
          .schema = realtime_schema,
          .check = check_realtime,
          .keys = config::declared_keys(RealtimeParams{}, RealtimeParams::kSection),
          .keys_after = RealtimeParams::kKeysAfter};
}

}  // namespace cbbg::experiments
