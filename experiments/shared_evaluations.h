#pragma once
// Evaluations shared by the seeds of one run. An evaluation that drew no random number
// (SeedEvaluation::seed_free: a closed loop that learns nothing, without noise) gives the same
// records under every seed, so the first seed to run it keeps them and the others take them
// instead of running it again: the records are the same bytes either way, and the time of
// one evaluation is saved per other seed. The transfer protocol shares its conditions'
// evaluations of an arm that learns nothing (pd_only) so.
//
// The seeds of a run are evaluated on several threads at once, each seed on one: a thread
// takes what another has finished, runs what no thread has started and leaves what another
// is running to the end, when it waits for it.

#include <cstddef>
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cbbg/experiments/protocol_kit.h"
#include "cbbg/experiments/seed_run.h"

namespace cbbg::experiments {

class SharedEvaluations {
 public:
  using Records = std::vector<EvaluationRecord>;
  // Evaluates item `item` (a condition, say) for the calling seed.
  using Evaluate = std::function<SeedEvaluation(std::size_t item)>;

  // The records of items 0 .. count - 1 of `owner` (an arm's name) for the calling seed: an
  // item's shared records when a seed ran it without drawing a random number, else
  // evaluate(item)'s. An exception of evaluate reaches the caller; the item is then left to
  // each seed to run.
  std::vector<Records> evaluate(const std::string& owner, std::size_t count,
                                const Evaluate& evaluate);

 private:
  using Shared = std::optional<Records>;  // none: each seed runs the item itself
  using Key = std::pair<std::string, std::size_t>;

  // Runs an item this seed claimed and tells the seeds waiting for it what they may take.
  Records run_claimed(std::promise<Shared>& claim, const Evaluate& evaluate, std::size_t item);
  // The records another seed shared for the item, or this seed's own run of it.
  Records take(const std::shared_future<Shared>& shared, const Evaluate& evaluate,
               std::size_t item);

  std::mutex mutex_;
  std::map<Key, std::shared_future<Shared>> items_;
};

}  // namespace cbbg::experiments
