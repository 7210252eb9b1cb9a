#pragma once
// Numeric linearisation of a Diagram about an operating point, as Drake's Linearize.

#include <optional>

#include "cbbg/framework/context.h"
#include "cbbg/framework/control/state_space.h"
#include "cbbg/framework/diagram.h"

namespace cbbg::control {

struct LinearizeOptions {
  // The central differences step in each coordinate z of x and u is
  // relative_step * max(1, |z|): about the cube root of the machine epsilon, which balances
  // the O(step^2) truncation error against the O(eps / step) rounding error, leaving about
  // 1e-10 relative error in the Jacobians of a smooth model.
  double relative_step = 1e-5;
  // When set, the operating point must be an equilibrium: every component of x' (continuous)
  // or of x[k+1] - x[k] (discrete) within this tolerance there, else std::invalid_argument.
  std::optional<double> equilibrium_tolerance;
};

// The linear model of `diagram` (a root diagram) about the operating point `context` (a
// context of it): the Jacobians of its dynamics and outputs there, by central differences.
//   u: the root diagram's exported input ports, concatenated in port order; the operating
//      input u0 is their values fixed in `context` (Context::fix_input), all of which must be
//      set.
//   y: the root diagram's exported output ports, concatenated in port order.
//   x: the continuous state the simulator integrates (Diagram::ode_size(), the leaves of
//      Diagram::ode_leaves() in order, as in Context::continuous_states()), and the result is
//      continuous time, x' = A x + B u, y = C x + D u (time_period 0), with x0 the context's.
//      A diagram whose only state is discrete, updated by periodic updates that all share
//      one period and offset, gives instead the discrete-time model x[k+1] = A x[k] + B u[k],
//      y[k] = C x[k] + D u[k] with time_period that period; there x is the discrete state of
//      the leaves with such updates, concatenated in leaf order, and x[k+1] what one event
//      instant's updates make of it (outputs evaluated first, as the Simulator does).
// Discrete state that no periodic update changes, parameters and time are held at their
// values in `context`. A diagram with both continuous and periodically updated discrete
// state, with periodic updates at more than one rate, or with a self-integrating block
// (declare_self_integrated_state) is not supported and throws std::invalid_argument naming
// the blocks. The model is the Jacobian, not an affine approximation: where the point is not
// an equilibrium the constant terms are dropped (see LinearizeOptions::equilibrium_tolerance).
//
// A single block is linearised by putting it in a one-block diagram that exports its ports:
//   DiagramBuilder builder("linearized");
//   const auto& block = builder.emplace<MyBlock>("block", ...);
//   builder.export_input(block.input_port("u"));
//   builder.export_output(block.output_port("y"));
//   const auto diagram = builder.build();
//   auto context = diagram->create_context();
//   context->fix_input(diagram->input_port(0), u0);  // and set the state x0
//   const StateSpace model = linearize(*diagram, *context);
//
// `context` is left as it was: the work is done on a clone.
StateSpace linearize(const Diagram& diagram, const Context& context,
                     const LinearizeOptions& options = {});

}  // namespace cbbg::control
