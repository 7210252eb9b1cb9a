// Runs the real `cbbg` binary and checks what a user sees: exit code, message, files.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/protocols.h"  // the keys of a cbbg run: the tree's and the protocols'
#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using cbbg::testing::cbbg;
using cbbg::testing::Outcome;
using cbbg::testing::read_file;
using cbbg::testing::start_cbbg;

class CbbgCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_directory_.emplace();
    scratch_ = scratch_directory_->path();
  }
  std::optional<cbbg::testing::ScratchDirectory> scratch_directory_;
  fs::path scratch_;
};

// A quick run: the analytic plant, few seeds.
constexpr const char* kQuick = "--set plant.kind=analytic --no-figures";

// exp3 from the command line: the skill per seed, the paired comparison, the actor_alone
// column and the skill figure.
TEST_F(CbbgCommand, Exp3WritesTheSkillThePairedComparisonAndItsFigure) {
  const fs::path out = scratch_ / "exp3";
  const auto run =
      cbbg("run --experiment exp3 --set plant.kind=analytic --seeds 3 --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("(trials until the actor alone balances; of the seeds that "
                                    "got there)"));
  const std::string summary = cbbg::testing::read_file(out / "summary.json");
  EXPECT_THAT(summary, HasSubstr("\"trials_to_skill\": ["));
  EXPECT_THAT(summary, HasSubstr("{\"a\": \"cbbg\", \"b\": \"bg_only\", \"figure\": "
                                 "\"trials_to_skill\", \"mean_b_minus_a\": "));
  EXPECT_THAT(cbbg::testing::read_file(out / "trials.csv"),
              ::testing::StartsWith("arm,seed,trial,failed,steps,mean_temperature,mean_entropy,"
                                    "final_theta,status,actor_alone\n"));
  EXPECT_GT(fs::file_size(out / "figures" / "skill.png"), 10000u);
}

