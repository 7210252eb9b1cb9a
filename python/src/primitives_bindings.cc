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

// The class comments and port tables of the headers, verbatim.
constexpr const char* kAdderDoc =
    R"(Adder: the signed sum of its inputs, elementwise: y = sum_i s_i u_i, each sign s_i +1 or
-1. A comparison is Adder("err", {{"r", +1}, {"y", -1}}, n): err = r - y.

| port         | dir | size | meaning                      |
|--------------|-----|------|------------------------------|
| <input name> | in  | n    | one per declared input, u_i  |
| y            | out | n    | sum_i s_i u_i                |

y reads every input directly (direct feedthrough). The first input is taken with its sign
(y = u_0 or -u_0), then each next one added or subtracted in order, so a two-input
difference is exactly r - y.)";

constexpr const char* kConstantSourceDoc = R"(ConstantSource: outputs a constant vector.

| port | dir | size | meaning       |
|------|-----|------|---------------|
| y    | out | n    | the value     |)";

constexpr const char* kCsvSinkDoc =
    R"(CsvSink: writes its inputs to a CSV file every `period` h from `offset` t_0, a row per
sample t_k = t_0 + k h:

    # written by cbbg CsvSink
    t,<columns of the first input>,<columns of the next>,...
    t_k,u_1(t_k),...,u_N(t_k)

| port         | dir | size     | meaning                                 |
|--------------|-----|----------|-----------------------------------------|
| <input name> | in  | its size | one per declared input, in column order |

A row holds the values every update at t_k reads (simulator.h step 2), the same a
SignalLog of the signal would record at t_k; numbers are written as number_text.h writes
them (the shortest text that reads back as the same double). Columns are named as given,
or after the input: its name, or name[i] where it has several elements.

Why a block and not a SignalLog: a log records one output port and belongs to a
Simulator, set up in code after the diagram is built; a sink is part of the diagram, wired
like any block to several signals at once, with one file and one time column for them all.

The file: the constructor checks its path, before any work; the first
Simulator::initialize of a simulation of the diagram creates the file (or replaces one a
CsvSink wrote) and writes the tag and the header; every later run of the diagram appends
its rows to the same file (t starts again at each run), until the block is destroyed,
which closes it. flush() makes the rows written so far readable meanwhile.

The rule of owned_files.h: a path is written only when nothing is there or the file there
carries kCsvSinkTag; a file of the user's, a directory, FIFO, socket or device is refused
(std::invalid_argument naming the path), at construction and again when the file is
opened, and never opened.

Limits: the open file lives in the block, not in a Context: simulate the diagram in one
context at a time (simulations of it in parallel would mix their rows in one file), and
give each sink its own path. Writing a row never allocates (the stream's buffer is made
when the file opens); a write the stream reports failed throws std::runtime_error.)";

constexpr const char* kDeadbandDoc =
    R"(Deadband (Simulink's Dead Zone): zero inside [lower, upper], the distance past the nearer
limit outside it, elementwise:

  y_i = 0              if lower_i <= u_i <= upper_i
  y_i = u_i - upper_i  if u_i > upper_i
  y_i = u_i - lower_i  if u_i < lower_i

| port | dir | size | meaning                  |
|------|-----|------|--------------------------|
| u    | in  | n    | input                    |
| y    | out | n    | u less the dead zone     |

The limits are one pair for every element or a pair per element; -inf below or inf above
leaves that side without a zone. A NaN input gives NaN. y reads u directly (direct
feedthrough).)";

constexpr const char* kDemultiplexerDoc =
    R"(Demultiplexer: splits its input, in order, into named outputs of given sizes (the mirror
of Multiplexer): output i is u[o_i, o_i + n_i), where o_i = n_0 + ... + n_{i-1}.

| port          | dir | size        | meaning                        |
|---------------|-----|-------------|--------------------------------|
| u             | in  | sum of n_i  | the vector to split            |
| <output name> | out | n_i         | one per declared output, a cut |

Every output reads u directly (direct feedthrough).)";

constexpr const char* kDiscreteDerivativeDoc =
    R"(DiscreteDerivative: the backward difference of its input sampled every period h. At the
sample instants t_k = offset + k h it stores u_k; its output is the difference of the
last two samples:

  y = (u_k - u_{k-1}) / h  from just after t_k until t_{k+1} included

The state holds the last two samples, x_last = u_k and x_before = u_{k-1} (zero before
any sample), and a count of samples (up to 2); y = (x_last - x_before) / h reads only the
state, never u directly, so a derivative breaks feedback loops.

