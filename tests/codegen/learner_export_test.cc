// The golden test of the learner export (`cbbg export --learner`): the exported online
// learner, compiled as plain C99 by gcc (-std=c99 -Wall -Wextra -Werror -pedantic; the learner
// itself also with -ffreestanding), fed every tick's measured signals of trials of the C++
// closed loop as it learns, must give the C++ controller's action at every tick, end the
// trials where the C++ loop ended them, and hold the C++ critic's and actor's weights after
// the last: to the bit in double.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/arms.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/policy_export.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/store/weights_file.h"
#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::testing {
namespace {

namespace fs = std::filesystem;

// One tick of a trial: what the controller measured, and the C++ controller's action.
struct Tick {
  std::vector<double> measured;
  double action = 0.0;
};

struct Trial {
  std::vector<Tick> ticks;
  bool ended = false;  // the loop ended it (the robot fell) before its duration
};

// What a learner did: its trials, and the critic's and actor's weights after the last.
struct Learning {
  std::vector<Trial> trials;
  std::vector<double> critic, actor;
};

const OutputPort& leaf(const OutputPort& port) {
  if (!port.block().is_diagram()) return port;
  const auto& diagram = static_cast<const Diagram&>(port.block());
  return leaf(*diagram.exported_outputs()[static_cast<std::size_t>(port.index())]);
}

// The learner's loop and a simulator of it whose context is the exported one.
struct LearnerRun {
  diagrams::ClosedLoop loop;
  Simulator simulator;
  double period;

  LearnerRun(const parameters::Parameters& parameters, const std::string& arm)
      : loop(diagrams::named_arm(arm).learner(parameters)),
        simulator(*loop.diagram, {}, parameters.run.seed),
        period(parameters.trial.period) {}

