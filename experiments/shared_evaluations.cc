#include "cbbg/experiments/shared_evaluations.h"

#include <chrono>

namespace cbbg::experiments {

std::vector<SharedEvaluations::Records> SharedEvaluations::evaluate(const std::string& owner,
                                                                    std::size_t count,
                                                                    const Evaluate& evaluate) {
  std::vector<Records> records(count);
  std::vector<std::pair<std::size_t, std::shared_future<Shared>>> running_elsewhere;
  for (std::size_t item = 0; item < count; ++item) {
    std::promise<Shared> claim;
    std::shared_future<Shared> other;
    {
      const std::lock_guard lock(mutex_);
      const auto [entry, claimed] = items_.try_emplace(Key{owner, item});
      if (claimed) {
        entry->second = claim.get_future().share();
      } else {
        other = entry->second;
      }
    }
    if (!other.valid()) {
      records[item] = run_claimed(claim, evaluate, item);
    } else if (other.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
      records[item] = take(other, evaluate, item);
    } else {
      running_elsewhere.emplace_back(item, other);
    }
  }
  // Every item this seed claimed is done: waiting now cannot hold up another seed.
  for (const auto& [item, other] : running_elsewhere) records[item] = take(other, evaluate, item);
  return records;
}

SharedEvaluations::Records SharedEvaluations::run_claimed(std::promise<Shared>& claim,
                                                          const Evaluate& evaluate,
                                                          std::size_t item) {
  SeedEvaluation evaluation;
  try {
    evaluation = evaluate(item);
  } catch (...) {
    claim.set_value(std::nullopt);  // the waiting seeds run it themselves
    throw;
  }
  claim.set_value(evaluation.seed_free ? Shared(evaluation.records) : std::nullopt);
  return std::move(evaluation.records);
}

SharedEvaluations::Records SharedEvaluations::take(const std::shared_future<Shared>& shared,
                                                   const Evaluate& evaluate, std::size_t item) {
  const Shared& records = shared.get();
  return records ? *records : evaluate(item).records;
}

}  // namespace cbbg::experiments
