// The user's data is safe: --out writes only where cbbg may, a live run locks its directory,
// a kill at any step of a commit resumes to the same bytes, a full disk or a read-only place
// stops a command with one line, and nothing is left half-written.

#include <sys/mount.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/store/fault_point.h"
#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace {

using cbbg::testing::Outcome;
using cbbg::testing::ScratchDirectory;
using cbbg::testing::start_cbbg;
using cbbg::testing::tree_of;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

// A quick run: the analytic plant, three seeds, no figures (their PNG bytes are matplotlib's).
constexpr const char* kQuick =
    "--log-level warn run --set plant.kind=analytic --seeds 3 --no-figures --set log.decimation=5";

// A small tmpfs this test mounts itself and unmounts at the end (root only; else skipped).
Outcome run(const std::string& arguments, const std::string& environment = "") {
  return cbbg::testing::cbbg(arguments, environment);
}

class Tmpfs {
 public:
  Tmpfs(const fs::path& where, const std::string& size) : where_(where) {
    fs::create_directories(where);
    mounted_ = ::mount("tmpfs", where.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
  }
  ~Tmpfs() {
    if (mounted_) ::umount2(where_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }
  bool remount(const std::string& options) {
    return ::mount("tmpfs", where_.c_str(), "tmpfs", MS_REMOUNT | (options == "ro" ? MS_RDONLY : 0),
                   options == "ro" ? nullptr : options.c_str()) == 0;
  }

 private:
  fs::path where_;
  bool mounted_ = false;
};

// The finished task records of a killed run into `out`, with their write times.
std::map<fs::path, fs::file_time_type> task_records(const std::string& out) {
  std::map<fs::path, fs::file_time_type> records;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(out + ".partial/tasks", error)) {
    if (entry.path().extension() == ".run") records[entry.path()] = entry.last_write_time();
  }
  return records;
}

class DataSafety : public ::testing::Test {
 public:
  void SetUp() override {
    scratch_directory_.emplace();
    scratch_ = scratch_directory_->path();
  }
  std::string path(const std::string& name) const { return (scratch_ / name).string(); }
  // A finished run's tree, the reference that every interrupted run must end as.
  std::map<std::string, std::string> reference(const std::string& extra = "") {
    const Outcome whole = run(std::string(kQuick) + extra + " --out " + path("whole"));
    EXPECT_EQ(whole.exit_code, 0) << whole.output;
    return tree_of(scratch_ / "whole");
  }
  std::optional<ScratchDirectory> scratch_directory_;
  fs::path scratch_;
};

TEST_F(DataSafety, OutRefusesWhatCbbgDidNotMakeAndTouchesNothing) {
  fs::create_directories(scratch_ / "mine");
  std::ofstream(scratch_ / "mine" / "notes.txt") << "my notes\n";
  std::ofstream(scratch_ / "plain") << "a file\n";
  fs::create_directories(scratch_ / "stray.partial");
  std::ofstream(scratch_ / "other.partial") << "not a directory\n";
  const auto before = tree_of(scratch_);
  const std::string cd = "cd '" + scratch_.string() + "' &&";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--out " + path("mine"),
       "--out '" + path("mine") +
           "' exists and was not made by cbbg run; cbbg never replaces what it did not make: "
           "give a new path"},
      {"--out " + path("plain"), "--out '" + path("plain") + "' is a file; give a directory path"},
      {"--out ''", "--out needs a directory path"},
      {"--out " + path("stray"),
       "'" + path("stray.partial") + "' is in the way and was not made by cbbg; move it away"},
      {"--out " + path("other"),
       "'" + path("other.partial") + "' is in the way and was not made by cbbg; move it away"},
      {"--replace --out " + path("mine"),
       "--out '" + path("mine") +
           "' exists and was not made by cbbg run; cbbg never replaces what it did not make: "
           "give a new path"},
  };
  for (const auto& [arguments, message] : cases) {
    const Outcome outcome = run(std::string(kQuick) + " " + arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments;
    EXPECT_THAT(outcome.output, HasSubstr("cbbg: error: " + message)) << arguments;
    EXPECT_EQ(tree_of(scratch_), before) << arguments;
  }
  const Outcome here = run(std::string(kQuick) + " --out .", cd);
  EXPECT_EQ(here.exit_code, 2);
  EXPECT_THAT(here.output, HasSubstr("--out '.' exists and was not made by cbbg run"));
  EXPECT_EQ(tree_of(scratch_), before);
}

