#include "cbbg/realtime/link_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace cbbg::realtime {

long long LinkFigures::refused_total() const {
  return std::accumulate(refused.begin(), refused.end(), 0LL);
}

double LinkFigures::latency_quantile(double q) const {
  if (latencies.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> sorted = latencies;
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  const std::size_t index = std::clamp<std::size_t>(rank, 1, sorted.size()) - 1;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(index), sorted.end());
  return sorted[index];
}

void LinkFigures::add(const LinkFigures& other) {
  ticks += other.ticks;
  deadline_misses += other.deadline_misses;
  lost += other.lost;
  for (std::size_t i = 0; i < kRefusals; ++i) refused[i] += other.refused[i];
  latencies.insert(latencies.end(), other.latencies.begin(), other.latencies.end());
}

std::string LinkFigures::line() const {
  const auto micro = [](double seconds) {
    return std::isnan(seconds) ? std::string("-") : std::to_string(std::lround(seconds * 1e6));
  };
  std::string text = std::to_string(ticks) + " ticks, " + std::to_string(deadline_misses) +
                     " deadline misses, latency p50 " + micro(latency_quantile(0.5)) + " us, p99 " +
                     micro(latency_quantile(0.99)) + " us, max " + micro(latency_quantile(1.0)) +
                     " us, " + std::to_string(lost) + " lost, " + std::to_string(refused_total()) +
                     " refused";
  std::string reasons;
  for (std::size_t i = 0; i < kRefusals; ++i) {
    if (refused[i] == 0) continue;
    reasons += (reasons.empty() ? "" : ", ") + std::to_string(refused[i]) + " " +
               to_string(static_cast<Refusal>(i));
  }
  return reasons.empty() ? text : text + " (" + reasons + ")";
}

}  // namespace cbbg::realtime
