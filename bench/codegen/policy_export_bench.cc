// The exported policy (`cbbg export`, codegen/) against the C++ blocks it is written from:
// ns per call of NAME_step for 49, 343 and 2401 features (what the features see: the pitch
// and its rate; with the wheels' mean rate; with their mean angle and rate), double and
// float, each over the same blocks evaluated by cbbg's framework in the same run; and the
// bytes of code (.text) and data (.rodata, .data) of each export compiled by gcc -O2.
//   build/bench/codegen/bench_policy_export

#include <dlfcn.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include <benchmark/benchmark.h>

#include "bench/ratio_reporter.h"
#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/codegen/c_export.h"
#include "cbbg/framework/diagram_builder.h"

namespace cbbg::bench {
namespace {

namespace fs = std::filesystem;

constexpr double kPeriod = 0.01;

blocks::NormalisedInputs inputs_for(int features) {
  return features == 49    ? blocks::NormalisedInputs::kPitch
         : features == 343 ? blocks::NormalisedInputs::kPitchWheelRate
                           : blocks::NormalisedInputs::kPitchWheels;
}

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

// A measured state that moves a little each call, within the grid.
void next_measured(Vector& measured, long call) {
  const double s = std::sin(1e-3 * static_cast<double>(call));
  measured << 0.1 * s, 0.2 * s, 0.5 * s, 0.5 * s, 1.0 * s, 1.0 * s;
}

// One export compiled by gcc -O2 into a shared object of its own, loaded; removed at the end.
class CompiledExport {
 public:
  using Step = double (*)(const double*);
  using StepFloat = float (*)(const float*);

  CompiledExport(const PolicyDiagram& policy, codegen::Scalar scalar)
      : directory_(fs::temp_directory_path() / ("cbbg-bench-export-" + std::to_string(::getpid()) +
                                                "-" + std::to_string(policy.actor->num_features()) +
                                                (scalar == codegen::Scalar::kFloat ? "f" : "d"))) {
    codegen::CExportOptions options;
    options.name = "policy";
    options.scalar = scalar;
    const codegen::CSources c = codegen::export_c(
        *policy.diagram, policy.actor->output_port("actor_action"), *policy.context, options);
    fs::create_directories(directory_);
    std::ofstream(directory_ / "policy.h") << c.header;
    std::ofstream(directory_ / "policy.c") << c.source;
    const std::string in = " -std=c99 -O2 " + (directory_ / "policy.c").string();
    shell("gcc -c" + in + " -o " + (directory_ / "policy.o").string());
    shell("gcc -shared -fPIC" + in + " -lm -o " + (directory_ / "policy.so").string());
    library_ = dlopen((directory_ / "policy.so").c_str(), RTLD_NOW | RTLD_LOCAL);
    if (library_ == nullptr) throw std::runtime_error(dlerror());
    step_ = dlsym(library_, "policy_step");
    read_sizes();
  }
  ~CompiledExport() {
    if (library_ != nullptr) dlclose(library_);
    fs::remove_all(directory_);
  }
  CompiledExport(const CompiledExport&) = delete;
  CompiledExport& operator=(const CompiledExport&) = delete;

  Step step() const { return reinterpret_cast<Step>(step_); }
  StepFloat step_float() const { return reinterpret_cast<StepFloat>(step_); }
  long code_bytes = 0;
  long data_bytes = 0;

 private:
  static void shell(const std::string& command) {
    if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
  }
  // .text, and .rodata with .data, from `size -A` of the object.
  void read_sizes() {
    const std::string command = "size -A -d " + (directory_ / "policy.o").string();
    FILE* pipe = popen(command.c_str(), "r");
    char section[128];
    long bytes = 0;
    char line[256];
    while (fgets(line, sizeof line, pipe) != nullptr) {
      if (std::sscanf(line, "%127s %ld", section, &bytes) != 2) continue;
      const std::string name = section;
      if (name == ".text") code_bytes += bytes;
      if (name.rfind(".rodata", 0) == 0 || name == ".data") data_bytes += bytes;
    }
    pclose(pipe);
  }

  fs::path directory_;
  void* library_ = nullptr;
  void* step_ = nullptr;
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
    // BM_ExportedPolicy/features:49/float:0 against BM_CppPolicy/49.
    const auto at = name.find("features:");
    if (name.rfind("BM_ExportedPolicy", 0) != 0 || at == std::string::npos) return std::string();
    return "BM_CppPolicy/" + name.substr(at + 9, name.find('/', at) - at - 9);
  });
}
