// Sweeps as a user runs them: a grid over keys, its tasks split into shards that run in any
// order (or at once) into one --out, merged into the same bytes as a single-process run;
// cbbg status; and every bad sweep input as one line and exit 2.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cbbg/framework/number_text.h"
#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace {

namespace fs = std::filesystem;
using cbbg::testing::cbbg;
using cbbg::testing::tree_of;
using ::testing::HasSubstr;

// A small sweep on the analytic plant: 2 x 2 grid points, 2 arms, 3 seeds: 24 tasks.
const std::string kSweep =
    "run --set plant.kind=analytic --seeds 3 --no-figures --grid actor.alpha=0.1,0.2 "
    "--grid critic.beta=0.05,0.1";

// Line `n` (from 0) of `text`.
std::string line(const std::string& text, int n) {
  std::istringstream lines(text);
  std::string result;
  for (int i = 0; i <= n; ++i) std::getline(lines, result);
  return result;
}

// The rows of an evaluation.csv of `arm` whose run balanced (status success).
int successes_of(const std::string& arm, const std::string& evaluation_csv) {
  std::istringstream rows(evaluation_csv);
  int count = 0;
  for (std::string row; std::getline(rows, row);) {
    count += row.starts_with(arm + ",") && row.ends_with(",success") ? 1 : 0;
  }
  return count;
}

class Sweep : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_directory_.emplace();
    scratch_ = scratch_directory_->path();
  }
  std::string out(const std::string& name) const { return (scratch_ / name).string(); }

  std::optional<cbbg::testing::ScratchDirectory> scratch_directory_;
  fs::path scratch_;
};

