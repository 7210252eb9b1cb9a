#pragma once
// Simulator: advances a Context of a root Diagram through time.
//
// Step semantics (tested in tests/framework/simulator_test.cc):
//  1. initialize() runs every block's initialization updates once, resets the integrator's
//     step size (a run depends on its context alone), then schedules periodic
//     events: an event of period p and offset o fires at t = o + k p, for the integers k with
//     o + k p >= the context's time at initialize(). Events whose times agree within
//     1e-9 * max(1, |t|) are simultaneous.
//  2. At an event instant t, in this order: (a) every output is evaluated from the state at
//     t; (b) logs due at t record those values; (c) every update due at t runs, reading the
//     values of (a) and the discrete state from before any update at t; (d) all new discrete
//     states are committed at once; (e) if an update returned EventStatus::terminate, the
//     simulation stops at t, after (d).
//  3. Between instants, continuous state advances with inputs recomputed from the committed
//     discrete state. A discrete block's output therefore holds its value (zero-order hold)
//     from the instant its state changes until the next one. Simulator-integrated blocks
//     share one error-controlled Dormand–Prince integrator (Boost.Odeint) at
//     options.accuracy; self-integrating blocks advance themselves over the same interval.
//  4. advance_to(t_end) fires the events at instants before t_end and integrates up to
//     t_end; events at exactly t_end fire at the start of the next advance_to, so
//     advance_to(a); advance_to(b) equals advance_to(b).
// A non-finite state (continuous after an interval, discrete after an update), or an
// integrator that cannot meet its accuracy, throws SimulationError naming the block.

#include <deque>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cbbg/framework/compiled_schedule.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/signal_log.h"

namespace cbbg {

// A simulation that cannot go on: non-finite state, or the integrator failing.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A simulation stopped from outside the model, which did nothing wrong: a block that drives a
// robot over a link lost it, or was asked to stop (SIGINT). A trial so stopped is neither a
// success nor a failure of what it tested.
class SimulationStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How the simulator walks the diagram at each tick; both compute the same values, bit for bit.
enum class Schedule {
  // A flat plan laid out at initialize() (compiled_schedule.h): the default.
  kCompiled,
  // The diagram's tables walked at every tick, the whole discrete state copied at every
  // instant: the simple way, kept to compare against (bench/framework).
  kInterpreted,
};

struct SimulatorOptions {
  // Relative and absolute error tolerance of the continuous integrator.
  double accuracy = 1e-6;
  // The integrator gives up (SimulationError) when its step falls below this.
  double min_step = 1e-12;
  Schedule schedule = Schedule::kCompiled;
};

struct SimulationStatus {
  bool terminated = false;  // true where an update ended the simulation
  double time = 0.0;        // the context's time on return
  const Block* terminated_by = nullptr;
  const char* reason = "";  // the update's reason for terminating
};

class Simulator {
 public:
  // Simulates a fresh context of `diagram` made with `root_seed`.
  explicit Simulator(const Diagram& diagram, SimulatorOptions options = {},
                     std::uint64_t root_seed = 0);
  // Simulates `context`, which must belong to `diagram`.
  Simulator(const Diagram& diagram, std::unique_ptr<Context> context,
            SimulatorOptions options = {});
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  const Diagram& diagram() const { return *diagram_; }
  Context& context() { return *context_; }
  const Context& context() const { return *context_; }
  const SimulatorOptions& options() const { return options_; }

  // Runs initialization updates and schedules events from the context's time. advance_to
  // calls it the first time; call it again after resetting the context for a new run.
  SimulationStatus initialize();
  SimulationStatus advance_to(double end_time);

  // Records `port` (an output of any block in the diagram) every `period` from `offset`.
  // The reference stays valid for the simulator's life.
  SignalLog& add_log(const OutputPort& port, double period, double offset = 0.0);
  const std::deque<SignalLog>& logs() const { return logs_; }

  // Event instants handled since construction (for tests and benchmarks).
  long long num_event_instants() const { return num_event_instants_; }

 private:
  // The events of one period, offset and next instant: they always fire together, so the
  // updates and logs due at an instant are listed once, at initialize(), not every tick.
  struct EventGroup {
    double period;
    double offset;
    long long next;   // fires next at offset + next * period
    Updates updates;  // in leaf order, each leaf's in declaration order
    UpdatePlan plan;  // the updates laid out for the compiled schedule
    std::vector<int> logs;
    double next_time() const { return offset + static_cast<double>(next) * period; }
  };
  struct Integrator;

  void check_root_inputs() const;
  void schedule_events();
  // The earliest instant of any group, into next_event_ (handle_events keeps it as it goes).
  void find_next_event();
  SimulationStatus handle_events(double time);
  // handle_events for a diagram whose events form one group: no search, no merge.
  SimulationStatus handle_single_group(double time);
  void record_logs(const EventGroup& group, double time);
  void integrate_to(double end_time);
  void integrate_ode(double start_time, double end_time);
  void check_continuous_state_finite() const;
  // The group of (period, offset, next), added at the end if there is none.
  EventGroup& group_of(double period, double offset, long long next);
  // Throws naming `culprit`, the first updated block whose state is not finite, if any.
  void check_discrete_state_finite(const Block* culprit) const;
  // The interpreted schedule's search: the first updated leaf whose state is not finite.
  const Block* first_non_finite_state(const Updates& updates) const;
  // Runs the updates of one group (`plan` laid out from `updates` for the compiled schedule).
  SimulationStatus run_updates(const Updates& updates, const UpdatePlan& plan);
  SimulationStatus run_interpreted_updates(const Updates& updates);
  // Lays out each group's updates for the compiled schedule.
  void plan_groups();
  void evaluate_outputs();

  const Diagram* diagram_;
  std::unique_ptr<Context> context_;
  SimulatorOptions options_;
  std::deque<SignalLog> logs_;
  std::vector<int> log_offsets_;  // each log's port in the signals, resolved once
  std::vector<EventGroup> groups_;
  double next_event_ = 0.0;
  Updates due_updates_;  // initialization updates, or those of groups due together
  UpdatePlan due_plan_;  // due_updates_ laid out, when groups coincide
  std::unique_ptr<Integrator> integrator_;
  CompiledSchedule compiled_;  // laid out at initialize() when options_.schedule is kCompiled
  bool initialized_ = false;
  bool terminated_ = false;
  SimulationStatus last_status_;
  long long num_event_instants_ = 0;
};

}  // namespace cbbg
