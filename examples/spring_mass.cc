// Compose, simulate and draw a diagram: a mass on a spring (continuous) held at a target by
// a PD controller sampled every 10 ms through a zero-order hold.
//
//   spring_mass [OUTPUT_DIR]   writes position.csv and spring_mass.dot (and .svg with dot)

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

// [docs spring-mass-includes]
#include <cbbg/framework/block_context.h>
#include <cbbg/framework/diagram_builder.h>
#include <cbbg/framework/graphviz.h>
#include <cbbg/framework/primitives/zero_order_hold.h>
#include <cbbg/framework/simulator.h>
// [docs spring-mass-includes end]

namespace {

using cbbg::Block;
using cbbg::BlockContext;
using cbbg::InputPort;
using cbbg::Vector;
using cbbg::VectorRef;

// [docs spring-mass-block]
// x'' = (-k x - c x' + force) / m. Input "force" (1); output "state" = (x, x').
//
// The constructor declares; each calculation is a const member function of the block, named
// in its declaration (declare_continuous_state<&MassSpring::calc_derivatives>). A lambda is
// accepted too, where a block is as small as this one:
//   declare_output_port("state", 2, [](const BlockContext& context, VectorRef y) { ... }, {});
class MassSpring final : public Block {
 public:
  MassSpring(std::string name, double mass, double stiffness, double damping)
      : Block(std::move(name)), mass_(mass), stiffness_(stiffness), damping_(damping) {
    force_ = &declare_input_port("force", 1, "applied force, N");
    declare_continuous_state<&MassSpring::calc_derivatives>(Vector::Zero(2));
    declare_output_port<&MassSpring::calc_state>("state", 2, {}, "position (m) and velocity (m/s)");
  }

 private:
  // (x', x''): the equation above.
  void calc_derivatives(const BlockContext& context, VectorRef derivatives) const {
    const auto x = context.continuous_state();
    derivatives[0] = x[1];
    derivatives[1] = (-stiffness_ * x[0] - damping_ * x[1] + context.input(*force_)[0]) / mass_;
  }
  // "state": the continuous state; it reads no input directly (no feedthrough).
  void calc_state(const BlockContext& context, VectorRef y) const {
    y = context.continuous_state();
  }

  double mass_;
  double stiffness_;
  double damping_;
  const InputPort* force_;
};
// [docs spring-mass-block end]

// force = kp (target - x) - kd x', read directly from the state (direct feedthrough).
class PdController final : public Block {
 public:
  PdController(std::string name, double target, double kp, double kd)
      : Block(std::move(name)), target_(target), kp_(kp), kd_(kd) {
    state_ = &declare_input_port("state", 2);
    declare_output_port<&PdController::calc_force>("force", 1, {state_});
  }

 private:
  // "force": the PD law on the state.
  void calc_force(const BlockContext& context, VectorRef force) const {
    const auto x = context.input(*state_);
    force[0] = kp_ * (target_ - x[0]) - kd_ * x[1];
  }

  double target_;
  double kp_;
  double kd_;
  const InputPort* state_;
};

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path out = argc > 1 ? argv[1] : ".";
  std::filesystem::create_directories(out);

  // [docs spring-mass-diagram]
  cbbg::DiagramBuilder builder("spring_mass");
  auto& plant = builder.emplace<MassSpring>("plant", 1.0, 4.0, 0.4);
  auto& controller = builder.emplace<PdController>("controller", 0.5, 40.0, 8.0);
  auto& hold = builder.emplace<cbbg::ZeroOrderHold>("hold", 1, 0.01);
  builder.connect(plant.output_port("state"), controller.input_port("state"));
  builder.connect(controller.output_port("force"), hold.input_port("u"));
  builder.connect(hold.output_port("y"), plant.input_port("force"));
  const auto diagram = builder.build();

  cbbg::Simulator simulator(*diagram, cbbg::SimulatorOptions{.accuracy = 1e-8});
  auto& log = simulator.add_log(plant.output_port("state"), 0.05);
  log.set_column_names({"x", "v"});
  simulator.advance_to(5.0);

  std::ofstream csv(out / "position.csv");
  log.write_csv(csv);
  const std::string dot = cbbg::to_dot(*diagram);
  cbbg::render_dot(dot, out / "spring_mass.dot");
  try {
    cbbg::render_dot(dot, out / "spring_mass.svg");
  } catch (const std::runtime_error& error) {
    std::cerr << error.what() << "\n";
  }
  // [docs spring-mass-diagram end]
  const double x = simulator.context().continuous_state(plant)[0];
  // The PD law against the spring settles at kp target / (kp + k) = 20 / 44.
  std::printf("x(5 s) = %.6f m (static equilibrium %.6f m), %d samples in %s\n", x,
              40.0 * 0.5 / 44.0, log.num_samples(), (out / "position.csv").c_str());
  return std::abs(x - 40.0 * 0.5 / 44.0) < 1e-3 ? 0 : 1;
}
