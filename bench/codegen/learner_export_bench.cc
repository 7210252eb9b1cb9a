// The exported online learner (`cbbg export --learner`, codegen/c_learner_export.h) against
// the C++ blocks it is written from: ns per tick of NAME_step (every output, then every
// block's update: the critic's and the actor's learning, a normal draw, the omega counter,
// the reward's memory, the failure check) for 49, 343 and 2401 features, double and float,
// each over the same blocks stepped by cbbg's Simulator in the same run; the bytes of code
// (.text) and data (.rodata, .data) of each export compiled by gcc -O2, and of its state.
//   build/bench/codegen/bench_learner_export

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "bench/codegen/compiled_c.h"
#include "bench/ratio_reporter.h"
#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/failure_detector.h"
#include "cbbg/blocks/mixer.h"
#include "cbbg/blocks/omega_schedule.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/blocks/reward.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/codegen/c_learner_export.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::bench {
namespace {

constexpr double kPeriod = 0.01;
constexpr unsigned int kFlushToZero = 0x8000;  // MXCSR bits
constexpr unsigned int kDenormalsAreZero = 0x0040;

// The CB-BG learner of the paper (Fig. 5) with the task's failure detector and reward, from
// the measured signals (an input) to the mixed action.
struct LearnerDiagram {
  explicit LearnerDiagram(int features) {
    DiagramBuilder b("learner");
    blocks::NormaliserParams view;
    view.inputs = inputs_for(features);
    auto& normaliser = b.emplace<blocks::Normaliser>("normaliser", view);
    auto& rbf = b.emplace<blocks::RbfFeatures>("features", blocks::RbfParams{}, view.size());
    const int n = rbf.num_features();
    auto& critic = b.emplace<blocks::Critic>("critic", n, blocks::CriticParams{}, kPeriod);
    auto& actor = b.emplace<blocks::Actor>("actor", n, blocks::ActorParams{}, kPeriod);
    auto& tropism = b.emplace<blocks::Tropism>("tropism", blocks::TropismParams{});
    auto& sampler =
        b.emplace<blocks::BoltzmannSampler>("sampler", blocks::SamplerParams{}, kPeriod);
    auto& omega = b.emplace<blocks::OmegaSchedule>("omega", blocks::OmegaParams{}, kPeriod);
    auto& supervisor = b.emplace<blocks::PdSupervisor>("supervisor", blocks::PdSupervisorParams{});
    auto& mix = b.emplace<blocks::Mixer>("mixer");
    auto& failure =
        b.emplace<blocks::FailureDetector>("failure", blocks::FailureDetectorParams{}, kPeriod);
    auto& reward = b.emplace<blocks::Reward>("reward", blocks::RewardParams{}, kPeriod);
    b.connect(normaliser, "x", rbf, "x");
    for (Block* learner : {static_cast<Block*>(&critic), static_cast<Block*>(&actor)})
      b.connect(rbf, "features", *learner, "features");
    b.connect(reward, "reward", critic, "reward");
    b.connect(failure, "failed", critic, "failed");
    b.connect(failure, "failed", reward, "failed");
    b.connect(critic, "td_error", actor, "td_error");
    b.connect(critic, "value", tropism, "value");
    b.connect(tropism, "temperature", sampler, "temperature");
    b.connect(actor, "actor_action", sampler, "actor_action");
    for (Block* reader : {static_cast<Block*>(&actor), static_cast<Block*>(&mix)}) {
      b.connect(supervisor, "action", *reader, "supervisor_action");
      b.connect(sampler, "exploration_action", *reader, "exploration_action");
      b.connect(omega, "omega", *reader, "omega");
    }
    for (Block* reader : {static_cast<Block*>(&normaliser), static_cast<Block*>(&supervisor),
                          static_cast<Block*>(&failure), static_cast<Block*>(&reward)})
      b.export_input(reader->input_port("measured"), "measured");  // one input, fanned out
    action = &mix.output_port("action");
    watched = &failure.output_port("failed");
    diagram = b.build();
  }

  const OutputPort* action = nullptr;
  const OutputPort* watched = nullptr;
  std::unique_ptr<Diagram> diagram;
};

// The learner's export, compiled with a wrapper that owns one state.
struct CompiledLearner {
  CompiledLearner(const LearnerDiagram& learner, const Context& context, codegen::Scalar scalar)
      : compiled("learner-" + std::to_string(context.discrete_states().size()) +
                     (scalar == codegen::Scalar::kFloat ? "f" : "d"),
                 "learner", sources(learner, context, scalar), {{"wrapper.c", kWrapper}}) {}

