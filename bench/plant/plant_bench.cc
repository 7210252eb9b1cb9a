// CPU cost of one 10 ms step of each robot plant under the PD law of docs/model.md §2.4 (zero-order
// hold, 20 s trials from theta_b = 0.1744), and what the diagram adds to the Simbody plant:
// the same Simbody model stepped by a plain loop that does the same work (read the state,
// PD law, saturate, hold the torque, integrate 10 ms).

#include <benchmark/benchmark.h>

#include <unistd.h>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "bench/ratio_reporter.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/mujoco/mujoco_params.h"
#include "cbbg/plant/multibody_robot.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/robot_dynamics.h"
#include "cbbg/plant/simbody_plant.h"
#ifdef CBBG_WITH_MUJOCO
#include "cbbg/plant/mujoco/mujoco_plant.h"
#include "cbbg/plant/mujoco/two_wheeler_mjcf.h"
#endif
#include "tests/support/allocation_counter.h"

namespace cbbg::plant::bench {
namespace {

constexpr double kPeriod = 0.01;
constexpr int kTrialTicks = 2000;  // 20 s

double pd_action(const double* x) {
  return 50.0 * x[kThetaB] + 10.0 * x[kThetaBDot] + (x[kPhiLeft] + x[kPhiRight]) / 2.0 +
         (x[kPhiLeftDot] + x[kPhiRightDot]) / 2.0;
}

class PdLaw final : public Block {
 public:
  explicit PdLaw(std::string name) : Block(std::move(name)) {
    const InputPort& state = declare_input_port("state", kStateSize);
    declare_output_port("torque", kTorqueSize,
                        [&state](const BlockContext& context, VectorRef torque) {
                          torque.setConstant(pd_action(context.input(state).data()));
                        },
                        {&state});
  }
};

// PD law -> zero-order hold -> plant, and a simulator stepping it tick by tick.
template <typename Plant>
class DiagramLoop {
 public:
  // For the MuJoCo plant, `mujoco` says its model (by default the two-wheeler of `params`).
  explicit DiagramLoop(const RobotParams& params = {}, const MujocoParams& mujoco = {}) {
    DiagramBuilder builder("robot");
    if constexpr (std::is_constructible_v<Plant, std::string, RobotParams>) {
      plant_ = &builder.emplace<Plant>("plant", params);
    } else {
      plant_ = &builder.emplace<Plant>("plant", mujoco, params);
    }
    auto& law = builder.emplace<PdLaw>("law");
    auto& hold = builder.emplace<ZeroOrderHold>("hold", kTorqueSize, kPeriod);
    builder.connect(*plant_, "state", law, "state");
    builder.connect(law, "torque", hold, "u");
    builder.connect(hold, "y", *plant_, "torque");
    diagram_ = builder.build();
    simulator_ = std::make_unique<Simulator>(*diagram_, SimulatorOptions{params.accuracy});
  }

  void step() {
    if (tick_ == kTrialTicks) {  // next trial
      tick_ = 0;
      simulator_->context().set_time(0.0);
      plant_->reset(simulator_->context(), kDefaultInitialPitch);
      simulator_->initialize();
    }
    ++tick_;
    simulator_->advance_to(tick_ * kPeriod);
  }
  double pitch() const { return simulator_->context().continuous_state(*plant_)[0]; }

 private:
  std::unique_ptr<Diagram> diagram_;
  Plant* plant_ = nullptr;
  std::unique_ptr<Simulator> simulator_;
  int tick_ = 0;
};

// The same Simbody model and the same work, without the framework.
class PlainSimbodyLoop {
 public:
  PlainSimbodyLoop()
      : params_(), run_(std::make_shared<const MultibodyRobot>(params_)), state_(kStateSize) {
    restart();
  }

  void step() {
    if (tick_ == kTrialTicks) restart();
    const double a = pd_action(state_.data());
    const Torques tau = saturate_torque(Torques(a, a), params_.torque_limit);
    run_.set_torque(tau[0], tau[1]);
    ++tick_;
    run_.advance_to(tick_ * kPeriod);
    run_.get_state(state_);
  }
  double pitch() const { return state_[kThetaB]; }

