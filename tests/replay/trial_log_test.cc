#include "cbbg/replay/trial_log.h"

#include <cmath>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/scratch_directory.h"

namespace cbbg::replay {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::ThrowsMessage;

constexpr const char* kStepsHeader =
    "arm,seed,trial,t,theta_b,dtheta_b,phi_l,phi_r,a_S,a_A,a_E,a,omega,V,delta,T,reward,x,y,"
    "yaw\n";

// A steps.csv row: pitch p, wheels w, action a, pose (x, 0, 0).
std::string step(const std::string& arm, int seed, int trial, double t, double p, double w,
                 double a, double x) {
  return arm + "," + std::to_string(seed) + "," + std::to_string(trial) + "," + std::to_string(t) +
         "," + std::to_string(p) + ",0," + std::to_string(w) + "," + std::to_string(w) + ",0,0,0," +
         std::to_string(a) + ",0,0,0,0,0," + std::to_string(x) + ",0,0\n";
}

class TrialLogs : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = scratch_.path() / name;
    std::ofstream(path) << text;
    return path;
  }
  cbbg::testing::ScratchDirectory scratch_;
};

TrialEntry entry(const std::string& arm, long long seed, int trial, const std::string& status) {
  return {arm, seed, trial, status};
}

TEST_F(TrialLogs, TrialsCsvGivesItsRowsInOrder) {
  const fs::path path = write("trials.csv",
                              "arm,seed,trial,failed,steps,status\n"
                              "cbbg,1,1,0,2000,success\nbg_only,1,1,1,49,failed\n");
  const auto entries = read_trial_entries(path);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1].arm, "bg_only");
  EXPECT_EQ(entries[1].status, "failed");
  EXPECT_EQ(entries[0].trial, 1);
}

TEST_F(TrialLogs, AMalformedRowIsNamedByFileAndLine) {
  const fs::path path =
      write("trials.csv", "arm,seed,trial,status\ncbbg,1,1,success\ncbbg,x,2,failed\n");
  EXPECT_THAT(
      [&] { read_trial_entries(path); },
      ThrowsMessage<InputError>(path.string() + ": line 3: seed is 'x', not a whole number"));
  const fs::path short_row = write("short.csv", "arm,seed,trial,status\ncbbg,1\n");
  EXPECT_THAT(
      [&] { read_trial_entries(short_row); },
      ThrowsMessage<InputError>(short_row.string() + ": line 2: has 2 fields; the header has 4"));
  const fs::path missing = scratch_.path() / "nowhere.csv";
  EXPECT_THAT([&] { read_trial_entries(missing); },
              ThrowsMessage<InputError>(missing.string() +
                                        ": cannot be read (is this a results directory?)"));
}

TEST_F(TrialLogs, StepsWithoutAColumnThePageNeedsAreRefusedByColumn) {
  const fs::path path = write("steps.csv", "arm,seed,trial,t,theta_b,phi_l,a\n");
  EXPECT_THAT([&] { read_trial_logs(path, {entry("cbbg", 1, 1, "success")}); },
              ThrowsMessage<InputError>(path.string() + ": no column 'phi_r' (a replay needs it)"));
}

