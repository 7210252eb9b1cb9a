#pragma once
// What a block writes of one of its calculations as C99, for the exported controller
// (c_export.h, `cbbg export`): the statements that compute an output from the inputs it
// reads, and the constants they name (parameters and learnt weights). A block opts in by
// implementing EmitsC; a user's block does the same, and a diagram with a block that does
// not is refused, naming it.

#include <string>
#include <vector>

namespace cbbg {
class Context;
}

namespace cbbg::codegen {

// The number type of the exported code.
enum class Scalar { kDouble, kFloat };

// A constant the calculation names: its values, written as a `static const` array, or as one
// number when `array` is false.
struct CConstant {
  std::string name;  // a C identifier
  std::vector<double> values;
  bool array = true;
};

// The constant `name` of one number, written as a number.
inline CConstant c_number(std::string name, double value) {
  return {std::move(name), {value}, false};
}

// One calculation of a block: an output's, or an update's (the learner export,
// c_learner_export.h). `body` is C99 statements (they may declare locals) over:
//   in0, in1, ...  `const real *`: for an output, the inputs it reads (Block::output_reads
//                  order); for an update, every input of the block (port order)
//   out            for an output: the output, `real *`
//   out0, out1, .. for an update: every output of the block at this instant (port order),
//                  `const real *`
//   @part          the block's discrete-state part `part` (Block::discrete_state_part) before
//                  the instant: in a policy, constant values; in a learner, the learner's
//   @@part         for an update: the part after the instant, which it writes (the same memory
//                  as @part for an update declared UpdateWrites::kInPlace)
//   $NAME          the constant NAME of `constants`
//   rng            for an update that `draws`: the block's generator, read through
//                  CBBG_NORMAL(rng) and CBBG_UNIFORM(rng) (framework/random.h's draws)
//   real           the scalar type; CBBG_EXP, CBBG_EXP2, CBBG_SQRT, CBBG_LOG, CBBG_COS and
//                  CBBG_FABS: <math.h>'s functions for it
// An update's body ends the trial with `return 1;` (EventStatus::terminate) and otherwise
// runs to its end. The statements must compute in the order the block's C++ does: then the
// double export reproduces it to the bit.
struct CCalculation {
  std::vector<CConstant> constants;
  std::string body;
  bool draws = false;  // an update's body draws from `rng`
};

class EmitsC {
 public:
  virtual ~EmitsC() = default;
  // The calculation of output `output` (its index) with the state `context` holds of the
  // block. Throws std::invalid_argument naming the port for an output it cannot write.
  virtual CCalculation c_calculation(int output, const Context& context) const = 0;
  // The periodic update `update` (its index in Block::periodic_updates) and the
  // initialization update `update` (Block::initialization_updates) as C, for the learner
  // export. An initialization update reads no input and no output. By default a block
  // cannot: both throw std::invalid_argument naming it.
  virtual CCalculation c_update(int update, const Context& context) const;
  virtual CCalculation c_initialization(int update, const Context& context) const;
};

// `value` as a C literal of `scalar`: the 17 digits a double needs to come back the same, or
// the value rounded to float in 9 digits with an `f` suffix.
std::string c_literal(double value, Scalar scalar);

// libstdc++'s std::clamp(value, low, high) as a C expression: (v < lo ? lo : hi < v ? hi : v).
std::string c_clamp(const std::string& value, const std::string& low, const std::string& high);

// C statements that set `target` to the dot product of the arrays `a` and `b` of `n` values
// in the order Eigen's a.dot(b) sums them (the blocks' C++ does): pairs of values in two
// accumulators of pairs (SSE2's two lanes), a last pair, the lanes added, the odd value last.
std::string c_dot(const std::string& target, const std::string& a, const std::string& b, int n);

}  // namespace cbbg::codegen
