// Arms by name: the presets' and those a program registers, known to every command.

#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/run_names.h"
#include "tests/diagrams/slot_fixtures.h"

namespace cbbg::diagrams {
namespace {

using ::testing::ThrowsMessage;

TEST(Arms, ARegisteredArmIsKnownByNameWhereverAPresetIs) {
  ControllerOptions half = preset("cbbg").options;
  half.omega = blocks::OmegaMode::kConstant;
  register_arm("cbbg_half", "omega held at 0.5", half);
  register_arm("pitch_law", "a control law alone", [](const parameters::Parameters&) {
    return std::unique_ptr<Diagram>();  // never built here
  });
  EXPECT_EQ(registered_arms().size(), 2U);
  EXPECT_EQ(registered_arms()[0].description, "omega held at 0.5");
  EXPECT_EQ(arm_names().back(), "pitch_law");
  EXPECT_EQ(diagram_names().back(), "pitch_law");
  EXPECT_NO_THROW(experiments::check_arm_names({"cbbg", "cbbg_half", "pitch_law"}));

  const Arm named = named_arm("cbbg_half");
  EXPECT_EQ(named.name, "cbbg_half");
  ASSERT_TRUE(named.policy);  // it learns: its learnt actor alone is evaluated
  const ClosedLoop loop = named.learner(testing::quick_parameters());
  auto context = loop.diagram->create_context(1);
  EXPECT_EQ(loop.diagram->eval_output(*context, *loop.telemetry)[kTelemetryOmega], 0.5);
  EXPECT_FALSE(named_arm("pitch_law").policy);  // no policy given: it learns nothing

  EXPECT_THAT([&] { register_arm("cbbg_half", "", half); },
              ThrowsMessage<std::invalid_argument>("arm 'cbbg_half' is registered twice"));
  EXPECT_THAT([&] { register_arm("cbbg", "", half); },
              ThrowsMessage<std::invalid_argument>("arm 'cbbg' is registered twice"));
  EXPECT_THAT(
      [&] { register_arm("learnt_actor", "", half); },
      ThrowsMessage<std::invalid_argument>("arm 'learnt_actor': the name is the learnt actor's"));
  EXPECT_THAT([&] { register_arm("two words", "", half); },
              ThrowsMessage<std::invalid_argument>(
                  "arm 'two words': a name is letters, digits, '_', '-' and '.'"));
  EXPECT_THAT([] { named_arm("nope"); },
              ThrowsMessage<std::invalid_argument>(
                  "unknown arm 'nope'; the arms are cbbg, cbbg_weighted, bg_only, cb_only, "
                  "pd_only, cbbg_half, pitch_law"));
}

}  // namespace
}  // namespace cbbg::diagrams
