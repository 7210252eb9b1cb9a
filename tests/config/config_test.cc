#include "cbbg/config/config.h"

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/experiments/protocols.h"  // the keys of a cbbg run: the tree's and the protocols'

#include "tests/support/error_of.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::config {
namespace {

using cbbg::testing::error_of;
using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string error_of_yaml(const std::string& text) {
  Config config;
  try {
    config.merge_yaml(text, "my.yaml");
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "no error";
}

std::string error_of_set(const std::string& assignment) {
  Config config;
  try {
    config.set(assignment);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "no error";
}

TEST(Config, StartsFromSpecDefaults) {
  const Config config;
  EXPECT_EQ(config.text("experiment"), "exp1");
  EXPECT_EQ(config.names("arms"), (std::vector<std::string>{"cbbg", "bg_only"}));
  EXPECT_EQ(config.integer("seeds"), 20);
  EXPECT_EQ(config.text("plant.kind"), "simbody");
  EXPECT_EQ(config.number("plant.body_pitch_inertia"), 1.5417);
  EXPECT_EQ(config.number("trial.failure_angle"), 0.5236);
  EXPECT_EQ(config.numbers("rbf.centres"), (std::vector<double>{-3, -2, -1, 0, 1, 2, 3}));
  EXPECT_EQ(config.number("critic.gamma"), 0.8);
  EXPECT_EQ(config.number("sampler.k_b"), 1.0);
  EXPECT_EQ(config.annealing("annealing"),
            (std::vector<AnnealingStep>{{1, 10}, {11, 5}, {16, 1}, {21, 0.5}, {23, 0.1}}));
}

TEST(Config, MergesNestedAndFlowMaps) {
  Config config;
  config.merge_yaml("critic: {gamma: 0.9}\nplant:\n  kind: analytic\n  body_mass: 12\nseeds: 3\n",
                    "my.yaml");
  EXPECT_EQ(config.number("critic.gamma"), 0.9);
  EXPECT_EQ(config.number("critic.beta"), 0.1);
  EXPECT_EQ(config.text("plant.kind"), "analytic");
  EXPECT_EQ(config.number("plant.body_mass"), 12.0);
  EXPECT_EQ(config.integer("seeds"), 3);
}

TEST(Config, SuggestsTheKeyMeantForAnUnknownOne) {
  EXPECT_EQ(error_of_yaml("critic:\n  gama: 0.9\n"),
            "my.yaml: unknown key 'critic.gama'; did you mean 'critic.gamma'?");
  EXPECT_EQ(error_of_yaml("gamma: 0.9\n"),
            "my.yaml: unknown key 'gamma'; did you mean 'critic.gamma'?");
  EXPECT_EQ(error_of_yaml("colour: red\n"),
            "my.yaml: unknown key 'colour'; `cbbg list` shows every key");
}

TEST(Config, RejectsWrongTypesNamingKeyAndAllowedValues) {
  EXPECT_EQ(error_of_yaml("seeds: many"),
            "my.yaml: seeds must be an integer in [1, 10000]; got 'many'");
  EXPECT_EQ(error_of_yaml("seeds: 2.5"),
            "my.yaml: seeds must be an integer in [1, 10000]; got '2.5'");
  EXPECT_EQ(error_of_yaml("critic: {beta: fast}"),
            "my.yaml: critic.beta must be a number; got 'fast'");
  EXPECT_EQ(error_of_yaml("actor: {rule: improvd}"),
            "my.yaml: actor.rule must be one of improved, weighted; got 'improvd'");
  EXPECT_EQ(error_of_yaml("plant: 3"),
            "my.yaml: plant is a section: give a map of its keys (kind, wheel_mass, body_mass, "
            "wheel_radius, track_width, com_height, wheel_inertia, body_pitch_inertia, "
            "body_yaw_inertia, body_roll_inertia, wheel_diametral_inertia, gravity, "
            "wheel_ground_friction, axle_friction, torque_limit, "
            "accuracy, simbody_integrator, simbody_model); got '3'");
  EXPECT_EQ(error_of_yaml("- 1\n- 2\n"), "my.yaml: a config is a map of keys; got [1, 2]");
}

TEST(Config, RejectsADuplicateKeyNamingItsLine) {
  EXPECT_EQ(error_of_yaml("seeds: 2\nseed: 4\nseeds: 3\n"),
            "my.yaml: key 'seeds' appears twice (again at line 3); give each key once");
  EXPECT_EQ(error_of_yaml("critic:\n  beta: 0.1\n  beta: 0.2\n"),
            "my.yaml: key 'critic.beta' appears twice (again at line 3); give each key once");
}

TEST(Config, RefusesFilesThatAreNoConfigBeforeReadingThem) {
  Config config;
  EXPECT_EQ(error_of<ConfigError>([&] { config.merge_file("/dev/zero"); }),
            "config file '/dev/zero' is not a regular file");
  cbbg::testing::ScratchDirectory scratch;
  const std::filesystem::path huge = scratch.path() / "huge.yaml";
  std::ofstream(huge) << std::string(kMaxConfigFileBytes + 1, '#');
  EXPECT_EQ(error_of<ConfigError>([&] { config.merge_file(huge); }),
            "config file '" + huge.string() + "' is larger than 1024 KiB; a config is a few keys");
}

TEST(Config, RejectsOutOfRangeValues) {
  EXPECT_EQ(error_of_yaml("critic: {gamma: 1.5}"),
            "my.yaml: critic.gamma must be in (0, 1]; got 1.5");
  EXPECT_EQ(error_of_yaml("critic: {gamma: 0}"), "my.yaml: critic.gamma must be in (0, 1]; got 0");
  EXPECT_EQ(error_of_yaml("critic: {lambda: 1}"),
            "my.yaml: critic.lambda must be in [0, 1); got 1");
  EXPECT_EQ(error_of_yaml("seed: -1"),
            "my.yaml: seed must be an integer in [0, 1000000000000]; got -1");
  EXPECT_EQ(error_of_yaml("seeds: 0"), "my.yaml: seeds must be an integer in [1, 10000]; got 0");
  EXPECT_EQ(error_of_yaml("seeds: 10001"),
            "my.yaml: seeds must be an integer in [1, 10000]; got 10001");
  EXPECT_EQ(error_of_yaml("max_trials: 100001"),
            "my.yaml: max_trials must be an integer in [1, 100000]; got 100001");
  EXPECT_EQ(error_of_yaml("trial: {failure_angle: 1.6}"),
            "my.yaml: trial.failure_angle must be in (0, 1.5707963267948966]; got 1.6");
  EXPECT_EQ(error_of_yaml("trial: {period: 0}"), "my.yaml: trial.period must be > 0; got 0");
  EXPECT_EQ(error_of_yaml("plant: {body_mass: -10}"),
            "my.yaml: plant.body_mass must be > 0; got -10");
  EXPECT_EQ(error_of_yaml("rbf: {width: -0.5}"), "my.yaml: rbf.width must be > 0; got -0.5");
}

TEST(Config, RejectsNanAndInfinity) {
  EXPECT_EQ(error_of_yaml("critic: {beta: .nan}"),
            "my.yaml: critic.beta must be a finite number; got '.nan'");
  EXPECT_EQ(error_of_yaml("plant: {body_mass: .inf}"),
            "my.yaml: plant.body_mass must be a finite number; got '.inf'");
  EXPECT_EQ(error_of_yaml("rbf: {centres: [0, -.inf]}"),
            "my.yaml: rbf.centres[1] must be a finite number; got '-.inf'");
}

TEST(Config, ChecksListsAndTheAnnealingSchedule) {
  EXPECT_EQ(error_of_yaml("arms: [cbbg, cbbg]"), "my.yaml: arms lists 'cbbg' twice");
  // Which names are arms is the presets' table's to say (experiments::check_run_names).
  EXPECT_EQ(error_of_yaml("arms: []"), "my.yaml: arms must be a non-empty list of names; got []");
  const std::string name =
      "a name (1 to 100 letters, digits, '_', '-' and '.', not starting "
      "with '-' or '.')";
  EXPECT_EQ(error_of_yaml("arms: [cbbg, [1]]"), "my.yaml: arms[1] must be " + name + "; got [1]");
  EXPECT_EQ(error_of_yaml("arms: [cbbg, a/b]"), "my.yaml: arms[1] must be " + name + "; got 'a/b'");
  EXPECT_EQ(error_of_yaml("experiment: ../x"),
            "my.yaml: experiment must be " + name + "; got '../x'");
  EXPECT_EQ(error_of_yaml("supervisor: {lqr_q: [1, 2, 3]}"),
            "my.yaml: supervisor.lqr_q must be a list of 4 numbers; got [1, 2, 3]");
  EXPECT_EQ(error_of_yaml("rbf: {centres: []}"),
            "my.yaml: rbf.centres must be a non-empty list of numbers; got []");
  EXPECT_EQ(error_of_yaml("annealing: [{from_trial: 1, k1: 10}, {from_trial: 11, k1: 5}, "
                          "{from_trial: 5, k1: 1}]"),
            "my.yaml: annealing must list trials in increasing order; annealing[2].from_trial "
            "is 5 after 11");
  EXPECT_EQ(error_of_yaml("annealing: [{from_trial: 2, k1: 10}]"),
            "my.yaml: annealing must start at from_trial 1; got 2");
  EXPECT_EQ(error_of_yaml("annealing: [{from_trial: 1, k1: -1}]"),
            "my.yaml: annealing[0].k1 must be > 0; got -1");
  EXPECT_EQ(error_of_yaml("annealing: [{from_trial: 1, k1: 1, T: 2}]"),
            "my.yaml: annealing[0] has an unknown key 'T'; allowed: from_trial, k1");
  // Found by the fuzzer: a key that is not a plain name once escaped as a yaml-cpp exception.
  EXPECT_EQ(error_of_yaml("annealing: [{[1]: 2}]"),
            "my.yaml: annealing[0] has an unknown key [1]; allowed: from_trial, k1");
  EXPECT_EQ(error_of_yaml("annealing: [{? : 1}]"),
            "my.yaml: annealing[0] has an unknown key {~: 1}; allowed: from_trial, k1");
}

TEST(Config, ReportsMalformedYamlWithItsPlace) {
  EXPECT_THAT(error_of_yaml("critic: {gamma: 0.9\nseeds: 2\n"),
              StartsWith("my.yaml: malformed YAML at line "));
}

TEST(Config, AFailedMergeChangesNothing) {
  Config config;
  EXPECT_THROW(config.merge_yaml("seeds: 5\ncritic: {gamma: 7}\n", "my.yaml"), ConfigError);
  EXPECT_EQ(config, Config());
  EXPECT_THROW(config.set("critic={gamma: 0.5, lambda: 2}"), ConfigError);
  EXPECT_EQ(config, Config());
}

TEST(Config, AnEmptyDocumentChangesNothing) {
  Config config;
  config.merge_yaml("", "empty.yaml");
  config.merge_yaml("# only a comment\n", "comment.yaml");
  EXPECT_EQ(config, Config());
}

TEST(Config, AppliesSetOverrides) {
  Config config;
  config.set("critic.gamma=0.9");
  config.set("rbf.centres=[-2, 0, 2]");
  config.set("plant={body_mass: 12, kind: analytic}");
  config.set("arms=[cbbg, pd_only]");
  EXPECT_EQ(config.number("critic.gamma"), 0.9);
  EXPECT_EQ(config.numbers("rbf.centres"), (std::vector<double>{-2, 0, 2}));
  EXPECT_EQ(config.number("plant.body_mass"), 12.0);
  EXPECT_EQ(config.text("plant.kind"), "analytic");
  EXPECT_EQ(config.names("arms"), (std::vector<std::string>{"cbbg", "pd_only"}));
}

TEST(Config, RejectsMalformedSetOverrides) {
  EXPECT_EQ(error_of_set("critic.gamma"), "--set critic.gamma: expected key.path=value");
  EXPECT_EQ(error_of_set("=3"), "--set =3: expected key.path=value");
  EXPECT_EQ(error_of_set("critic.gamma="),
            "--set critic.gamma=: critic.gamma has no value after '='");
  EXPECT_EQ(error_of_set("critic.gama=0.5"),
            "--set critic.gama=0.5: unknown key 'critic.gama'; did you mean 'critic.gamma'?");
  EXPECT_EQ(error_of_set("seeds=-3"),
            "--set seeds=-3: seeds must be an integer in [1, 10000]; got -3");
  EXPECT_EQ(error_of_set("critic.gamma=nan"),
            "--set critic.gamma=nan: critic.gamma must be a number; got 'nan'");
}

TEST(Config, ReportsAMissingFile) {
  Config config;
  try {
    config.merge_file("/nonexistent/cbbg.yaml");
    ADD_FAILURE();
  } catch (const ConfigError& error) {
    EXPECT_STREQ(error.what(),
                 "config file '/nonexistent/cbbg.yaml' cannot be read (missing or unreadable)");
  }
}

TEST(Config, TheResolvedYamlLoadsBackToTheSameConfig) {
  Config config;
  config.set("critic.gamma=0.1");  // 0.1 must come back as exactly 0.1
  config.set("plant.kind=analytic");
  config.set("annealing=[{from_trial: 1, k1: 3}, {from_trial: 4, k1: 0.25}]");
  config.set("sensors.noise_std=[0.001, 0, 0, 0, 0, 1e-9]");
  const std::string yaml = config.to_yaml();
  EXPECT_THAT(yaml,
              HasSubstr("critic:\n  kind: td_lambda\n  beta: 0.1\n  gamma: 0.1\n  lambda: 0.8\n"));
  EXPECT_THAT(yaml,
              HasSubstr("annealing:\n  - {from_trial: 1, k1: 3}\n  - {from_trial: 4, k1: 0.25}\n"));
  Config reloaded;
  reloaded.merge_yaml(yaml, "config.yaml");
  EXPECT_EQ(reloaded, config);
}

TEST(Config, SuggestionsNeedAClosePrefix) {
  EXPECT_EQ(closest_key("plant.body_mas"), "plant.body_mass");
  EXPECT_EQ(closest_key("totally_unrelated_key"), "");
}

}  // namespace
}  // namespace cbbg::config
