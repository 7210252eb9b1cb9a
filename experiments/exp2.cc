// exp2 (paper Figs. 12-14): one trial of the coordinated arm, then the operant arm carrying on
// what was learnt, k1 from the annealing schedule.

#include <algorithm>
#include <stdexcept>

#include "cbbg/config/declared_keys.h"
#include "cbbg/experiments/builtin_protocols.h"
#include "cbbg/experiments/exp2_params.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/experiments/protocol_kit.h"

namespace cbbg::experiments {
namespace {

// k1 of `trial` under the annealing schedule (steps sorted by from_trial, the first at 1).
double annealed_k1(const std::vector<config::AnnealingStep>& schedule, int trial) {
  double k1 = schedule.front().k1;
  for (const auto& step : schedule) {
    if (step.from_trial <= trial) k1 = step.k1;
  }
  return k1;
}

void set_k1(const diagrams::ClosedLoop& loop, Context& context, double k1) {
  if (loop.learner.tropism == nullptr) {
    throw std::invalid_argument("exp2 anneals k1: the closed loop '" + loop.diagram->name() +
                                "' has no tropism");
  }
  loop.learner.tropism->set_k1(context, k1);
}

// A trial of the annealing, with its oscillation columns.
TrialRecord annealing_trial(int trial, double k1, const TrialOutcome& outcome) {
  return {trial,
          k1,
          outcome,
          {{"pitch_rms", outcome.pitch_rms},
           {"pitch_peak_to_peak", outcome.pitch_peak_to_peak},
           {"mean_forward_speed", outcome.mean_forward_speed}}};
}

void run_annealing(const parameters::Parameters& p, const diagrams::Arm& coordinated,
                   const diagrams::Arm& operant, const TelemetryOptions& telemetry,
                   const LearntWeights* initial_weights, SeedRun& run) {
  const double theta0 = p.trial.theta0;
  const double duration = p.trial.duration;
  const Exp2Params own = config::read_section<Exp2Params>(p.own, Exp2Params::kSection);
  const std::vector<config::AnnealingStep>& schedule = own.annealing;
  SeedLoop first(p, coordinated, telemetry, initial_weights, run.seed);
  set_k1(first.loop, first.runner.context(), annealed_k1(schedule, 1));
  run.trials.push_back(
      annealing_trial(1, annealed_k1(schedule, 1), first.run_trial(theta0, duration, 1)));

  // The operant loop carries on: weights, the omega counter and the random streams.
  SeedLoop later(p, operant, telemetry, first);
  for (int trial = 2; trial <= own.exp2.trials; ++trial) {
    const double k1 = annealed_k1(schedule, trial);
    set_k1(later.loop, later.runner.context(), k1);
    run.trials.push_back(annealing_trial(trial, k1, later.run_trial(theta0, duration, trial)));
  }
  int balanced = 0;
  for (const auto& trial : run.trials) {
    if (trial.outcome.status != TrialStatus::kSuccess) continue;
    ++balanced;
    if (!run.succeeded) {
      run.succeeded = true;
      run.failures_before_success = trial.trial - 1;
    }
  }
  if (!run.succeeded) run.failures_before_success = static_cast<int>(run.trials.size());
  run.figures.push_back({"balanced_trials", static_cast<double>(balanced)});
  keep_weights(learnt_weights(later.loop, later.runner.context(), provenance(p, run)), run);
}

ResultsSchema exp2_schema(const parameters::Parameters&) {
  return {.trial_columns = {{"pitch_rms", ValueType::kNumber,
                             "theta_b's RMS about its mean from trial.settle_time on, rad"},
                            {"pitch_peak_to_peak", ValueType::kNumber,
                             "theta_b's peak-to-peak from trial.settle_time on, rad"},
                            {"mean_forward_speed", ValueType::kNumber,
                             "the mean forward speed from trial.settle_time on, m/s"}},
          .evaluates = false,
          .figures = {{.name = "balanced_trials",
                       .type = ValueType::kInteger,
                       .meaning = "the trials that balanced",
                       .summary = FigureSummary::kNone}},
          .pairs_failures = false,
          .headline = "balanced_trials",
          .console = ConsoleTable::kTrials,
          .plots = {"annealing"}};
}

}  // namespace

ExperimentResults run_exp2(const parameters::Parameters& parameters,
                           const diagrams::Arm& coordinated, const diagrams::Arm& operant,
                           const ExperimentOptions& options) {
  check_training(parameters);
  auto body = [&](SeedRun& run, const TelemetryOptions& telemetry) {
    run_annealing(parameters, coordinated, operant, telemetry, options.initial_weights, run);
  };
  ExperimentResults results = run_tasks(parameters, {coordinated.name}, body, options);
  results.experiment = "exp2";
  results.steps_header = steps_csv_header(coordinated.learner(parameters).signals);
  return results;
}

Protocol exp2_protocol() {
  return {
      .name = "exp2",
      .meaning = "one cbbg trial, then omega = 1 with the annealing schedule (paper Figs. 12-14)",
      .arms = [](const parameters::RunParams&) { return std::vector<std::string>{"cbbg"}; },
      .run =
          [](const parameters::Parameters& p, const std::vector<diagrams::Arm>& arms,
             const ExperimentOptions& options) {
            return run_exp2(p, arms.front(), diagrams::named_arm("bg_only"), options);
          },
      .schema = exp2_schema,
      .keys = config::declared_keys(Exp2Params{}, Exp2Params::kSection),
      .keys_after = Exp2Params::kKeysAfter};
}

}  // namespace cbbg::experiments
