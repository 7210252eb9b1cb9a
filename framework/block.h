#pragma once
// Block: the unit of composition. A leaf block declares named, sized ports, its state, its
// parameters and its events, and what it calculates as its own const member functions (named
// calculations: declare_output_port<&Adder::calc_sum>(...)) or lambdas; a Diagram (diagram.h)
// is a Block made of other blocks.

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/framework/calculation.h"
#include "cbbg/framework/port.h"
#include "cbbg/framework/types.h"

namespace cbbg {

class BlockContext;
class Diagram;

// What an update tells the simulator: carry on, or end the simulation (a trial ends when the
// robot falls). The reason must be a string with static storage (a literal), so that
// returning it never allocates.
class EventStatus {
 public:
  static EventStatus succeeded() { return EventStatus(nullptr); }
  static EventStatus terminate(const char* reason) { return EventStatus(reason); }
  bool terminates() const { return reason_ != nullptr; }
  const char* reason() const { return reason_ == nullptr ? "" : reason_; }

 private:
  explicit EventStatus(const char* reason) : reason_(reason) {}
  const char* reason_;
};

// Per-context working memory a block may need besides its numeric state (a multibody
// integrator, say). Created once per Context and copied with it; never shared between
// contexts, so one Diagram can run in many threads at once.
class BlockScratch {
 public:
  virtual ~BlockScratch() = default;
  virtual std::unique_ptr<BlockScratch> clone() const = 0;
};

// What a block calculates. Each is declared either as a named calculation, a const member
// function of the block given as a template argument (declare_output_port<&Adder::calc_sum>), or
// as a callable (a lambda) of the std::function type below; calculation.h says how each is called.

// Computes an output port's value from the context. Must not change anything.
using OutputFunction = std::function<void(const BlockContext&, VectorRef value)>;
using OutputCalculation = Calculation<void, const BlockContext&, VectorRef>;
// Writes the block's next discrete state; `next_state` holds the current one on entry. Every
// update at one instant reads the values from before any of them ran.
using UpdateFunction = std::function<EventStatus(BlockContext&, VectorRef next_state)>;
using UpdateCalculation = Calculation<EventStatus, BlockContext&, VectorRef>;
// Time derivatives of the block's continuous state, for the simulator's integrator.
using DerivativeFunction = std::function<void(const BlockContext&, VectorRef derivatives)>;
using DerivativeCalculation = Calculation<void, const BlockContext&, VectorRef>;
// Advances a self-integrating block's continuous state to `end_time`; its inputs are held.
using AdvanceFunction = std::function<void(BlockContext&, double end_time)>;
using AdvanceCalculation = Calculation<void, BlockContext&, double>;

// Where a periodic update writes its block's next discrete state.
enum class UpdateWrites {
  // Into a copy: context.discrete_state() keeps the values from before the instant.
  kCopy,
  // Into the state itself, which saves copying it at every instant: next_state and
  // context.discrete_state() are the same memory. Only for an update that reads each element of
  // its state before writing it (as x = x + dx does), and its block's only periodic update.
  // The interpreted schedule (SimulatorOptions) copies all the same.
  kInPlace,
};

struct PeriodicUpdate {
  double period;
  double offset;
  UpdateCalculation update;
  UpdateWrites writes = UpdateWrites::kCopy;
};

// What an output reads besides the inputs it lists.
enum class OutputSources {
  // Anything of its block: time, continuous and discrete state, parameters.
  kAnything,
  // Only its block's discrete state and parameters: never time or continuous state. Such an
  // output holds still between events wherever its inputs do, so the simulator computes it once
  // per interval instead of at every stage of the integrator.
  kDiscreteState,
};

struct Parameter {
  std::string name;
  Vector default_value;
};

// How long a part of a block's discrete state lives: across trials (learnt weights, a tick
// counter) or within one trial (a trace, the previous tick), when Context::reset_trial_state
// puts it back to its initial value.
enum class StateLifetime { kPersistent, kPerTrial };

// A named part of a block's discrete state: where it lies in the block's state vector.
struct StatePart {
  std::string name;
  int offset = 0;
  int size = 0;
  StateLifetime lifetime = StateLifetime::kPersistent;

  // The part inside the block's whole state vector (a view, a Map or a Ref).
  template <typename State>
  auto of(State&& state) const {
    return state.segment(offset, size);
  }
};

class Block {
 public:
  explicit Block(std::string name);
  virtual ~Block();
  Block(const Block&) = delete;
  Block& operator=(const Block&) = delete;

  const std::string& name() const { return name_; }
  // What kind of block it is, for pictures and messages: its C++ class without namespaces
  // ("PdSupervisor", a user's "LeanSupervisor"), which a block may override.
  virtual std::string type_name() const;
  // Names from the root diagram down, joined by '/': "cbbg/controller/critic".
  std::string path() const;
  const Diagram* parent() const { return parent_; }
  virtual bool is_diagram() const { return false; }

  int num_input_ports() const { return static_cast<int>(inputs_.size()); }
  int num_output_ports() const { return static_cast<int>(outputs_.size()); }
  const InputPort& input_port(int index) const;
  const OutputPort& output_port(int index) const;
  // By name; an unknown name throws, listing the ports the block has.
  const InputPort& input_port(std::string_view name) const;
  const OutputPort& output_port(std::string_view name) const;
  // By name, or null for a port the block does not have (an optional port).
  const InputPort* find_input_port(std::string_view name) const;
  const OutputPort* find_output_port(std::string_view name) const;
  // "a, b, c": the ports' names, for messages.
  std::string input_port_names() const;
  std::string output_port_names() const;

