// config::Sweep: axes from --grid and from a config file's sweep: section, the grid's order,
// each point's config, and its errors, each naming where the axis came from.

#include "cbbg/config/sweep.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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

// Whatever a user may type as a grid value is either refused before anything is written, or
// written as YAML that reads back to the same values and the same grid points.
TEST(SweepGrid, HostileValuesAreRefusedOrReadBackUnchanged) {
  const std::vector<std::string> keys = {"critic.beta", "arms", "evaluation.angles", "plant.kind"};
  const std::vector<std::string> values = {"0.1 # note",
                                           "0.1#x",
                                           "  0.2",
                                           "'0.1'",
                                           "\"0.1\"",
                                           "0.1\n# more",
                                           "0.1 # é ünï",
                                           "[cbbg, bg_only] # mine",
                                           "[bg_only]",
                                           "a: b",
                                           "'it''s'",
                                           "\"x\\ny\"",
                                           "é",
                                           "#",
                                           "[cbbg",
                                           ":",
                                           "'analytic' # fast",
                                           "\"simbody\"",
                                           "'[0.1, 0.2]'",
                                           "[0.05, 0.1] # two",
                                           "- 1",
                                           "&a 1",
                                           "!!str 0.1",
                                           "{}",
                                           "~"};
  int accepted = 0;
  for (const std::string& key : keys) {
    for (const std::string& value : values) {
      SCOPED_TRACE(key + "=" + value);
      Sweep sweep;
      try {
        sweep.add_flag(key + "=" + value);
        sweep.check(Config());
      } catch (const ConfigError&) {
        continue;  // refused with a message, before any file is written
      }
      ++accepted;
      const std::string yaml = sweep.to_yaml();
      Sweep again;
      ASSERT_NO_THROW(again.add_yaml(yaml, "config.yaml")) << yaml;
      EXPECT_EQ(again.axes()[0].values, sweep.axes()[0].values) << yaml;
      EXPECT_EQ(again.config(Config(), 0).to_yaml(), sweep.config(Config(), 0).to_yaml());
    }
  }
  EXPECT_GE(accepted, 12);  // the comments, quotes and spaces around valid values
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
