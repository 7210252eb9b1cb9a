#pragma once
// The parameter tree of a cbbg run: the run's own keys and the sections of the blocks and
// plants it is made of, in the order config.yaml and `cbbg list` show them. Each section's
// struct declares its own keys once (framework/parameters.h); the blocks' and the plant's are
// theirs, the run's are here. This tree registers their keys with the config engine
// (config/declared_keys.h), which knows none of them, before main; a protocol registers its
// own sections with itself (experiments/protocols.h), a user's block or plant the same way,
// and their values travel in `own`.

#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/exploration_params.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/omega_schedule.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/push_params.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/blocks/reward.h"
#include "cbbg/blocks/sensors.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/config/config.h"
#include "cbbg/config/declared_keys.h"
#include "cbbg/config/own_sections.h"
#include "cbbg/framework/parameters.h"
#include "cbbg/plant/robot_params.h"

namespace cbbg::parameters {

using config::kMaxSeed;
using config::kMaxSeeds;
using config::kMaxTrials;

// What runs, how often: the keys without a section.
struct RunParams {
  std::string experiment = "exp1";
  std::vector<std::string> arms{"cbbg", "bg_only"};
  long long seeds = 20;
  long long seed = 1;
  long long max_trials = 100;

  template <class Archive>
  void describe(Archive& a) {
    // Protocols and presets are named by their own tables (experiments/, diagrams/presets.h),
    // which `cbbg run` checks these against; a library run records its own arms here.
    a.text("experiment", experiment,
           "a protocol (exp1, exp2, exp3, transfer, a registered one) or a diagram, run alone "
           "under exp1's protocol (`cbbg list`)",
           {});
    a.names("arms", arms,
            "diagrams compared in one run (exp1, exp3, transfer): presets for `cbbg run` (`cbbg "
            "list`); "
            "a library run records its own arms here",
            {});
    a.integer("seeds", seeds, "independent runs per arm; run k uses root seed + k",
              interval(1, kMaxSeeds));
    a.integer("seed", seed, "root seed", interval(0, kMaxSeed));
    a.integer("max_trials", max_trials, "exp1: give up after this many trials without a success",
              interval(1, kMaxTrials));
  }
};

// plant.*: which plant, and the robot's physical parameters.
struct PlantSection {
  std::string kind = "simbody";
  plant::RobotParams robot;

  template <class Archive>
  void describe(Archive& a) {
    a.text("kind", kind, "simbody (3-D multibody, reference) | analytic (fast)",
           config::with_registered_words("plant.kind", {"simbody", "analytic"}));
    robot.describe(a);
  }
};

// trial.*: how every trial starts, is sampled, fails and succeeds.
struct TrialParams {
  double theta0 = plant::kDefaultInitialPitch;
  double duration = 20.0;
  double failure_angle = 0.5236;
  double period = 0.01;
  double settle_time = 5.0;

  template <class Archive>
  void describe(Archive& a) {
    a.number("theta0", theta0, "initial pitch of every trial, rad", kFinite);
    a.number("duration", duration, "a trial that lasts this long succeeds, s", kPositive);
    a.number("failure_angle", failure_angle, "|theta_b| beyond this fails the trial, rad",
             interval(0.0, std::numbers::pi / 2.0, kOpen, kClosed));
    a.number("period", period, "sampling period Ts of the controller, s", kPositive);
    a.number("settle_time", settle_time,
             "the oscillation figures of trials.csv (exp2) start here, s", kNonNegative);
  }
};

// supervisor.*: which supervisor, and each one's parameters.
struct SupervisorSection {
  std::string kind = "pd";
  blocks::PdSupervisorParams pd;
  blocks::LqrSupervisorParams lqr;

  template <class Archive>
  void describe(Archive& a) {
    a.text("kind", kind, "pd (docs/model.md §2.4) | lqr (Riccati gains of the linearised robot)",
           {"pd", "lqr"});
    pd.describe(a);
    lqr.describe(a);
  }
};

struct LogParams {
  long long decimation = 1;

  template <class Archive>
  void describe(Archive& a) {
    a.integer("decimation", decimation, "steps.csv keeps every n-th tick; 0 writes no steps.csv",
              kNonNegative);
  }
};

// evaluation.*: the angles the learnt actor is evaluated from, and the changed robot it may
// be evaluated on (experiments/evaluation_conditions.h).
struct EvaluationParams {
  std::vector<double> angles{0.05, 0.1, 0.15, 0.2, 0.25};
  double body_mass_scale = 1.0;
  double com_height_scale = 1.0;
  double noise_std = 0.0;
  double push_torque = 0.0;
  double push_start = 5.0;
  double push_duration = 0.2;
  double push_force = 0.0;
  double push_pitch_torque = 0.0;