TEST_F(TrialLogs, APoseSignalThePlantLacksIsZero) {
  // A cart-pole's log: x, but no y nor yaw.
  const fs::path path = write("steps.csv",
                              "arm,seed,trial,t,theta_b,phi_l,phi_r,a,x\n"
                              "cbbg,1,1,0,0.1,0,0,0.5,0.25\n"
                              "cbbg,1,1,0.01,0.09,0.1,0.1,0.4,0.5\n");
  const std::vector<TrialLog> logs = read_trial_logs(path, {entry("cbbg", 1, 1, "success")});
  ASSERT_EQ(logs.size(), 1U);
  EXPECT_EQ(logs[0].x, (std::vector<double>{0.25, 0.5}));
  EXPECT_EQ(logs[0].y, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(logs[0].yaw, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(logs[0].theta_b, (std::vector<double>{0.1, 0.09}));
}

TEST_F(TrialLogs, ReadsTheWantedTrialsInTheWantedOrder) {
  const fs::path path =
      write("steps.csv", std::string(kStepsHeader) + step("cbbg", 1, 1, 0.0, 0.17, 0.0, 8.0, 0.0) +
                             step("cbbg", 1, 1, 0.01, 0.16, 0.1, 7.0, 0.015) +
                             step("cbbg", 1, 2, 0.0, 0.17, 0.0, 6.0, 0.0) +
                             step("cbbg", 2, 1, 0.0, 0.5, 0.0, 5.0, 0.0));
  const auto logs =
      read_trial_logs(path, {entry("cbbg", 1, 2, "success"), entry("cbbg", 1, 1, "failed")});
  ASSERT_EQ(logs.size(), 2u);
  EXPECT_EQ(logs[0].entry.trial, 2);
  EXPECT_THAT(logs[0].a, ElementsAre(6.0));
  EXPECT_THAT(logs[1].t, ElementsAre(0.0, 0.01));
  EXPECT_THAT(logs[1].theta_b, ElementsAre(0.17, 0.16));
  EXPECT_THAT(logs[1].x, ElementsAre(0.0, 0.015));
  EXPECT_THAT(logs[1].phi_r, ElementsAre(0.0, 0.1));
}

TEST_F(TrialLogs, ADivergedTrialEndsAtItsLastFinitePose) {
  const fs::path path =
      write("steps.csv", std::string(kStepsHeader) + step("cbbg", 1, 1, 0.0, 0.17, 0.0, 8.0, 0.0) +
                             step("cbbg", 1, 1, 0.01, 0.2, 0.1, 7.0, 0.01) +
                             "cbbg,1,1,0.02,nan,0,0,0,0,0,0,1,0,0,0,0,0,0,0,0\n");
  const auto logs = read_trial_logs(path, {entry("cbbg", 1, 1, "diverged")});
  EXPECT_THAT(logs[0].t, ElementsAre(0.0, 0.01));
}

TEST_F(TrialLogs, AWantedTrialWithoutTicksIsNamed) {
  const fs::path path =
      write("steps.csv", std::string(kStepsHeader) + step("cbbg", 1, 1, 0.0, 0.17, 0.0, 8.0, 0.0));
  EXPECT_THAT([&] { read_trial_logs(path, {entry("cbbg", 1, 7, "success")}); },
              ThrowsMessage<InputError>(path.string() +
                                        ": no ticks of cbbg, seed 1, trial 7 (was it run with "
                                        "log.decimation: 0, or cut short?)"));
}

std::vector<TrialEntry> exp2_like() {
  return {entry("cbbg", 1, 1, "failed"),    entry("cbbg", 1, 2, "success"),
          entry("cbbg", 1, 3, "success"),   entry("cbbg", 1, 4, "failed"),
          entry("bg_only", 1, 1, "failed"), entry("cbbg", 2, 1, "success")};
}

std::vector<int> numbers(const std::vector<TrialEntry>& entries) {
  std::vector<int> trials;
  for (const auto& e : entries) trials.push_back(e.trial);
  return trials;
}

TEST(ChooseTrials, ByDefaultTheFirstTheFirstSuccessfulAndTheLastOfTheFirstArmAndSeed) {
  EXPECT_THAT(numbers(choose_trials(exp2_like(), {})), ElementsAre(1, 2, 4));
  // A first trial that succeeds, and is also the last, is shown once.
  EXPECT_THAT(numbers(choose_trials(exp2_like(), {"cbbg", 2, {}})), ElementsAre(1));
  EXPECT_THAT(numbers(choose_trials(exp2_like(), {"bg_only", std::nullopt, {}})), ElementsAre(1));
  EXPECT_THAT(numbers(choose_trials(exp2_like(), {std::nullopt, std::nullopt, {3, 1}})),
              ElementsAre(3, 1));
}

TEST(ChooseTrials, AChoiceTheRunLacksNamesTheFlagAndWhatThereIs) {
  EXPECT_THAT(
      [] {
        choose_trials(exp2_like(), {"pd_only", std::nullopt, {}});
      },
      ThrowsMessage<ChoiceError>("--arm: no arm 'pd_only' in this run; it has 'cbbg', 'bg_only'"));
  EXPECT_THAT(
      [] {
        choose_trials(exp2_like(), {"cbbg", 9, {}});
      },
      ThrowsMessage<ChoiceError>("--seed: arm 'cbbg' has no seed 9; its seeds are 1 to 2"));
  EXPECT_THAT(
      [] {
        choose_trials(exp2_like(), {"cbbg", 1, {5}});
      },
      ThrowsMessage<ChoiceError>("--trial: arm 'cbbg', seed 1 has trials 1 to 4; got 5"));
  EXPECT_THAT([] { choose_trials({}, {}); }, ThrowsMessage<InputError>("trials.csv has no trials"));
}

}  // namespace
}  // namespace cbbg::replay
