// Every command that writes follows one discipline (store/output_guard.h): it replaces only
// what cbbg made, refuses anything else before any work with exit 2 and the path, cleans
// its own temporaries on resume and merge, and writes config text that reads back.

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/store/fault_point.h"
#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace {

using cbbg::testing::Outcome;
using cbbg::testing::read_file;
using cbbg::testing::ScratchDirectory;
using cbbg::testing::tree_of;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

constexpr const char* kQuick =
    "--log-level warn run --set plant.kind=analytic --seeds 2 --no-figures --set log.decimation=5";
constexpr const char* kLearner =
    "--log-level warn run --set plant.kind=analytic --experiment bg_only --seeds 1 --no-figures";

Outcome run(const std::string& arguments, const std::string& environment = "") {
  return cbbg::testing::cbbg(arguments, environment);
}

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// Every name below `root` that is one of cbbg's temporaries, old pattern or new.
std::string temporaries_below(const fs::path& root) {
  static const std::regex temporary(R"(.*(\.cbbg-tmp-|\.tmp-[0-9]+-[0-9]+$).*)");
  std::string found;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, temporary)) found += entry.path().string() + " ";
  }
  return found;
}

class OutputDiscipline : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_directory_.emplace();
    scratch_ = scratch_directory_->path();
  }
  std::string path(const std::string& name) const { return (scratch_ / name).string(); }
  // Runs `arguments`, expects exit 2 with `message` on one line, and the scratch unchanged.
  void expect_refused(const std::string& arguments, const std::string& message) {
    const auto before = tree_of(scratch_);
    const Outcome outcome = run(arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments << "\n" << outcome.output;
    EXPECT_THAT(outcome.output, HasSubstr(message)) << arguments;
    EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << outcome.output;
    EXPECT_EQ(tree_of(scratch_), before) << arguments << ": something was written or changed";
  }
  std::optional<ScratchDirectory> scratch_directory_;
  fs::path scratch_;
};

TEST_F(OutputDiscipline, PlotKeepsTheUsersFilesAndRefusesTheirNames) {
  const std::string out = path("r");
  ASSERT_EQ(run(std::string(kQuick) + " --out " + out).exit_code, 0);
  write(out + "/figures/notes.txt", "my notes\n");
  const Outcome plotted = run("plot " + out);
  ASSERT_EQ(plotted.exit_code, 0) << plotted.output;
  EXPECT_EQ(read_file(out + "/figures/notes.txt"), "my notes\n");
  EXPECT_TRUE(fs::exists(out + "/figures/failures.png"));
  // Drawn again: cbbg's own figures are replaced, the user's notes stay.
  ASSERT_EQ(run("plot " + out).exit_code, 0);
  EXPECT_EQ(read_file(out + "/figures/notes.txt"), "my notes\n");

  const std::string fresh = path("fresh");
  ASSERT_EQ(run(std::string(kQuick) + " --out " + fresh).exit_code, 0);
  write(fresh + "/figures/diagram.svg", "<svg>mine</svg>");
  expect_refused("plot " + fresh,
                 "cbbg plot: '" + fresh + "/figures/diagram.svg' exists and cbbg did not write it");
  fs::remove(fresh + "/figures/diagram.svg");
  write(fresh + "/figures/failures.png", "my plot");
  const auto before = tree_of(scratch_);
  const Outcome taken = run("plot " + fresh);
  EXPECT_EQ(taken.exit_code, 2);
  EXPECT_THAT(taken.output, HasSubstr(fresh + "/figures/failures.png: exists and cbbg did not "
                                              "write it"));
  EXPECT_EQ(tree_of(scratch_), before);
}

TEST_F(OutputDiscipline, PlotDrawsNoPresetDiagramForAUsersArm) {
  const std::string out = path("mine");
  ASSERT_EQ(run(std::string(kLearner) + " --out " + out).exit_code, 0);
  // A run made through the library with an arm of the user's: its results name that arm.
  for (const char* file : {"trials.csv", "steps.csv", "summary.json", "evaluation.csv"}) {
    const std::string text = read_file(out + "/" + file);
    write(out + "/" + file, std::regex_replace(text, std::regex("bg_only"), "my_arm"));
  }
  const Outcome plotted = run("plot " + out);
  EXPECT_EQ(plotted.exit_code, 0) << plotted.output;
  EXPECT_THAT(plotted.output,
              HasSubstr("no diagram.svg: arm 'my_arm' is not a preset nor registered"));
  EXPECT_FALSE(fs::exists(out + "/figures/diagram.svg"));
  EXPECT_TRUE(fs::exists(out + "/figures/replay_my_arm.html"));
}