TEST_F(Sweep, WritesEveryGridPointAndSweepCsv) {
  const auto run = cbbg(kSweep + " --jobs 2 --out " + out("single"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* point : {"001", "002", "003", "004"}) {
    for (const char* file : {"config.yaml", "trials.csv", "evaluation.csv", "summary.json"}) {
      EXPECT_TRUE(fs::exists(scratch_ / "single" / "points" / point / file)) << point << file;
    }
  }
  const std::string csv = cbbg::testing::read_file(scratch_ / "single" / "sweep.csv");
  EXPECT_THAT(csv,
              ::testing::StartsWith("point,actor.alpha,critic.beta,arm,seeds,succeeded,"
                                    "failures_before_success_median,failures_before_success_min,"
                                    "failures_before_success_max,evaluated,balanced,"
                                    "balance_rate\n001,0.1,0.05,cbbg,3,3,"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 4 * 2);
  // The balance rate is the point's evaluation.csv counted: 3 seeds x 5 angles per arm.
  const int balanced = successes_of(
      "cbbg", cbbg::testing::read_file(scratch_ / "single" / "points" / "001" / "evaluation.csv"));
  EXPECT_THAT(line(csv, 1), ::testing::EndsWith(",15," + std::to_string(balanced) + "," +
                                                cbbg::format_number(balanced / 15.0)));
  // Each point's config is the base config with the point's values.
  EXPECT_THAT(cbbg::testing::read_file(scratch_ / "single" / "points" / "004" / "config.yaml"),
              HasSubstr("alpha: 0.2"));
  EXPECT_THAT(cbbg::testing::read_file(scratch_ / "single" / "config.yaml"),
              HasSubstr("sweep:\n  actor.alpha: [0.1, 0.2]\n  critic.beta: [0.05, 0.1]\n"));
  EXPECT_FALSE(fs::exists(out("single") + ".partial"));
}

TEST_F(Sweep, ShardsInAnyOrderMergeToTheBytesOfASingleProcessRun) {
  ASSERT_EQ(cbbg(kSweep + " --out " + out("single")).exit_code, 0);
  for (const int k : {3, 1, 4, 2}) {
    const auto shard = cbbg(kSweep + " --shard " + std::to_string(k) + "/4 --out " + out("four"));
    ASSERT_EQ(shard.exit_code, 0) << shard.output;
  }
  const auto status = cbbg("status " + out("four"));
  EXPECT_THAT(status.output, HasSubstr("4 grid point(s), 24 task(s): 24 done, 0 missing"));
  EXPECT_THAT(status.output, HasSubstr("per-tick logs: off (log.decimation 0, a sweep's default)"));
  const auto merge = cbbg("merge " + out("four"));
  ASSERT_EQ(merge.exit_code, 0) << merge.output;
  EXPECT_EQ(tree_of(scratch_ / "four"), tree_of(scratch_ / "single"));
  EXPECT_THAT(cbbg("status " + out("four")).output, HasSubstr("four: merged"));
}

TEST_F(Sweep, KeepsNoPerTickLogsUnlessTold) {
  ASSERT_EQ(cbbg(kSweep + " --out " + out("quiet")).exit_code, 0);
  EXPECT_FALSE(fs::exists(scratch_ / "quiet" / "points" / "001" / "steps.csv"));
  const auto logged = cbbg(kSweep + " --set log.decimation=50 --shard 1/2 --out " + out("logged"));
  ASSERT_EQ(logged.exit_code, 0) << logged.output;
  EXPECT_THAT(cbbg("status " + out("logged")).output,
              HasSubstr("per-tick logs: steps.csv, every 50th tick (log.decimation)"));
  ASSERT_EQ(cbbg(kSweep + " --set log.decimation=50 --shard 2/2 --out " + out("logged")).exit_code,
            0);
  ASSERT_EQ(cbbg("merge " + out("logged")).exit_code, 0);
  EXPECT_TRUE(fs::exists(scratch_ / "logged" / "points" / "001" / "steps.csv"));
}

TEST_F(Sweep, ShardsRunningAtOnceShareOneOut) {
  ASSERT_EQ(cbbg(kSweep + " --out " + out("single")).exit_code, 0);
  std::vector<pid_t> shards;
  for (int k = 1; k <= 3; ++k) {
    shards.push_back(cbbg::testing::start_cbbg(kSweep + " --shard " + std::to_string(k) +
                                               "/3 --out " + out("together")));
  }
  for (const pid_t pid : shards) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  ASSERT_EQ(cbbg("merge " + out("together")).exit_code, 0);
  EXPECT_EQ(tree_of(scratch_ / "together"), tree_of(scratch_ / "single"));
}

// A shard killed while saving a task (at each step of the save, at its 5th task) and run
// again finishes with the same bytes.
TEST_F(Sweep, AKilledShardRunAgainGivesTheSameBytes) {
  ASSERT_EQ(cbbg(kSweep + " --out " + out("single")).exit_code, 0);
  for (const char* step : {"task:steps", "task:weights", "task:record"}) {
    const std::string name = std::string("killed_") + (step + 5);
    const auto killed = cbbg(kSweep + " --jobs 1 --shard 1/2 --out " + out(name),
                             std::string("CBBG_FAULT_AT=") + step + "@5");
    ASSERT_EQ(killed.exit_code, 86) << step << killed.output;
    for (const char* shard : {"1/2", "2/2"}) {
      const auto run = cbbg(kSweep + " --shard " + shard + " --out " + out(name));
      ASSERT_EQ(run.exit_code, 0) << step << run.output;
    }
    ASSERT_EQ(cbbg("merge " + out(name)).exit_code, 0) << step;
    EXPECT_EQ(tree_of(scratch_ / name), tree_of(scratch_ / "single")) << step;
  }
}

// A merge killed at every step of its commit, and run again, ends with the same bytes.
TEST_F(Sweep, AMergeKilledAtEveryCommitStepFinishesToTheSameBytes) {
  ASSERT_EQ(cbbg(kSweep + " --out " + out("single")).exit_code, 0);
  for (const char* step :
       {"commit:results", "commit:marker", "commit:publish", "commit:clean", "commit:unmark"}) {
    const std::string name = std::string("merge_") + (step + 7);
    ASSERT_EQ(cbbg(kSweep + " --shard 1/1 --out " + out(name)).exit_code, 0);
    const auto killed = cbbg("merge " + out(name), std::string("CBBG_FAULT_AT=") + step);
    ASSERT_EQ(killed.exit_code, 86) << step << killed.output;
    const auto again = cbbg("merge " + out(name));
    ASSERT_EQ(again.exit_code, 0) << step << again.output;
    EXPECT_EQ(tree_of(scratch_ / name), tree_of(scratch_ / "single")) << step;
    EXPECT_FALSE(fs::exists(out(name) + ".partial")) << step;
  }
}

TEST_F(Sweep, MergeNamesTheMissingTasksAndChangesNothing) {
  ASSERT_EQ(cbbg(kSweep + " --shard 2/3 --out " + out("partial")).exit_code, 0);
  const auto before = tree_of(scratch_ / "partial.partial");
  const auto status = cbbg("status " + out("partial"));
  EXPECT_THAT(status.output, HasSubstr("24 task(s): 8 done, 16 missing"));
  EXPECT_THAT(status.output, HasSubstr("missing: point 001 (actor.alpha=0.1, critic.beta=0.05) "
                                       "cbbg seed 1"));
  const auto merge = cbbg("merge " + out("partial"));
  EXPECT_EQ(merge.exit_code, 1);
  EXPECT_THAT(merge.output,
              HasSubstr("cbbg: error: 16 of 24 tasks are missing (point 001 (actor.alpha=0.1, "
                        "critic.beta=0.05) cbbg seed 1; "));
  EXPECT_FALSE(fs::exists(scratch_ / "partial"));
  auto after = tree_of(scratch_ / "partial.partial");
  after.erase(".cbbg-lock");  // the merge's lock file stays (it is locked only while held)
  EXPECT_EQ(after, before);
}

TEST_F(Sweep, AShardOfAnotherSweepIsRefused) {
  ASSERT_EQ(cbbg(kSweep + " --shard 1/2 --out " + out("mixed")).exit_code, 0);
  const auto other = cbbg(kSweep + " --set critic.gamma=0.9 --shard 2/2 --out " + out("mixed"));
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_THAT(other.output, HasSubstr("belongs to a different sweep (its config.yaml differs)"));
}

TEST_F(Sweep, ShardsMustAgreeOnFigures) {
  ASSERT_EQ(cbbg(kSweep + " --shard 1/2 --out " + out("mixed")).exit_code, 0);
  std::string with_figures = kSweep;
  with_figures.replace(with_figures.find(" --no-figures"), 13, "");
  const auto other = cbbg(with_figures + " --shard 2/2 --out " + out("mixed"));
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_THAT(other.output, HasSubstr("'s shards were started with --no-figures; give every "
                                      "shard the same options"));
}

TEST_F(Sweep, TheMergeDrawsTheHeadlineAgainstEachSweptKey) {
  std::string with_figures = kSweep;
  with_figures.replace(with_figures.find(" --no-figures"), 13, "");
  ASSERT_EQ(cbbg(with_figures + " --out " + out("drawn")).exit_code, 0);
  for (const char* figure : {"sweep_actor.alpha.png", "sweep_critic.beta.png"}) {
    EXPECT_GT(fs::file_size(scratch_ / "drawn" / "figures" / figure), 10000u) << figure;
  }
}

TEST_F(Sweep, AConfigFilesSweepSectionIsAGrid) {
  {
    std::ofstream file(scratch_ / "sweep.yaml");
    file << "plant: {kind: analytic}\nseeds: 3\nsweep:\n  actor.alpha: [0.1, 0.2]\n"
            "  critic.beta: [0.05, 0.1]\n";
  }
  ASSERT_EQ(cbbg("run --no-figures --config " + (scratch_ / "sweep.yaml").string() + " --out " +
                 out("from_file"))
                .exit_code,
            0);
  ASSERT_EQ(cbbg(kSweep + " --out " + out("from_flags")).exit_code, 0);
  EXPECT_EQ(cbbg::testing::read_file(scratch_ / "from_file" / "sweep.csv"),
            cbbg::testing::read_file(scratch_ / "from_flags" / "sweep.csv"));
}

TEST_F(Sweep, BadSweepInputIsOneLineAndExitTwoAndWritesNothing) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"run --grid actor.alpha", "--grid actor.alpha: give KEY=V1,V2,..."},
      {"run --grid actor.alpha=0.1,fast",
       "--grid actor.alpha=0.1,fast: actor.alpha must be a number; got 'fast'"},
      {"run --grid actor.alpa=0.1", "unknown key 'actor.alpa'; did you mean 'actor.alpha'?"},
      {"run --grid actor.alpha=0.1,,0.2", "--grid actor.alpha=0.1,,0.2: an empty value"},
      {"run --grid actor.alpha=0.1 --grid actor.alpha=0.2", "actor.alpha is swept twice"},
      {"run --grid seeds=2,0", "--grid seeds=2,0: seeds must be"},
      {"run --shard 0/3", "--shard must be K/N with 1 <= K <= N <= 100000; got '0/3'"},
      {"run --shard 4/3", "--shard must be K/N with 1 <= K <= N <= 100000; got '4/3'"},
      {"run --shard two", "--shard must be K/N with 1 <= K <= N <= 100000; got 'two'"},
      {"run --grid actor.alpha=0.1 --replace",
       "a sweep (--grid, --shard or a config's sweep:) "
       "takes no --resume"},
      {"merge", "DIR is required"},
      {"merge nowhere", "no sweep at 'nowhere'"},
      {"status nowhere", "no sweep at 'nowhere'"},
  };
  for (const auto& [arguments, message] : cases) {
    const bool run = arguments.rfind("run", 0) == 0;
    const auto outcome = cbbg(run ? arguments + " --out " + out("bad") : arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments << "\n" << outcome.output;
    EXPECT_THAT(outcome.output, HasSubstr(message)) << arguments;
    EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << arguments;
  }
  EXPECT_FALSE(fs::exists(out("bad")));
  EXPECT_FALSE(fs::exists(out("bad") + ".partial"));
}

}  // namespace