| port | dir | size | meaning                                |
|------|-----|------|----------------------------------------|
| u    | in  | n    | the signal to differentiate            |
| y    | out | n    | (u_k - u_{k-1}) / h, the last samples' |

Timing (simulator.h step 2): at t_k every output is evaluated before any update, so what
other blocks' updates and logs read at t_k is (u_{k-1} - u_{k-2}) / h, one period late
for a discrete block at the same period; a continuous block sees (u_k - u_{k-1}) / h
during (t_k, t_{k+1}]. So that the output never depends on when a downstream block
samples it (it is a function of the state alone), this design follows Drake's
DiscreteDerivative.

The initial transient: with InitialTransient::kSuppress (the default), y is zero until
two samples have been stored, that is until just after t_1; with kKeep, the samples
before the first are zero, so y is u_0 / h during (t_0, t_1]. A new trial
(Context::reset_trial_state) forgets the samples and the count.)";

constexpr const char* kDiscreteLinearSystemDoc =
    R"(DiscreteLinearSystem: the discrete-time state-space model, updated every `period` h from
`offset` t_0 (t_k = t_0 + k h):

    x_{k+1} = A x_k + B u_k,    y = C x + D u,    x_0 = x0,

with n >= 1 states, m >= 1 inputs and p >= 1 outputs: A is n x n, B n x m, C p x n and
D p x m. u_k is the input at t_k (the value every update at t_k reads, simulator.h step
2); x_{k+1} is held from t_k until t_{k+1}. y is evaluated from the held state and the
present input, so with D = 0 it is held too.

| port | dir | size | meaning   |
|------|-----|------|-----------|
| u    | in  | m    | the input |
| y    | out | p    | C x + D u |

y reads u directly (direct feedthrough) only when D has a nonzero element; with D = 0 it
reads the state alone, so the system can close a feedback loop. x is the discrete-state
part "x", StateLifetime::kPerTrial: each trial starts again from x0.)";

constexpr const char* kFirstOrderLowPassDoc =
    R"(FirstOrderLowPass: a first-order lag of time constant tau > 0, elementwise on n signals:

    x' = (u - x) / tau,    y = x,    x(0) = x0,

so under a constant input u, y(t) = u + (x0 - u) exp(-t / tau): a unit step from x0 = 0
gives 1 - exp(-t / tau). Its DC gain is 1 and its cut-off frequency 1 / tau rad/s.

| port | dir | size | meaning                 |
|------|-----|------|-------------------------|
| u    | in  | n    | the signal to smooth    |
| y    | out | n    | x, the smoothed signal  |

y reads the state alone, never u directly: the filter can close a feedback loop. x is
continuous state, integrated by the simulator (simulator.h step 3); reset_trial_state
keeps it, Context::reset_state puts x0 back.)";

constexpr const char* kGainDoc =
    R"(Gain: y = k u, elementwise with a scalar k, or y = K u with a matrix K of m rows and n
columns (for a scalar gain, m = n = its size).

| port | dir | size | meaning    |
|------|-----|------|------------|
| u    | in  | n    | input      |
| y    | out | m    | k u or K u |

y reads u directly (direct feedthrough).)";

constexpr const char* kIntegratorDoc =
    R"(Integrator: integrates its input in continuous time, from an initial value:

  x' = u,  x(0) = initial value,  y = x

| port | dir | size | meaning                      |
|------|-----|------|------------------------------|
| u    | in  | n    | the rate x'                  |
| y    | out | n    | x, the integral from x(0)    |

x is continuous state, which the simulator integrates (simulator.h step 3). y reads only
x, never u directly: an integrator breaks feedback loops. Like all continuous state, x is
kept by Context::reset_trial_state; Context::reset_state(block) puts it back to its
initial value.)";

constexpr const char* kLinearSystemDoc = R"(LinearSystem: the continuous-time state-space model

    x' = A x + B u,    y = C x + D u,    x(0) = x0,

with n >= 1 states, m >= 1 inputs and p >= 1 outputs: A is n x n, B n x m, C p x n and
D p x m. The simulator integrates x with its other continuous state (simulator.h step 3,
to its accuracy).

| port | dir | size | meaning   |
|------|-----|------|-----------|
| u    | in  | m    | the input |
| y    | out | p    | C x + D u |

y reads u directly (direct feedthrough) only when D has a nonzero element; with D = 0 it
reads the state alone, so the system can close a feedback loop through blocks that feed
through. x is continuous state: Context::reset_trial_state keeps it, Context::reset_state
puts x0 back.)";