  // `count` trials of `duration` s from pitch `theta0`, every tick recorded.
  Learning learn(int count, double duration, double theta0) {
    Learning learning;
    Trial* current = nullptr;
    std::vector<double> measured;
    SignalLog& sensed =
        simulator.add_log(leaf(loop.diagram->block("sensors").output_port("measured")), period);
    sensed.keep_in_memory(false);
    sensed.set_sink(
        [&measured](double, const double* values) { measured.assign(values, values + 6); });
    SignalLog& acted = simulator.add_log(leaf(loop.controller->output_port("action")), period);
    acted.keep_in_memory(false);
    acted.set_sink([&](double, const double* values) {
      current->ticks.push_back({measured, values[0]});
    });
    for (int k = 0; k < count; ++k) {
      current = &learning.trials.emplace_back();
      loop.start_trial(simulator.context(), theta0);
      simulator.initialize();
      current->ended = simulator.advance_to(duration - period / 2).terminated;
    }
    const Context& context = simulator.context();
    const auto critic = context.discrete_state(loop.learner.critic->learner_block());
    const auto actor = context.discrete_state(loop.learner.actor->learner_block());
    const int n = loop.learner.actor->num_features();
    learning.critic.assign(critic.begin(), critic.begin() + n);
    learning.actor.assign(actor.begin(), actor.begin() + n);
    return learning;
  }
};

// Runs `command` through the shell; fails the test with its output unless it succeeds.
void run(const std::string& command) {
  const std::string line = "(" + command + ") > command.log 2>&1";
  ASSERT_EQ(std::system(line.c_str()), 0) << command << "\n" << read_file("command.log");
}

// A driver of the learner `name`: "T" starts a trial, "M" and six numbers step it (printing
// the action and whether the trial ended); at the end it prints the weights of the members
// `critic` and `actor` (n each). With an argument, the generators start from that seed.
std::string driver_of(const std::string& name, const std::string& critic, const std::string& actor,
                      int n) {
  const std::string p = name + "_";
  return "#include <stdio.h>\n#include <stdlib.h>\n#include \"" + name + ".h\"\n" + "static " + p +
         "state learner;\n" + "int main(int argc, char **argv) {\n  char kind[2];\n  int i;\n  " +
         p + "init(&learner);\n  if (argc > 1) " + p +
         "seed(&learner, strtoull(argv[1], 0, 10));\n" +
         "  while (scanf(\"%1s\", kind) == 1) {\n    double in[6];\n    " + p +
         "real measured[6], action;\n    int ended;\n" + "    if (kind[0] == 'T') {\n      " + p +
         "start_trial(&learner);\n      continue;\n    }\n" +
         "    if (scanf(\"%lf %lf %lf %lf %lf %lf\", in, in + 1, in + 2, in + 3, in + 4, in + 5) "
         "!= 6) return 1;\n" +
         "    for (i = 0; i < 6; ++i) measured[i] = (" + p + "real)in[i];\n" + "    ended = " + p +
         "step(&learner, measured, &action);\n" +
         "    printf(\"%.17g %d\\n\", (double)action, ended);\n  }\n" + "  for (i = 0; i < " +
         std::to_string(n) + "; ++i) printf(\"w %.17g %.17g\\n\", (double)learner." + critic +
         ".weights[i], (double)learner." + actor + ".weights[i]);\n  return 0;\n}\n";
}

// What the exported learner did over the recorded trials.
struct Replay {
  std::vector<double> actions;
  std::vector<int> ended;
  std::vector<double> critic, actor;
};

// The learner `name` in `directory`, built by gcc and run over `learning`'s measured signals
// (with `seed`, from N_seed instead of the exported generators).
Replay replay(const fs::path& directory, const std::string& name, const Learning& learning,
              const std::string& critic, const std::string& actor, const std::string& seed = "") {
  const std::string flags = "gcc -std=c99 -Wall -Wextra -Werror -pedantic -O2";
  const fs::path here = fs::current_path();
  fs::current_path(directory);
  std::ofstream("driver.c") << driver_of(name, critic, actor,
                                         static_cast<int>(learning.actor.size()));
  {
    std::ofstream input("ticks.txt");
    char number[32];
    for (const Trial& trial : learning.trials) {
      input << "T\n";
      for (const Tick& tick : trial.ticks) {
        input << "M";
        for (const double value : tick.measured) {
          std::snprintf(number, sizeof number, " %.17g", value);
          input << number;
        }
        input << "\n";
      }
    }
  }
  Replay replay;
  [&] {
    run(flags + " -ffreestanding -c " + name + ".c -o " + name + ".o");
    run(flags + " driver.c " + name + ".o -lm -o driver");
    run("./driver " + seed + " < ticks.txt > replay.txt");
  }();
  std::ifstream output("replay.txt");
  for (std::string word; output >> word;) {
    if (word == "w") {
      double c = 0, a = 0;
      output >> c >> a;
      replay.critic.push_back(c);
      replay.actor.push_back(a);
    } else {
      int ended = 0;
      output >> ended;
      replay.actions.push_back(std::stod(word));
      replay.ended.push_back(ended);
    }
  }
  fs::current_path(here);
  return replay;
}

parameters::Parameters analytic(const std::vector<std::string>& sets = {}) {
  config::Config config;
  config.set("plant.kind=analytic");
  for (const std::string& set : sets) config.set(set);
  return diagrams::validated_parameters(config);
}

// The ticks where the replay's action differs from the C++ one, or where it ends a trial the
// C++ loop did not end there.
int differing_ticks(const Learning& learning, const Replay& replay) {
  int differing = 0;
  std::size_t at = 0;
  for (const Trial& trial : learning.trials) {
    for (std::size_t t = 0; t < trial.ticks.size(); ++t, ++at) {
      if (at >= replay.actions.size()) return differing + 1;
      const bool last = t + 1 == trial.ticks.size();
      differing += replay.actions[at] != trial.ticks[t].action ||
                   (replay.ended[at] != 0) != (last && trial.ended);
    }
  }
  return differing + static_cast<int>(replay.actions.size() - at);
}

std::size_t ticks_of(const Learning& learning) {
  std::size_t ticks = 0;
  for (const Trial& trial : learning.trials) ticks += trial.ticks.size();
  return ticks;
}

// A learner's arm and keys.
struct Variant {
  const char* name;
  const char* arm;
  std::vector<std::string> sets;
};

// The C++ loop's learner from zero weights: four trials of 10 s, while omega rises from the
// supervisor's to the actor's action and the exploration draws at every tick.
class LearnerExport : public ::testing::TestWithParam<Variant> {
 protected:
  void SetUp() override {
    run_ = std::make_unique<LearnerRun>(analytic(GetParam().sets), GetParam().arm);
    codegen::CLearnerOptions options;
    options.period = run_->period;
    write(experiments::export_learner(run_->loop, run_->simulator.context(), options),
          "cbbg_learner", scratch_.path() / "double");
    options.name = "learner32";
    options.scalar = codegen::Scalar::kFloat;
    write(experiments::export_learner(run_->loop, run_->simulator.context(), options), "learner32",
          scratch_.path() / "single");
    learning_ = run_->learn(4, 10.0, 0.1);
    critic_ = run_->loop.learner.critic->learner_block().name();
    actor_ = run_->loop.learner.actor->learner_block().name();
  }
  static void write(const codegen::CSources& sources, const std::string& name,
                    const fs::path& directory) {
    fs::create_directories(directory);
    std::ofstream(directory / (name + ".h")) << sources.header;
    std::ofstream(directory / (name + ".c")) << sources.source;
  }

