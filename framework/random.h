#pragma once
// Per-block random generators derived from one root seed and the block's path.

#include <cstdint>
#include <random>
#include <string_view>

namespace cbbg {

// The generator each block owns in the Context. std::mt19937_64 is fully specified by the
// standard, so a seed gives the same stream on every platform.
using RandomGenerator = std::mt19937_64;

// Seed of the generator of the block at `block_path` under `root_seed`: a hash of both, so
// two blocks of one diagram get unrelated streams and renaming a block changes only its own.
std::uint64_t derive_seed(std::uint64_t root_seed, std::string_view block_path);
// The hash of `block_path` derive_seed mixes with the root seed: FNV-1a 64 of its bytes.
std::uint64_t path_hash(std::string_view block_path);

// One standard normal draw that keeps no state outside the generator (unlike
// std::normal_distribution, which caches a second value), so cloning a Context clones
// everything that decides the next draw. Box–Muller on two 53-bit uniforms.
double draw_standard_normal(RandomGenerator& generator);

// Uniform draw on [0, 1) from the top 53 bits of one generator output.
double draw_uniform(RandomGenerator& generator);

}  // namespace cbbg
