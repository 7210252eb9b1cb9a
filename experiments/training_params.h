#pragma once
// training.*: what the robot meets while it learns, and only then (the evaluations after it
// stay as evaluation.* sets them). Registered as a section by training_disturbances.cc, read
// from the run's parameters.own.

#include "cbbg/framework/parameters.h"

namespace cbbg::experiments {

struct TrainingParams {
  static constexpr const char* kSection = "training";
  static constexpr const char* kKeysAfter = "evaluation";  // its place in config.yaml

  double noise_std = 0.0;
  double push_force = 0.0;
  double push_duration = 0.5;
  double pitch_spread = 0.0;
  double body_mass_spread = 0.0;
  long long curriculum_trials = 0;

  template <class Archive>
  void describe(Archive& a) {
    a.number("noise_std", noise_std,
             "training only: Gaussian noise std added (in quadrature) to the measured pitch, rad, "
             "and pitch rate, rad/s, of every learning trial",
             kNonNegative);
    a.number("push_force", push_force,
             "training only: each learning trial is pushed once from outside at the centre of "
             "mass, a force drawn uniformly from [-push_force, push_force], N, at a time drawn "
             "uniformly over the trial; 0 = none",
             kNonNegative);
    a.number("push_duration", push_duration, "training only: how long that push lasts, s",
             kPositive);
    a.number("pitch_spread", pitch_spread,
             "training only: each learning trial starts from its initial pitch (trial.theta0, "
             "or the protocol's) plus a draw uniform in +-pitch_spread, rad; 0 = none",
             kNonNegative);
    a.number("body_mass_spread", body_mass_spread,
             "training only: each learning trial's robot has its body's mass and inertias times "
             "a draw uniform in 1 +- body_mass_spread (as evaluation.body_mass_scale changes "
             "them, through plant.kind), the weights carried from trial to trial; 0 = none",
             interval(0.0, 1.0, kClosed, kOpen));
    a.integer("curriculum_trials", curriculum_trials,
              "training only: the noise, the push, the initial pitch's and the body mass's "
              "spreads grow linearly from none at trial 1 to the values above at trial "
              "curriculum_trials + 1; 0 = all of them from the first trial",
              kNonNegative);
  }

  bool disturbs() const {
    return noise_std > 0.0 || push_force > 0.0 || pitch_spread > 0.0 || body_mass_spread > 0.0;
  }
};

}  // namespace cbbg::experiments
