#include "cbbg/framework/random.h"

#include <cmath>
#include <numbers>

namespace cbbg {
namespace {

// SplitMix64 finaliser: a bijective mix with good avalanche, so nearby inputs diverge.
std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::uint64_t path_hash(std::string_view block_path) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : block_path) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::uint64_t derive_seed(std::uint64_t root_seed, std::string_view block_path) {
  return mix64(mix64(root_seed) ^ path_hash(block_path));
}

double draw_uniform(RandomGenerator& generator) {
  return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

double draw_standard_normal(RandomGenerator& generator) {
  // 1 - u lies in (0, 1], so the logarithm is finite.
  const double u1 = 1.0 - draw_uniform(generator);
  const double u2 = draw_uniform(generator);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace cbbg
