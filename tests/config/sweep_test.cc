// config::Sweep: axes from --grid and from a config file's sweep: section, the grid's order,
// each point's config, and its errors, each naming where the axis came from.

#include "cbbg/config/sweep.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <algorithm>

namespace cbbg::config {
namespace {

using ::testing::ThrowsMessage;

TEST(SweepGrid, AGridFlagSplitsAtCommasOutsideBrackets) {
  Sweep sweep;
  sweep.add_flag("rbf.centres=[-1, 0, 1],[-2,0,2]");
  ASSERT_EQ(sweep.axes().size(), 1u);
  EXPECT_EQ(sweep.axes()[0].key, "rbf.centres");
  // Each value in YAML's flow form, as the sweep's config.yaml writes it.
  EXPECT_EQ(sweep.axes()[0].values, (std::vector<std::string>{"[-1, 0, 1]", "[-2, 0, 2]"}));
  EXPECT_EQ(sweep.axes()[0].source, "--grid rbf.centres=[-1, 0, 1],[-2,0,2]");
}

TEST(SweepGrid, PointsRunTheFirstAxisSlowest) {
  Sweep sweep;
  sweep.add_flag("actor.alpha=0.1,0.2");
  sweep.add_flag("critic.beta=0.05,0.1,0.2");
  EXPECT_EQ(sweep.points(), 6u);
  EXPECT_EQ(sweep.values(0), (std::vector<std::string>{"0.1", "0.05"}));
  EXPECT_EQ(sweep.values(2), (std::vector<std::string>{"0.1", "0.2"}));
  EXPECT_EQ(sweep.values(3), (std::vector<std::string>{"0.2", "0.05"}));
  const Config point = sweep.config(Config(), 5);
  EXPECT_EQ(point.number("actor.alpha"), 0.2);
  EXPECT_EQ(point.number("critic.beta"), 0.2);
  EXPECT_EQ(Sweep().points(), 1u);
}

TEST(SweepGrid, AConfigFilesSectionGivesTheSameAxesAndConfigIgnoresIt) {
  const std::string yaml =
      "seeds: 3\nsweep:\n  actor.alpha: [0.1, 0.2]\n  rbf.centres: [[-1, 1]]\n";
  Sweep sweep;
  sweep.add_yaml(yaml, "my.yaml");
  ASSERT_EQ(sweep.axes().size(), 2u);
  EXPECT_EQ(sweep.axes()[0].values, (std::vector<std::string>{"0.1", "0.2"}));
  EXPECT_EQ(sweep.axes()[1].values, (std::vector<std::string>{"[-1, 1]"}));
  EXPECT_EQ(sweep.axes()[1].source, "my.yaml: sweep.rbf.centres");
  EXPECT_EQ(sweep.to_yaml(), "sweep:\n  actor.alpha: [0.1, 0.2]\n  rbf.centres: [[-1, 1]]\n");
  Config config;
  config.merge_yaml(yaml, "my.yaml");  // the sweep: section is the sweep's, not a key
  EXPECT_EQ(config.integer("seeds"), 3);
  Sweep again;  // what config.yaml records reads back to the same sweep
  again.add_yaml(sweep.to_yaml(), "config.yaml");
  EXPECT_EQ(again.to_yaml(), sweep.to_yaml());
}

TEST(SweepGrid, BadAxesAreRefusedNamingTheirSource) {
  Sweep sweep;
  EXPECT_THAT([&] { sweep.add_flag("actor.alpha"); },
              ThrowsMessage<ConfigError>(
                  "--grid actor.alpha: give KEY=V1,V2,... (e.g. --grid actor.alpha=0.1,0.2)"));
  EXPECT_THAT(
      [&] { sweep.add_flag("actor.alpha=0.1,"); },
      ThrowsMessage<ConfigError>("--grid actor.alpha=0.1,: an empty value; give V1,V2,..."));
  sweep.add_flag("actor.alpha=0.1");
  EXPECT_THAT([&] { sweep.add_yaml("sweep: {actor.alpha: [0.2]}", "my.yaml"); },
              ThrowsMessage<ConfigError>("my.yaml: sweep.actor.alpha: actor.alpha is swept twice "
                                         "(also by --grid actor.alpha=0.1)"));
  EXPECT_THAT([&] { Sweep().add_yaml("sweep: [1, 2]", "my.yaml"); },
              ThrowsMessage<ConfigError>("my.yaml: sweep is a map of keys to lists of values "
                                         "(sweep: {actor.alpha: [0.1, 0.2]})"));
  EXPECT_THAT([&] { Sweep().add_yaml("sweep: {actor.alpha: 0.1}", "my.yaml"); },
              ThrowsMessage<ConfigError>(
                  "my.yaml: sweep.actor.alpha must be a list of values, e.g. [0.1, 0.2]"));
  Sweep typo;
  typo.add_flag("actor.alpa=0.1");
  EXPECT_THAT([&] { typo.check(Config()); },
              ThrowsMessage<ConfigError>("--grid actor.alpa=0.1: unknown key 'actor.alpa'; did "
                                         "you mean 'actor.alpha'?"));
  Sweep huge;
  huge.add_flag("actor.alpha=1,2,3,4,5,6,7,8,9,10");
  EXPECT_THAT(
      [&] {
        huge.add_flag("critic.beta=1,2,3,4,5,6,7,8,9,10");
        huge.add_flag("critic.gamma=1,2,3,4,5,6,7,8,9,10");
        huge.add_flag("critic.lambda=1,2,3,4,5,6,7,8,9,10");
        huge.add_flag("actor.rule=a,b");
      },
      ThrowsMessage<ConfigError>(
          "--grid actor.rule=a,b: the grid would have more than 10000 points"));
}

}  // namespace
}  // namespace cbbg::config

