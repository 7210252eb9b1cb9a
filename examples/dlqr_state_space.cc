// Compose from the toolbox alone: a DC motor with position, x = (theta, omega), as a
// continuous LinearSystem, brought back to rest from theta = 1 rad by a discrete LQR designed
// on its linearisation, discretised at 10 ms; u = -K x, sampled through a zero-order hold.
//
//   dlqr_state_space OUTPUT_DIR   writes dlqr.csv and dlqr_state_space.dot (and .svg with dot)

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

// [docs dlqr-state-space-includes]
#include <cbbg/framework/control/discretize.h>
#include <cbbg/framework/control/linearize.h>
#include <cbbg/framework/control/lqr.h>
#include <cbbg/framework/diagram_builder.h>
#include <cbbg/framework/graphviz.h>
#include <cbbg/framework/primitives/csv_sink.h>
#include <cbbg/framework/primitives/gain.h>
#include <cbbg/framework/primitives/linear_system.h>
#include <cbbg/framework/primitives/zero_order_hold.h>
#include <cbbg/framework/simulator.h>
// [docs dlqr-state-space-includes end]

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::cerr << "usage: dlqr_state_space OUTPUT_DIR\n";
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);

  // theta' = omega, omega' = (-omega + k u) / tau: k = 5 rad/s per V, tau = 0.2 s. C = I, so
  // the output is the state, which the controller measures.
  const double k = 5.0, tau = 0.2, h = 0.01;
  Eigen::MatrixXd A(2, 2), B(2, 1);
  A << 0.0, 1.0, 0.0, -1.0 / tau;
  B << 0.0, k / tau;
  const Eigen::MatrixXd C = Eigen::MatrixXd::Identity(2, 2), D = Eigen::MatrixXd::Zero(2, 1);
  const cbbg::Vector x0 = (cbbg::Vector(2) << 1.0, 0.0).finished();

  // [docs dlqr-state-space]
  // The plant as a diagram of its own, its ports exported: what linearize reads.
  cbbg::DiagramBuilder plant_builder("motor");
  auto& motor = plant_builder.emplace<cbbg::LinearSystem>("dynamics", A, B, C, D, x0);
  plant_builder.export_input(motor.input_port("u"), "u");
  plant_builder.export_output(motor.output_port("y"), "x");
  auto plant = plant_builder.build();
  auto operating_point = plant->create_context();
  operating_point->fix_input(plant->input_port(0), cbbg::Vector::Zero(1));
  const cbbg::control::StateSpace linear = cbbg::control::linearize(*plant, *operating_point);
  const double linearize_error =
      std::max((linear.A - A).cwiseAbs().maxCoeff(), (linear.B - B).cwiseAbs().maxCoeff());

  // The design, on the linearisation: exact under a zero-order hold (c2d), then the discrete
  // LQR on (Ad, Bd), so the gain is optimal for the loop as sampled, not only as h -> 0.
  const cbbg::control::StateSpace discrete = cbbg::control::c2d(linear, h);
  const Eigen::MatrixXd Q = Eigen::Vector2d(10.0, 0.1).asDiagonal();
  const Eigen::MatrixXd R = Eigen::MatrixXd::Identity(1, 1);
  const Eigen::MatrixXd K = cbbg::control::discrete_lqr(discrete.A, discrete.B, Q, R).K;
  const Eigen::MatrixXd closed_loop = discrete.A - discrete.B * K;

  // The loop: the plant diagram nests as a block; the hold samples x every h, the gain -K
  // makes u from the sample, held until the next one.
  cbbg::DiagramBuilder builder("dlqr_state_space");
  auto& motor_block = builder.add(std::move(plant));
  auto& hold = builder.emplace<cbbg::ZeroOrderHold>("hold", 2, h);
  auto& feedback = builder.emplace<cbbg::Gain>("minus_K", -K);
  // A row at t_k holds what the updates at t_k read (simulator.h): x(t_k), and the u held up
  // to t_k (0 at t = 0, before the hold's first sample).
  auto& csv = builder.emplace<cbbg::CsvSink>(
      "csv", out / "dlqr.csv",
      std::vector<cbbg::CsvSink::Input>{{"x", 2, {"theta", "omega"}}, {"u"}}, h);
  builder.connect(motor_block.output_port("x"), hold.input_port("u"));
  builder.connect(hold.output_port("y"), feedback.input_port("u"));
  builder.connect(feedback.output_port("y"), motor_block.input_port("u"));
  builder.connect(motor_block.output_port("x"), csv.input_port("x"));
  builder.connect(feedback.output_port("y"), csv.input_port("u"));
  // [docs dlqr-state-space end]
  const auto diagram = builder.build();

  const std::string dot = cbbg::to_dot(*diagram);
  cbbg::render_dot(dot, out / "dlqr_state_space.dot");
  try {
    cbbg::render_dot(dot, out / "dlqr_state_space.svg");
  } catch (const std::runtime_error& no_svg) {  // no Graphviz here: the .dot is enough
    std::cerr << no_svg.what() << "\n";
  }

  std::printf("linearize: A, B back to %.1e; K = [%.4f %.4f]\n", linearize_error, K(0, 0), K(0, 1));
  const Eigen::VectorXcd poles = closed_loop.eigenvalues();
  for (const std::complex<double>& z : poles) {
    std::printf("eig(Ad - Bd K): %.6f %+.6fi, |z| = %.6f\n", z.real(), z.imag(), std::abs(z));
  }

  // The simulated state at t_k against the discrete model's (Ad - Bd K)^k x0: the same
  // numbers, up to the integrator's accuracy, since c2d is exact under the hold.
  cbbg::Simulator simulator(*diagram, cbbg::SimulatorOptions{.accuracy = 1e-10});
  cbbg::Vector predicted = x0;
  long step = 0;
  double worst = 0.0, norm = 0.0;
  for (const double t : {0.0, 0.25, 0.5, 1.0, 2.0, 3.0}) {
    simulator.advance_to(t);
    for (; step < std::lround(t / h); ++step) predicted = closed_loop * predicted;
    const cbbg::Vector x = simulator.context().continuous_state(motor);
    worst = std::max(worst, (x - predicted).cwiseAbs().maxCoeff());
    norm = x.norm();
    std::printf("t = %.2f s: theta = %+.6f rad, omega = %+.6f rad/s, |x| = %.2e\n", t, x[0], x[1],
                norm);
  }
  std::printf("|x(3 s)| / |x(0)| = %.2e; simulated vs (Ad - Bd K)^k x0: %.1e\n", norm / x0.norm(),
              worst);
  const bool stable = poles.cwiseAbs().maxCoeff() < 1.0;
  return linearize_error < 1e-6 && stable && worst < 1e-6 && norm < 1e-3 * x0.norm() ? 0 : 1;
} catch (const std::exception& error) {
  std::cerr << "dlqr_state_space: " << error.what() << "\n";
  return 2;
}
