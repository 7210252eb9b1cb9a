// Compose from the toolbox alone: a discrete PID controller (10 ms, output limits) holds a
// first-order plant, K / (tau s + 1), at a stepped set-point. No block is written here.
//
//   pid_first_order OUTPUT_DIR   writes pid.csv and pid_first_order.dot (and .svg with dot)

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

// [docs pid-first-order-includes]
#include <cbbg/framework/diagram_builder.h>
#include <cbbg/framework/graphviz.h>
#include <cbbg/framework/primitives/adder.h>
#include <cbbg/framework/primitives/csv_sink.h>
#include <cbbg/framework/primitives/first_order_low_pass.h>
#include <cbbg/framework/primitives/gain.h>
#include <cbbg/framework/primitives/pid_controller.h>
#include <cbbg/framework/primitives/step_source.h>
#include <cbbg/framework/simulator.h>
// [docs pid-first-order-includes end]

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::cerr << "usage: pid_first_order OUTPUT_DIR\n";
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);

  // [docs pid-first-order]
  // The plant: gain K = 2, time constant tau = 0.5 s; its steady state is y = K u.
  const double plant_gain = 2.0, tau = 0.5, target = 1.0, period = 0.01;
  // ki / kp = 1 / tau cancels the plant's lag: the loop is close to first order, time
  // constant tau / (kp K) = 0.125 s, so it settles well within 5 s without overshoot. The
  // limits [0, 1] leave room for the steady command target / K = 0.5 and clip the first
  // samples after the step; conditional integration keeps the integral from winding up.
  const cbbg::PidController::Params pid_params{
      .kp = 2.0, .ki = 2.0 / tau, .kd = 0.01, .u_min = 0.0, .u_max = 1.0};

  cbbg::DiagramBuilder builder("pid_first_order");
  auto& setpoint = builder.emplace<cbbg::StepSource>("setpoint", 0.0, target, 0.5);
  auto& error = builder.emplace<cbbg::Adder>(
      "error", std::vector<cbbg::Adder::Input>{{"reference", +1}, {"measured", -1}}, 1);
  auto& pid = builder.emplace<cbbg::PidController>("pid", pid_params, period);
  auto& actuator = builder.emplace<cbbg::Gain>("actuator", plant_gain, 1);
  auto& plant = builder.emplace<cbbg::FirstOrderLowPass>("plant", tau, 1);
  // The sink is a block of the diagram; it refuses a path holding a file it did not write.
  // A row at t_k holds what the updates at t_k read (simulator.h): u is the command held up
  // to t_k.
  auto& csv = builder.emplace<cbbg::CsvSink>(
      "csv", out / "pid.csv", std::vector<cbbg::CsvSink::Input>{{"r"}, {"y"}, {"u"}}, period);
  builder.connect(setpoint.output_port("y"), error.input_port("reference"));
  builder.connect(plant.output_port("y"), error.input_port("measured"));
  builder.connect(error.output_port("y"), pid.input_port("e"));
  builder.connect(pid.output_port("u"), actuator.input_port("u"));
  builder.connect(actuator.output_port("y"), plant.input_port("u"));
  builder.connect(setpoint.output_port("y"), csv.input_port("r"));
  builder.connect(plant.output_port("y"), csv.input_port("y"));
  builder.connect(pid.output_port("u"), csv.input_port("u"));
  // [docs pid-first-order end]
  const auto diagram = builder.build();

  const std::string dot = cbbg::to_dot(*diagram);
  cbbg::render_dot(dot, out / "pid_first_order.dot");
  try {
    cbbg::render_dot(dot, out / "pid_first_order.svg");
  } catch (const std::runtime_error& no_svg) {  // no Graphviz here: the .dot is enough
    std::cerr << no_svg.what() << "\n";
  }

  cbbg::Simulator simulator(*diagram, cbbg::SimulatorOptions{.accuracy = 1e-8});
  // An in-memory log of y as well, for the peak (the sink's rows go to the file).
  auto& y_log = simulator.add_log(plant.output_port("y"), period);
  simulator.advance_to(5.0);

  auto& context = simulator.context();
  const double y = diagram->eval_output(context, plant.output_port("y"))[0];
  const double u = diagram->eval_output(context, pid.output_port("u"))[0];
  const double peak = y_log.values().maxCoeff();
  // At rest the integral holds u = target / K, the plant's steady state for y = target.
  std::printf(
      "y(5 s) = %.6f (set-point %g), settling error %.2e, peak %.6f, u = %.6f (target / K = %g)\n",
      y, target, target - y, peak, u, target / plant_gain);
  return std::abs(target - y) < 1e-3 && peak <= target + 1e-6 ? 0 : 1;
} catch (const std::exception& error) {
  std::cerr << "pid_first_order: " << error.what() << "\n";
  return 2;
}