TEST_F(CbbgCommand, UnknownKeyExitsTwoWithASuggestionAndWritesNothing) {
  const fs::path out = scratch_ / "results";
  const Outcome outcome = cbbg("run --set critic.gama=0.5 --out " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.output,
            "cbbg: error: --set critic.gama=0.5: unknown key 'critic.gama'; did you mean "
            "'critic.gamma'?\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CbbgCommand, OutOfRangeAndNonFiniteValuesExitTwo) {
  const fs::path out = scratch_ / "results";
  Outcome outcome = cbbg("run --set critic.gamma=1.5 --out " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.output,
            "cbbg: error: --set critic.gamma=1.5: critic.gamma must be in (0, 1]; got 1.5\n");
  outcome = cbbg("run --set plant.body_mass=.nan --out " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.output, HasSubstr("plant.body_mass must be a finite number"));
  outcome = cbbg("run --experiment exp4 --out " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.output,
            "cbbg: error: --experiment exp4: experiment must be one of exp1, exp2, exp3, evaluate, "
            "transfer, realtime, cbbg, cbbg_weighted, bg_only, cb_only, pd_only; got 'exp4'\n");
  EXPECT_FALSE(fs::exists(out));
}

// A protocol's own check refuses before anything is written, in one line, exit 2.
TEST_F(CbbgCommand, AProtocolsOwnRefusalsExitTwoAndWriteNothing) {
  const fs::path out = scratch_ / "results";
  Outcome outcome = cbbg("run --experiment evaluate --set arms=[cbbg] --out " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.output,
            "cbbg: error: the evaluate protocol tests the weights of --load-weights; arm 'cbbg' "
            "learns and none were given\n");
  outcome = cbbg("run --experiment transfer --set transfer.conditions=[critic.gamma=0.5] --out " +
                 out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.output,
            "cbbg: error: transfer.conditions[0]: a condition sets what the evaluation sees: keys "
            "of evaluation.*, plant.* (not plant.kind), sensors.*, push.* or a registered "
            "section; got 'critic.gamma'\n");
  outcome = cbbg(
      "run --experiment transfer --set transfer.conditions=[evaluation.noise_std=-1] "
      "--out " +
      out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.output,
            "cbbg: error: --set transfer.conditions=[evaluation.noise_std=-1]: "
            "transfer.conditions[0]: evaluation.noise_std must be >= 0; got -1\n");
  outcome = cbbg(
      "run --experiment transfer --grid transfer.training=exp1,exp3 "
      "--set transfer.conditions=[plant.kind=analytic] --out " +
      out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.output, HasSubstr("cbbg: error: grid point 001: transfer.conditions[0]: a "
                                        "condition sets what the evaluation sees"));
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CbbgCommand, EveryKindOfBadValueExitsTwoWithItsMessageAndWritesNothing) {
  const fs::path out = scratch_ / "results";
  const std::pair<const char*, const char*> cases[] = {
      {"--set trial.period=0", "trial.period must be > 0; got 0"},
      {"--set plant.body_mass=-1", "plant.body_mass must be > 0; got -1"},
      {"--set rbf.width=-0.5", "rbf.width must be > 0; got -0.5"},
      {"--set critic.lambda=1", "critic.lambda must be in [0, 1); got 1"},
      {"--set seed=-4", "seed must be an integer in [0, 1000000000000]; got -4"},
      {"--set max_trials=2.5", "max_trials must be an integer in [1, 100000]; got '2.5'"},
      {"--set 'annealing=[{from_trial: 1, k1: 10}, {from_trial: 1, k1: 5}]'",
       "annealing must list trials in increasing order"},
      {"--set sampler.k_b=.inf", "sampler.k_b must be a finite number; got '.inf'"},
      {"--set actor.rule=best", "actor.rule must be one of improved, weighted; got 'best'"},
      {"--set supervisor.kind=lqr --set supervisor.lqr_q=[1,0,1,1]",
       "give no stabilising LQR gain"},
      {"--set trial=3", "trial is a section: give a map of its keys"},
  };
  for (const auto& [arguments, message] : cases) {
    const Outcome outcome = cbbg(std::string("run ") + arguments + " --out " + out.string());
    EXPECT_EQ(outcome.exit_code, 2) << arguments;
    EXPECT_THAT(outcome.output, HasSubstr(message)) << arguments;
    EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << arguments;
    EXPECT_FALSE(fs::exists(out)) << arguments;
    EXPECT_FALSE(fs::exists(scratch_ / "results.partial")) << arguments;
  }
}

TEST_F(CbbgCommand, ABadConfigFileExitsTwoNamingTheFile) {
  const fs::path config = scratch_ / "bad.yaml";
  std::ofstream(config) << "critic:\n  gamma: [0.5\n";
  const fs::path out = scratch_ / "results";
  Outcome outcome = cbbg("run --config " + config.string() + " --out " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.output,
              HasSubstr("cbbg: error: " + config.string() + ": malformed YAML at line"));
  outcome = cbbg("run --config " + (scratch_ / "missing.yaml").string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.output, HasSubstr("missing.yaml"));
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CbbgCommand, CommandLineMisuseExitsTwo) {
  EXPECT_EQ(cbbg("frobnicate").exit_code, 2);
  EXPECT_EQ(cbbg("run --jobs 0").exit_code, 2);
  EXPECT_EQ(cbbg("run --jobs many").exit_code, 2);
  EXPECT_EQ(cbbg("run --no-such-flag").exit_code, 2);
  const Outcome help = cbbg("run --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.output, HasSubstr("--experiment"));
}

TEST_F(CbbgCommand, DecimationZeroWritesNoStepsFile) {
  const fs::path out = scratch_ / "quiet";
  const Outcome outcome = cbbg(std::string("run ") + kQuick +
                               " --seeds 1 --set log.decimation=0 --out " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_TRUE(fs::exists(out / "trials.csv"));
  EXPECT_FALSE(fs::exists(out / "steps.csv"));
}

TEST_F(CbbgCommand, RunWritesTheResultsDirectory) {
  const fs::path out = scratch_ / "results";
  const Outcome outcome = cbbg(std::string("run ") + kQuick + " --seeds 2 --out " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  for (const char* file : {"config.yaml", "summary.json", "trials.csv", "steps.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  }
  EXPECT_THAT(read_file(out / "trials.csv"),
              ::testing::StartsWith("arm,seed,trial,failed,steps,mean_temperature,mean_entropy,"
                                    "final_theta,status\ncbbg,1,1,"));
  EXPECT_THAT(read_file(out / "summary.json"), HasSubstr("\"bg_only\": {"));
  // The resolved config loads back and names the overrides.
  cbbg::config::Config resolved;
  resolved.merge_file(out / "config.yaml");
  EXPECT_EQ(resolved.text("plant.kind"), "analytic");
  EXPECT_EQ(resolved.integer("seeds"), 2);
  // No staging directory is left beside it.
  for (const auto& entry : fs::directory_iterator(scratch_)) {
    EXPECT_EQ(entry.path().filename(), "results");
  }
}

TEST_F(CbbgCommand, ResultsAreByteIdenticalWhateverTheThreadCount) {
  const std::string common = std::string("run ") + kQuick + " --seeds 3 --set log.decimation=7";
  ASSERT_EQ(cbbg(common + " --jobs 1 --out " + (scratch_ / "one").string()).exit_code, 0);
  ASSERT_EQ(cbbg(common + " --jobs 2 --out " + (scratch_ / "two").string()).exit_code, 0);
  for (const char* file :
       {"config.yaml", "summary.json", "trials.csv", "evaluation.csv", "steps.csv"}) {
    const std::string one = read_file(scratch_ / "one" / file);
    EXPECT_FALSE(one.empty()) << file;
    EXPECT_EQ(one, read_file(scratch_ / "two" / file)) << file;
  }
}

TEST_F(CbbgCommand, ListShowsEveryConfigKey) {
  const Outcome outcome = cbbg("list");
  EXPECT_EQ(outcome.exit_code, 0);
  for (const auto& spec : cbbg::config::schema()) {
    EXPECT_THAT(outcome.output, HasSubstr("  " + spec.path + " ")) << spec.path;
  }
  for (const auto& name : cbbg::diagrams::arm_names()) {
    EXPECT_THAT(outcome.output, HasSubstr("  " + name + " ")) << name;
  }
}

TEST_F(CbbgCommand, GraphDrawsANamedDiagram) {
  const fs::path dot = scratch_ / "bg_only.dot";
  const Outcome outcome = cbbg("graph --diagram bg_only -o " + dot.string());
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
  const std::string text = read_file(dot);
  EXPECT_THAT(text, HasSubstr("digraph \"bg_only\""));
  EXPECT_THAT(text, HasSubstr("subgraph \"cluster_bg_only/controller/basal_ganglia\" {"));
  EXPECT_THAT(text, HasSubstr("\"bg_only/controller/basal_ganglia.out.exploration_action\" -> "
                              "\"bg_only/controller/mixer\":in_exploration_action;"));
  EXPECT_THAT(text, ::testing::Not(HasSubstr("cerebellum")));  // bg_only has no supervisor
  EXPECT_THAT(text, ::testing::Not(HasSubstr("\"bg_only/telemetry\"")));
  const Outcome all = cbbg("graph --diagram bg_only --show-telemetry -o " + dot.string());
  EXPECT_EQ(all.exit_code, 0) << all.output;
  EXPECT_THAT(read_file(dot), HasSubstr("\"bg_only/telemetry\""));
  const Outcome unknown = cbbg("graph --diagram nope -o " + dot.string());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.output,
            "cbbg: error: --diagram: unknown diagram 'nope'; the diagrams are cbbg, cbbg_weighted, "
            "bg_only, cb_only, pd_only, learnt_actor\n");
  const Outcome format = cbbg("graph --diagram cbbg -o " + (scratch_ / "x.pdf").string());
  EXPECT_EQ(format.exit_code, 2);
  EXPECT_THAT(format.output, HasSubstr("unknown extension '.pdf'"));
}

TEST_F(CbbgCommand, WeightsSavedByARunLoadIntoEvalAndTheNextRun) {
  const fs::path weights = scratch_ / "bg.txt";
  const std::string quick = std::string(kQuick) + " --experiment bg_only --seeds 1";
  const Outcome saved = cbbg("run " + quick + " --save-weights " + weights.string() + " --out " +
                             (scratch_ / "first").string());
  ASSERT_EQ(saved.exit_code, 0) << saved.output;
  EXPECT_THAT(read_file(weights), ::testing::StartsWith("cbbg-weights 1\n"));
  EXPECT_EQ(read_file(scratch_ / "first" / "weights" / "bg_only_seed1.txt"), read_file(weights));

  const Outcome eval =
      cbbg("eval --set plant.kind=analytic --angles 0.05,0.1 --load-weights " + weights.string());
  EXPECT_EQ(eval.exit_code, 0) << eval.output;
  EXPECT_THAT(eval.output, HasSubstr("0.05"));

  // Learning from the saved weights needs fewer trials than learning from zero did.
  const Outcome again = cbbg("run " + quick + " --load-weights " + weights.string() + " --out " +
                             (scratch_ / "second").string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  const auto trials = [&](const char* run) {
    const std::string csv = read_file(scratch_ / run / "trials.csv");
    return std::count(csv.begin(), csv.end(), '\n') - 1;  // less the header
  };
  EXPECT_LT(trials("second"), trials("first"));
  EXPECT_THAT(read_file(scratch_ / "second" / "trials.csv"), HasSubstr(",success\n"));

  const Outcome many = cbbg("run " + std::string(kQuick) + " --seeds 2 --save-weights " +
                            weights.string() + " --out " + (scratch_ / "third").string());
  EXPECT_EQ(many.exit_code, 2);
  EXPECT_THAT(many.output, HasSubstr("--save-weights keeps the weights of one learning run; this "
                                     "run has 4"));
  const Outcome layout = cbbg("run " + quick + " --set rbf.centres=[-1,0,1] --load-weights " +
                              weights.string() + " --out " + (scratch_ / "fourth").string());
  EXPECT_EQ(layout.exit_code, 2);
  EXPECT_THAT(layout.output, HasSubstr("was made for rbf.centres"));
  EXPECT_FALSE(fs::exists(scratch_ / "third"));
  EXPECT_FALSE(fs::exists(scratch_ / "fourth"));
}

TEST_F(CbbgCommand, AKilledRunLeavesNoResultsAndResumesToTheSameBytes) {
  // The Simbody plant makes each seed take long enough to be killed between seeds.
  const std::string common = "run --no-figures --seeds 4 --jobs 1 --set log.decimation=5";
  ASSERT_EQ(cbbg(common + " --out " + (scratch_ / "whole").string()).exit_code, 0);

  const fs::path out = scratch_ / "killed";
  const fs::path tasks = scratch_ / "killed.partial" / "tasks";
  const pid_t pid = start_cbbg(common + " --out " + out.string());
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  auto finished_tasks = [&tasks] {
    int records = 0;
    if (fs::exists(tasks)) {
      for (const auto& entry : fs::directory_iterator(tasks)) {
        records += entry.path().extension() == ".run" ? 1 : 0;
      }
    }
    return records;
  };
  while (finished_tasks() < 2 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  const int done_before_kill = finished_tasks();
  EXPECT_GE(done_before_kill, 2);
  EXPECT_LT(done_before_kill, 8);
  EXPECT_FALSE(fs::exists(out)) << "a killed run must not leave a results directory";

  // A new run into the same place refuses to overwrite the interrupted one.
  const Outcome blocked = cbbg(common + " --out " + out.string());
  EXPECT_EQ(blocked.exit_code, 2);
  EXPECT_THAT(blocked.output, HasSubstr("holds an interrupted run: continue it with --resume"));
  EXPECT_EQ(cbbg("run --resume " + out.string() + " --seeds 3").exit_code, 2);

  // The resume restores the run's own options: --no-figures too.
  const Outcome resumed = cbbg("run --jobs 2 --resume " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_FALSE(fs::exists(scratch_ / "killed.partial"));
  EXPECT_FALSE(fs::exists(out / "figures"));
  for (const char* file :
       {"config.yaml", "summary.json", "trials.csv", "evaluation.csv", "steps.csv"}) {
    const std::string whole = read_file(scratch_ / "whole" / file);
    EXPECT_FALSE(whole.empty()) << file;
    EXPECT_EQ(read_file(out / file), whole) << file;
  }
  EXPECT_EQ(cbbg("run --resume " + out.string()).exit_code, 2);  // nothing left to resume
}

}  // namespace
