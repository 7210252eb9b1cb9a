#include "cbbg/framework/control/linearize.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::control {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// "'a', 'b'": the paths of the leaves, for messages.
std::string leaf_paths(const Diagram& diagram, const std::vector<int>& leaves) {
  std::string paths;
  for (const int leaf : leaves) {
    paths += (paths.empty() ? "'" : ", '") +
             diagram.leaves()[static_cast<size_t>(leaf)].block->path() + "'";
  }
  return paths;
}

// The diagram's dynamics and outputs as functions of (x, u), each evaluated on a fresh copy
// of the operating point (so random generators and unperturbed state start alike).
class Model {
 public:
  Model(const Diagram& diagram, const Context& operating_point)
      : diagram_(diagram), base_(operating_point.clone()), work_(operating_point.clone()) {
    for (int port = 0; port < diagram.num_input_ports(); ++port) {
      inputs_.push_back({diagram.root_input_offset(port), diagram.input_port(port).size()});
      num_inputs_ += diagram.input_port(port).size();
    }
    for (int port = 0; port < diagram.num_output_ports(); ++port) {
      outputs_.push_back(
          {diagram.signal_offset(diagram.output_port(port)), diagram.output_port(port).size()});
      num_outputs_ += diagram.output_port(port).size();
    }
  }

  // Discrete time: x is the discrete state of `leaves`, stepped by `updates`.
  void use_discrete_state(const std::vector<int>& leaves,
                          std::vector<std::pair<int, const UpdateCalculation*>> updates) {
    discrete_ = true;
    updates_ = std::move(updates);
    for (const int leaf : leaves) {
      const LeafLayout& layout = diagram_.leaves()[static_cast<size_t>(leaf)];
      const auto size = static_cast<int>(layout.block->initial_discrete_state().size());
      states_.push_back({layout.discrete_offset, size});
      num_states_ += size;
    }
  }
  // Continuous time: x is the simulator-integrated continuous state.
  void use_continuous_state() { num_states_ = diagram_.ode_size(); }

  int num_states() const { return num_states_; }
  int num_inputs() const { return num_inputs_; }
  int num_outputs() const { return num_outputs_; }

  VectorXd state() const {
    VectorXd x(num_states_);
    if (!discrete_) return base_->continuous_states().head(num_states_);
    int at = 0;
    for (const auto& [offset, size] : states_) {
      x.segment(at, size) = base_->discrete_states().segment(offset, size);
      at += size;
    }
    return x;
  }
  VectorXd input() const { return gather(base_->signals(), inputs_, num_inputs_); }

  // x' (continuous) or x[k+1] (discrete) at (x, u).
  VectorXd dynamics(const VectorXd& x, const VectorXd& u) {
    set(x, u);
    Context& context = *work_;
    if (!discrete_) {
      VectorXd x_dot(num_states_);
      diagram_.evaluate_continuous_inputs(context);
      for (const int index : diagram_.ode_leaves()) {
        const LeafLayout& leaf = diagram_.leaves()[static_cast<size_t>(index)];
        const BlockContext view(context, leaf);
        leaf.block->derivative_calculation()(
            view,
            x_dot.segment(leaf.continuous_offset, leaf.block->initial_continuous_state().size()));
      }
      return x_dot;
    }
    diagram_.evaluate_outputs(context);
    context.next_discrete_states() = context.discrete_states();
    for (const auto& [index, update] : updates_) {
      const LeafLayout& leaf = diagram_.leaves()[static_cast<size_t>(index)];
      BlockContext view(context, leaf);
      (*update)(view, VectorView(context.next_discrete_states().data() + leaf.discrete_offset,
                                 leaf.block->initial_discrete_state().size()));
    }
    return gather(context.next_discrete_states(), states_, num_states_);
  }

  // y at (x, u).
  VectorXd outputs(const VectorXd& x, const VectorXd& u) {
    set(x, u);
    diagram_.evaluate_outputs(*work_);
    return gather(work_->signals(), outputs_, num_outputs_);
  }

 private:
  struct Slice {
    int offset;
    int size;
  };

  static VectorXd gather(const Vector& from, const std::vector<Slice>& slices, int size) {
    VectorXd out(size);
    int at = 0;
    for (const auto& [offset, length] : slices) {
      out.segment(at, length) = from.segment(offset, length);
      at += length;
    }
    return out;
  }
  static void scatter(const VectorXd& from, const std::vector<Slice>& slices, Vector& to) {
    int at = 0;
    for (const auto& [offset, length] : slices) {
      to.segment(offset, length) = from.segment(at, length);
      at += length;
    }
  }

  void set(const VectorXd& x, const VectorXd& u) {
    Context& context = *work_;
    context.assign_from(*base_);
    if (discrete_) {
      scatter(x, states_, context.discrete_states());
    } else {
      context.continuous_states().head(num_states_) = x;
    }
    scatter(u, inputs_, context.signals());
  }

  const Diagram& diagram_;
  std::unique_ptr<Context> base_;
  std::unique_ptr<Context> work_;
  std::vector<Slice> inputs_;   // root inputs in the signals
  std::vector<Slice> outputs_;  // root outputs in the signals
  std::vector<Slice> states_;   // discrete: the state's parts in the discrete states
  std::vector<std::pair<int, const UpdateCalculation*>> updates_;
  bool discrete_ = false;
  int num_states_ = 0;
  int num_inputs_ = 0;
  int num_outputs_ = 0;
};

