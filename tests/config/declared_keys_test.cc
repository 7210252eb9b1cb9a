// Keys made from declarations (config/declared_keys.h): every built-in key's default, range
// and message come from its params struct; a user's own section is set, swept, checked and
// recorded like a built-in one; the typed tree reads back what was set.

#include "cbbg/config/declared_keys.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/config/sweep.h"
#include "cbbg/experiments/protocols.h"  // the keys of a cbbg run: the tree's and the protocols'
#include "cbbg/framework/number_text.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::config {
namespace {

using parameters::Parameters;
using parameters::read_parameters;
using parameters::write_parameters;
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
  // The tree's keys, in its order, with the protocols' keys placed among them taken out.
  std::vector<KeySpec> tree;
  for (const KeySpec& spec : schema()) {
    if (!experiments::is_protocol_key(spec.path)) tree.push_back(spec);
  }
  const std::vector<KeySpec> declared = declared_keys(Parameters{}, "");
  ASSERT_GE(tree.size(), declared.size());
  for (std::size_t i = 0; i < declared.size(); ++i) {
    EXPECT_EQ(tree[i].path, declared[i].path);
    EXPECT_EQ(tree[i].default_value, declared[i].default_value) << declared[i].path;
  }
  // The tree a default Config reads back is the structs' own initialisers.
  const Parameters read = read_parameters(Config());
  EXPECT_EQ(read.critic.beta, defaults.critic.beta);
  EXPECT_EQ(read.plant.robot.body_mass, defaults.plant.robot.body_mass);
  EXPECT_EQ(read.sensors.noise_std, defaults.sensors.noise_std);
  EXPECT_EQ(read.run.arms, defaults.run.arms);
}

// One value just outside a declared bound, and the message that must refuse it.
struct Refusal {
  std::string assignment;  // "critic.gamma=1.5"
  std::string message;     // "--set critic.gamma=1.5: critic.gamma must be in (0, 1]; got 1.5"
};

// Every refusal the declaration of `spec` promises: a number past each finite bound (its
// first element for a list); a word outside its choices.
std::vector<Refusal> refusals_of(const KeySpec& spec) {
  std::vector<Refusal> refusals;
  auto past = [&](double bound, bool exclusive, double step) {
    const double value = exclusive ? bound : bound + step;
    const std::string text = format_number(value);
    if (spec.kind == Kind::kNumbers) {
      const auto& list = std::get<std::vector<double>>(spec.default_value);
      std::string items = "[" + text;
      for (std::size_t i = 1; i < std::max<std::size_t>(list.size(), 1); ++i) items += ", 0.5";
      const std::string assignment = spec.path + "=" + items + "]";
      refusals.push_back(
          {assignment, "--set " + assignment + ": " + spec.path + "[0] must be " +
                           allowed_values(spec).substr(allowed_values(spec).find("each ") + 5) +
                           "; got " + text});
      return;
    }
    const std::string assignment = spec.path + "=" + text;
    refusals.push_back({assignment, "--set " + assignment + ": " + spec.path + " must be " +
                                        allowed_values(spec) + "; got " + text});
  };
  const bool numeric =
      spec.kind == Kind::kNumber || spec.kind == Kind::kInteger || spec.kind == Kind::kNumbers;
  if (numeric && std::isfinite(spec.min)) past(spec.min, spec.min_exclusive, -1.0);
  if (numeric && std::isfinite(spec.max)) past(spec.max, spec.max_exclusive, +1.0);
  if (spec.kind == Kind::kText && !spec.choices.empty()) {
    const std::string assignment = spec.path + "=no_such_word";
    refusals.push_back({assignment, "--set " + assignment + ": " + spec.path + " must be " +
                                        allowed_values(spec) + "; got 'no_such_word'"});
  }
  return refusals;
}

// The table of every key's default, range and message is the declarations' own (schema()
// is made from them): nothing here lists a key by hand.
TEST(DeclaredKeys, EveryKeyHasItsDeclaredDefaultAndRefusesWhatItsDeclarationRefuses) {
  const Config defaults;
  int refused = 0;
  for (const KeySpec& spec : schema()) {
    SCOPED_TRACE(spec.path);
    EXPECT_EQ(defaults.value(spec.path), spec.default_value);
    Config config;
    EXPECT_NO_THROW(config.assign(spec.path, spec.default_value));
    for (const Refusal& refusal : refusals_of(spec)) {
      EXPECT_THAT([&] { config.set(refusal.assignment); },
                  ThrowsMessage<ConfigError>(refusal.message));
      ++refused;
    }
    EXPECT_EQ(config, defaults);  // a refused value leaves the config as it was
  }
  EXPECT_GE(refused, 60);
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
// plant take the typed tree, and no function of theirs takes or reads a Config but the edge
// itself (diagrams/validated_parameters). (Plain text search: GCC 12 warns falsely on
// std::regex under the sanitizers' -O1.)
TEST(DeclaredKeys, NoCodeBelowTheEdgeLooksAKeyUpByString) {
  std::vector<std::string> lookups{"config::Config ", "Config&", "read_parameters("};
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
      if (entry.path().stem() == "validated_parameters") continue;  // the edge
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
