// The golden test of `cbbg export`: the exported policy of weights a run learnt (exp3's
// bg_only arm, seed 1, until its actor balances alone), compiled as plain C99 by gcc (-std=c99
// -Wall -Wextra -Werror -pedantic; the policy itself also with -ffreestanding), fed every
// tick's measured signals of a 20 s trial of the C++ closed loop (the learnt actor alone,
// which balances it), must give the C++ actor's action: to the bit in double, within 1e-5 of
// the trial's largest action in float; for the paper's 49 features and for the 343 and 2401
// of the views that see the wheels.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/apps/learnt_policy.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/framework/block_harness.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/store/weights_file.h"
#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::testing {
namespace {

namespace fs = std::filesystem;

// Every tick of a trial: what the controller measured, and the C++ actor's action.
struct Recording {
  std::vector<std::vector<double>> measured;
  std::vector<double> action;
};

// 20 s of the learnt actor alone (the `cbbg eval` loop) with `weights`, on the analytic plant,
// its features seeing `inputs` (normaliser.inputs).
Recording record_trial(const experiments::LearntWeights& weights, const std::string& inputs) {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("normaliser.inputs=" + inputs);
  const parameters::Parameters parameters = diagrams::validated_parameters(config);
  const diagrams::ClosedLoop loop = app::policy_of(weights.provenance.arm)(parameters);
  Simulator simulator(*loop.diagram);
  experiments::load_learnt_weights(loop, simulator.context(), weights);
  const double period = parameters.trial.period;
  const SignalLog& measured =
      simulator.add_log(loop.diagram->block("sensors").output_port("measured"), period);
  const SignalLog& action =
      simulator.add_log(loop.learner.actor->learner_block().output_port("actor_action"), period);
  simulator.advance_to(20.0 - period / 2);
  Recording recording;
  for (Eigen::Index t = 0; t < measured.values().cols(); ++t) {
    const Eigen::VectorXd column = measured.values().col(t);
    recording.measured.emplace_back(column.begin(), column.end());
    recording.action.push_back(action.values()(0, t));
  }
  return recording;
}

// Runs `command` through the shell; fails the test with its output unless it succeeds.
void run(const std::string& command) {
  const std::string line = "(" + command + ") > command.log 2>&1";
  ASSERT_EQ(std::system(line.c_str()), 0) << command << "\n" << read_file("command.log");
}

// A driver of the exported `name`: reads six numbers a line, prints the action of each.
std::string driver_of(const std::string& name) {
  return "#include <stdio.h>\n#include \"" + name + ".h\"\n" +
         "int main(void) {\n  double in[6];\n  " + name + "_real measured[6];\n" +
         "  while (scanf(\"%lf %lf %lf %lf %lf %lf\", in, in + 1, in + 2, in + 3, in + 4, "
         "in + 5) == 6) {\n    int i;\n    for (i = 0; i < 6; ++i) measured[i] = (" +
         name + "_real)in[i];\n    printf(\"%.17g\\n\", (double)" + name +
         "_step(measured));\n  }\n  return 0;\n}\n";
}

// The exported policy `name` in `directory`, built by gcc and run over the recording.
std::vector<double> exported_actions(const fs::path& directory, const std::string& name,
                                     const Recording& recording) {
  const std::string flags = "gcc -std=c99 -Wall -Wextra -Werror -pedantic -O2";
  const fs::path here = fs::current_path();
  fs::current_path(directory);
  std::ofstream("driver.c") << driver_of(name);
  {
    std::ofstream input("measured.txt");
    char number[32];
    for (const auto& tick : recording.measured) {
      for (std::size_t i = 0; i < tick.size(); ++i) {
        std::snprintf(number, sizeof number, "%.17g", tick[i]);
        input << number << (i + 1 < tick.size() ? " " : "\n");
      }
    }
  }
  std::vector<double> actions;
  [&] {
    run(flags + " -ffreestanding -c " + name + ".c -o " + name + ".o");
    run(flags + " driver.c " + name + ".o -lm -o driver");
    run("./driver < measured.txt > actions.txt");
  }();
  std::ifstream output("actions.txt");
  for (double action; output >> action;) actions.push_back(action);
  fs::current_path(here);
  return actions;
}

// What the features see (normaliser.inputs) and how many they are.
struct View {
  const char* inputs;
  std::size_t features;
};

class PolicyExport : public ::testing::TestWithParam<View> {
 protected:
  void SetUp() override {
    const Outcome learnt =
        cbbg("run --experiment exp3 --seeds 1 --set 'arms=[bg_only]' --set plant.kind=analytic " +
             view().substr(1) + " --no-figures --no-replay --out " +
             (scratch_.path() / "run").string() + " --save-weights " + weights_file().string());
    ASSERT_EQ(learnt.exit_code, 0) << learnt.output;
    weights_ = store::load_weights(weights_file());
    ASSERT_EQ(static_cast<std::size_t>(weights_.features), GetParam().features);
    recording_ = record_trial(weights_, GetParam().inputs);
    ASSERT_EQ(recording_.action.size(), 2000u);  // it balanced the whole 20 s
  }
  fs::path weights_file() const { return scratch_.path() / "weights.txt"; }
  // The --set that gives the weights' view to a command (as `cbbg eval` needs it too).
  static std::string view() { return " --set normaliser.inputs=" + std::string(GetParam().inputs); }

