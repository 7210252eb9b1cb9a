// Keys made from declarations (config/declared_keys.h): every built-in key's default, range
// and message come from its params struct; a user's own section is set, swept, checked and
// recorded like a built-in one; the typed tree reads back what was set.

#include "config/declared_keys.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "config/parameters.h"
#include "config/sweep.h"
#include "framework/number_text.h"

namespace cbbg::config {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A user's own section, as a user's code declares it.
struct DlqrParams {
  double q_theta = 100.0;
  double q_dtheta = 1.0;
  std::string discretisation = "zoh";

  template <class Archive>
  void describe(Archive& a) {
    a.number("q_theta", q_theta, "state weight on the pitch", kNonNegative);
    a.number("q_dtheta", q_dtheta, "state weight on the pitch rate", kNonNegative);
    a.text("discretisation", discretisation, "zoh | tustin", {"zoh", "tustin"});
  }
};

// Registered once for the whole test program, before its first Config.
const bool kRegistered = [] {
  register_section<DlqrParams>("dlqr");
  return true;
}();

TEST(DeclaredKeys, EveryBuiltInKeyComesFromADeclarationWithItsDefault) {
  const Parameters defaults;
  const std::vector<KeySpec> declared = declared_keys(Parameters{}, "");
  ASSERT_GE(schema().size(), declared.size());
  for (std::size_t i = 0; i < declared.size(); ++i) {
    EXPECT_EQ(schema()[i].path, declared[i].path);
    EXPECT_EQ(schema()[i].default_value, declared[i].default_value) << declared[i].path;
  }
  // The tree a default Config reads back is the structs' own initialisers.
  const Parameters read = read_parameters(Config());
  EXPECT_EQ(read.critic.beta, defaults.critic.beta);
  EXPECT_EQ(read.plant.robot.body_mass, defaults.plant.robot.body_mass);
  EXPECT_EQ(read.sensors.noise_std, defaults.sensors.noise_std);
  EXPECT_EQ(read.annealing, defaults.annealing);
  EXPECT_EQ(read.run.arms, defaults.run.arms);
}

TEST(DeclaredKeys, EveryBoundedKeyRefusesAValueOutsideWithItsOwnMessage) {
  int checked = 0;
  for (const KeySpec& spec : schema()) {
    if (spec.kind != Kind::kNumber && spec.kind != Kind::kInteger) continue;
    if (!std::isfinite(spec.min)) continue;
    SCOPED_TRACE(spec.path);
    const double below = spec.min - 1.0;
    Config config;
    try {
      config.set(spec.path + "=" + std::to_string(below));
      ADD_FAILURE() << "accepted " << below;
    } catch (const ConfigError& error) {
      // The key, and the bound its declaration gives.
      const std::string bound = spec.kind == Kind::kInteger
                                    ? std::to_string(static_cast<long long>(spec.min))
                                    : format_number(spec.min);
      EXPECT_THAT(error.what(), HasSubstr(spec.path + " must be "));
      EXPECT_THAT(error.what(), HasSubstr(bound));
    }
    ++checked;
  }
  EXPECT_GE(checked, 30);
}

TEST(DeclaredKeys, ATypedTreeReadsBackWhatWasSetAndWritesBackTheSameConfig) {
  Config config;
  config.set("critic.gamma=0.5");
  config.set("plant.simbody_integrator=rk3");
  config.set("sensors.noise_std=[0.01, 0, 0, 0, 0, 0]");
  const Parameters read = read_parameters(config);
  EXPECT_EQ(read.critic.gamma, 0.5);
  EXPECT_EQ(read.plant.robot.simbody_integrator, plant::SimbodyIntegrator::kRungeKutta3);
  EXPECT_EQ(read.sensors.noise_std[0], 0.01);
  Config written;
  write_parameters(read, written);
  EXPECT_EQ(written.to_yaml(), config.to_yaml());
  Parameters bad = read;
  bad.critic.gamma = 1.5;
  EXPECT_THAT([&] { write_parameters(bad, written); },
              ThrowsMessage<ConfigError>("critic.gamma must be in (0, 1]; got 1.5"));
}

TEST(DeclaredKeys, AUsersSectionIsSetSweptCheckedAndRecorded) {
  ASSERT_TRUE(kRegistered);
  Config config;
  EXPECT_EQ(read_section<DlqrParams>(config, "dlqr").q_theta, 100.0);
  config.set("dlqr.q_theta=50");
  EXPECT_EQ(read_section<DlqrParams>(config, "dlqr").q_theta, 50.0);
  EXPECT_THAT(
      [&] { config.set("dlqr.q_theta=-1"); },
      ThrowsMessage<ConfigError>("--set dlqr.q_theta=-1: dlqr.q_theta must be >= 0; got -1"));
  EXPECT_THAT([&] { config.set("dlqr.q_thta=1"); },
              ThrowsMessage<ConfigError>(HasSubstr("did you mean 'dlqr.q_theta'?")));
  EXPECT_THAT([&] { config.set("dlqr.discretisation=euler"); },
              ThrowsMessage<ConfigError>(HasSubstr("must be one of zoh, tustin; got 'euler'")));
  // Recorded in config.yaml, and read back from it.
  const std::string yaml = config.to_yaml();
  EXPECT_THAT(yaml, HasSubstr("dlqr:\n  q_theta: 50\n  q_dtheta: 1\n  discretisation: zoh\n"));
  Config again;
  again.merge_yaml(yaml, "config.yaml");
  EXPECT_EQ(again, config);
  // Swept over a grid of 2 x 2 points, each point's config holding its values.
  Sweep sweep;
  sweep.add_flag("dlqr.q_theta=10,100");
  sweep.add_yaml("sweep: {dlqr.discretisation: [zoh, tustin]}", "my.yaml");
  sweep.check(config);
  ASSERT_EQ(sweep.points(), 4u);
  const DlqrParams last = read_section<DlqrParams>(sweep.config(config, 3), "dlqr");
  EXPECT_EQ(last.q_theta, 100.0);
  EXPECT_EQ(last.discretisation, "tustin");
  Sweep bad;
  bad.add_flag("dlqr.q_dtheta=1,-2");
  EXPECT_THAT([&] { bad.check(config); },
              ThrowsMessage<ConfigError>(HasSubstr("dlqr.q_dtheta must be >= 0; got -2")));
  EXPECT_THROW(register_section<DlqrParams>("dlqr"), std::invalid_argument);
}

// Below the edge nothing looks a key up by string: diagrams, experiments, blocks and the
// plant read the typed tree. (Plain text search: GCC 12 warns falsely on std::regex under
// the sanitizers' -O1.)
TEST(DeclaredKeys, NoCodeBelowTheEdgeLooksAKeyUpByString) {
  std::vector<std::string> lookups;
  for (const char* receiver : {"config", "training", "point", "c"}) {
    for (const char* accessor : {"number", "integer", "text", "numbers", "names", "annealing"}) {
      lookups.push_back(std::string(receiver) + "." + accessor + "(\"");
    }
  }
  int files = 0;
  for (const char* folder : {"diagrams", "experiments", "blocks", "plant"}) {
    const std::filesystem::path root = std::filesystem::path(CBBG_SOURCE_DIR) / folder;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      const std::string ending = entry.path().extension().string();
      if (ending != ".cc" && ending != ".h") continue;
      ++files;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      for (const std::string& lookup : lookups) {
        EXPECT_EQ(text.str().find(lookup), std::string::npos) << entry.path() << ": " << lookup;
      }
    }
  }
  EXPECT_GE(files, 40);
}

}  // namespace
}  // namespace cbbg::config
