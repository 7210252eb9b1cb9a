#pragma once
// Unit-tests one block alone: the harness puts it in a diagram of its own, as the simulator
// runs it in a controller. Its inputs become the diagram's inputs (set them with
// set_input), its outputs are evaluated on demand, tick() fires one event instant (outputs
// from the current state, then the updates, committed together), and its discrete state is
// read whole or by part name.
//
//   cbbg::testing::BlockHarness<MyBlock> harness("mine", my_params);
//   harness.set_input("measured", Vector::Zero(6));
//   EXPECT_EQ(harness.scalar_output("action"), 0.0);
//   harness.tick();
//   EXPECT_EQ(harness.state_part("weights")[0], 0.5);

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/simulator.h"

namespace cbbg::testing {

template <typename B>
class BlockHarness {
 public:
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

  // Fires the next event instant (the first one initialises the simulation first).
  SimulationStatus tick() {
    const double end = (static_cast<double>(ticks_) + 0.5) * kPeriod;
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
  const B* block_ = nullptr;
  std::unique_ptr<Diagram> diagram_;
  std::unique_ptr<Simulator> simulator_;
  long long ticks_ = 0;
};

}  // namespace cbbg::testing
