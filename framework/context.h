#pragma once
// Context: everything that changes during a simulation, in contiguous storage: time, the
// signals on every wire, discrete and continuous state, parameters, and one random generator
// per block, derived from the root seed and the block's path below the root diagram. A Diagram is
// fixed after build; a Context is what a run owns. Clone one to restart a trial or to run in
// parallel.

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/random.h"
#include "cbbg/framework/types.h"

namespace cbbg {

class Diagram;
struct LeafLayout;

class Context {
 public:
  // Made by Diagram::create_context.
  Context(const Diagram& diagram, std::uint64_t root_seed);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  std::unique_ptr<Context> clone() const;
  // Copies every value of `other` (a context of the same diagram) into this one without
  // allocating: the way to restart from a stored initial context.
  void assign_from(const Context& other);

  const Diagram& diagram() const { return *diagram_; }
  std::uint64_t root_seed() const { return root_seed_; }
  double time() const { return time_; }
  void set_time(double time) { time_ = time; }

  // Per-block state and parameters; `block` is any leaf of the diagram.
  VectorView discrete_state(const Block& block);
  ConstVectorView discrete_state(const Block& block) const;
  VectorView continuous_state(const Block& block);
  ConstVectorView continuous_state(const Block& block) const;
  ConstVectorView parameter(const Block& block, std::string_view name) const;
  // Throws, naming the block and parameter, when the size differs from the declared one.
  void set_parameter(const Block& block, std::string_view name, const Vector& value);
  RandomGenerator& random_generator(const Block& block);
  const RandomGenerator& random_generator(const Block& block) const;
  // Restores the block's declared initial discrete and continuous state.
  void reset_state(const Block& block);
  // Restores every block's initial state and sets the time to zero; parameters, fixed inputs
  // and random generators are kept.
  void reset_all_state();
  // A new trial: time zero and every discrete-state part declared StateLifetime::kPerTrial
  // back to its initial value; persistent parts (learnt weights), continuous state,
  // parameters and generators are kept. Never allocates.
  void reset_trial_state();
  // Carries the learning of `other`, a context of another diagram, into this one (a change
  // of protocol halfway, as experiment 2's switch to operant learning): for each leaf here
  // with a leaf of the same path below the root there whose state parts have the same names
  // and sizes, its persistent parts and its random generator. Per-trial and continuous
  // state, parameters and time stay as they are.
  void continue_from(const Context& other);
  // Copies the parameters of `other`'s leaves (a context of another diagram) into the leaves
  // here of the same path whose parameters have the same names and sizes, except `own` and
  // the blocks inside it, whose parameters stay this diagram's (a plant built for another
  // robot). With continue_from: a trial run in another diagram as the protocol set it up.
  void copy_parameters_from(const Context& other, const Block* own = nullptr);
  // Re-seeds every block's generator from `root_seed` and its path below the root diagram.
  void reseed(std::uint64_t root_seed);
  // Whether every block's generator is where the seed put it (at creation or the last
  // reseed): no block has drawn a random number since, so what ran since is the same under
  // any seed (a closed loop takes its randomness from these generators alone).
  bool generators_at_seed() const;

  // The value of an input port the root diagram exports: it must be set before simulating.
  void fix_input(const InputPort& diagram_input, const Vector& value);
  // The last evaluated value of an output port (Diagram::evaluate_outputs fills them).
  ConstVectorView signal(const OutputPort& port) const;

  // Whole storage, for the simulator and for block views.
  Vector& signals() { return signals_; }
  const Vector& signals() const { return signals_; }
  Vector& discrete_states() { return discrete_; }
  const Vector& discrete_states() const { return discrete_; }
  Vector& next_discrete_states() { return next_discrete_; }
  Vector& continuous_states() { return continuous_; }
  const Vector& continuous_states() const { return continuous_; }
  const Vector& parameters() const { return parameters_; }
  RandomGenerator& random_generator(int leaf) { return generators_[static_cast<size_t>(leaf)]; }
  BlockScratch* scratch(int leaf) { return scratch_[static_cast<size_t>(leaf)].get(); }

 private:
  const LeafLayout& layout_of(const Block& block) const;

  const Diagram* diagram_;
  std::uint64_t root_seed_;
  double time_ = 0.0;
  Vector signals_;
  Vector discrete_;
  Vector next_discrete_;
  Vector continuous_;
  Vector parameters_;
  std::vector<RandomGenerator> generators_;
  std::vector<std::unique_ptr<BlockScratch>> scratch_;
};

}  // namespace cbbg
