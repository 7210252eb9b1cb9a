// The exported policy (`cbbg export`, codegen/) against the C++ blocks it is written from:
// ns per call of NAME_step for 49, 343 and 2401 features (what the features see: the pitch
// and its rate; with the wheels' mean rate; with their mean angle and rate), double and
// float, each over the same blocks evaluated by cbbg's framework in the same run; and the
// bytes of code (.text) and data (.rodata, .data) of each export compiled by gcc -O2.
//   build/bench/codegen/bench_policy_export

#include <cmath>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "bench/codegen/compiled_c.h"
#include "bench/ratio_reporter.h"
#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/codegen/c_export.h"
#include "cbbg/framework/diagram_builder.h"

namespace cbbg::bench {
namespace {

constexpr double kPeriod = 0.01;

// measured -> normaliser -> features -> actor -> action, the actor's weights all set.
struct PolicyDiagram {
  explicit PolicyDiagram(int features) {
    DiagramBuilder builder("policy");
    blocks::NormaliserParams view;
    view.inputs = inputs_for(features);
    auto& normaliser = builder.emplace<blocks::Normaliser>("normaliser", view);
    auto& rbf = builder.emplace<blocks::RbfFeatures>("features", blocks::RbfParams{}, view.size());
    auto& made =
        builder.emplace<blocks::Actor>("actor", rbf.num_features(), blocks::ActorParams{}, kPeriod);
    builder.connect(normaliser, "x", rbf, "x");
    builder.connect(rbf, "features", made, "features");
    for (const char* unused : {"td_error", "supervisor_action", "exploration_action", "omega"}) {
      builder.fix_input(made.input_port(unused), Vector::Zero(1));
    }
    builder.export_input(normaliser.input_port("measured"), "measured");
    builder.export_output(made.output_port("actor_action"), "action");
    actor = &made;
    diagram = builder.build();
    context = diagram->create_context();
    VectorView theta = actor->mutable_weights(*context);
    for (Eigen::Index k = 0; k < theta.size(); ++k)
      theta[k] = std::sin(0.37 * static_cast<double>(k));
  }

  const blocks::Actor* actor = nullptr;
  std::unique_ptr<Diagram> diagram;
  std::unique_ptr<Context> context;
};

// The policy's export, compiled.
struct CompiledExport {
  CompiledExport(const PolicyDiagram& policy, codegen::Scalar scalar)
      : compiled("export-" + std::to_string(policy.actor->num_features()) +
                     (scalar == codegen::Scalar::kFloat ? "f" : "d"),
                 "policy", sources(policy, scalar)),
        code_bytes(compiled.code_bytes),
        data_bytes(compiled.data_bytes) {}

  static codegen::CSources sources(const PolicyDiagram& policy, codegen::Scalar scalar) {
    codegen::CExportOptions options;
    options.name = "policy";
    options.scalar = scalar;
    return codegen::export_c(*policy.diagram, policy.actor->output_port("actor_action"),
                             *policy.context, options);
  }
  using Step = double (*)(const double*);
  using StepFloat = float (*)(const float*);
  Step step() const { return compiled.function<Step>("policy_step"); }
  StepFloat step_float() const { return compiled.function<StepFloat>("policy_step"); }

  CompiledC compiled;
  long code_bytes;
  long data_bytes;
};

void BM_CppPolicy(benchmark::State& state) {
  PolicyDiagram policy(static_cast<int>(state.range(0)));
  const InputPort& measured_port = policy.diagram->input_port("measured");
  const OutputPort& action = policy.diagram->output_port("action");
  Vector measured(6);
  long call = 0;
  double sum = 0.0;
  for (auto _ : state) {
    next_measured(measured, ++call);
    policy.context->fix_input(measured_port, measured);
    sum += policy.diagram->eval_output(*policy.context, action)[0];
  }
  benchmark::DoNotOptimize(sum);
}

void BM_ExportedPolicy(benchmark::State& state) {
  PolicyDiagram policy(static_cast<int>(state.range(0)));
  const bool single = state.range(1) == 1;
  const CompiledExport compiled(policy,
                                single ? codegen::Scalar::kFloat : codegen::Scalar::kDouble);
  Vector measured(6);
  float measured_float[6];
  long call = 0;
  double sum = 0.0;
  for (auto _ : state) {
    next_measured(measured, ++call);
    if (single) {
      for (int i = 0; i < 6; ++i) measured_float[i] = static_cast<float>(measured[i]);
      sum += compiled.step_float()(measured_float);
    } else {
      sum += compiled.step()(measured.data());
    }
  }
  benchmark::DoNotOptimize(sum);
  state.counters["code_bytes"] = static_cast<double>(compiled.code_bytes);
  state.counters["data_bytes"] = static_cast<double>(compiled.data_bytes);
}

BENCHMARK(BM_CppPolicy)->Arg(49)->Arg(343)->Arg(2401);
BENCHMARK(BM_ExportedPolicy)
    ->ArgsProduct({{49, 343, 2401}, {0, 1}})
    ->ArgNames({"features", "float"});

}  // namespace
}  // namespace cbbg::bench

int main(int argc, char** argv) {
  return cbbg::bench::run_benchmarks_with_ratios(argc, argv, [](const std::string& name) {
    return cbbg::bench::baseline_by_features(name, "BM_ExportedPolicy", "BM_CppPolicy");
  });
}
