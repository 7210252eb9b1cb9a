// config::Sweep: axes from --grid and from a config file's sweep: section, the grid's order,
// each point's config, and its errors, each naming where the axis came from.

#include "config/sweep.h"

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
  EXPECT_EQ(sweep.axes()[0].values, (std::vector<std::string>{"[-1, 0, 1]", "[-2,0,2]"}));
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