TEST_F(OutputDiscipline, WeightsEvaluationsReplaysAndDrawingsReplaceOnlyCbbgsOwn) {
  const std::string weights = path("w.txt");
  ASSERT_EQ(
      run(std::string(kLearner) + " --out " + path("a") + " --save-weights " + weights).exit_code,
      0);
  // cbbg's own weights file is replaced; a user's never.
  EXPECT_EQ(
      run(std::string(kLearner) + " --out " + path("b") + " --save-weights " + weights).exit_code,
      0);
  write(path("mine.txt"), "my weights\n");
  expect_refused(
      std::string(kLearner) + " --out " + path("c") + " --save-weights " + path("mine.txt"),
      "--save-weights '" + path("mine.txt") + "' exists and cbbg did not write it");

  const std::string eval = "--log-level warn eval --set plant.kind=analytic --load-weights " +
                           weights + " --angles 0.1 --out ";
  ASSERT_EQ(run(eval + path("e")).exit_code, 0);
  ASSERT_EQ(run(eval + path("e")).exit_code, 0);  // its own evaluation.csv, by the manifest
  write(path("theirs/evaluation.csv"), "theta0\n1\n");
  expect_refused(eval + path("theirs"),
                 "--out: '" + path("theirs/evaluation.csv") + "' exists and cbbg did not write it");

  ASSERT_EQ(run("graph --diagram cbbg -o " + path("d.png")).exit_code, 0);
  EXPECT_EQ(run("graph --diagram cbbg -o " + path("d.png")).exit_code, 0);
  write(path("photo.png"), "\x89PNG not cbbg's");
  expect_refused("graph --diagram cbbg -o " + path("photo.png"),
                 "-o '" + path("photo.png") + "' exists and cbbg did not write it");
  write(path("page.html"), "<html>mine</html>");
  expect_refused("replay " + path("a") + " -o " + path("page.html"),
                 "-o '" + path("page.html") + "' exists and cbbg did not write it");
}

TEST_F(OutputDiscipline, AFifoIsRefusedAndNeverOpened) {
  ASSERT_EQ(run(std::string(kLearner) + " --out " + path("a") + " --save-weights " + path("w.txt"))
                .exit_code,
            0);
  ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0644), 0);
  // A command that opened the FIFO would never return; the test's timeout would show it.
  expect_refused("replay " + path("a") + " -o " + path("pipe"),
                 "-o '" + path("pipe") + "' is a FIFO; give a regular file's path");
  ASSERT_EQ(::mkfifo(path("pipe.svg").c_str(), 0644), 0);
  expect_refused("graph --diagram cbbg -o " + path("pipe.svg"), "is a FIFO");
  expect_refused(std::string(kLearner) + " --out " + path("b") + " --save-weights " + path("pipe"),
                 "--save-weights '" + path("pipe") + "' is a FIFO");
  fs::create_directories(path("e"));
  ASSERT_EQ(::mkfifo(path("e/evaluation.csv").c_str(), 0644), 0);
  expect_refused(
      "eval --set plant.kind=analytic --load-weights " + path("w.txt") + " --out " + path("e"),
      "'" + path("e/evaluation.csv") + "' is a FIFO");
}

TEST_F(OutputDiscipline, MergeRefusesAUsersFileAmongTheTasks) {
  const std::string sweep = path("s");
  const std::string shard = std::string(kQuick) + " --grid critic.beta=0.1,0.2 --shard 1/1 --out ";
  ASSERT_EQ(run(shard + sweep).exit_code, 0);
  write(sweep + ".partial/tasks/001/notes.txt", "mine\n");
  expect_refused("merge " + sweep, "'" + sweep +
                                       ".partial/tasks/001/notes.txt' is not a task file "
                                       "of cbbg's");
  fs::remove(sweep + ".partial/tasks/001/notes.txt");
  EXPECT_EQ(run("--log-level warn merge " + sweep).exit_code, 0);
}