TEST_F(DataSafety, ReplacingIsExplicitAndNeverTakesAUsersFile) {
  const std::string out = path("results");
  ASSERT_EQ(run(std::string(kQuick) + " --seed 5 --out " + out).exit_code, 0);
  const auto first = tree_of(out);
  const Outcome again = run(std::string(kQuick) + " --out " + out);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_THAT(again.output, HasSubstr("holds the results of an earlier run; add --replace"));
  EXPECT_EQ(tree_of(out), first);

  std::ofstream(scratch_ / "results" / "my_analysis.txt") << "mine\n";
  const Outcome foreign = run(std::string(kQuick) + " --replace --out " + out);
  EXPECT_EQ(foreign.exit_code, 2);
  EXPECT_THAT(foreign.output, HasSubstr("holds 'my_analysis.txt', which cbbg did not write"));
  fs::remove(scratch_ / "results" / "my_analysis.txt");

  const auto expected = reference();
  const Outcome replaced = run(std::string(kQuick) + " --replace --out " + out);
  ASSERT_EQ(replaced.exit_code, 0) << replaced.output;
  EXPECT_EQ(tree_of(out), expected);
  EXPECT_FALSE(fs::exists(out + ".partial"));
}

// Kills `command` at every step of a task's save and of the commit (replacing earlier
// results too, when `replacing`), resumes, and expects the bytes of the run never killed.
void kill_at_every_step(DataSafety& test, const std::string& name, const std::string& command,
                        bool replacing) {
  const Outcome whole = run(command + " --out " + test.path(name + "_whole"));
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const auto expected = tree_of(test.path(name + "_whole"));
  for (const char* step : cbbg::store::kFaultPoints) {
    for (const bool replace : {false, true}) {
      if (replace && !replacing) continue;
      const std::string out = test.path(name + (replace ? "_r_" : "_") + step);
      if (replace) {
        ASSERT_EQ(run(command + " --seed 9 --out " + out).exit_code, 0);
      }
      const std::string fault = std::string("CBBG_FAULT_AT=") + step +
                                (std::string(step).rfind("task", 0) == 0 ? "@2" : "");
      const Outcome killed = run(command + (replace ? " --replace" : "") + " --out " + out, fault);
      ASSERT_EQ(killed.exit_code, cbbg::store::kFaultExitCode) << step << killed.output;
      // Replacing, the target always holds complete results, old or new.
      if (replace) {
        EXPECT_TRUE(fs::exists(out / fs::path(".cbbg-results"))) << step;
      }
      const auto records = task_records(out);
      const Outcome resumed = run("--log-level warn run --resume " + out);
      ASSERT_EQ(resumed.exit_code, 0) << name << " " << step << ": " << resumed.output;
      EXPECT_EQ(tree_of(out), expected) << name << " " << step << (replace ? ", replacing" : "");
      EXPECT_FALSE(fs::exists(out + ".partial")) << step;
      EXPECT_TRUE(fs::exists(out)) << step;
      // The resume redid no finished task: their records were not written again.
      for (const auto& [record, written] : records) {
        EXPECT_FALSE(fs::exists(record) && fs::last_write_time(record) != written)
            << name << " " << step << ": " << record << " was written again";
      }
      const Outcome nothing = run("run --resume " + out);
      EXPECT_EQ(nothing.exit_code, 2) << step;
      EXPECT_THAT(nothing.output,
                  HasSubstr("nothing to resume: '" + out + "' holds finished results"));
    }
  }
}

