// The toolbox in Python: every block of framework/primitives (cbbg.Gain, cbbg.PidController,
// ...) and the control helpers of framework/control (the submodule cbbg.control).

#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "cbbg/framework/control/discretize.h"
#include "cbbg/framework/control/linearize.h"
#include "cbbg/framework/control/lqr.h"
#include "cbbg/framework/control/riccati.h"
#include "cbbg/framework/control/state_space.h"
#include "cbbg/framework/primitives/adder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/csv_sink.h"
#include "cbbg/framework/primitives/deadband.h"
#include "cbbg/framework/primitives/demultiplexer.h"
#include "cbbg/framework/primitives/discrete_derivative.h"
#include "cbbg/framework/primitives/discrete_linear_system.h"
#include "cbbg/framework/primitives/first_order_low_pass.h"
#include "cbbg/framework/primitives/gain.h"
#include "cbbg/framework/primitives/integrator.h"
#include "cbbg/framework/primitives/linear_system.h"
#include "cbbg/framework/primitives/multiplexer.h"
#include "cbbg/framework/primitives/pid_controller.h"
#include "cbbg/framework/primitives/ramp_source.h"
#include "cbbg/framework/primitives/rate_limiter.h"
#include "cbbg/framework/primitives/saturation.h"
#include "cbbg/framework/primitives/selector.h"
#include "cbbg/framework/primitives/sine_source.h"
#include "cbbg/framework/primitives/step_source.h"
#include "cbbg/framework/primitives/unit_delay.h"
#include "cbbg/framework/primitives/white_noise.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg_docstrings.h"
#include "params_binding.h"

