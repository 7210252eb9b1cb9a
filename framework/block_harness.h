#pragma once
// Unit-tests one block alone: the harness puts it in a diagram of its own, as the simulator
// runs it in a controller. Its inputs become the diagram's inputs (set them with
// set_input), its outputs are evaluated on demand, tick() fires one event instant (outputs
// from the current state, then the updates, committed together), whatever the block's
// period, and its discrete state is read whole or by part name.
//
//   cbbg::testing::BlockHarness<MyBlock> harness("mine", my_params);
//   harness.set_input("measured", Vector::Zero(6));
//   EXPECT_EQ(harness.scalar_output("action"), 0.0);
//   harness.tick();
//   EXPECT_EQ(harness.state_part("weights")[0], 0.5);

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "cbbg/framework/block.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/layout.h"
#include "cbbg/framework/signal_log.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::testing {

template <typename B>
class BlockHarness {
 public:
  // The controller's tick, s, which most blocks under test take as their period; how far
  // tick() moves time for a block with no periodic event.
  static constexpr double kPeriod = 0.01;

  // Builds the diagram around B(args...); the simulation's root seed is 0 (see reseed).
  template <typename... Args>
  explicit BlockHarness(Args&&... args) {
    DiagramBuilder builder("harness");
    block_ = &builder.emplace<B>(std::forward<Args>(args)...);
    for (int i = 0; i < block_->num_input_ports(); ++i) {
      builder.export_input(block_->input_port(i));
    }
    for (int i = 0; i < block_->num_output_ports(); ++i) {
      builder.export_output(block_->output_port(i));
    }
    diagram_ = builder.build();
    simulator_ = std::make_unique<Simulator>(*diagram_);
  }

  const B& block() const { return *block_; }
  Context& context() { return simulator_->context(); }
  Simulator& simulator() { return *simulator_; }
  // Seeds every generator from `root_seed`, before the first tick.
  void reseed(std::uint64_t root_seed) { context().reseed(root_seed); }

  void set_input(std::string_view name, const Vector& value) {
    context().fix_input(diagram_->input_port(name), value);
  }
  void set_input(std::string_view name, double value) {
    set_input(name, Vector::Constant(1, value));
  }

  // The output's value from the current state and inputs.
  Vector output(std::string_view name) {
    return diagram_->eval_output(context(), block_->output_port(name));
  }
  double scalar_output(std::string_view name) { return output(name)[0]; }

  // A copy of the block's discrete state.
  Vector state() const {
    const Context& context = simulator_->context();
    return context.discrete_state(*block_);
  }

  // A copy of the block's discrete state part `name` ("weights"); an unknown name throws,
  // naming the parts the block has.
  Vector state_part(std::string_view name) const {
    return block_->discrete_state_part(name).of(state());
  }

  // Fires the simulator's next event instant, and only it: time stops halfway to the instant
  // after it (the first tick initialises the simulation first). A block with no periodic
  // event has no instant; time then moves on by kPeriod.
  SimulationStatus tick() {
    const double next = earliest(context().time(), false);
    const double after = earliest(next, true);
    const double end = std::isfinite(after) ? next + 0.5 * (after - next)
                                            : (static_cast<double>(ticks_) + 0.5) * kPeriod;
    ++ticks_;
    return simulator_->advance_to(end);
  }
  long long ticks() const { return ticks_; }

  // A new trial: the time restarts at 0 and the initialization updates run again; state
  // the caller did not reset (learnt weights) carries over.
  void restart_time() {
    context().set_time(0.0);
    ticks_ = 0;
    simulator_->initialize();
  }

 private:
  // Whether two instants are one, as the simulator tells them (simulator.h step 1).
  static bool same_instant(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
  }

  // The first instant offset + k period (k >= 0) at or after `time`, one simultaneous with
  // `time` counting as at it (the simulator's rule); with `later`, the first after that one.
  static double instant(double period, double offset, double time, bool later) {
    double k = std::max(0.0, std::ceil((time - offset) / period));
    if (k > 0.0 && same_instant(offset + (k - 1.0) * period, time)) k -= 1.0;
    if (later && same_instant(offset + k * period, time)) k += 1.0;
    return offset + k * period;
  }

  // The earliest instant() of any periodic update or log the simulator schedules; infinity
  // when there is none.
  double earliest(double time, bool later) const {
    double next = std::numeric_limits<double>::infinity();
    for (const LeafLayout& leaf : diagram_->leaves()) {
      for (const PeriodicUpdate& update : leaf.block->periodic_updates()) {
        next = std::min(next, instant(update.period, update.offset, time, later));
      }
    }
    for (const SignalLog& log : simulator_->logs()) {
      next = std::min(next, instant(log.period(), log.offset(), time, later));
    }
    return next;
  }

  const B* block_ = nullptr;
  std::unique_ptr<Diagram> diagram_;
  std::unique_ptr<Simulator> simulator_;
  long long ticks_ = 0;
};

}  // namespace cbbg::testing