// Sets up `model`'s state (continuous or discrete) and returns the time period (0 for
// continuous time); throws for what linearize does not support.
double choose_state(const Diagram& diagram, Model& model) {
  if (!diagram.self_integrating_leaves().empty()) {
    throw std::invalid_argument(
        "linearize: diagram '" + diagram.path() + "' has self-integrating blocks (" +
        leaf_paths(diagram, diagram.self_integrating_leaves()) +
        "), whose continuous state the simulator does not integrate; linearize supports only "
        "continuous state declared with declare_continuous_state");
  }
  // Leaves whose discrete state periodic updates change.
  std::vector<int> updated;
  for (const auto& leaf : diagram.leaves()) {
    if (leaf.block->initial_discrete_state().size() > 0 &&
        !leaf.block->periodic_updates().empty()) {
      updated.push_back(leaf.index);
    }
  }
  if (updated.empty()) {
    model.use_continuous_state();
    return 0.0;
  }
  if (diagram.ode_size() > 0) {
    throw std::invalid_argument(
        "linearize: diagram '" + diagram.path() + "' has both continuous state (" +
        leaf_paths(diagram, diagram.ode_leaves()) + ") and periodically updated discrete state (" +
        leaf_paths(diagram, updated) +
        "); linearize supports one kind only (a purely continuous or purely discrete diagram)");
  }
  const PeriodicUpdate& first =
      diagram.leaves()[static_cast<size_t>(updated.front())].block->periodic_updates().front();
  std::vector<std::pair<int, const UpdateCalculation*>> updates;
  for (const int index : updated) {
    const Block& block = *diagram.leaves()[static_cast<size_t>(index)].block;
    for (const PeriodicUpdate& update : block.periodic_updates()) {
      if (update.period != first.period || update.offset != first.offset) {
        throw std::invalid_argument("linearize: diagram '" + diagram.path() +
                                    "' updates its discrete state at more than one rate (period " +
                                    format_number(first.period) + " s, offset " +
                                    format_number(first.offset) + " s, and block '" + block.path() +
                                    "' with period " + format_number(update.period) +
                                    " s, offset " + format_number(update.offset) +
                                    " s); linearize supports one periodic update rate only");
      }
      updates.emplace_back(index, &update.update);
    }
  }
  model.use_discrete_state(updated, std::move(updates));
  return first.period;
}

}  // namespace

StateSpace linearize(const Diagram& diagram, const Context& context,
                     const LinearizeOptions& options) {
  if (&context.diagram() != &diagram) {
    throw std::invalid_argument("linearize: the context does not belong to diagram '" +
                                diagram.path() + "'");
  }
  if (!std::isfinite(options.relative_step) || options.relative_step <= 0.0) {
    throw std::invalid_argument("linearize: relative_step must be positive and finite; got " +
                                format_number(options.relative_step));
  }
  for (int port = 0; port < diagram.num_input_ports(); ++port) {
    const auto value =
        context.signals().segment(diagram.root_input_offset(port), diagram.input_port(port).size());
    if (value.hasNaN()) {
      throw std::invalid_argument("linearize: input '" + diagram.input_port(port).path() +
                                  "' of the root diagram has no value; fix the operating input "
                                  "with Context::fix_input");
    }
  }
  Model model(diagram, context);
  StateSpace linear;
  linear.time_period = choose_state(diagram, model);

  const VectorXd x0 = model.state();
  const VectorXd u0 = model.input();
  const int n = model.num_states();
  const int m = model.num_inputs();
  const int p = model.num_outputs();
  if (options.equilibrium_tolerance) {
    VectorXd drift = model.dynamics(x0, u0);
    if (linear.is_discrete()) drift -= x0;
    const double largest = n == 0 ? 0.0 : drift.cwiseAbs().maxCoeff();
    if (!(largest <= *options.equilibrium_tolerance)) {
      throw std::invalid_argument(
          std::string("linearize: the operating point is not an equilibrium: the largest ") +
          (linear.is_discrete() ? "change of the state over a period" : "state derivative") +
          " is " + format_number(largest) + ", above the tolerance " +
          format_number(*options.equilibrium_tolerance));
    }
  }

  linear.A.resize(n, n);
  linear.B.resize(n, m);
  linear.C.resize(p, n);
  linear.D.resize(p, m);
  // Column j of the Jacobians of (f, g) in z (x or u): central differences with a step that
  // is exactly representable as the difference of the perturbed and unperturbed values.
  const auto differentiate = [&](bool in_state, int j, auto&& f) {
    VectorXd x = x0;
    VectorXd u = u0;
    double& z = in_state ? x[j] : u[j];
    const double z0 = z;
    const double step = options.relative_step * std::max(1.0, std::abs(z0));
    const double above = z0 + step;
    const double below = z0 - step;
    z = above;
    const VectorXd plus = f(x, u);
    z = below;
    const VectorXd minus = f(x, u);
    return VectorXd((plus - minus) / (above - below));
  };
  const auto dynamics = [&model](const VectorXd& x, const VectorXd& u) {
    return model.dynamics(x, u);
  };
  const auto outputs = [&model](const VectorXd& x, const VectorXd& u) {
    return model.outputs(x, u);
  };
  for (int j = 0; j < n; ++j) {
    linear.A.col(j) = differentiate(true, j, dynamics);
    linear.C.col(j) = differentiate(true, j, outputs);
  }
  for (int j = 0; j < m; ++j) {
    linear.B.col(j) = differentiate(false, j, dynamics);
    linear.D.col(j) = differentiate(false, j, outputs);
  }
  return linear;
}

}  // namespace cbbg::control