  ScratchDirectory scratch_;
  std::unique_ptr<LearnerRun> run_;
  Learning learning_;
  std::string critic_, actor_;
};

TEST_P(LearnerExport, TheDoubleLearnerActsAndLearnsAsTheCppLoopToTheBit) {
  ASSERT_GT(ticks_of(learning_), 1000u);
  const Replay replayed =
      replay(scratch_.path() / "double", "cbbg_learner", learning_, critic_, actor_);
  EXPECT_EQ(differing_ticks(learning_, replayed), 0) << "of " << ticks_of(learning_) << " ticks";
  EXPECT_EQ(replayed.critic, learning_.critic);
  EXPECT_EQ(replayed.actor, learning_.actor);
  // It learnt: the weights moved from zero.
  double largest = 0.0;
  for (const double weight : learning_.actor) largest = std::max(largest, std::abs(weight));
  EXPECT_GT(largest, 0.1);
}

TEST_P(LearnerExport, SeedingGivesTheGeneratorsARunOfThatSeedStartsWith) {
  const Replay exported =
      replay(scratch_.path() / "double", "cbbg_learner", learning_, critic_, actor_);
  const Replay seeded = replay(scratch_.path() / "double", "cbbg_learner", learning_, critic_,
                               actor_, std::to_string(analytic(GetParam().sets).run.seed));
  EXPECT_EQ(seeded.actions, exported.actions);
  const Replay other = replay(scratch_.path() / "double", "cbbg_learner", learning_, critic_,
                              actor_, std::to_string(analytic(GetParam().sets).run.seed + 1));
  EXPECT_NE(other.actions, exported.actions);
}

TEST_P(LearnerExport, TheFloatLearnerStaysCloseToTheCppLoop) {
  const Replay replayed =
      replay(scratch_.path() / "single", "learner32", learning_, critic_, actor_);
  ASSERT_EQ(replayed.actions.size(), ticks_of(learning_));
  double largest = 0.0, difference = 0.0;
  std::size_t at = 0;
  for (const Trial& trial : learning_.trials) {
    for (const Tick& tick : trial.ticks) {
      largest = std::max(largest, std::abs(tick.action));
      difference = std::max(difference, std::abs(replayed.actions[at++] - tick.action));
    }
  }
  double weights = 0.0, weight_difference = 0.0;
  for (std::size_t i = 0; i < learning_.actor.size(); ++i) {
    weights = std::max(weights, std::abs(learning_.actor[i]));
    weight_difference =
        std::max(weight_difference, std::abs(replayed.actor[i] - learning_.actor[i]));
  }
  std::printf(
      "float learner over %zu ticks: largest action difference %.3g of %.3g; "
      "largest actor weight difference %.3g of %.3g\n",
      at, difference, largest, weight_difference, weights);
  EXPECT_LT(difference, 1e-5 * largest);
  EXPECT_LT(weight_difference, 1e-5 * weights);
}

// `cbbg export --learner`: the learner of a weights file, its generators as run.seed's,
// goes on learning as the C++ loop does from the same weights, to the bit.
class LearnerExportCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const Outcome learnt = cbbg(
        "run --experiment cbbg --seeds 1 --set plant.kind=analytic "
        "--no-figures --no-replay --out " +
        (scratch_.path() / "run").string() + " --save-weights " + weights_file().string());
    ASSERT_EQ(learnt.exit_code, 0) << learnt.output;
  }
  fs::path weights_file() const { return scratch_.path() / "weights.txt"; }
  Outcome export_learner(const std::string& flags) const {
    return cbbg("export --learner --load-weights " + weights_file().string() +
                " --set plant.kind=analytic --out " + (scratch_.path() / "robot").string() + flags);
  }

  ScratchDirectory scratch_;
};

