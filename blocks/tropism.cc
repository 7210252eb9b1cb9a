#include "cbbg/blocks/tropism.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cbbg/blocks/parameter_checks.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::blocks {

TropismKind parse_tropism_kind(std::string_view text) {
  if (text == "value") return TropismKind::kValue;
  if (text == "fixed") return TropismKind::kFixed;
  throw std::invalid_argument("tropism.kind must be value or fixed; got '" + std::string(text) +
                              "'");
}

std::string_view to_string(TropismKind kind) {
  return kind == TropismKind::kFixed ? "fixed" : "value";
}

void TropismParams::validate() const { check_declared(*this, kSection); }

Tropism::Tropism(std::string name, const TropismParams& params)
    : Block(std::move(name)), params_(params) {
  params_.validate();
  k1_index_ = declare_parameter("k1", Vector::Constant(1, params_.k1));
  value_ = &declare_input_port("value", 1, "V(s_t)");
  declare_output_port<&Tropism::calc_temperature>(
      "temperature", 1, {value_},  // read by "value" only; "fixed" keeps the same topology
      params_.kind == TropismKind::kFixed ? "T = k1 / 2" : "T = k1 / (1 + exp(k2 V))");
}

void Tropism::calc_temperature(const BlockContext& context, VectorRef temperature) const {
  const double k1 = context.parameter(k1_index_)[0];
  if (params_.kind == TropismKind::kFixed) {
    temperature[0] = k1 / 2.0;
    return;
  }
  temperature[0] = k1 / (1.0 + std::exp(params_.k2 * context.input(*value_)[0]));
}

void Tropism::set_k1(Context& context, double k1) const {
  check_positive("tropism.k1", k1);
  context.set_parameter(*this, "k1", Vector::Constant(1, k1));
}

double Tropism::k1(const Context& context) const { return context.parameter(*this, "k1")[0]; }

codegen::CCalculation Tropism::c_calculation(int, const Context& context) const {
  // in0 V.
  codegen::CCalculation c;
  c.constants = {codegen::c_number("k1", k1(context))};
  if (params_.kind == TropismKind::kFixed) {
    c.body = "  (void)in0;\n  out[0] = $k1 / (real)2;\n";
    return c;
  }
  c.constants.push_back(codegen::c_number("k2", params_.k2));
  c.body = "  out[0] = $k1 / ((real)1 + CBBG_EXP($k2 * in0[0]));\n";
  return c;
}

}  // namespace cbbg::blocks