namespace cbbg::config {
namespace {

// `text` as messages echo it: a newline as '?', so that they stay one line.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', '?');
  return text;
}

// Whatever a user may type as a grid value is either refused before anything is written, with
// the message its key's rule gives, or written as YAML that reads back to the same values and
// the same grid points.
TEST(SweepGrid, HostileValuesAreRefusedOrReadBackUnchanged) {
  const std::vector<std::string> keys = {"critic.beta", "arms", "evaluation.angles", "plant.kind"};
  auto number = [](const std::string& got) { return "critic.beta must be a number; got " + got; };
  auto names = [](const std::string& got) {
    return "arms must be a non-empty list of names; got " + got;
  };
  auto angles = [](const std::string& got) {
    return "evaluation.angles must be a non-empty list of numbers; got " + got;
  };
  std::string kinds;  // simbody, analytic and the kinds this build has (mujoco)
  for (const KeySpec& spec : schema()) {
    if (spec.path == "plant.kind") kinds = join(spec.choices);
  }
  auto kind = [&kinds](const std::string& got) {
    return "plant.kind must be one of " + kinds + "; got " + got;
  };
  // Each key's answer: "" where it takes the value, else its refusal after "--grid key=value: ".
  auto every = [&](const std::string& got) -> std::vector<std::string> {
    return {number(got), names(got), angles(got), kind(got)};
  };
  auto all = [](const std::string& refusal) -> std::vector<std::string> {
    return {refusal, refusal, refusal, refusal};
  };
  auto numbers_only = [&](const std::string& got) -> std::vector<std::string> {
    return {"", names(got), angles(got), kind(got)};
  };
  const std::string empty = "an empty value; give V1,V2,...";
  const std::vector<std::pair<std::string, std::vector<std::string>>> values = {
      {"0.1 # note", numbers_only("'0.1'")},
      {"0.1#x", every("'0.1#x'")},
      {"  0.2", numbers_only("'0.2'")},
      {"'0.1'", numbers_only("'0.1'")},
      {"\"0.1\"", numbers_only("'0.1'")},
      {"0.1\n# more", numbers_only("'0.1'")},
      {"0.1 # é ünï", numbers_only("'0.1'")},
      {"[cbbg, bg_only] # mine",
       {number("[cbbg, bg_only]"), "", "evaluation.angles[0] must be a number; got 'cbbg'",
        kind("[cbbg, bg_only]")}},
      {"[bg_only]",
       {number("[bg_only]"), "", "evaluation.angles[0] must be a number; got 'bg_only'",
        kind("[bg_only]")}},
      {"a: b", every("{a: b}")},
      {"'it''s'", every("'it's'")},
      // Every rule shows a control character as '?': a message stays one line.
      {"\"x\\ny\"", {number("'x?y'"), names("'x?y'"), angles("'x?y'"), kind("'x?y'")}},
      {"é", every("'é'")},
      {"#", all(empty)},
      {"[cbbg", all("'[cbbg' is not a YAML value: end of sequence flow not found")},
      {":", every("{~: ~}")},
      {"'analytic' # fast", {number("'analytic'"), names("'analytic'"), angles("'analytic'"), ""}},
      {"\"simbody\"", {number("'simbody'"), names("'simbody'"), angles("'simbody'"), ""}},
      {"'[0.1, 0.2]'", every("'[0.1, 0.2]'")},
      {"[0.05, 0.1] # two", {number("[0.05, 0.1]"), "", "", kind("[0.05, 0.1]")}},
      {"- 1", {number("[1]"), "", "", kind("[1]")}},
      {"&a 1", numbers_only("'1'")},
      {"!!str 0.1", numbers_only("'0.1'")},
      {"{}", every("{}")},
      {"~", all(empty)}};
  int accepted = 0;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    for (const auto& [value, answers] : values) {
      const std::string flag = keys[k] + "=" + value;
      SCOPED_TRACE(flag);
      Sweep sweep;
      const std::string& refusal = answers[k];
      if (!refusal.empty()) {
        EXPECT_THAT(
            [&] {
              sweep.add_flag(flag);
              sweep.check(Config());
            },
            ThrowsMessage<ConfigError>("--grid " + one_line(flag) + ": " + refusal));
        continue;  // refused with a message, before any file is written
      }
      ASSERT_NO_THROW({
        sweep.add_flag(flag);
        sweep.check(Config());
      });
      ++accepted;
      const std::string yaml = sweep.to_yaml();
      Sweep again;
      ASSERT_NO_THROW(again.add_yaml(yaml, "config.yaml")) << yaml;
      EXPECT_EQ(again.axes()[0].values, sweep.axes()[0].values) << yaml;
      EXPECT_EQ(again.config(Config(), 0).to_yaml(), sweep.config(Config(), 0).to_yaml());
    }
  }
  // The comments, quotes and spaces around valid values, and the lists where lists belong.
  EXPECT_EQ(accepted, 16);
}

TEST(SweepGrid, ASweepKeyThatIsNotAKeyPathIsNamed) {
  EXPECT_THAT([] { Sweep().add_yaml("sweep: {[a, b]: [1]}", "my.yaml"); },
              ThrowsMessage<ConfigError>(
                  "my.yaml: a sweep's key is a key path such as actor.alpha; got [a, b]"));
  EXPECT_THAT([] { Sweep().add_flag("actor.alpha=[0.1"); },
              ThrowsMessage<ConfigError>(
                  ::testing::StartsWith("--grid actor.alpha=[0.1: '[0.1' is not a YAML value")));
}

}  // namespace
}  // namespace cbbg::config