 private:
  void restart() {
    tick_ = 0;
    state_.setZero();
    state_[kThetaB] = kDefaultInitialPitch;
    run_.set_state(0.0, state_);
  }

  RobotParams params_;
  MultibodyRobotRun run_;
  Eigen::VectorXd state_;
  int tick_ = 0;
};

template <typename Loop>
void run_steps(benchmark::State& state, Loop& loop) {
  for (auto _ : state) loop.step();  // one iteration = one 10 ms step
  benchmark::DoNotOptimize(loop.pitch());
}

void BM_AnalyticPlantStep(benchmark::State& state) {
  DiagramLoop<AnalyticPlant> loop;
  run_steps(state, loop);
}

void BM_SimbodyPlantStep(benchmark::State& state) {
  DiagramLoop<SimbodyPlant> loop;
  run_steps(state, loop);
}

void BM_SimbodyPlainLoop(benchmark::State& state) {
  PlainSimbodyLoop loop;
  run_steps(state, loop);
}

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// The diagram and the plain loop in alternating slices of 100 steps within one benchmark,
// so that both see the same machine load; counters give each one's CPU per step and the
// ratio.
void BM_SimbodyDiagramOverPlainLoop(benchmark::State& state) {
  DiagramLoop<SimbodyPlant> diagram;
  PlainSimbodyLoop plain;
  constexpr int kSlice = 100;
  double diagram_seconds = 0.0;
  double plain_seconds = 0.0;
  long slices = 0;
  for (auto _ : state) {
    const double start = thread_cpu_seconds();
    for (int i = 0; i < kSlice; ++i) plain.step();
    const double middle = thread_cpu_seconds();
    for (int i = 0; i < kSlice; ++i) diagram.step();
    const double end = thread_cpu_seconds();
    plain_seconds += middle - start;
    diagram_seconds += end - middle;
    ++slices;
  }
  benchmark::DoNotOptimize(diagram.pitch() + plain.pitch());
  const double steps = static_cast<double>(slices * kSlice);
  state.counters["plain_us_per_step"] = 1e6 * plain_seconds / steps;
  state.counters["diagram_us_per_step"] = 1e6 * diagram_seconds / steps;
  state.counters["diagram_over_plain"] = diagram_seconds / plain_seconds;
}

// What a new trial costs: the Simbody plant's reset (rewrite the context's state; the
// scratch restarts its integrator at the next step) plus that first step, against building
// a context (which builds a multibody system for its scratch) plus its first step.
void BM_SimbodyResetAndFirstStep(benchmark::State& state) {
  DiagramBuilder builder("robot");
  auto& plant = builder.emplace<SimbodyPlant>("plant", RobotParams{});
  builder.export_input(plant.input_port("torque"), "torque");
  const auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.context().fix_input(diagram->input_port("torque"), Vector::Zero(2));
  for (auto _ : state) {
    simulator.context().set_time(0.0);
    plant.reset(simulator.context(), kDefaultInitialPitch);
    simulator.initialize();
    simulator.advance_to(kPeriod);
  }
}

void BM_SimbodyNewContextAndFirstStep(benchmark::State& state) {
  DiagramBuilder builder("robot");
  auto& plant = builder.emplace<SimbodyPlant>("plant", RobotParams{});
  builder.export_input(plant.input_port("torque"), "torque");
  const auto diagram = builder.build();
  for (auto _ : state) {
    Simulator simulator(*diagram);
    simulator.context().fix_input(diagram->input_port("torque"), Vector::Zero(2));
    simulator.advance_to(kPeriod);
  }
}

// The Simbody configurations offered (plant.simbody_model x plant.simbody_integrator), each
// at the default accuracy: CPU per step, heap allocations per step, and the pitch error
// after 3 s of PD control from the trial pitch against the reference (the constrained
// model under Runge-Kutta-Merson at accuracy 1e-10). The baseline is the configuration
// before the rolling model: constrained, merson.
struct SimbodyConfiguration {
  const char* name;
  SimbodyModel model;
  SimbodyIntegrator integrator;
};
constexpr SimbodyConfiguration kConfigurations[] = {
    {"constrained_merson", SimbodyModel::kNoSlipConstraints, SimbodyIntegrator::kMerson},
    {"rolling_merson", SimbodyModel::kRollingBase, SimbodyIntegrator::kMerson},
    {"rolling_rk3", SimbodyModel::kRollingBase, SimbodyIntegrator::kRungeKutta3},
    {"rolling_verlet", SimbodyModel::kRollingBase, SimbodyIntegrator::kVerlet},
};

double pitch_after_3s(const RobotParams& params) {
  DiagramLoop<SimbodyPlant> loop(params);
  for (int tick = 0; tick < 300; ++tick) loop.step();
  return loop.pitch();
}

// All configurations in alternating slices of 100 steps within one benchmark, so that they
// see the same machine load (single runs here vary by 20 % and more); counters per
// configuration.
void BM_SimbodyConfigurations(benchmark::State& state) {
  constexpr int kCount = static_cast<int>(std::size(kConfigurations));
  constexpr int kSlice = 100;
  RobotParams reference;
  reference.accuracy = 1e-10;
  reference.simbody_model = SimbodyModel::kNoSlipConstraints;
  const double reference_pitch = pitch_after_3s(reference);
  std::vector<std::unique_ptr<DiagramLoop<SimbodyPlant>>> loops;
  double seconds[kCount] = {};
  long long allocations[kCount] = {};
  for (const SimbodyConfiguration& configuration : kConfigurations) {
    RobotParams params;
    params.simbody_model = configuration.model;
    params.simbody_integrator = configuration.integrator;
    const std::string name = configuration.name;
    state.counters[name + "_pitch_error_rad"] = std::abs(pitch_after_3s(params) - reference_pitch);
    loops.push_back(std::make_unique<DiagramLoop<SimbodyPlant>>(params));
    loops.back()->step();  // past the first step, which sets the integrator up
  }
  long slices = 0;
  for (auto _ : state) {
    for (int k = 0; k < kCount; ++k) {
      const long long allocated = cbbg::testing::allocation_count();
      const double start = thread_cpu_seconds();
      for (int i = 0; i < kSlice; ++i) loops[static_cast<size_t>(k)]->step();
      seconds[k] += thread_cpu_seconds() - start;
      allocations[k] += cbbg::testing::allocation_count() - allocated;
    }
    ++slices;
  }
  const double steps = static_cast<double>(slices * kSlice);
  for (int k = 0; k < kCount; ++k) {
    const std::string name = kConfigurations[k].name;
    state.counters[name + "_us_per_step"] = 1e6 * seconds[k] / steps;
    state.counters[name + "_over_baseline"] = seconds[k] / seconds[0];
    state.counters[name + "_allocs_per_step"] = static_cast<double>(allocations[k]) / steps;
  }
}

#ifdef CBBG_WITH_MUJOCO
void BM_MujocoPlantStep(benchmark::State& state) {
  DiagramLoop<MujocoPlant> loop;
  run_steps(state, loop);
}

// The MuJoCo two-wheeler as it was first written, kept so that the benchmark compares it with
// today's: its tyres touching the ground as cylinders (two contacts each) at 2 ms steps, in a
// model file of the bench's own, removed when it ends.
class CylinderTyresModel {
 public:
  CylinderTyresModel()
      : path_(std::filesystem::temp_directory_path() /
              ("cbbg-bench-cylinder-tyres-" + std::to_string(::getpid()) + ".xml")) {
    std::string text = two_wheeler_mjcf(RobotParams{});
    replace_all(text, R"(type="sphere" size="0.15" friction="1 0.005 0.0001" group="3")",
                R"(type="cylinder" size="0.15 0.02" zaxis="0 1 0" friction="1 0.005 0.0001")");
    replace_all(text, R"(timestep="0.005")", R"(timestep="0.002")");
    std::ofstream(path_) << text;
  }
  ~CylinderTyresModel() { std::filesystem::remove(path_); }
  CylinderTyresModel(const CylinderTyresModel&) = delete;
  CylinderTyresModel& operator=(const CylinderTyresModel&) = delete;