  static codegen::CSources sources(const LearnerDiagram& learner, const Context& context,
                                   codegen::Scalar scalar) {
    codegen::CLearnerOptions options;
    options.name = "learner";
    options.scalar = scalar;
    options.period = kPeriod;
    options.watched = {learner.watched};
    return codegen::export_learner_c(*learner.diagram, *learner.action, context, options);
  }
  static constexpr const char* kWrapper =
      "#include \"learner.h\"\nstatic learner_state state;\n"
      "unsigned long bench_start(void) {\n  learner_init(&state);\n"
      "  learner_start_trial(&state);\n  return sizeof state;\n}\n"
      "int bench_step(const learner_real *measured, learner_real *action) {\n"
      "  return learner_step(&state, measured, action);\n}\n";

  CompiledC compiled;
};

void BM_CppLearner(benchmark::State& state) {
  const LearnerDiagram learner(static_cast<int>(state.range(0)));
  Simulator simulator(*learner.diagram, {}, 1);
  const InputPort& measured_port = learner.diagram->input_port("measured");
  Vector measured(6);
  next_measured(measured, 0);
  simulator.context().fix_input(measured_port, measured);
  simulator.initialize();
  long call = 0;
  double time = 0.0;
  for (auto _ : state) {
    next_measured(measured, ++call);
    simulator.context().fix_input(measured_port, measured);
    time += kPeriod;
    simulator.advance_to(time);  // the tick at the previous time: outputs, then updates
  }
  benchmark::DoNotOptimize(simulator.context().discrete_states().data());
}

template <typename Real>
void step_export(benchmark::State& state, const CompiledLearner& learner) {
  using Step = int (*)(const Real*, Real*);
  const Step step = learner.compiled.function<Step>("bench_step");
  const auto bytes = learner.compiled.function<unsigned long (*)()>("bench_start")();
  Vector measured(6);
  Real in[6];
  Real action = 0;
  double sum = 0.0;
  long call = 0;
  for (auto _ : state) {
    next_measured(measured, ++call);
    for (int i = 0; i < 6; ++i) in[i] = static_cast<Real>(measured[i]);
    step(in, &action);
    sum += static_cast<double>(action);
  }
  benchmark::DoNotOptimize(sum);
  state.counters["state_bytes"] = static_cast<double>(bytes);
}

// float: 0 double, 1 float, 2 float with subnormal numbers flushed to zero (x86's MXCSR
// FTZ and DAZ; many microcontrollers' FPUs flush by default): the decaying critic trace and
// the far features fall below float's normal range, where x86 computes slowly.
void BM_ExportedLearner(benchmark::State& state) {
  const LearnerDiagram learner(static_cast<int>(state.range(0)));
  const auto context = learner.diagram->create_context(1);
  const long kind = state.range(1);
  const CompiledLearner compiled(learner, *context,
                                 kind == 0 ? codegen::Scalar::kDouble : codegen::Scalar::kFloat);
#if defined(__SSE__)
  const unsigned int control = _mm_getcsr();
  if (kind == 2) _mm_setcsr(control | kFlushToZero | kDenormalsAreZero);
#else
  if (kind == 2) return state.SkipWithError("no MXCSR on this processor");
#endif
  if (kind == 0) {
    step_export<double>(state, compiled);
  } else {
    step_export<float>(state, compiled);
  }
#if defined(__SSE__)
  _mm_setcsr(control);
#endif
  state.counters["code_bytes"] = static_cast<double>(compiled.compiled.code_bytes);
  state.counters["data_bytes"] = static_cast<double>(compiled.compiled.data_bytes);
}

BENCHMARK(BM_CppLearner)->Arg(49)->Arg(343)->Arg(2401);
BENCHMARK(BM_ExportedLearner)
    ->ArgsProduct({{49, 343, 2401}, {0, 1, 2}})
    ->ArgNames({"features", "float"});

}  // namespace
}  // namespace cbbg::bench

int main(int argc, char** argv) {
  return cbbg::bench::run_benchmarks_with_ratios(argc, argv, [](const std::string& name) {
    return cbbg::bench::baseline_by_features(name, "BM_ExportedLearner", "BM_CppLearner");
  });
}
