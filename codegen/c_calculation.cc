#include "cbbg/codegen/c_calculation.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cbbg/framework/block.h"

namespace cbbg::codegen {
namespace {

[[noreturn]] void cannot_update(const EmitsC& emitter, const char* kind) {
  const auto* block = dynamic_cast<const Block*>(&emitter);
  throw std::invalid_argument("block '" + (block != nullptr ? block->path() : "?") +
                              "' cannot write its " + kind +
                              " as C: it does not implement codegen::EmitsC::c_" + kind);
}

}  // namespace

CCalculation EmitsC::c_update(int, const Context&) const { cannot_update(*this, "update"); }

CCalculation EmitsC::c_initialization(int, const Context&) const {
  cannot_update(*this, "initialization");
}

std::string c_literal(double value, Scalar scalar) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument("a constant of the exported code is not finite: " +
                                std::to_string(value));
  }
  char text[64];
  if (scalar == Scalar::kFloat) {
    std::snprintf(text, sizeof text, "%.9gf", static_cast<double>(static_cast<float>(value)));
  } else {
    std::snprintf(text, sizeof text, "%.17g", value);
  }
  std::string literal = text;
  // A whole number needs a point to be a floating literal ("2f" is no C).
  const auto digits_end = literal.find_first_of("f");
  const std::string number = literal.substr(0, digits_end);
  if (number.find_first_of(".eEn") == std::string::npos) {
    literal.insert(number.size(), ".0");
  }
  return literal;
}

std::string c_clamp(const std::string& value, const std::string& low, const std::string& high) {
  return "(" + value + " < " + low + " ? " + low + " : " + high + " < " + value + " ? " + high +
         " : " + value + ")";
}

std::string c_dot(const std::string& target, const std::string& a, const std::string& b, int n) {
  const auto product = [&](const std::string& at) {
    return a + "[" + at + "] * " + b + "[" + at + "]";
  };
  if (n < 2)
    return n == 1 ? "  " + target + " = " + product("0") + ";\n" : "  " + target + " = 0;\n";
  const int quads = n / 4 * 4;  // the values the two accumulators take, four at a time
  const int pairs = n / 2 * 2;
  std::string c = "  {\n    real r0 = " + product("0") + ", r1 = " + product("1") + ";\n";
  if (pairs > 2) {
    c += "    real q0 = " + product("2") + ", q1 = " + product("3") + ";\n";
    c += "    for (int k = 4; k < " + std::to_string(quads) + "; k += 4) {\n";
    c += "      r0 += " + product("k") + ";\n      r1 += " + product("k + 1") + ";\n";
    c += "      q0 += " + product("k + 2") + ";\n      q1 += " + product("k + 3") + ";\n    }\n";
    c += "    r0 += q0;\n    r1 += q1;\n";
    if (pairs > quads) {
      const std::string at = std::to_string(quads);
      c +=
          "    r0 += " + product(at) + ";\n    r1 += " + product(std::to_string(quads + 1)) + ";\n";
    }
  }
  c += "    " + target + " = r0 + r1;\n";
  if (n > pairs) c += "    " + target + " += " + product(std::to_string(pairs)) + ";\n";
  return c + "  }\n";
}

}  // namespace cbbg::codegen