  MujocoParams params() const {
    MujocoParams p;
    p.model = path_.string();
    return p;
  }

 private:
  static void replace_all(std::string& text, const std::string& from, const std::string& to) {
    std::size_t found = 0;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
      text.replace(at, from.size(), to);
      at += to.size();
      ++found;
    }
    if (found == 0) throw std::logic_error("the two-wheeler's model has no '" + from + "'");
  }

  std::filesystem::path path_;
};

// The two-wheelers in alternating slices of 100 ticks within one benchmark, so that they see
// the same machine load: CPU per 10 ms tick of each; MuJoCo's (its 5 ms steps, spheres
// touching the ground) over Simbody's (the rolling model, Runge-Kutta-Merson), over the
// analytic plant's, and over MuJoCo's first model (cylinders at 2 ms).
void BM_PlantsPerTick(benchmark::State& state) {
  const CylinderTyresModel cylinders;
  DiagramLoop<AnalyticPlant> analytic;
  DiagramLoop<SimbodyPlant> simbody;
  DiagramLoop<MujocoPlant> mujoco;
  DiagramLoop<MujocoPlant> first_mujoco(RobotParams{}, cylinders.params());
  constexpr int kSlice = 100;
  double seconds[4] = {};
  long slices = 0;
  for (auto _ : state) {
    double start = thread_cpu_seconds();
    for (int i = 0; i < kSlice; ++i) analytic.step();
    double end = thread_cpu_seconds();
    seconds[0] += end - start;
    start = end;
    for (int i = 0; i < kSlice; ++i) simbody.step();
    end = thread_cpu_seconds();
    seconds[1] += end - start;
    start = end;
    for (int i = 0; i < kSlice; ++i) mujoco.step();
    end = thread_cpu_seconds();
    seconds[2] += end - start;
    start = end;
    for (int i = 0; i < kSlice; ++i) first_mujoco.step();
    seconds[3] += thread_cpu_seconds() - start;
    ++slices;
  }
  benchmark::DoNotOptimize(analytic.pitch() + simbody.pitch() + mujoco.pitch() +
                           first_mujoco.pitch());
  const double ticks = static_cast<double>(slices * kSlice);
  state.counters["analytic_us_per_tick"] = 1e6 * seconds[0] / ticks;
  state.counters["simbody_us_per_tick"] = 1e6 * seconds[1] / ticks;
  state.counters["mujoco_us_per_tick"] = 1e6 * seconds[2] / ticks;
  state.counters["mujoco_cylinders_2ms_us_per_tick"] = 1e6 * seconds[3] / ticks;
  state.counters["mujoco_over_simbody"] = seconds[2] / seconds[1];
  state.counters["mujoco_over_analytic"] = seconds[2] / seconds[0];
  state.counters["mujoco_over_cylinders_2ms"] = seconds[2] / seconds[3];
}

BENCHMARK(BM_MujocoPlantStep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlantsPerTick)->Unit(benchmark::kMillisecond)->MinTime(5.0);
#endif

BENCHMARK(BM_AnalyticPlantStep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SimbodyConfigurations)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_SimbodyPlantStep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SimbodyPlainLoop)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SimbodyDiagramOverPlainLoop)->Unit(benchmark::kMillisecond)->MinTime(5.0);
BENCHMARK(BM_SimbodyResetAndFirstStep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SimbodyNewContextAndFirstStep)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cbbg::plant::bench

int main(int argc, char** argv) {
  return cbbg::bench::run_benchmarks_with_ratios(argc, argv, [](const std::string& name) {
    if (name == "BM_SimbodyPlantStep") return std::string("BM_SimbodyPlainLoop");
    if (name == "BM_MujocoPlantStep") return std::string("BM_SimbodyPlantStep");
    return std::string();
  });
}