TEST_F(DataSafety, AKillAtEveryStepOfACommitResumesToTheSameBytes) {
  kill_at_every_step(*this, "exp1", kQuick, /*replacing=*/true);
}

TEST_F(DataSafety, AKillAtEveryStepOfADiagramRunAloneResumesToTheSameBytes) {
  // The results record the one arm that ran, not the config's arms: nothing the resume
  // reads may be rewritten on the way.
  kill_at_every_step(*this, "alone", std::string(kQuick) + " --experiment bg_only", false);
}

TEST_F(DataSafety, AKillAtEveryStepOfExp2AndExp3ResumesToTheSameBytes) {
  kill_at_every_step(*this, "exp2",
                     std::string(kQuick) +
                         " --experiment exp2 --set exp2.trials=3 --set "
                         "'annealing=[{from_trial: 1, k1: 10}]'",
                     false);
  kill_at_every_step(*this, "exp3",
                     std::string(kQuick) +
                         " --experiment exp3 --set max_trials=4 "
                         "--set evaluation.angles=[0.1]",
                     false);
}

TEST_F(DataSafety, AKillAtEveryStepOfAnEvaluationResumesToTheSameBytes) {
  const Outcome learnt =
      run("--log-level warn run --set plant.kind=analytic --experiment bg_only "
          "--seeds 1 --no-figures --out " +
          path("learnt") + " --save-weights " + path("w.txt"));
  ASSERT_EQ(learnt.exit_code, 0) << learnt.output;
  kill_at_every_step(*this, "evaluate",
                     std::string(kQuick) +
                         " --experiment evaluate --set arms=[bg_only] "
                         "--set evaluation.angles=[0.05,0.1] --load-weights " +
                         path("w.txt"),
                     false);
}

TEST_F(DataSafety, AKillAtEveryStepOfATransferRunResumesToTheSameBytes) {
  kill_at_every_step(*this, "transfer",
                     std::string(kQuick) +
                         " --experiment transfer --set transfer.training=exp1 --set max_trials=10 "
                         "--set 'transfer.conditions=[evaluation.body_mass_scale=1.3]' "
                         "--set evaluation.angles=[0.1]",
                     false);
}

TEST_F(DataSafety, ALiveRunLocksItsDirectoryAndADeadOneDoesNot) {
  // The Simbody plant makes the run last long enough to meet it while it works.
  const std::string slow = "run --no-figures --seeds 4 --jobs 1 --set log.decimation=5 --out ";
  const std::string out = path("busy");
  const pid_t pid = start_cbbg(slow + out);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out + ".partial/tasks") && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const Outcome second = run(slow + out);
  EXPECT_EQ(second.exit_code, 2);
  EXPECT_THAT(second.output, HasSubstr("'" + out + ".partial' is in use by another cbbg run"));
  const Outcome resume = run("run --resume " + out);
  EXPECT_EQ(resume.exit_code, 2);
  EXPECT_THAT(resume.output, HasSubstr("'" + out + ".partial' is in use by another cbbg run (pid " +
                                       std::to_string(pid) + ")"));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before the test met it";
  // The dead run's lock died with it.
  const Outcome resumed = run("--log-level warn run --resume " + out);
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_TRUE(fs::exists(fs::path(out) / ".cbbg-results"));
}

