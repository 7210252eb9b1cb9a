#pragma once
// Learning under disturbance (training.*, training_params.h): every protocol's learning
// trials, those of a SeedLoop (protocol_kit.h), meet sensor noise, a push from outside, a
// spread of initial pitches and of body masses, grown trial by trial by a curriculum;
// evaluations do not.
//
// The learning loop is built with the largest of them (training_loop_parameters: its sensors'
// pitch and pitch-rate noise, a push block of the largest force); before each trial the
// disturbances set that trial's share in the context: the sensors' noise_scale, the push's
// pulse, and the initial pitch. A trial of another body mass runs in a loop built for that
// robot (trial_robot), carrying on the seed's learning (SeedLoop::run_trial). The draws come
// from a stream of the seed's own, derived from its root seed and "training"
// (framework/random.h), so every arm of one seed meets the same pushes, angles and masses in
// the same trials (common random numbers), and a run is the same bytes on any thread count.

#include <cstdint>

#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/experiments/training_params.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/random.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::experiments {

// Registers training.*'s keys after evaluation.*'s, and its check, once; what
// kTrainingSectionRegistered does before main in every program that includes this header.
bool register_training_section();
[[maybe_unused]] inline const bool kTrainingSectionRegistered = register_training_section();

// The training.* section of `p`.
TrainingParams training_params(const parameters::Parameters& p);

// Before any work: throws config::ConfigError naming the key when training.* cannot be
// applied: a training push beside push.* (one push per trial), a spread of initial pitches
// reaching trial.failure_angle, a spread of body masses plant.kind cannot make or makes
// invalid.
void check_training(const parameters::Parameters& p);

// `p` with the body's mass and inertias times `factor`, through plant.kind's kind as
// evaluation.body_mass_scale changes them. Throws config::ConfigError naming
// training.body_mass_spread when the kind has no body mass to change.
parameters::Parameters with_body_mass_scale(const parameters::Parameters& p, double factor);

// The parameters a learning loop is built from: `p` with training.noise_std added in
// quadrature to sensors.noise_std's pitch and pitch rate, and, with training.push_force, a
// push from outside of that force (each trial's own is set in the context). `p` itself when
// training.* disturbs nothing.
parameters::Parameters training_loop_parameters(const parameters::Parameters& p);

// One seed's training disturbances: one stream of draws, over the learning loops its trials
// run in (exp2 carries on from one loop to another).
class TrainingDisturbances {
 public:
  TrainingDisturbances(const parameters::Parameters& p, std::uint64_t seed);

  // Throws config::ConfigError naming the key when `loop`, built from
  // training_loop_parameters(p), lacks what training.* needs: the library's sensors for the
  // noise, plant.kind's plant for the body masses.
  void check(const diagrams::ClosedLoop& loop) const;

  // Whether each trial has a robot of its own (training.body_mass_spread).
  bool varies_robot() const { return params_.body_mass_spread > 0.0; }
  // Trial `trial`'s robot: `p` with its body mass times a draw within the trial's share of
  // training.body_mass_spread. Draw it before the trial's other draws (before_trial).
  parameters::Parameters trial_robot(const parameters::Parameters& p, int trial);

  // Sets trial `trial`'s noise and push in `context`, a context of `loop`, and returns its
  // initial pitch: theta0 (trial.theta0) plus a draw within the trial's share of
  // training.pitch_spread.
  double before_trial(const diagrams::ClosedLoop& loop, Context& context, int trial, double theta0);

  // The share of the disturbances trial `trial` meets: (trial - 1) / curriculum_trials, at
  // most 1; 1 without a curriculum.
  double share(int trial) const;

 private:
  void set_noise(const Block& sensors, Context& context, double share) const;
  void set_push(const Block& push, Context& context, double share);

  TrainingParams params_;
  double duration_;
  double base_noise_[2];  // sensors.noise_std of the pitch and its rate, as configured
  RandomGenerator generator_;
};

}  // namespace cbbg::experiments