  // What a leaf block declared (empty for a Diagram).
  const OutputCalculation& output_calculation(int output_index) const {
    return output_calculations_[static_cast<std::size_t>(output_index)];
  }
  // Inputs that the output reads directly (direct feedthrough), by input index.
  const std::vector<int>& output_reads(int output_index) const;
  OutputSources output_sources(int output_index) const {
    return output_sources_[static_cast<std::size_t>(output_index)];
  }
  const Vector& initial_discrete_state() const { return initial_discrete_state_; }
  // The named parts of the discrete state, in declaration order, back to back.
  const std::vector<StatePart>& discrete_state_parts() const { return state_parts_; }
  // The named part; an unknown name throws, listing the parts the block has.
  const StatePart& discrete_state_part(std::string_view name) const;
  const Vector& initial_continuous_state() const { return initial_continuous_state_; }
  bool has_continuous_state() const { return initial_continuous_state_.size() > 0; }
  // True where the block advances its own continuous state (advance_calculation), false where
  // the simulator integrates it from derivative_calculation.
  bool integrates_itself() const { return static_cast<bool>(advance_); }
  const DerivativeCalculation& derivative_calculation() const { return derivatives_; }
  const AdvanceCalculation& advance_calculation() const { return advance_; }
  const std::vector<PeriodicUpdate>& periodic_updates() const { return periodic_updates_; }
  const std::vector<UpdateCalculation>& initialization_updates() const { return init_updates_; }
  const std::vector<Parameter>& parameters() const { return parameters_; }
  // Index of the named parameter; an unknown name throws, listing the parameters.
  int parameter_index(std::string_view name) const;

  // Working memory for one context; null when the block needs none.
  virtual std::unique_ptr<BlockScratch> make_scratch() const { return nullptr; }

 protected:
  const InputPort& declare_input_port(std::string name, int size, std::string description = {});
  // `reads` lists the inputs the output reads directly; an output that reads only state lists
  // none, which is what breaks feedback loops. `Calc` is a const member function
  // void (const BlockContext&, VectorRef value) of the block.
  template <auto Calc>
  const OutputPort& declare_output_port(std::string name, int size,
                                        std::vector<const InputPort*> reads,
                                        std::string description = {},
                                        OutputSources sources = OutputSources::kAnything) {
    return declare_output(std::move(name), size, OutputCalculation::member<Calc>(*this),
                          std::move(reads), std::move(description), sources);
  }
  // The same with a callable for a calculation.
  const OutputPort& declare_output_port(std::string name, int size, OutputFunction calc,
                                        std::vector<const InputPort*> reads,
                                        std::string description = {},
                                        OutputSources sources = OutputSources::kAnything);
  // A numeric parameter stored in the context, so it can change between runs (annealing)
  // and differ between cloned contexts. Returns its index for BlockContext::parameter.
  int declare_parameter(std::string name, Vector default_value);
  // Appends a named part to the discrete state and returns where it lies. Parts marked
  // kPerTrial are reset to `initial_value` at each trial; the others persist.
  StatePart declare_discrete_state(std::string name, Vector initial_value, StateLifetime lifetime);
  // `Update` is a const member function EventStatus (BlockContext&, VectorRef next_state).
  template <auto Update>
  void declare_periodic_update(double period, double offset,
                               UpdateWrites writes = UpdateWrites::kCopy) {
    declare_periodic(period, offset, UpdateCalculation::member<Update>(*this), writes);
  }
  void declare_periodic_update(double period, double offset, UpdateFunction update,
                               UpdateWrites writes = UpdateWrites::kCopy);
  // Runs once when a simulation is initialised, before the events at the initial time.
  template <auto Update>
  void declare_initialization_update() {
    init_updates_.push_back(UpdateCalculation::member<Update>(*this));
  }
  void declare_initialization_update(UpdateFunction update);
  // `Derivatives` is a const member function void (const BlockContext&, VectorRef derivatives).
  template <auto Derivatives>
  void declare_continuous_state(Vector initial_value) {
    declare_derivatives(std::move(initial_value),
                        DerivativeCalculation::member<Derivatives>(*this));
  }
  void declare_continuous_state(Vector initial_value, DerivativeFunction derivatives);
  // `Advance` is a const member function void (BlockContext&, double end_time).
  template <auto Advance>
  void declare_self_integrated_state(Vector initial_value) {
    declare_advance(std::move(initial_value), AdvanceCalculation::member<Advance>(*this));
  }
  void declare_self_integrated_state(Vector initial_value, AdvanceFunction advance);

 private:
  friend class DiagramBuilder;
  friend class Diagram;  // a diagram that ends releases its children (~Diagram)

  const OutputPort& declare_output(std::string name, int size, OutputCalculation calc,
                                   std::vector<const InputPort*> reads, std::string description,
                                   OutputSources sources);
  void declare_periodic(double period, double offset, UpdateCalculation update,
                        UpdateWrites writes);
  void declare_derivatives(Vector initial_value, DerivativeCalculation derivatives);
  void declare_advance(Vector initial_value, AdvanceCalculation advance);
  void check_new_port_name(const std::string& name, int size) const;
  void check_no_continuous_state() const;

  std::string name_;
  const Diagram* parent_ = nullptr;
  // Deques keep port references valid as more ports are declared.
  std::deque<InputPort> inputs_;
  std::deque<OutputPort> outputs_;
  std::vector<OutputCalculation> output_calculations_;
  std::vector<std::vector<int>> output_reads_;
  std::vector<OutputSources> output_sources_;
  Vector initial_discrete_state_;
  std::vector<StatePart> state_parts_;
  Vector initial_continuous_state_;
  DerivativeCalculation derivatives_;
  AdvanceCalculation advance_;
  std::vector<PeriodicUpdate> periodic_updates_;
  std::vector<UpdateCalculation> init_updates_;
  std::vector<Parameter> parameters_;
};

}  // namespace cbbg
