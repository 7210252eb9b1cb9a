// Evaluations shared by the seeds of a run: what drew no random number is run once, what
// did is each seed's own, on one thread or many, and a failure is no one's answer.

#include "cbbg/experiments/shared_evaluations.h"

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace cbbg::experiments {
namespace {

using Records = SharedEvaluations::Records;

// One record whose final pitch tells which seed ran the item.
SeedEvaluation evaluation_of(int seed, std::size_t item, bool seed_free) {
  EvaluationRecord record;
  record.theta0 = static_cast<double>(item);
  record.outcome.final_theta = seed;
  return {{record}, seed_free};
}

double runner_of(const Records& records) { return records.front().outcome.final_theta; }

TEST(SharedEvaluations, WhatDrewNoRandomNumberRunsOnceForEverySeed) {
  SharedEvaluations shared;
  int runs = 0;
  const auto by = [&](int seed) {
    return [&runs, seed](std::size_t item) {
      ++runs;
      return evaluation_of(seed, item, true);
    };
  };
  const std::vector<Records> first = shared.evaluate("pd_only", 3, by(1));
  const std::vector<Records> second = shared.evaluate("pd_only", 3, by(2));
  EXPECT_EQ(runs, 3);
  ASSERT_EQ(second.size(), 3U);
  for (std::size_t item = 0; item < 3; ++item) {
    EXPECT_EQ(runner_of(second[item]), 1.0);
    EXPECT_EQ(second[item].front().theta0, double(item));
  }
  // Another arm's items are its own.
  shared.evaluate("other", 3, by(3));
  EXPECT_EQ(runs, 6);
}

TEST(SharedEvaluations, WhatDrewARandomNumberIsEachSeedsOwn) {
  SharedEvaluations shared;
  const auto noisy_second = [](int seed) {
    return [seed](std::size_t item) { return evaluation_of(seed, item, item != 1); };
  };
  shared.evaluate("pd_only", 2, noisy_second(1));
  const std::vector<Records> second = shared.evaluate("pd_only", 2, noisy_second(2));
  EXPECT_EQ(runner_of(second[0]), 1.0);
  EXPECT_EQ(runner_of(second[1]), 2.0);
}

TEST(SharedEvaluations, SeedsOnManyThreadsRunEachSharedItemOnce) {
  SharedEvaluations shared;
  constexpr int kSeeds = 6;
  constexpr std::size_t kItems = 20;
  std::atomic<int> runs{0};
  std::vector<std::vector<Records>> results(kSeeds);
  std::vector<std::thread> threads;
  for (int seed = 0; seed < kSeeds; ++seed) {
    threads.emplace_back([&, seed] {
      results[static_cast<std::size_t>(seed)] =
          shared.evaluate("pd_only", kItems, [&, seed](std::size_t item) {
            ++runs;
            std::this_thread::yield();
            return evaluation_of(seed, item, item % 2 == 0);
          });
    });
  }
  for (auto& thread : threads) thread.join();
  // The shared half once, the other half once per seed.
  EXPECT_EQ(runs.load(), int(kItems / 2) + kSeeds * int(kItems / 2));
  for (std::size_t item = 0; item < kItems; ++item) {
    for (int seed = 0; seed < kSeeds; ++seed) {
      const double runner = runner_of(results[static_cast<std::size_t>(seed)][item]);
      if (item % 2 == 0) {
        EXPECT_EQ(runner, runner_of(results[0][item])) << item;
      } else {
        EXPECT_EQ(runner, seed) << item;
      }
    }
  }
}

TEST(SharedEvaluations, AFailedItemReachesItsSeedAndIsLeftToTheOthers) {
  SharedEvaluations shared;
  EXPECT_THROW(shared.evaluate("pd_only", 2,
                               [](std::size_t item) -> SeedEvaluation {
                                 if (item == 1) throw std::runtime_error("diverged");
                                 return evaluation_of(1, item, true);
                               }),
               std::runtime_error);
  const std::vector<Records> second =
      shared.evaluate("pd_only", 2, [](std::size_t item) { return evaluation_of(2, item, true); });
  EXPECT_EQ(runner_of(second[0]), 1.0);
  EXPECT_EQ(runner_of(second[1]), 2.0);
}

}  // namespace
}  // namespace cbbg::experiments
