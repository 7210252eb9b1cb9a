#pragma once
// What a real-time link measures over a trial: deadline misses, the round trip of each torque
// (the robot's clock, from its measurement sent to the answer received), the datagrams lost
// and those refused, by reason (wire.h's Refusal).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cbbg/realtime/wire.h"

namespace cbbg::realtime {

inline constexpr std::size_t kRefusals = 6;  // the values of Refusal

struct LinkFigures {
  long long ticks = 0;            // measurements applied
  long long deadline_misses = 0;  // torques the robot did not have by its deadline
  // Measurements not applied: never arrived (a gap in their sequence), or passed over for a
  // newer one queued behind them.
  long long lost = 0;
  std::array<long long, kRefusals> refused{};  // datagrams dropped, by Refusal
  std::vector<double> latencies;               // round trips the robot measured, s

  long long refused_total() const;
  void refuse(Refusal refusal) { ++refused[static_cast<std::size_t>(refusal)]; }
  // The latencies' quantile q in [0, 1] (nearest rank); NaN when there are none.
  double latency_quantile(double q) const;
  void add(const LinkFigures& other);
  // One line: "1999 ticks, 0 deadline misses, latency p50 81 us, p99 140 us, max 350 us, ...".
  std::string line() const;
};

}  // namespace cbbg::realtime