TEST_F(DataSafety, ResumeChecksItsConfigAndGivesOneAdviceForEveryState) {
  const std::string out = path("r");
  const Outcome killed = run(std::string(kQuick) + " --out " + out, "CBBG_FAULT_AT=task:record@2");
  ASSERT_EQ(killed.exit_code, cbbg::store::kFaultExitCode);
  const Outcome status = run("status " + out);
  EXPECT_EQ(status.exit_code, 0);
  // The kill at the second record may come before the first is written: 0 or 1 done.
  EXPECT_THAT(status.output,
              ::testing::MatchesRegex(out +
                                      ": interrupted, [01] of 6 task\\(s\\) done; continue it "
                                      "with cbbg run --resume " +
                                      out + "\n"));
  std::ofstream(out + ".partial/run-config.yaml", std::ios::app) << "# edited\n";
  const Outcome edited = run("run --resume " + out);
  EXPECT_EQ(edited.exit_code, 2);
  EXPECT_THAT(edited.output, HasSubstr("run-config.yaml' is not the config the run began with"));
  const Outcome blocked = run(std::string(kQuick) + " --out " + out);
  EXPECT_EQ(blocked.exit_code, 2);
  EXPECT_THAT(blocked.output,
              HasSubstr("holds an interrupted run: continue it with --resume " + out));
  const Outcome options = run("run --resume " + out + " --no-figures");
  EXPECT_EQ(options.exit_code, 2);
  EXPECT_THAT(options.output, HasSubstr("--resume continues with the config, weights and options"));
  const Outcome none = run("run --resume " + path("never"));
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.output, HasSubstr("nothing to resume: neither '" + path("never.partial") +
                                     "' nor '" + path("never") + "' holds an interrupted run"));
  const Outcome empty = run("run --resume ''");
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_THAT(empty.output, HasSubstr("--resume needs the results directory"));
}

TEST_F(DataSafety, AFullDiskStopsTheRunWithOneLineAndResumesOnceThereIsRoom) {
  Tmpfs disk(scratch_ / "disk", "300k");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a tmpfs needs root";
  const auto expected = reference(" --set log.decimation=1");
  const std::string out = (scratch_ / "disk" / "results").string();
  const Outcome full = run(std::string(kQuick) + " --set log.decimation=1 --out " + out);
  EXPECT_EQ(full.exit_code, 1);
  EXPECT_THAT(full.output, HasSubstr("No space left on device"));
  EXPECT_THAT(full.output, HasSubstr("continue with cbbg run --resume " + out));
  EXPECT_EQ(std::count(full.output.begin(), full.output.end(), '\n'), 1) << full.output;
  EXPECT_FALSE(fs::exists(out));
  ASSERT_TRUE(disk.remount("size=64m"));
  const Outcome resumed = run("--log-level warn run --resume " + out);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(tree_of(out), expected);
}

TEST_F(DataSafety, EveryCommandRefusedARead_onlyPlaceExitsOneWithOneLine) {
  Tmpfs disk(scratch_ / "ro", "8m");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a tmpfs needs root";
  const std::string results = (scratch_ / "ro" / "results").string();
  const std::string one_learner =
      "--log-level warn run --set plant.kind=analytic --no-figures --experiment bg_only --seeds 1";
  const Outcome learnt =
      run(one_learner + " --out " + results + " --save-weights " + path("w.txt"));
  ASSERT_EQ(learnt.exit_code, 0) << learnt.output;
  ASSERT_TRUE(disk.remount("ro"));
  const std::string ro = (scratch_ / "ro").string();
  const std::vector<std::string> commands = {
      std::string(kQuick) + " --out " + ro + "/new",
      "graph --diagram cbbg -o " + ro + "/cbbg.dot",
      "eval --set plant.kind=analytic --load-weights " + path("w.txt") + " --out " + ro + "/eval",
      "plot " + results,
      one_learner + " --out " + path("x") + " --save-weights " + ro + "/w.txt",
  };
  for (const auto& command : commands) {
    const Outcome outcome = run(command);
    EXPECT_EQ(outcome.exit_code, 1) << command << "\n" << outcome.output;
    EXPECT_THAT(outcome.output, HasSubstr("Read-only file system")) << command;
    EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << command;
  }
  EXPECT_FALSE(fs::exists(path("x")));
  disk.remount("rw");
}

}  // namespace