namespace cbbg::python {

// PidController::Params has no describe() (it is no config section): its fields, declared
// here as the header comments them, so that it binds like every other params struct.
template <>
struct ParamsDeclarations<PidController::Params> {
  template <class Archive>
  static void describe(Archive& a, PidController::Params& params) {
    a.number("kp", params.kp, "proportional gain", kNonNegative);
    a.number("ki", params.ki, "integral gain, per second", kNonNegative);
    a.number("kd", params.kd, "derivative gain, in seconds", kNonNegative);
    a.number("u_min", params.u_min, "lower limit of the command", "-inf for none; <= u_max");
    a.number("u_max", params.u_max, "upper limit of the command", "inf for none; >= u_min");
  }
};

namespace {

// Adder.Input (name, sign), Multiplexer.Input and Demultiplexer.Output (name, size): a name
// and a number, made as objects or, wherever a list of them is taken, as (name, number)
// tuples.
template <class Part, int Part::*number>
void bind_named_part(py::handle scope, const char* class_name, const char* number_name,
                     const char* doc) {
  // "Adder.Input": what messages and reprs call it.
  const std::string label = std::string(py::str(scope.attr("__name__"))) + "." + class_name;
  py::class_<Part>(scope, class_name, doc)
      .def(py::init([](std::string name, int value) {
             return Part{std::move(name), value};
           }),
           py::arg("name"), py::arg(number_name))
      .def(py::init([label, number_name](const py::tuple& pair) {
             if (pair.size() != 2) {
               throw py::value_error(label + ": a tuple (name, " + number_name +
                                     ") has two items, got " + std::to_string(pair.size()));
             }
             return Part{pair[0].cast<std::string>(), pair[1].cast<int>()};
           }),
           py::arg("pair"), "From a tuple (name, number).")
      .def_readwrite("name", &Part::name)
      .def_readwrite(number_name, number)
      .def("__repr__", [label, number_name](const Part& part) {
        return label + "(name='" + part.name + "', " + number_name + "=" +
               std::to_string(part.*number) + ")";
      });
  py::implicitly_convertible<py::tuple, Part>();
}

// CsvSink.Input: a name, or (name, size) or (name, size, columns), or the object itself.
void bind_csv_input(py::handle scope) {
  using Input = CsvSink::Input;
  py::class_<Input>(scope, "Input", "One input of a CsvSink: its name, size and column names.")
      .def(py::init([](std::string name, int size, std::vector<std::string> columns) {
             return Input{std::move(name), size, std::move(columns)};
           }),
           py::arg("name"), py::arg("size") = 1, py::arg("columns") = std::vector<std::string>{})
      .def(py::init([](const py::tuple& items) {
             if (items.empty() || items.size() > 3) {
               throw py::value_error(
                   "CsvSink.Input: a tuple (name[, size[, columns]]) has one "
                   "to three items, got " +
                   std::to_string(items.size()));
             }
             Input input{items[0].cast<std::string>()};
             if (items.size() > 1) input.size = items[1].cast<int>();
             if (items.size() > 2) input.columns = items[2].cast<std::vector<std::string>>();
             return input;
           }),
           py::arg("items"), "From a tuple (name[, size[, columns]]).")
      .def_readwrite("name", &Input::name)
      .def_readwrite("size", &Input::size)
      .def_readwrite("columns", &Input::columns, "One name per element; empty: the input's.")
      .def("__repr__", [](const Input& input) {
        return "CsvSink.Input(name='" + input.name + "', size=" + std::to_string(input.size) + ")";
      });
  py::implicitly_convertible<py::str, Input>();
  py::implicitly_convertible<py::tuple, Input>();
}

// Overloads that take a vector come before those that take a number: pybind11 tries them in
// order, without conversions first, so a float never reaches a vector's overload nor a
// one-element array a float's.

void bind_sources(py::module_& m) {
  py::class_<ConstantSource, Block>(m, "ConstantSource", kConstantSourceDoc)
      .def(py::init<std::string, Vector>(), py::arg("name"), py::arg("value"));
  py::class_<StepSource, Block>(m, "StepSource", kStepSourceDoc)
      .def(py::init<std::string, const Vector&, const Vector&, double>(), py::arg("name"),
           py::arg("initial_value"), py::arg("final_value"), py::arg("step_time"))
      .def(py::init<std::string, double, double, double>(), py::arg("name"),
           py::arg("initial_value"), py::arg("final_value"), py::arg("step_time"));
  py::class_<RampSource, Block>(m, "RampSource", kRampSourceDoc)
      .def(py::init<std::string, const Vector&, double, const Vector&>(), py::arg("name"),
           py::arg("slope"), py::arg("start_time"), py::arg("initial_value"))
      .def(py::init<std::string, double, double, double>(), py::arg("name"), py::arg("slope"),
           py::arg("start_time"), py::arg("initial_value") = 0.0);
  py::class_<SineSource, Block>(m, "SineSource", kSineSourceDoc)
      .def(py::init<std::string, const Vector&, const Vector&, const Vector&, const Vector&>(),
           py::arg("name"), py::arg("amplitude"), py::arg("angular_frequency"), py::arg("phase"),
           py::arg("bias"))
      .def(py::init<std::string, double, double, double, double>(), py::arg("name"),
           py::arg("amplitude"), py::arg("angular_frequency"), py::arg("phase") = 0.0,
           py::arg("bias") = 0.0);
  py::class_<WhiteNoise, Block>(m, "WhiteNoise", kWhiteNoiseDoc)
      .def(py::init<std::string, const Vector&, const Vector&, double, double>(), py::arg("name"),
           py::arg("mean"), py::arg("standard_deviation"), py::arg("period"),
           py::arg("offset") = 0.0)
      .def(py::init<std::string, double, double, int, double, double>(), py::arg("name"),
           py::arg("mean"), py::arg("standard_deviation"), py::arg("size"), py::arg("period"),
           py::arg("offset") = 0.0);
}

void bind_routing(py::module_& m) {
  py::class_<Adder, Block> adder(m, "Adder", kAdderDoc);
  bind_named_part<Adder::Input, &Adder::Input::sign>(
      adder, "Input", "sign", "One input of an Adder: its name and sign, +1 or -1.");
  adder.def(py::init<std::string, const std::vector<Adder::Input>&, int>(), py::arg("name"),
            py::arg("inputs"), py::arg("size"),
            "inputs: Adder.Input objects or (name, sign) tuples, e.g. [(\"r\", 1), (\"y\", -1)].");

  py::class_<Multiplexer, Block> mux(m, "Multiplexer", kMultiplexerDoc);
  bind_named_part<Multiplexer::Input, &Multiplexer::Input::size>(
      mux, "Input", "size", "One input of a Multiplexer: its name and size.");
  mux.def(py::init<std::string, const std::vector<Multiplexer::Input>&>(), py::arg("name"),
          py::arg("inputs"), "inputs: Multiplexer.Input objects or (name, size) tuples.");

  py::class_<Demultiplexer, Block> demux(m, "Demultiplexer", kDemultiplexerDoc);
  bind_named_part<Demultiplexer::Output, &Demultiplexer::Output::size>(
      demux, "Output", "size", "One output of a Demultiplexer: its name and size.");
  demux.def(py::init<std::string, const std::vector<Demultiplexer::Output>&>(), py::arg("name"),
            py::arg("outputs"), "outputs: Demultiplexer.Output objects or (name, size) tuples.");

  py::class_<Selector, Block>(m, "Selector", kSelectorDoc)
      .def(py::init<std::string, int, std::vector<int>>(), py::arg("name"), py::arg("input_size"),
           py::arg("indices"));
  py::class_<Gain, Block>(m, "Gain", kGainDoc)
      .def(py::init<std::string, Eigen::MatrixXd>(), py::arg("name"), py::arg("matrix"))
      .def(py::init<std::string, double, int>(), py::arg("name"), py::arg("gain"), py::arg("size"));
}

void bind_nonlinear(py::module_& m) {
  py::class_<Saturation, Block>(m, "Saturation", kSaturationDoc)
      .def(py::init<std::string, Vector, Vector>(), py::arg("name"), py::arg("lower"),
           py::arg("upper"))
      .def(py::init<std::string, double, double, int>(), py::arg("name"), py::arg("lower"),
           py::arg("upper"), py::arg("size"));
  py::class_<Deadband, Block>(m, "Deadband", kDeadbandDoc)
      .def(py::init<std::string, Vector, Vector>(), py::arg("name"), py::arg("lower"),
           py::arg("upper"))
      .def(py::init<std::string, double, double, int>(), py::arg("name"), py::arg("lower"),
           py::arg("upper"), py::arg("size"));
  py::class_<RateLimiter, Block>(m, "RateLimiter", kRateLimiterDoc)
      .def(py::init<std::string, const Vector&, double, double, double, double>(), py::arg("name"),
           py::arg("initial_value"), py::arg("rising_rate"), py::arg("falling_rate"),
           py::arg("period"), py::arg("offset") = 0.0)
      .def(py::init<std::string, int, double, double, double, double>(), py::arg("name"),
           py::arg("size"), py::arg("rising_rate"), py::arg("falling_rate"), py::arg("period"),
           py::arg("offset") = 0.0);
}

void bind_continuous(py::module_& m) {
  py::class_<Integrator, Block>(m, "Integrator", kIntegratorDoc)
      .def(py::init<std::string, const Vector&>(), py::arg("name"), py::arg("initial_value"))
      .def(py::init<std::string, int>(), py::arg("name"), py::arg("size"));
  py::class_<FirstOrderLowPass, Block>(m, "FirstOrderLowPass", kFirstOrderLowPassDoc)
      .def(py::init<std::string, double, const Vector&>(), py::arg("name"),
           py::arg("time_constant"), py::arg("initial_value"))
      .def(py::init<std::string, double, int>(), py::arg("name"), py::arg("time_constant"),
           py::arg("size"))
      .def_property_readonly("time_constant", &FirstOrderLowPass::time_constant);
  using Matrix = const Eigen::MatrixXd&;
  py::class_<LinearSystem, Block>(m, "LinearSystem", kLinearSystemDoc)
      .def(py::init<std::string, Matrix, Matrix, Matrix, Matrix, const Vector&>(), py::arg("name"),
           py::arg("A"), py::arg("B"), py::arg("C"), py::arg("D"), py::arg("initial_state"))
      .def(py::init<std::string, Matrix, Matrix, Matrix, Matrix>(), py::arg("name"), py::arg("A"),
           py::arg("B"), py::arg("C"), py::arg("D"), "x0 = 0.")
      // Copies: an array viewing the block's matrices would let Python change a built block.
      .def_property_readonly("A", [](const LinearSystem& s) { return Eigen::MatrixXd(s.A()); })
      .def_property_readonly("B", [](const LinearSystem& s) { return Eigen::MatrixXd(s.B()); })
      .def_property_readonly("C", [](const LinearSystem& s) { return Eigen::MatrixXd(s.C()); })
      .def_property_readonly("D", [](const LinearSystem& s) { return Eigen::MatrixXd(s.D()); })
      .def_property_readonly("has_direct_feedthrough", &LinearSystem::has_direct_feedthrough);
}

void bind_discrete(py::module_& m) {
  using Matrix = const Eigen::MatrixXd&;
  using DLS = DiscreteLinearSystem;
  py::class_<DLS, Block>(m, "DiscreteLinearSystem", kDiscreteLinearSystemDoc)
      .def(py::init<std::string, Matrix, Matrix, Matrix, Matrix, const Vector&, double, double>(),
           py::arg("name"), py::arg("A"), py::arg("B"), py::arg("C"), py::arg("D"),
           py::arg("initial_state"), py::arg("period"), py::arg("offset") = 0.0)
      .def_property_readonly("A", [](const DLS& s) { return Eigen::MatrixXd(s.A()); })
      .def_property_readonly("B", [](const DLS& s) { return Eigen::MatrixXd(s.B()); })
      .def_property_readonly("C", [](const DLS& s) { return Eigen::MatrixXd(s.C()); })
      .def_property_readonly("D", [](const DLS& s) { return Eigen::MatrixXd(s.D()); })
      .def_property_readonly("has_direct_feedthrough", &DLS::has_direct_feedthrough);

  py::class_<DiscreteDerivative, Block> derivative(m, "DiscreteDerivative", kDiscreteDerivativeDoc);
  py::enum_<DiscreteDerivative::InitialTransient>(derivative, "InitialTransient")
      .value("SUPPRESS", DiscreteDerivative::InitialTransient::kSuppress)
      .value("KEEP", DiscreteDerivative::InitialTransient::kKeep);
  derivative.def(py::init<std::string, int, double, DiscreteDerivative::InitialTransient, double>(),
                 py::arg("name"), py::arg("size"), py::arg("period"),
                 py::arg("transient") = DiscreteDerivative::InitialTransient::kSuppress,
                 py::arg("offset") = 0.0);

  py::class_<UnitDelay, Block>(m, "UnitDelay", kUnitDelayDoc)
      .def(py::init<std::string, const Vector&, double, double>(), py::arg("name"),
           py::arg("initial_value"), py::arg("period"), py::arg("offset") = 0.0)
      .def(py::init<std::string, int, double, double>(), py::arg("name"), py::arg("size"),
           py::arg("period"), py::arg("offset") = 0.0);
  py::class_<ZeroOrderHold, Block>(m, "ZeroOrderHold", kZeroOrderHoldDoc)
      .def(py::init<std::string, const Vector&, double, double>(), py::arg("name"),
           py::arg("initial_value"), py::arg("period"), py::arg("offset") = 0.0)
      .def(py::init<std::string, int, double, double>(), py::arg("name"), py::arg("size"),
           py::arg("period"), py::arg("offset") = 0.0);

  py::class_<PidController, Block> pid(m, "PidController", kPidControllerDoc);
  bind_params<PidController::Params>(pid, "Params", "The gains and limits of a PidController.");
  pid.def(py::init<std::string, const PidController::Params&, double, int, double>(),
          py::arg("name"), py::arg("params"), py::arg("period"), py::arg("size") = 1,
          py::arg("offset") = 0.0)
      // A copy: the block's own params never change.
      .def_property_readonly("params", [](const PidController& block) { return block.params(); })
      .def_property_readonly("period", &PidController::period);
}

void bind_sinks(py::module_& m) {
  py::class_<CsvSink, Block> sink(m, "CsvSink", kCsvSinkDoc);
  bind_csv_input(sink);
  sink.def(py::init<std::string, std::filesystem::path, const std::vector<CsvSink::Input>&, double,
                    double>(),
           py::arg("name"), py::arg("path"), py::arg("inputs"), py::arg("period"),
           py::arg("offset") = 0.0,
           "inputs: CsvSink.Input objects, names, or (name[, size[, columns]]) tuples.")
      .def_property_readonly("file_path", &CsvSink::file_path)
      .def_property_readonly("column_names", &CsvSink::column_names, "The columns after \"t\".")
      .def_property_readonly("num_rows", &CsvSink::num_rows, "Rows written since the file opened.")
      .def("flush", &CsvSink::flush, "Hands the rows written so far to the file.");
}

void bind_state_space(py::module_& control_module) {
  using control::StateSpace;
  // The header's comment above the struct, after the summary its file comment opens with.
  const std::string doc =
      std::string("A linear time-invariant system in state-space form.\n\n") + kStateSpaceDoc;
  py::class_<StateSpace>(control_module, "StateSpace", doc.c_str())
      .def(py::init([](Eigen::MatrixXd A, Eigen::MatrixXd B, Eigen::MatrixXd C, Eigen::MatrixXd D,
                       double time_period) {
             return StateSpace{std::move(A), std::move(B), std::move(C), std::move(D), time_period};
           }),
           py::arg("A"), py::arg("B"), py::arg("C") = Eigen::MatrixXd(),
           py::arg("D") = Eigen::MatrixXd(), py::arg("time_period") = 0.0)
      .def_readwrite("A", &StateSpace::A)
      .def_readwrite("B", &StateSpace::B)
      .def_readwrite("C", &StateSpace::C)
      .def_readwrite("D", &StateSpace::D)
      .def_readwrite("time_period", &StateSpace::time_period, "0: continuous time.")
      .def_property_readonly("is_discrete", &StateSpace::is_discrete)
      .def_property_readonly("num_states", &StateSpace::num_states)
      .def_property_readonly("num_inputs", &StateSpace::num_inputs)
      .def_property_readonly("num_outputs", &StateSpace::num_outputs)
      .def("__repr__", [](const StateSpace& s) {
        return "<cbbg.control.StateSpace " +
               std::string(s.is_discrete() ? "discrete" : "continuous") + ": " +
               std::to_string(s.num_states()) + " states, " + std::to_string(s.num_inputs()) +
               " inputs, " + std::to_string(s.num_outputs()) + " outputs>";
      });
}

void bind_regulators(py::module_& control_module) {
  using Matrix = const Eigen::MatrixXd&;
  // Pure numerics: the GIL is released while they run.
  const auto no_gil = py::call_guard<py::gil_scoped_release>();
  control_module.def(
      "solve_continuous_riccati", &control::solve_continuous_riccati, py::arg("A"), py::arg("B"),
      py::arg("Q"), py::arg("R"), no_gil,
      "The stabilising solution X of A' X + X A - X B R^-1 B' X + Q = 0 (the CARE).");
  control_module.def(
      "solve_discrete_riccati", &control::solve_discrete_riccati, py::arg("A"), py::arg("B"),
      py::arg("Q"), py::arg("R"), no_gil,
      "The stabilising solution X of A' X A - X - A' X B (R + B' X B)^-1 B' X A + Q = 0 "
      "(the DARE).");
  control_module.def("continuous_riccati_residual", &control::continuous_riccati_residual,
                     py::arg("A"), py::arg("B"), py::arg("Q"), py::arg("R"), py::arg("X"), no_gil,
                     "A' X + X A - X B R^-1 B' X + Q, zero at a solution of the CARE.");
  control_module.def(
      "discrete_riccati_residual", &control::discrete_riccati_residual, py::arg("A"), py::arg("B"),
      py::arg("Q"), py::arg("R"), py::arg("X"), no_gil,
      "A' X A - X - A' X B (R + B' X B)^-1 B' X A + Q, zero at a solution of the DARE.");

  py::class_<control::LqrResult>(control_module, "LqrResult", kLqrResultDoc)
      .def_readonly("K", &control::LqrResult::K, "m x n")
      .def_readonly("S", &control::LqrResult::S, "n x n, symmetric");
  control_module.def(
      "lqr", &control::lqr, py::arg("A"), py::arg("B"), py::arg("Q"), py::arg("R"), no_gil,
      "For x' = A x + B u minimising the integral of x' Q x + u' R u: K = R^-1 B' S, S "
      "the stabilising solution of the CARE.");
  control_module.def(
      "discrete_lqr", &control::discrete_lqr, py::arg("A"), py::arg("B"), py::arg("Q"),
      py::arg("R"), no_gil,
      "For x[k+1] = A x[k] + B u[k] minimising the sum of x' Q x + u' R u: K = (R + B' S "
      "B)^-1 B' S A, S the stabilising solution of the DARE.");

  control_module.def("c2d", py::overload_cast<const control::StateSpace&, double>(&control::c2d),
                     py::arg("continuous"), py::arg("h"), no_gil,
                     "The exact zero-order-hold discretisation (MATLAB's c2d(sys, h, 'zoh')): Ad = "
                     "e^(A h), Bd = (integral from 0 to h of e^(A s) ds) B, Cd = C, Dd = D.");
  control_module.def("c2d", py::overload_cast<Matrix, Matrix, double>(&control::c2d), py::arg("A"),
                     py::arg("B"), py::arg("h"), no_gil, "The same for x' = A x + B u alone.");
}

void bind_linearize(py::module_& control_module) {
  py::class_<control::LinearizeOptions>(control_module, "LinearizeOptions")
      .def(py::init([](double relative_step, std::optional<double> equilibrium_tolerance) {
             return control::LinearizeOptions{relative_step, equilibrium_tolerance};
           }),
           py::arg("relative_step") = 1e-5, py::arg("equilibrium_tolerance") = py::none())
      .def_readwrite("relative_step", &control::LinearizeOptions::relative_step,
                     "The central differences' step in a coordinate z is relative_step * max(1, "
                     "|z|).")
      .def_readwrite("equilibrium_tolerance", &control::LinearizeOptions::equilibrium_tolerance,
                     "When set, the operating point must be an equilibrium within it.");
  // The GIL is released: a block written in Python takes it for its own calls.
  control_module.def(
      "linearize", &control::linearize, py::arg("diagram"), py::arg("context"),
      py::arg("options") = control::LinearizeOptions{}, py::call_guard<py::gil_scoped_release>(),
      "The linear model of a root diagram about the operating point `context`: u its "
      "exported inputs (fixed in the context), y its exported outputs, x its continuous "
      "state (or, for a diagram with only periodically updated discrete state at one "
      "rate, that state and a discrete-time model). See framework/control/linearize.h.");
}

void bind_control(py::module_& m) {
  py::module_ control_module =
      m.def_submodule("control",
                      "Control helpers: Riccati equations, LQR, zero-order-hold discretisation, "
                      "numeric linearisation. Matrices are NumPy 2-D arrays.");
  bind_state_space(control_module);
  bind_regulators(control_module);
  bind_linearize(control_module);
}

}  // namespace

void bind_primitives(py::module_& m) {
  bind_sources(m);
  bind_routing(m);
  bind_nonlinear(m);
  bind_continuous(m);
  bind_discrete(m);
  bind_sinks(m);
  bind_control(m);
}

}  // namespace cbbg::python