  template <class Archive>
  void describe(Archive& a) {
    a.numbers("angles", angles, "initial pitches the learnt actor is evaluated from, rad", kFinite);
    a.number("body_mass_scale", body_mass_scale,
             "evaluation only: body mass and inertias times this (training stays nominal)",
             kPositive);
    a.number("com_height_scale", com_height_scale,
             "evaluation only: centre-of-mass height times this (training stays nominal)",
             kPositive);
    a.number("noise_std", noise_std,
             "evaluation only: Gaussian noise std added to the measured pitch (rad) and pitch "
             "rate (rad/s), on top of sensors.noise_std",
             kNonNegative);
    a.number("push_torque", push_torque,
             "evaluation only: a push through the motors, N m on each wheel (push.torque)",
             kFinite);
    a.number("push_force", push_force,
             "evaluation only: a push from outside, N at the body's centre of mass (push.force)",
             kFinite);
    a.number("push_pitch_torque", push_pitch_torque,
             "evaluation only: a push from outside, N m on the body (push.pitch_torque); with "
             "push_torque and push_force all 0, push.* as set",
             kFinite);
    a.number("push_start", push_start, "evaluation only: when that push begins, s", kNonNegative);
    a.number("push_duration", push_duration, "evaluation only: how long that push lasts, s",
             kPositive);
  }
};

// The whole tree, in the order of config.yaml.
struct Parameters {
  RunParams run;
  PlantSection plant;
  TrialParams trial;
  blocks::NormaliserParams normaliser;
  blocks::RbfParams rbf;
  SupervisorSection supervisor;
  blocks::CriticParams critic;
  blocks::ActorParams actor;
  blocks::TropismParams tropism;
  blocks::SamplerParams sampler;
  blocks::ExplorationParams exploration;
  blocks::OmegaParams omega;
  blocks::RewardParams reward;
  blocks::SensorsParams sensors;
  blocks::PushParams push;
  LogParams log;
  EvaluationParams evaluation;
  // The registered sections' values (a protocol's, a user's), by full key; not declared here.
  config::OwnSections own;

  // The rules across sections: trial.duration >= trial.period; trial.theta0 and every
  // evaluation.angles entry strictly inside trial.failure_angle (check_inside_failure_angle).
  // Throws config::ConfigError naming both keys and their values.
  void check_across_sections() const;
  // Throws config::ConfigError unless `angle`, the value of `key`, lies strictly inside
  // trial.failure_angle: a trial from there would fail at once.
  void check_inside_failure_angle(const std::string& key, double angle) const;

  template <class Archive>
  void describe(Archive& a) {
    run.describe(a);
    a.section("plant", plant);
    a.section("trial", trial);
    a.section(blocks::NormaliserParams::kSection, normaliser);
    a.section(blocks::RbfParams::kSection, rbf);
    a.section("supervisor", supervisor);
    a.section(blocks::CriticParams::kSection, critic);
    a.section(blocks::ActorParams::kSection, actor);
    a.section(blocks::TropismParams::kSection, tropism);
    a.section(blocks::SamplerParams::kSection, sampler);
    a.section(blocks::ExplorationParams::kSection, exploration);
    a.section(blocks::OmegaParams::kSection, omega);
    a.section(blocks::RewardParams::kSection, reward);
    a.section(blocks::SensorsParams::kSection, sensors);
    a.section(blocks::PushParams::kSection, push);
    a.section("log", log);
    a.section("evaluation", evaluation);
  }
};

// Registers the tree's keys first among the config's, once; what kTreeRegistered does.
bool register_tree();
// Every program that includes this header has the tree's keys before main, whatever it
// makes first (a Config, a protocol, a section of its own).
[[maybe_unused]] inline const bool kTreeRegistered = register_tree();

// The typed tree of `config`, whose every value was checked against its declaration as it
// arrived, the registered sections' values in `own`. Cross-key rules and a block's own
// invariants are checked by diagrams::validated_parameters, the edge of a run.
Parameters read_parameters(const config::Config& config);
// Writes `parameters` into `config`, the registered sections too. Throws ConfigError naming
// the first value outside its declaration.
void write_parameters(const Parameters& parameters, config::Config& config);

}  // namespace cbbg::parameters
