#include "cbbg/framework/primitives/discrete_linear_system.h"

#include <utility>
#include <vector>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/primitives/argument_checks.h"
#include "cbbg/framework/primitives/linear_system.h"

namespace cbbg {

DiscreteLinearSystem::DiscreteLinearSystem(std::string name, const Eigen::MatrixXd& A,
                                           const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                                           const Eigen::MatrixXd& D, const Vector& initial_state,
                                           double period, double offset)
    : Block(std::move(name)), A_(A), B_(B), C_(C), D_(D), feedthrough_(false) {
  const std::string label = primitive_checks::label("DiscreteLinearSystem", this->name());
  check_state_space(label, A_, B_, C_, D_, initial_state);
  primitive_checks::check_period(label, period, offset);
  feedthrough_ = (D_.array() != 0.0).any();
  u_ = &declare_input_port("u", static_cast<int>(B_.cols()), "the input");
  declare_discrete_state("x", initial_state, StateLifetime::kPerTrial);
  std::vector<const InputPort*> reads;
  if (feedthrough_) reads.push_back(u_);
  declare_output_port<&DiscreteLinearSystem::calc_y>("y", static_cast<int>(C_.rows()),
                                                     std::move(reads), "C x + D u",
                                                     OutputSources::kDiscreteState);
  declare_periodic_update<&DiscreteLinearSystem::step>(period, offset);
}

void DiscreteLinearSystem::calc_y(const BlockContext& context, VectorRef y) const {
  y.noalias() = C_ * context.discrete_state();
  if (feedthrough_) y.noalias() += D_ * context.input(*u_);
}

EventStatus DiscreteLinearSystem::step(BlockContext& context, VectorRef next) const {
  // `next` and the state the context holds are separate storage: no aliasing.
  next.noalias() = A_ * context.discrete_state();
  next.noalias() += B_ * context.input(*u_);
  return EventStatus::succeeded();
}

}  // namespace cbbg