TEST_F(OutputDiscipline, CheckChecksWhatARunChecksAndWritesNothing) {
  const auto before = tree_of(scratch_);
  const Outcome fine = run(std::string(kQuick) + " --check --out " + path("new"));
  EXPECT_EQ(fine.exit_code, 0) << fine.output;
  EXPECT_EQ(fine.output, "the run checks out; nothing was written\n");
  const Outcome sweep =
      run(std::string(kQuick) + " --check --grid critic.beta=0.1,0.2 --out " + path("sweep"));
  EXPECT_EQ(sweep.exit_code, 0) << sweep.output;
  EXPECT_EQ(sweep.output,
            "the sweep checks out (2 grid point(s), 8 task(s)); nothing was written\n");
  expect_refused(std::string(kQuick) + " --check --set critic.gama=1 --out " + path("new"),
                 "unknown key 'critic.gama'; did you mean 'critic.gamma'?");
  EXPECT_EQ(tree_of(scratch_), before);
}

TEST_F(OutputDiscipline, StatusAndMergeKnowAnOrdinaryRunFromASweep) {
  // status tells how far an ordinary run got; merge, for sweeps, refuses it.
  const std::string finished = path("r");
  ASSERT_EQ(run(std::string(kQuick) + " --out " + finished).exit_code, 0);
  const Outcome done = run("status " + finished);
  EXPECT_EQ(done.exit_code, 0);
  EXPECT_EQ(done.output, finished + ": finished results of cbbg run\n");
  expect_refused("merge " + finished,
                 "'" + finished + "' holds the results of a cbbg run, not of a sweep");
  const std::string killed = path("k");
  ASSERT_EQ(run(std::string(kQuick) + " --jobs 1 --out " + killed, "CBBG_FAULT_AT=task:record@2")
                .exit_code,
            cbbg::store::kFaultExitCode);
  const Outcome interrupted = run("status " + killed);
  EXPECT_EQ(interrupted.exit_code, 0);
  EXPECT_EQ(interrupted.output, killed + ": interrupted, 1 of 4" +
                                    " task(s) done; continue it with cbbg run --resume " + killed +
                                    "\n");
  expect_refused("merge " + killed, "'" + killed +
                                        ".partial' holds an interrupted cbbg run, not a sweep: "
                                        "continue it with cbbg run --resume " +
                                        killed);
  const std::string sweep = path("s");
  ASSERT_EQ(
      run(std::string(kQuick) + " --grid critic.beta=0.1 --shard 1/2 --out " + sweep).exit_code, 0);
  expect_refused(std::string(kQuick) + " --out " + sweep,
                 "'" + sweep + ".partial' holds a sweep's unfinished tasks");
}

TEST_F(OutputDiscipline, ResumeRemovesItsOwnTemporariesAndNeverPublishesOne) {
  const std::string whole = path("whole");
  ASSERT_EQ(run(std::string(kQuick) + " --out " + whole).exit_code, 0);
  const auto expected = tree_of(whole);
  const std::string out = path("r");
  ASSERT_EQ(run(std::string(kQuick) + " --out " + out, "CBBG_FAULT_AT=commit:marker").exit_code,
            cbbg::store::kFaultExitCode);
  // What a kill in the middle of atomic writes leaves: new and old patterns, files and a
  // plot's staging folder.
  write(out + ".partial/.summary.json.cbbg-tmp-elsewhere-1-0", "{half");
  write(out + ".partial/trials.csv.tmp-4242-7", "arm,se");
  write(out + ".partial/.figures.cbbg-tmp-host-1-0/failures.png", "half");
  write(out + ".partial/tasks/.0.run.cbbg-tmp-host-1-3", "cbbg-task");
  const Outcome resumed = run("--log-level warn run --resume " + out);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(tree_of(out), expected);
  EXPECT_EQ(temporaries_below(scratch_), "");

  // A leftover of an earlier version inside finished results is cbbg's, not the user's.
  write(out + "/summary.json.tmp-99-1", "{");
  const Outcome replaced = run(std::string(kQuick) + " --replace --out " + out);
  EXPECT_EQ(replaced.exit_code, 0) << replaced.output;
  EXPECT_EQ(tree_of(out), expected);
}