  ScratchDirectory scratch_;
  experiments::LearntWeights weights_;
  Recording recording_;
};

TEST_P(PolicyExport, TheDoubleExportGivesTheActorsActionToTheBit) {
  const fs::path out = scratch_.path() / "double";
  const Outcome exported =
      cbbg("export --load-weights " + weights_file().string() + view() + " --out " + out.string());
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  const std::vector<double> actions = exported_actions(out, "cbbg_policy", recording_);
  ASSERT_EQ(actions.size(), recording_.action.size());
  int differing = 0;
  for (std::size_t t = 0; t < actions.size(); ++t) differing += actions[t] != recording_.action[t];
  EXPECT_EQ(differing, 0) << "of " << actions.size() << " ticks";
  // The trial moved the actor: its action is no constant.
  const auto [low, high] = std::minmax_element(actions.begin(), actions.end());
  EXPECT_GT(*high - *low, 0.1);
}

TEST_P(PolicyExport, TheFloatExportStaysWithinATenThousandthOfAPercent) {
  const fs::path out = scratch_.path() / "single";
  const Outcome exported = cbbg("export --load-weights " + weights_file().string() + view() +
                                " --out " + out.string() + " --scalar float --name policy32");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  const std::vector<double> actions = exported_actions(out, "policy32", recording_);
  ASSERT_EQ(actions.size(), recording_.action.size());
  double largest = 0.0;
  double difference = 0.0;
  for (std::size_t t = 0; t < actions.size(); ++t) {
    largest = std::max(largest, std::abs(recording_.action[t]));
    difference = std::max(difference, std::abs(actions[t] - recording_.action[t]));
  }
  std::printf("float export, %zu features: largest difference %.3g of the largest action %.3g\n",
              GetParam().features, difference, largest);
  EXPECT_LT(difference, 1e-5 * largest);
}

// With --omega, the export is the whole CB-BG controller at that omega without exploration:
// a = omega a_A + (1 - omega) a_S, the supervisor and the mixer written by their blocks; the
// same to the bit as the C++ blocks' a_A (the actor's, recorded) and a_S (the supervisor's:
// the PD's, or with supervisor.kind: lqr the LQR's, its gains designed on the same robot).
class PolicyExportWithOmega : public ::testing::Test {
 protected:
  void SetUp() override {
    const Outcome learnt = cbbg(
        "run --experiment exp3 --seeds 1 --set 'arms=[cbbg]' --set plant.kind=analytic "
        "--no-figures --no-replay --out " +
        (scratch_.path() / "run").string() + " --save-weights " + weights_file().string());
    ASSERT_EQ(learnt.exit_code, 0) << learnt.output;
    recording_ = record_trial(store::load_weights(weights_file()), "pitch");
    ASSERT_EQ(recording_.action.size(), 2000u);
  }
  fs::path weights_file() const { return scratch_.path() / "weights.txt"; }

  // The ticks where the export of `flags` differs from omega a_A + (1 - omega) a_S, a_S the
  // `supervisor` block's.
  template <typename Supervisor>
  int differing_ticks(const std::string& flags, BlockHarness<Supervisor>& supervisor) {
    const fs::path out = scratch_.path() / "mixed";
    const Outcome exported = cbbg("export --load-weights " + weights_file().string() +
                                  " --omega 0.25 --out " + out.string() + flags);
    EXPECT_EQ(exported.exit_code, 0) << exported.output;
    const std::vector<double> actions = exported_actions(out, "cbbg_policy", recording_);
    EXPECT_EQ(actions.size(), recording_.action.size());
    const double w = 0.25;
    int differing = 0;
    for (std::size_t t = 0; t < actions.size(); ++t) {
      supervisor.set_input("measured", Eigen::Map<const Vector>(recording_.measured[t].data(), 6));
      const double expected =
          w * recording_.action[t] + (1.0 - w) * supervisor.scalar_output("action");
      differing += actions[t] != expected;
    }
    return differing;
  }

  ScratchDirectory scratch_;
  Recording recording_;
};

TEST_F(PolicyExportWithOmega, TheMixedPolicyGivesTheCppBlocksActionToTheBit) {
  BlockHarness<blocks::PdSupervisor> supervisor("supervisor", blocks::PdSupervisorParams{});
  EXPECT_EQ(differing_ticks("", supervisor), 0) << "of 2000 ticks";
}

TEST_F(PolicyExportWithOmega, AnLqrSupervisorIsWrittenAsCToTheBitToo) {
  BlockHarness<blocks::LqrSupervisor> supervisor("supervisor", plant::RobotParams{},
                                                 blocks::LqrSupervisorParams{});
  EXPECT_EQ(differing_ticks(" --set supervisor.kind=lqr", supervisor), 0) << "of 2000 ticks";
}

INSTANTIATE_TEST_SUITE_P(Views, PolicyExport,
                         ::testing::Values(View{"pitch", 49}, View{"pitch_wheel_rate", 343},
                                           View{"pitch_wheels", 2401}),
                         [](const auto& view) { return std::string(view.param.inputs); });

}  // namespace
}  // namespace cbbg::testing
