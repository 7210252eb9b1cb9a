// Per-tick cost of a diagram: a chain of N trivial blocks (y = u / 2 + 1) closed by a
// zero-order hold, against the same arithmetic written as a plain loop; on both schedules, and
// with the blocks' calculation a lambda instead of a named member function.

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "bench/ratio_reporter.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/zero_order_hold.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::bench {
namespace {

constexpr double kPeriod = 0.01;

// y = u / 2 + 1, a named calculation (the library's blocks are written so).
class HalvePlusOne final : public Block {
 public:
  explicit HalvePlusOne(std::string name) : Block(std::move(name)) {
    u_ = &declare_input_port("u", 1);
    declare_output_port<&HalvePlusOne::calc_y>("y", 1, {u_});
  }

 private:
  void calc_y(const BlockContext& context, VectorRef y) const {
    y[0] = 0.5 * context.input(*u_)[0] + 1.0;
  }
  const InputPort* u_;
};

// The same with a lambda (a callable, held in a std::function).
class HalvePlusOneLambda final : public Block {
 public:
  explicit HalvePlusOneLambda(std::string name) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_output_port(
        "y", 1,
        [&u](const BlockContext& context, VectorRef y) { y[0] = 0.5 * context.input(u)[0] + 1.0; },
        {&u});
  }
};

template <typename Step>
std::unique_ptr<Diagram> make_chain(int length) {
  DiagramBuilder builder("chain");
  auto& hold = builder.emplace<ZeroOrderHold>("hold", 1, kPeriod);
  const OutputPort* previous = &hold.output_port("y");
  for (int i = 0; i < length; ++i) {
    auto& step = builder.emplace<Step>("step" + std::to_string(i));
    builder.connect(*previous, step.input_port("u"));
    previous = &step.output_port("y");
  }
  builder.connect(*previous, hold.input_port("u"));
  return builder.build();
}

template <typename Step = HalvePlusOne>
void run_chain(benchmark::State& state, Schedule schedule) {
  const auto diagram = make_chain<Step>(static_cast<int>(state.range(0)));
  Simulator simulator(*diagram, SimulatorOptions{.schedule = schedule});
  double time = 0.0;
  for (auto _ : state) {
    time += kPeriod;
    simulator.advance_to(time);  // exactly one tick
  }
  benchmark::DoNotOptimize(simulator.context().discrete_states()[0]);
}

void BM_Diagram(benchmark::State& state) { run_chain(state, Schedule::kCompiled); }
// The schedule before the compiled one, measured in the same run.
void BM_DiagramInterpreted(benchmark::State& state) { run_chain(state, Schedule::kInterpreted); }
// Blocks whose calculations are lambdas, on the compiled schedule.
void BM_DiagramOfLambdas(benchmark::State& state) {
  run_chain<HalvePlusOneLambda>(state, Schedule::kCompiled);
}

// The baseline as one would write it: the chain's arithmetic with nothing in its way. Only the
// tick's result is kept from the optimiser (a dependent chain of multiply-adds cannot be
// folded), so the loop is not slowed by a barrier per block.
void BM_PlainLoop(benchmark::State& state) {
  const auto length = state.range(0);
  double held = 0.0;
  for (auto _ : state) {
    double x = held;
    for (long i = 0; i < length; ++i) x = 0.5 * x + 1.0;
    held = x;
    benchmark::DoNotOptimize(held);
  }
}

BENCHMARK(BM_Diagram)->Arg(1)->Arg(10)->Arg(100);
BENCHMARK(BM_DiagramInterpreted)->Arg(1)->Arg(10)->Arg(100);
BENCHMARK(BM_DiagramOfLambdas)->Arg(1)->Arg(10)->Arg(100);
BENCHMARK(BM_PlainLoop)->Arg(1)->Arg(10)->Arg(100);

}  // namespace
}  // namespace cbbg::bench

int main(int argc, char** argv) {
  return cbbg::bench::run_benchmarks_with_ratios(argc, argv, [](const std::string& name) {
    // Both schedules against the plain loop of the same length.
    const auto slash = name.find('/');
    return name.rfind("BM_Diagram", 0) == 0 ? "BM_PlainLoop" + name.substr(slash) : std::string();
  });
}