TEST_F(OutputDiscipline, AShardRemovesTheStagingAKilledShardLeftBesideTheSweep) {
  const std::string sweep = path("s");
  const std::string shard = std::string(kQuick) + " --grid critic.beta=0.1,0.2 --out " + sweep;
  ASSERT_EQ(run(shard + " --shard 1/2").exit_code, 0);
  // Shard 2 was killed while it made s.partial, which shard 1 had made meanwhile.
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string staging = path(".s.partial.cbbg-tmp-" + std::string(host) + "-999999999-0");
  write(staging + "/.cbbg-sweep-run", "cbbg-sweep 1\n");
  ASSERT_EQ(run(shard + " --shard 2/2").exit_code, 0);
  EXPECT_FALSE(fs::exists(staging));
  ASSERT_EQ(run("--log-level warn merge " + sweep).exit_code, 0);
  EXPECT_EQ(temporaries_below(scratch_), "");
}

TEST_F(OutputDiscipline, ACorruptTaskRecordNamesTheTaskToRedoAndThatWorks) {
  const std::string whole = path("whole");
  ASSERT_EQ(run(std::string(kQuick) + " --out " + whole).exit_code, 0);
  const std::string out = path("r");
  // One thread, so the records written before the kill are tasks 0 and 1.
  ASSERT_EQ(
      run(std::string(kQuick) + " --jobs 1 --out " + out, "CBBG_FAULT_AT=task:record@3").exit_code,
      cbbg::store::kFaultExitCode);
  const std::string record = out + ".partial/tasks/1.run";
  ASSERT_TRUE(fs::exists(record));
  write(record, "cbbg-task 2\narm cbbg\nseed 2\ntrial x\n");
  const Outcome failed = run("--log-level warn run --resume " + out);
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_THAT(failed.output, HasSubstr("remove '" + record + "' to redo that task (cbbg seed 2)"));
  fs::remove(record);
  const Outcome resumed = run("--log-level warn run --resume " + out);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(tree_of(out), tree_of(whole));
}

// A run killed under an earlier cbbg, whose task records this one does not read: refused in one
// line that says what to do, which is not --resume.
TEST_F(OutputDiscipline, AnEarlierTaskRecordIsRefusedSayingWhatToDo) {
  const std::string out = path("r");
  ASSERT_EQ(
      run(std::string(kQuick) + " --jobs 1 --out " + out, "CBBG_FAULT_AT=task:record@2").exit_code,
      cbbg::store::kFaultExitCode);
  const std::string record = out + ".partial/tasks/0.run";
  ASSERT_TRUE(fs::exists(record));
  write(record, "cbbg-task 1\narm cbbg\nseed 1\nsucceeded 1\nend\n");
  const Outcome refused = run("--log-level warn run --resume " + out);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_EQ(refused.output, "cbbg: error: '" + record +
                                "' is a task record of an earlier cbbg (cbbg-task 1), which this "
                                "one cannot continue: finish the run with the cbbg that started "
                                "it, or start it again in a new directory\n");
  EXPECT_TRUE(fs::exists(record));  // nothing of the run is touched
}

TEST_F(OutputDiscipline, AGridValueWithACommentReadsBackEverywhere) {
  const std::string sweep = path("s");
  const Outcome swept =
      run(std::string(kQuick) + " --grid 'critic.beta=0.1 # note,0.2' --out " + sweep);
  ASSERT_EQ(swept.exit_code, 0) << swept.output;
  EXPECT_THAT(read_file(sweep + "/config.yaml"), HasSubstr("critic.beta: [0.1, 0.2]\n"));
  const Outcome status = run("status " + sweep);
  EXPECT_EQ(status.exit_code, 0) << status.output;
  EXPECT_THAT(status.output, HasSubstr(": merged"));
  const Outcome plotted = run("plot " + sweep);
  EXPECT_EQ(plotted.exit_code, 0) << plotted.output;
}

}  // namespace
