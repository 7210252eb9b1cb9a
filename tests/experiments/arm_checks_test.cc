// What is checked before any work: every arm built once (a factory's refusal is the user's
// mistake), a learner no larger than a weights file holds, a registered section's own checks
// and defaults.

#include <memory>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/blocks/learner.h"
#include "cbbg/config/declared_keys.h"
#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/arm_checks.h"
#include "cbbg/framework/block.h"

namespace cbbg::experiments {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

parameters::Parameters run_of(const std::string& arms) {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("arms=" + arms);
  return diagrams::validated_parameters(config);
}

/// Wide: input "x" (2), output "features" (`size`), all zero: features of any size.
class Wide final : public Block {
 public:
  Wide(std::string name, int size) : Block(std::move(name)) {
    const InputPort& x = declare_input_port("x", 2);
    declare_output_port("features", size, &Wide::zero, {&x});
  }

 private:
  static void zero(const BlockContext&, VectorRef phi) { phi.setZero(); }
};

TEST(ArmChecks, AFactoryThatRefusesTheParametersIsTheUsersMistake) {
  diagrams::register_arm(
      "refusing_arm", "a supervisor whose design fails",
      [](const parameters::Parameters&) -> std::shared_ptr<Diagram> {
        throw std::runtime_error("the discrete Riccati equation has no solution for dlqr.q");
      });
  EXPECT_THAT([] { check_arms_build(run_of("[cbbg, refusing_arm]")); },
              ThrowsMessage<config::ConfigError>(
                  "arm 'refusing_arm' cannot be built from this config: the discrete Riccati "
                  "equation has no solution for dlqr.q"));
  EXPECT_NO_THROW(check_arms_build(run_of("[cbbg, bg_only, pd_only]")));
}

TEST(ArmChecks, ALearnerLargerThanAWeightsFileHoldsIsRefused) {
  auto wide = [](int size) {
    diagrams::ControllerOptions options = diagrams::preset("bg_only").options;
    options.slots.features = [size](const std::string& name, const parameters::Parameters&) {
      return std::make_shared<Wide>(name, size);
    };
    return options;
  };
  diagrams::register_arm("widest_allowed", "as many features as a learner may have",
                         wide(blocks::kMaxFeatures));
  diagrams::register_arm("one_too_wide", "one feature more", wide(blocks::kMaxFeatures + 1));
  EXPECT_NO_THROW(check_arms_build(run_of("[widest_allowed]")));
  EXPECT_THAT([] { check_arms_build(run_of("[widest_allowed, one_too_wide]")); },
              ThrowsMessage<config::ConfigError>(::testing::StartsWith(
                  "arm 'one_too_wide' has 1000001 features per learner; a learner holds at most "
                  "1000000, what a weights file stores: make its features smaller (its layout: "
                  "normaliser.")));
}

TEST(ArmChecks, AnRbfGridTooLargeToStoreIsRefusedBeforeItIsBuilt) {
  config::Config config;
  config.set("normaliser.inputs=pitch_wheels");
  std::string centres = "rbf.centres=[";
  for (int c = 0; c < 32; ++c) {
    if (c > 0) centres += ',';
    centres += std::to_string(c);
  }
  config.set(centres + "]");
  EXPECT_THAT([&] { diagrams::validated_parameters(config); },
              ThrowsMessage<config::ConfigError>(
                  "rbf.centres (32 of them) over normaliser.inputs (4 inputs) make 1048576 "
                  "features per learner; a learner holds at most 1000000, what a weights file "
                  "stores: use fewer rbf.centres or normaliser.inputs"));
  config.set(
      "rbf.centres=[0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,24,25,"
      "26,27,28,29,30]");  // 31^4 = 923521 units
  EXPECT_NO_THROW(diagrams::validated_parameters(config));
}

TEST(ArmChecks, TheTasksAtOnceMustFitInTheMemoryTheMachineHas) {
  const std::size_t task = check_arms_build(run_of("[bg_only]"));
#if defined(__SANITIZE_ADDRESS__)
  EXPECT_EQ(task, 0u);  // the sanitizer's allocator reports no heap use: no figure, no check
#else
  EXPECT_GT(task, 10'000u);  // its weights, traces and features at least
#endif
  EXPECT_NO_THROW(check_run_memory(task, 2));
  EXPECT_THAT([] { check_run_memory(std::size_t{1} << 50, 3); },
              ThrowsMessage<config::ConfigError>(::testing::AllOf(
                  ::testing::StartsWith("this run would hold about 3377699.7 GB (1125899.9 GB "
                                        "per task, 3 at once) and the machine has "),
                  ::testing::EndsWith(" available: lower --jobs, or the features (rbf.centres, "
                                      "normaliser.inputs, a layout of your own)"))));
}

struct GainParams {
  double low = 1.0;
  double high = 2.0;
  template <class Archive>
  void describe(Archive& a) {
    a.number("low", low, "the lower gain", kPositive);
    a.number("high", high, "the higher gain", kPositive);
  }
  void validate() const {
    if (!(low < high)) throw std::invalid_argument("gains.low must be below gains.high");
  }
};

TEST(ArmChecks, ARegisteredSectionsChecksRunAtTheEdge) {
  config::register_section<GainParams>("gains", [](const GainParams& gains) {
    if (gains.high > 100.0) throw config::ConfigError("gains.high above 100 saturates the motor");
  });
  config::Config config;
  EXPECT_NO_THROW(diagrams::validated_parameters(config));
  config.set("gains.low=3");
  EXPECT_THAT([&] { diagrams::validated_parameters(config); },
              ThrowsMessage<config::ConfigError>("gains.low must be below gains.high"));
  config.set("gains.high=200");
  EXPECT_THAT([&] { diagrams::validated_parameters(config); },
              ThrowsMessage<config::ConfigError>("gains.high above 100 saturates the motor"));
}

struct BadDefaultParams {
  double gain = -1.0;
  template <class Archive>
  void describe(Archive& a) {
    a.number("gain", gain, "a gain", kPositive);
  }
};

TEST(ArmChecks, ASectionWhoseDefaultItsDeclarationRefusesIsNotRegistered) {
  EXPECT_THAT([] { config::register_section<BadDefaultParams>("bad_default"); },
              ThrowsMessage<std::invalid_argument>(
                  "config key 'bad_default.gain' has a default outside its declaration: "
                  "bad_default.gain must be > 0; got -1"));
  for (const config::KeySpec& spec : config::schema()) {
    EXPECT_NE(spec.path, "bad_default.gain");
    EXPECT_NO_THROW(config::check_default(spec)) << spec.path;
  }
}

}  // namespace
}  // namespace cbbg::experiments
