#pragma once
// The random generator of an exported learner: framework/random.h's, written in C99, so that
// its draws are the C++ blocks' own (std::mt19937_64, 2,504 bytes of state; the normal draw
// by Box-Muller on two uniforms). The float export draws its uniforms from 24 bits.

#include <cstdint>
#include <string>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/random.h"

namespace cbbg::codegen {

// `typedef struct { uint64_t x[312]; int p; } NAME_random;` for the header.
std::string c_random_type(const std::string& name);

// The generator's functions (static), and the macros a body draws through: CBBG_UNIFORM(g),
// CBBG_NORMAL(g); NAME_random_seed(g, seed) seeds as std::mt19937_64(seed) does, and
// NAME_derive_seed(root, hash) is framework/random.h's derive_seed of a path's hash.
std::string c_random_functions(const std::string& name, Scalar scalar);

// `generator`'s state as an initializer of NAME_random: "{{x0, ...}, p}".
std::string c_random_state(const RandomGenerator& generator);

// `value` as a C99 literal of uint64_t.
std::string c_uint64(std::uint64_t value);

}  // namespace cbbg::codegen
