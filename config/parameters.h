#pragma once
// The parameter tree of a cbbg run: every section, in the order config.yaml and `cbbg list`
// show them. Each section's struct declares its own keys once (framework/parameters.h); the
// blocks' and the plant's are theirs, the run's and the protocols' are here. The config layer
// makes its keys from these declarations (config/config.h) and reads them back into the
// typed tree (read_parameters).

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
#include "cbbg/config/own_sections.h"
#include "cbbg/framework/parameters.h"
#include "cbbg/plant/robot_params.h"

namespace cbbg::config {

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

// `words` and the words registered for the text key `key` since (register_choice,
// config/declared_keys.h): what a key open to a user's words declares it allows.
std::vector<std::string> with_registered_words(std::string_view key,
                                               std::vector<std::string> words);

// plant.*: which plant, and the robot's physical parameters.
struct PlantSection {
  std::string kind = "simbody";
  plant::RobotParams robot;

  template <class Archive>
  void describe(Archive& a) {
    a.text("kind", kind, "simbody (3-D multibody, reference) | analytic (fast)",
           with_registered_words("plant.kind", {"simbody", "analytic"}));
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

struct Exp2Params {
  long long trials = 30;

  template <class Archive>
  void describe(Archive& a) {
    a.integer("trials", trials, "exp2: trials in all, the CB-coordinated one included",
              interval(2, kMaxTrials));
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

struct Exp3Params {
  std::vector<double> angles{0.05, 0.1744, 0.25};

  template <class Archive>
  void describe(Archive& a) {
    a.numbers("angles", angles, "exp3: the learnt actor alone must balance from each of these, rad",
              kFinite);
  }
};

// How transfer trains each arm and seed: as exp3 does, until its actor alone balances, or as
// exp1 does, until its first success.
enum class TransferTraining { kUntilSkill, kUntilSuccess };

// transfer.*: train once, evaluate under many conditions (experiments/transfer.h).
struct TransferParams {
  TransferTraining training = TransferTraining::kUntilSkill;
  std::vector<std::string> conditions{
      "evaluation.body_mass_scale=1", "evaluation.body_mass_scale=1.3",
      "evaluation.com_height_scale=1.3", "evaluation.noise_std=0.05", "evaluation.push_torque=5"};

  template <class Archive>
  void describe(Archive& a) {
    a.choice("training", training,
             "transfer: each arm and seed trains once as exp3 does (until its actor alone "
             "balances) or as exp1 does (until its first success)",
             Choices<TransferTraining>{{"exp3", TransferTraining::kUntilSkill},
                                       {"exp1", TransferTraining::kUntilSuccess}});
    a.settings("conditions", conditions,
               "transfer: what was learnt is evaluated from evaluation.angles under each of these "
               "conditions, a column each; keys of evaluation.*, plant.* (not plant.kind), "
               "sensors.*, push.* or a registered section");
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
  std::vector<AnnealingStep> annealing{{1, 10}, {11, 5}, {16, 1}, {21, 0.5}, {23, 0.1}};
  Exp2Params exp2;
  LogParams log;
  EvaluationParams evaluation;
  Exp3Params exp3;
  TransferParams transfer;
  // The sections users registered (config/declared_keys.h), by full key; not declared here.
  OwnSections own;

  // The rules across sections: trial.duration >= trial.period; trial.theta0 and every
  // evaluation.angles and exp3.angles entry strictly inside trial.failure_angle. Throws
  // ConfigError naming both keys and their values.
  void check_across_sections() const;

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
    a.annealing("annealing", annealing,
                "exp2: k1 from a trial on (trial 1 is the CB-coordinated one)");
    a.section("exp2", exp2);
    a.section("log", log);
    a.section("evaluation", evaluation);
    a.section("exp3", exp3);
    a.section("transfer", transfer);
  }
};

// The typed tree of `config`, whose every value was checked against its declaration as it
// arrived, the registered sections' values in `own`. Cross-key rules and a block's own
// invariants are checked by diagrams::validated_parameters, the edge of a run.
Parameters read_parameters(const Config& config);
// Writes `parameters` into `config`, the registered sections too. Throws ConfigError naming
// the first value outside its declaration.
void write_parameters(const Parameters& parameters, Config& config);

}  // namespace cbbg::config
