#include "cbbg/codegen/c_random.h"

#include <cinttypes>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace cbbg::codegen {
namespace {

// std::mt19937_64's parameters (the standard's [rand.predef]).
constexpr int kWords = 312;

}  // namespace

std::string c_uint64(std::uint64_t value) {
  char text[32];
  std::snprintf(text, sizeof text, "0x%016" PRIx64 "ULL", value);
  return text;
}

std::string c_random_type(const std::string& name) {
  return "/* A std::mt19937_64 generator: its " + std::to_string(kWords) +
         " words and the index of the next. */\ntypedef struct {\n  uint64_t x[" +
         std::to_string(kWords) + "];\n  int p;\n} " + name + "_random;\n";
}

std::string c_random_functions(const std::string& name, Scalar scalar) {
  const std::string g = name + "_random";
  std::string c = "\n/* The generator: std::mt19937_64, as the C++ blocks draw from it. */\n";
  c += "static void " + name + "_twist(" + g + " *g) {\n";
  c += "  int i;\n  for (i = 0; i < 312; ++i) {\n";
  c += "    const uint64_t y = (g->x[i] & 0xffffffff80000000ULL) | "
       "(g->x[(i + 1) % 312] & 0x7fffffffULL);\n";
  c += "    g->x[i] = g->x[(i + 156) % 312] ^ (y >> 1) ^ ((y & 1) ? 0xb5026f5aa96619e9ULL : 0);\n";
  c += "  }\n  g->p = 0;\n}\n\n";
  c += "static uint64_t " + name + "_next(" + g + " *g) {\n  uint64_t z;\n";
  c += "  if (g->p >= 312) " + name + "_twist(g);\n  z = g->x[g->p++];\n";
  c += "  z ^= (z >> 29) & 0x5555555555555555ULL;\n  z ^= (z << 17) & 0x71d67fffeda60000ULL;\n";
  c += "  z ^= (z << 37) & 0xfff7eee000000000ULL;\n  return z ^ (z >> 43);\n}\n\n";
  // framework/random.h's draw_uniform: 53 bits in double; float takes 24, so 1 - u > 0.
  // Inline: C warns of an unused static function, and a learner may draw only one kind.
  c += "static inline real " + name + "_uniform(" + g + " *g) {\n";
  c += scalar == Scalar::kFloat ? "  return (real)(" + name + "_next(g) >> 40) * 0x1.0p-24f;\n"
                                : "  return (real)(" + name + "_next(g) >> 11) * 0x1.0p-53;\n";
  c += "}\n\n";
  c += "static inline real " + name + "_normal(" + g + " *g) {\n";
  c += "  const real u1 = (real)1 - " + name + "_uniform(g);\n";
  c += "  const real u2 = " + name + "_uniform(g);\n";
  c += "  return CBBG_SQRT((real)-2 * CBBG_LOG(u1)) * CBBG_COS(" +
       c_literal(2.0 * std::numbers::pi, scalar) + " * u2);\n}\n\n";
  c += "static void " + name + "_random_seed(" + g + " *g, uint64_t seed) {\n  int i;\n";
  c += "  g->x[0] = seed;\n  for (i = 1; i < 312; ++i) {\n";
  c += "    g->x[i] = 6364136223846793005ULL * (g->x[i - 1] ^ (g->x[i - 1] >> 62)) + "
       "(uint64_t)i;\n  }\n  g->p = 312;\n}\n\n";
  c += "static uint64_t " + name + "_mix64(uint64_t z) {\n  z += 0x9e3779b97f4a7c15ULL;\n";
  c += "  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;\n";
  c += "  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;\n  return z ^ (z >> 31);\n}\n\n";
  c += "static uint64_t " + name + "_derive_seed(uint64_t root, uint64_t path_hash) {\n";
  c += "  return " + name + "_mix64(" + name + "_mix64(root) ^ path_hash);\n}\n\n";
  c += "#define CBBG_UNIFORM(g) " + name + "_uniform(g)\n";
  c += "#define CBBG_NORMAL(g) " + name + "_normal(g)\n";
  return c;
}

std::string c_random_state(const RandomGenerator& generator) {
  std::stringstream words;
  words << generator;  // libstdc++: the 312 words, then the index, spaced
  std::string c = "{{";
  for (int i = 0; i < kWords; ++i) {
    std::uint64_t word = 0;
    if (!(words >> word)) throw std::logic_error("a random generator's state did not read back");
    c += (i % 3 == 0 ? "\n    " : " ") + c_uint64(word) + (i + 1 < kWords ? "," : "");
  }
  int index = 0;
  if (!(words >> index)) throw std::logic_error("a random generator's index did not read back");
  return c + "},\n  " + std::to_string(index) + "}";
}

}  // namespace cbbg::codegen
