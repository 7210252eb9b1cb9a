// cbbg replay as a user runs it: the page it writes, and what it refuses.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/replay/replay_page.h"
#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace {

namespace fs = std::filesystem;
using cbbg::testing::cbbg;
using cbbg::testing::read_file;
using ::testing::HasSubstr;

class ReplayCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One small exp1 run (2 arms, 1 seed) for every case, in a folder of its own.
    run_ =
        new fs::path(fs::temp_directory_path() / ("cbbg_replay_cli_" + std::to_string(::getpid())));
    fs::remove_all(*run_);
    const auto made = cbbg("run --set plant.kind=analytic --seeds 1 --out " + run_->string());
    ASSERT_EQ(made.exit_code, 0) << made.output;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*run_);
    delete run_;
  }
  std::string out(const std::string& name) const { return (scratch_.path() / name).string(); }

  static fs::path* run_;
  cbbg::testing::ScratchDirectory scratch_;
};
fs::path* ReplayCommand::run_ = nullptr;

TEST_F(ReplayCommand, RunLeavesAReplayPerArmInFigures) {
  for (const char* arm : {"cbbg", "bg_only"}) {
    const std::string page =
        read_file(*run_ / "figures" / (std::string("replay_") + arm + ".html"));
    EXPECT_THAT(page, HasSubstr(cbbg::replay::kGeneratorTag));
    EXPECT_THAT(page, HasSubstr(std::string("\"trials\":[{\"arm\":\"") + arm +
                                "\",\"seed\":1,\"trial\":1,"));
    EXPECT_THAT(page, HasSubstr("exp1, analytic plant: " + run_->filename().string()));
  }
}

TEST_F(ReplayCommand, WritesTheChosenTrials) {
  const auto result =
      cbbg("replay " + run_->string() + " --arm bg_only --trial 2 1 -o " + out("r.html"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::string page = read_file(out("r.html"));
  const auto second = page.find("\"trial\":2,");
  const auto first = page.find("\"trial\":1,");
  ASSERT_NE(second, std::string::npos);
  EXPECT_LT(second, first);  // in the order asked
  // Written again over its own page: allowed.
  EXPECT_EQ(cbbg("replay " + run_->string() + " -o " + out("r.html")).exit_code, 0);
}

TEST_F(ReplayCommand, RefusesWhatItCannotShowWithOneLine) {
  std::ofstream(out("mine.html")) << "my notes";
  const std::pair<std::string, std::string> cases[] = {
      {"replay " + run_->string() + " --arm pd_only -o " + out("a.html"),
       "cbbg: error: --arm: no arm 'pd_only' in this run; it has 'cbbg', 'bg_only'\n"},
      {"replay " + run_->string() + " --trial 0 -o " + out("a.html"),
       "cbbg: error: --trial must be 1 or more; got 0\n"},
      {"replay " + run_->string() + " --seed 4 -o " + out("a.html"),
       "cbbg: error: --seed: arm 'cbbg' has no seed 4; its seeds are 1 to 1\n"},
      {"replay " + scratch_.path().string() + " -o " + out("a.html"),
       "cbbg: error: '" + scratch_.path().string() +
           "' is not a results directory (it has no config.yaml)\n"},
      {"replay " + run_->string() + " -o " + out("mine.html"),
       "cbbg: error: -o '" + out("mine.html") +
           "' exists and cbbg did not write it; cbbg never replaces a file of yours: give a "
           "new path\n"},
      {"replay " + run_->string() + " -o " + out("no/such/dir/a.html"), ""},
  };
  for (const auto& [arguments, message] : cases) {
    const auto result = cbbg(arguments);
    EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.output;
    if (!message.empty()) {
      EXPECT_EQ(result.output, message) << arguments;
    }
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  }
  EXPECT_EQ(read_file(out("mine.html")), "my notes");
  EXPECT_FALSE(fs::exists(out("a.html")));
}

TEST_F(ReplayCommand, AMissingPageIsTheMachinesFault) {
  const auto result = cbbg("replay " + run_->string() + " -o " + out("a.html"),
                           "CBBG_REPLAY_PAGE=/nonexistent/replay.html");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.output, HasSubstr("the replay page '/nonexistent/replay.html' is missing"));
  EXPECT_FALSE(fs::exists(out("a.html")));
}

TEST_F(ReplayCommand, NoReplayLeavesFiguresWithoutThem) {
  const auto result =
      cbbg("run --set plant.kind=analytic --seeds 1 --no-replay --out " + out("run"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(fs::exists(out("run") + "/figures/failures.png"));
  EXPECT_FALSE(fs::exists(out("run") + "/figures/replay_cbbg.html"));
}

}  // namespace