constexpr const char* kMultiplexerDoc =
    R"(Multiplexer: concatenates its inputs, in order, into one vector.

| port          | dir | size        | meaning                  |
|---------------|-----|-------------|--------------------------|
| <input name>  | in  | its size    | one per declared input   |
| y             | out | sum of them | the inputs, concatenated |)";

constexpr const char* kPidControllerDoc =
    R"(PidController: a discrete PID controller with output limits and anti-windup by conditional
integration, elementwise on n error signals, sampled every `period` h from `offset` t_0
(t_k = t_0 + k h). Its input is the error e = reference - measurement (an Adder with signs
+1, -1 forms it), so one block serves any sign convention and set-point weighting stays
outside.

| port | dir | size | meaning                                 |
|------|-----|------|-----------------------------------------|
| e    | in  | n    | the error, reference - measurement      |
| u    | out | n    | the command u_k, held until t_{k+1}     |

At each sample t_k, in this order, for each element:
 1. e_k = e(t_k), the error every update at t_k reads (simulator.h step 2);
 2. D_k = (e_k - e_{k-1}) / h, the backward difference; D_0 = 0 (e_{-1} is taken as e_0,
    so the first sample gives no derivative kick);
 3. v_k = kp e_k + ki I_k + kd D_k, the unsaturated command, with I_0 = 0;
 4. u_k = sat(v_k) = min(max(v_k, u_min), u_max), held on u from t_k until t_{k+1};
 5. anti-windup by conditional integration: I_{k+1} = I_k when the command saturates and
    e_k would drive it further (v_k > u_max and e_k > 0, or v_k < u_min and e_k < 0);
    otherwise I_{k+1} = I_k + h e_k (the forward rectangle rule: I_k sums the errors before
    t_k, times h);
 6. e_k is kept as the next sample's e_{k-1}.

Conditional integration rather than back-calculation: it needs no tracking gain to tune,
and the integral never moves further into a limit it is already past.

u reads the block's state alone (no direct feedthrough): the controller closes a loop with
a plant that feeds through, and a continuous plant sees u_k over [t_k, t_{k+1}) (a zero-
order hold with no computational delay); a discrete block that samples u at t_{k+1}
reads u_k. Before the first sample u is sat(0). The state parts "integral" (I),
"previous_error" (e_{k-1}), "command" (u) and "started" (1 after the first sample) are all
StateLifetime::kPerTrial: each trial starts afresh.)";

constexpr const char* kRampSourceDoc =
    R"(RampSource: a ramp of a given slope from a start time, elementwise:

    y(t) = y0 for t < t_start,    y(t) = y0 + s (t - t_start) for t >= t_start.

| port | dir | size | meaning                        |
|------|-----|------|--------------------------------|
| y    | out | n    | y0 + s max(0, t - t_start)     |

y depends on the context's time alone (no input, no state).)";

constexpr const char* kRateLimiterDoc =
    R"(RateLimiter: a discrete rate limit of period h. At the sample instants t_k = offset + k h,
its output moves toward the input by at most rising h up or falling h down:

  y_k = y_{k-1} + clamp(u_k - y_{k-1}, -falling h, rising h),  y_{-1} = initial value

elementwise; where the step is within the limits, y_k = u_k exactly. Both rates are
magnitudes (>= 0, in units of u per second); inf leaves that direction unlimited.

| port | dir | size | meaning                  |
|------|-----|------|--------------------------|
| u    | in  | n    | the signal to limit      |
| y    | out | n    | the rate-limited signal  |

The state holds y; y reads only the state, never u directly, so a rate limiter breaks
feedback loops. Timing (simulator.h step 2): at t_k every output is evaluated before any
update, so what other blocks' updates and logs read at t_k is y_{k-1}; the update at t_k
then computes y_k from u_k, which y shows from just after t_k until t_{k+1} included. A
discrete block at the same period therefore sees the limited signal one period late (as
through a UnitDelay); a continuous block sees y_k during (t_k, t_{k+1}]. The state is per
trial: Context::reset_trial_state puts the initial value back.)";

constexpr const char* kSaturationDoc =
    R"(Saturation: clamps its input elementwise between a lower and an upper limit:

  y_i = min(max(u_i, lower_i), upper_i)

| port | dir | size | meaning                 |
|------|-----|------|-------------------------|
| u    | in  | n    | input                   |
| y    | out | n    | u clamped to the limits |

The limits are one pair for every element or a pair per element; -inf below or inf above
leaves that side open. y reads u directly (direct feedthrough).)";

