#pragma once

#include <string>
#include <string_view>

#include "cbbg/codegen/c_calculation.h"
#include "cbbg/framework/block.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/parameters.h"

namespace cbbg::blocks {

// Config key tropism.kind: how the temperature follows the value.
enum class TropismKind {
  kValue,  // "value": T = k1 / (1 + exp(k2 V)), the paper's
  kFixed,  // "fixed": T = k1 / 2, the paper's at V = 0, whatever V
};

// "value" or "fixed"; anything else throws naming tropism.kind.
TropismKind parse_tropism_kind(std::string_view text);
std::string_view to_string(TropismKind kind);

// Config keys tropism.*.
struct TropismParams {
  double k1 = 10.0;  // tropism.k1: the annealing factor, > 0 (the context parameter's default)
  double k2 = 0.1;   // tropism.k2: how strongly a high value cools the temperature
  TropismKind kind = TropismKind::kValue;  // tropism.kind

  static constexpr const char* kSection = "tropism";
  template <class Archive>
  void describe(Archive& a) {
    a.number("k1", k1, "annealing factor: T = k1 / (1 + exp(k2 V))", kPositive);
    a.number("k2", k2, "how strongly a high value cools the temperature", kFinite);
    a.choice("kind", kind,
             "value (the paper's: T = k1 / (1 + exp(k2 V))) | fixed (T = k1 / 2, whatever V)",
             Choices<TropismKind>{{"value", TropismKind::kValue}, {"fixed", TropismKind::kFixed}});
  }

  // Throws naming the key unless k1 is finite and > 0, k2 is finite and kind is one of the two.
  void validate() const;
};

/// Tropism: the exploration temperature from the critic's value (docs/model.md §2.5).
///
/// | port        | dir | size | meaning                       |
/// |-------------|-----|------|-------------------------------|
/// | value       | in  | 1    | V(s_t), from the Critic       |
/// | temperature | out | 1    | T                             |
///
/// Equation: T = k1 / (1 + exp(k2 V)): high value, low temperature. With tropism.kind fixed,
/// T = k1 / 2 (the paper's T at V = 0) whatever V: exploration no longer cools as the critic
/// learns, yet still follows k1's annealing.
/// Parameters: k1 is the context parameter "k1" (default tropism.k1), so the annealing
/// schedule changes it between trials without rebuilding (set_k1); k2 = tropism.k2, kind =
/// tropism.kind.
class Tropism final : public Block, public codegen::EmitsC {
 public:
  Tropism(std::string name, const TropismParams& params);

  // Its temperature as C (cbbg export; codegen::EmitsC), k1 as `context` holds it.
  codegen::CCalculation c_calculation(int output, const Context& context) const override;

  // Sets k1 in `context` for the next trials; throws naming tropism.k1 unless finite, > 0.
  void set_k1(Context& context, double k1) const;
  double k1(const Context& context) const;

 private:
  // "temperature": T = k1 / (1 + exp(k2 V)), or k1 / 2 with kind fixed.
  void calc_temperature(const BlockContext& context, VectorRef temperature) const;

  TropismParams params_;
  int k1_index_;
  const InputPort* value_;
};

}  // namespace cbbg::blocks
