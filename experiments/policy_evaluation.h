#pragma once
// Evaluates a learnt policy: a closed loop in which the learnt actor drives alone with frozen
// weights (an arm's policy, diagrams/presets.h: a = a_A, no exploration, no supervisor), from
// each of a list of initial pitches, several times per pitch with consecutive seeds. A push
// (blocks::TorquePush) is part of the closed loop the factory builds.
//
// Every run starts from a clean context seeded with its own seed, so a run's outcome depends
// only on the weights, the config, its initial pitch, its seed and the push: not on which
// runs came before. With sensor noise (sensors.noise_std) the repeats differ; without it they
// are identical.

#include <optional>
#include <vector>

#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/experiments/learnt_weights.h"
#include "cbbg/experiments/trial_runner.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

struct EvaluationSettings {
  std::vector<double> angles;  // initial pitches theta_b(0), rad (finite, non-empty)
  int repeats = 1;             // runs per angle, with seeds seed, seed + 1, ... (>= 1)

  // Throws std::invalid_argument naming the setting unless every value is in its range.
  void validate() const;
};

// The runs from one initial pitch.
struct AngleEvaluation {
  double theta0 = 0.0;
  // Run r used seed first_seed + r. mean_temperature and mean_entropy are NaN: the policy
  // alone has neither.
  std::vector<TrialOutcome> runs;

  // Runs that lasted trial.duration without failing.
  int balanced() const;
};

struct PolicyEvaluation {
  long long first_seed = 0;  // the parameters' seed
  std::vector<AngleEvaluation> angles;
  // No run drew a random number (Context::generators_at_seed): the runs are those of any
  // seed, since the seed reaches a closed loop only through its blocks' generators.
  bool seed_free = true;
};

// Runs the policy of `weights` in the closed loop `policy` builds from `parameters` (plant.kind,
// trial.duration, trial.period, trial.failure_angle, sensors.*) from each angle,
// settings.repeats times. The weights' feature count must match the loop's features
// (store::check_layout gives the user's message; here a mismatch throws
// std::invalid_argument, as does a loop without an actor).
PolicyEvaluation evaluate_policy(const parameters::Parameters& parameters,
                                 const diagrams::ClosedLoopFactory& policy,
                                 const LearntWeights& weights, const EvaluationSettings& settings);

// The same runs of a closed loop that learns nothing (pd_only: the supervisor alone), as it
// is. Throws std::invalid_argument for a loop that learns.
PolicyEvaluation evaluate_controller(const parameters::Parameters& parameters,
                                     const diagrams::ClosedLoopFactory& controller,
                                     const EvaluationSettings& settings);

}  // namespace cbbg::experiments