TEST_F(LearnerExportCommand, TheLearnerOfAWeightsFileLearnsOnAsTheCppLoopDoes) {
  const Outcome exported = export_learner("");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  EXPECT_THAT(read_file(scratch_.path() / "robot" / "cbbg_learner.h"),
              ::testing::HasSubstr("the whole online learner, its generators as run.seed's"));
  const parameters::Parameters parameters = analytic();
  LearnerRun run(parameters, "cbbg");
  experiments::load_learnt_weights(run.loop, run.simulator.context(),
                                   store::load_weights(weights_file()));
  const Learning learning = run.learn(2, 20.0, parameters.trial.theta0);
  const Replay replayed = replay(scratch_.path() / "robot", "cbbg_learner", learning,
                                 run.loop.learner.critic->learner_block().name(),
                                 run.loop.learner.actor->learner_block().name());
  EXPECT_EQ(differing_ticks(learning, replayed), 0) << "of " << ticks_of(learning) << " ticks";
  EXPECT_EQ(replayed.critic, learning.critic);
  EXPECT_EQ(replayed.actor, learning.actor);
}

TEST_F(LearnerExportCommand, RefusesOmegaWithTheLearner) {
  const Outcome with_omega = export_learner(" --omega 0.5");
  EXPECT_EQ(with_omega.exit_code, 2);
  EXPECT_EQ(with_omega.output,
            "cbbg: error: --learner and --omega exclude each other: the learner mixes at its own "
            "omega schedule\n");
  EXPECT_FALSE(fs::exists(scratch_.path() / "robot"));
}

// The paper's learner (exp1's arm: TD(lambda) critic, the improved actor, Boltzmann
// exploration, the sliding reward); the other critic and actor rules; the fixed temperature,
// the reward that sees the wheels and 343 features; Gaussian exploration that decays, with the
// quadratic reward; Ornstein-Uhlenbeck exploration.
INSTANTIATE_TEST_SUITE_P(
    Learners, LearnerExport,
    ::testing::Values(
        Variant{"paper", "cbbg", {}},
        Variant{"td0_weighted", "cbbg", {"critic.kind=td0", "actor.rule=weighted"}},
        Variant{"fixed_temperature_wheels",
                "cbbg",
                {"tropism.kind=fixed", "reward.k_phi=0.1", "normaliser.inputs=pitch_wheel_rate"}},
        Variant{"gaussian_quadratic",
                "cbbg",
                {"exploration.kind=gaussian", "exploration.half_life=5", "reward.kind=quadratic"}},
        Variant{"ou", "cbbg", {"exploration.kind=ou"}},
        Variant{
            "per_axis_wheels", "cbbg", {"rbf.units=per_axis", "normaliser.inputs=pitch_wheels"}}),
    [](const auto& variant) { return std::string(variant.param.name); });

}  // namespace
}  // namespace cbbg::testing