constexpr const char* kSelectorDoc =
    R"(Selector: some elements of its input, in the order given: y_i = u[indices_i].

| port | dir | size           | meaning          |
|------|-----|----------------|------------------|
| u    | in  | n              | input            |
| y    | out | indices.size() | u at the indices |)";

constexpr const char* kSineSourceDoc =
    R"(SineSource: a sinusoid, elementwise, with its frequency in radians per second:

    y(t) = b + a sin(omega t + phi)

(a: amplitude; omega: angular frequency in rad/s, 2 pi times the frequency in Hz; phi:
phase in rad; b: bias).

| port | dir | size | meaning                  |
|------|-----|------|--------------------------|
| y    | out | n    | b + a sin(omega t + phi) |

y depends on the context's time alone (no input, no state).)";

constexpr const char* kStepSourceDoc =
    R"(StepSource: a step from an initial to a final value at a step time, elementwise:

    y(t) = y0 for t < t_step,    y(t) = y1 for t >= t_step.

| port | dir | size | meaning                 |
|------|-----|------|-------------------------|
| y    | out | n    | y0 before t_step, y1 on |

y depends on the context's time alone (no input, no state). A continuous block fed by it
sees the jump wherever it falls: the integrator's error control shortens its steps there.)";

constexpr const char* kUnitDelayDoc =
    R"(UnitDelay (z^-1): delays its input by one sample period h. At the sample instants
t_k = offset + k h:

  y_k = x_k,  x_{k+1} = u_k,  x_0 = initial value

| port | dir | size | meaning                                        |
|------|-----|------|------------------------------------------------|
| u    | in  | n    | the signal to delay                            |
| y    | out | n    | the sample before (the initial value at first) |

Timing (simulator.h step 2): at t_k every output is evaluated before any update, so what
other blocks' updates and logs read at t_k is y_k = u_{k-1} (the initial value at t_0);
the update then stores u_k, which y shows from just after t_k until t_{k+1}. A discrete
block at the same period thus sees u one period late; a continuous block sees the latest
sample held, as ZeroOrderHold's output (the two blocks compute the same; their names say
what they are for). y reads only the state, never u directly: a delay breaks feedback
loops. The state is per trial: Context::reset_trial_state puts the initial value back.)";

constexpr const char* kWhiteNoiseDoc =
    R"(WhiteNoise: discrete Gaussian white noise, a fresh independent draw every `period` h from
`offset` t_0 (t_k = t_0 + k h), held in between (a zero-order hold), elementwise:

    y = mu + sigma z,    z ~ N(0, 1) independently for each element and draw.

| port | dir | size | meaning                              |
|------|-----|------|--------------------------------------|
| y    | out | n    | the last draw, mu + sigma z          |

Each Simulator::initialize draws y's first value, and each sample t_k draws the next,
held from t_k until t_{k+1}; a log of the same period and offset records every draw once
(the first at t_0, the one drawn at t_k at t_{k+1}). Each draw takes one standard normal
per element, in element order, from the block's generator in the Context
(BlockContext::random_generator, seeded from the root seed and the block's path), so a
run repeats exactly under the same root seed, another seed gives another sequence, and a
clone of a context draws what the original would. y has no input and reads the state
part "value", StateLifetime::kPerTrial: reset_trial_state puts mu back until the next
initialisation draws, and keeps the generator, so a new trial gets new noise.)";

constexpr const char* kZeroOrderHoldDoc =
    R"(ZeroOrderHold: samples its input every `period` and holds it until the next sample.

| port  | dir | size | meaning                               |
|-------|-----|------|---------------------------------------|
| u     | in  | n    | the signal to sample                  |
| y     | out | n    | the last sample (initial value first) |

y reads only the block's state, never u directly: a hold breaks feedback loops.)";

constexpr const char* kStateSpaceDoc = R"(A linear time-invariant system in state-space form.

Continuous time (time_period == 0):  x' = A x + B u,           y = C x + D u.
Discrete time (time_period > 0):     x[k+1] = A x[k] + B u[k], y[k] = C x[k] + D u[k],
with x[k] the state at t0 + k time_period.
Sizes: A n x n, B n x m, C p x n, D p x m (any of n, m, p may be zero).)";

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
  py::class_<StateSpace>(control_module, "StateSpace", kStateSpaceDoc)
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

  py::class_<control::LqrResult>(control_module, "LqrResult",
                                 "The optimal state feedback u = -K x and the cost-to-go x' S x.")
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
