#include "cbbg/framework/simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/numeric/odeint.hpp>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/interrupt.h"
#include "cbbg/framework/short_vectors.h"

namespace cbbg {
namespace odeint = boost::numeric::odeint;

namespace {

constexpr double kSimultaneous = 1e-9;  // relative tolerance for simultaneous events
constexpr double kFirstStep = 1e-3;     // the integrator's first trial step, s

bool same_instant(double a, double b) {
  return std::abs(a - b) <= kSimultaneous * std::max(1.0, std::abs(b));
}

// The first k with offset + k period at or after `now` (an instant simultaneous with now
// counts as now).
long long first_event_index(double period, double offset, double now) {
  const double k = std::ceil((now - offset) / period);
  long long next = std::max(0LL, static_cast<long long>(k));
  // Step back where rounding skipped an instant that is simultaneous with now.
  if (next > 0 && same_instant(offset + static_cast<double>(next - 1) * period, now)) --next;
  return next;
}

}  // namespace

// The error-controlled Dormand–Prince 5(4) stepper of Boost.Odeint over the
// simulator-integrated prefix of the continuous state. Kept across intervals, so its
// buffers are sized once and its step size carries over.
struct Simulator::Integrator {
  using State = std::vector<double>;
  using Stepper = odeint::controlled_runge_kutta<odeint::runge_kutta_dopri5<State>>;

  explicit Integrator(double accuracy, int size)
      : stepper(Stepper::error_checker_type(accuracy, accuracy)),
        state(static_cast<size_t>(size)) {}

  Stepper stepper;
  State state;
  double step = kFirstStep;  // the step the controller proposed last
};

Simulator::Simulator(const Diagram& diagram, SimulatorOptions options, std::uint64_t root_seed)
    : Simulator(diagram, diagram.create_context(root_seed), options) {}

Simulator::Simulator(const Diagram& diagram, std::unique_ptr<Context> context,
                     SimulatorOptions options)
    : diagram_(&diagram), context_(std::move(context)), options_(options) {
  if (!context_ || &context_->diagram() != &diagram) {
    throw std::invalid_argument("Simulator: the context does not belong to diagram '" +
                                diagram.path() + "'");
  }
  if (!std::isfinite(options.accuracy) || options.accuracy <= 0.0) {
    throw std::invalid_argument("Simulator: accuracy must be positive and finite; got " +
                                std::to_string(options.accuracy));
  }
  integrator_ = std::make_unique<Integrator>(options.accuracy, diagram.ode_size());
}

Simulator::~Simulator() = default;

SignalLog& Simulator::add_log(const OutputPort& port, double period, double offset) {
  const int signal_offset = diagram_->signal_offset(port);  // throws unless in this diagram
  SignalLog& log = logs_.emplace_back(port, period, offset);
  log_offsets_.push_back(signal_offset);
  if (initialized_) {
    // Joins a running schedule: only the new log's samples are added, nothing fires again.
    group_of(period, offset, first_event_index(period, offset, context_->time()))
        .logs.push_back(static_cast<int>(logs_.size()) - 1);
    find_next_event();
  }
  return log;
}

void Simulator::check_root_inputs() const {
  for (int port = 0; port < diagram_->num_input_ports(); ++port) {
    const auto value = context_->signals().segment(diagram_->root_input_offset(port),
                                                   diagram_->input_port(port).size());
    if (value.hasNaN()) {
      throw std::invalid_argument("simulate: input '" + diagram_->input_port(port).path() +
                                  "' of the root diagram has no value; set it with "
                                  "Context::fix_input");
    }
  }
}

Simulator::EventGroup& Simulator::group_of(double period, double offset, long long next) {
  for (EventGroup& group : groups_) {
    if (group.period == period && group.offset == offset && group.next == next) return group;
  }
  return groups_.emplace_back(EventGroup{period, offset, next, {}, {}, {}});
}

void Simulator::schedule_events() {
  groups_.clear();
  const double now = context_->time();
  for (const auto& leaf : diagram_->leaves()) {
    const auto& updates = leaf.block->periodic_updates();
    for (const auto& update : updates) {
      group_of(update.period, update.offset, first_event_index(update.period, update.offset, now))
          .updates.emplace_back(leaf.index, &update.update);
    }
  }
  for (size_t l = 0; l < logs_.size(); ++l) {
    const double period = logs_[l].period();
    const double offset = logs_[l].offset();
    group_of(period, offset, first_event_index(period, offset, now))
        .logs.push_back(static_cast<int>(l));
  }
  find_next_event();
}

void Simulator::find_next_event() {
  next_event_ = std::numeric_limits<double>::infinity();
  for (const auto& group : groups_) next_event_ = std::min(next_event_, group.next_time());
}

SimulationStatus Simulator::run_updates(const Updates& updates, const UpdatePlan& plan) {
  if (options_.schedule == Schedule::kInterpreted) return run_interpreted_updates(updates);
  SimulationStatus status;
  const char* reason = CompiledSchedule::run_updates(plan, &status.terminated_by);
  if (reason != nullptr) {
    status.terminated = true;
    status.reason = reason;
  }
  check_discrete_state_finite(CompiledSchedule::first_non_finite_state(plan));
  return status;
}

SimulationStatus Simulator::run_interpreted_updates(const Updates& updates) {
  Context& context = *context_;
  context.next_discrete_states() = context.discrete_states();
  SimulationStatus status;
  for (const auto& [leaf_index, update] : updates) {
    const LeafLayout& leaf = diagram_->leaves()[static_cast<size_t>(leaf_index)];
    BlockContext view(context, leaf);
    const EventStatus result =
        (*update)(view, VectorView(context.next_discrete_states().data() + leaf.discrete_offset,
                                   leaf.block->initial_discrete_state().size()));
    if (result.terminates() && !status.terminated) {
      status.terminated = true;
      status.terminated_by = leaf.block;
      status.reason = result.reason();
    }
  }
  // Swapped, not copied back: the two buffers trade places at every instant.
  context.discrete_states().swap(context.next_discrete_states());
  check_discrete_state_finite(first_non_finite_state(updates));
  return status;
}

void Simulator::evaluate_outputs() {
  if (options_.schedule == Schedule::kCompiled) {
    compiled_.evaluate_outputs();
  } else {
    diagram_->evaluate_outputs(*context_);
  }
}

void Simulator::check_discrete_state_finite(const Block* culprit) const {
  if (culprit != nullptr) {
    throw SimulationError(
        "block '" + culprit->path() +
        "': discrete state became non-finite at t = " + std::to_string(context_->time()));
  }
}

const Block* Simulator::first_non_finite_state(const Updates& updates) const {
  // One vectorised pass over the whole state on every instant; the search for the block
  // only when it fails.
  const Vector& state = context_->discrete_states();
  if (all_finite(state.data(), state.size())) return nullptr;
  for (const auto& [leaf_index, update] : updates) {
    const LeafLayout& leaf = diagram_->leaves()[static_cast<size_t>(leaf_index)];
    const auto size = leaf.block->initial_discrete_state().size();
    if (!context_->discrete_states().segment(leaf.discrete_offset, size).allFinite()) {
      return leaf.block;
    }
  }
  return nullptr;
}

SimulationStatus Simulator::initialize() {
  check_root_inputs();
  terminated_ = false;
  // The step size is integrator memory, not state: forgetting it makes a run a function of
  // its context alone, so a restart from a stored context repeats bit for bit.
  integrator_->step = kFirstStep;
  schedule_events();
  due_updates_.clear();
  for (const auto& leaf : diagram_->leaves()) {
    for (const auto& update : leaf.block->initialization_updates()) {
      due_updates_.emplace_back(leaf.index, &update);
    }
  }
  last_status_ = SimulationStatus{};
  // Initialisation updates always copy the state (an in-place promise is the periodic
  // update's), so they run interpreted, before the plan is laid out on the storage they swap.
  if (!due_updates_.empty()) {
    diagram_->evaluate_outputs(*context_);
    last_status_ = run_interpreted_updates(due_updates_);
  }
  if (options_.schedule == Schedule::kCompiled) {
    compiled_.compile(*diagram_, *context_);
    plan_groups();
  }
  last_status_.time = context_->time();
  terminated_ = last_status_.terminated;
  initialized_ = true;
  return last_status_;
}

void Simulator::plan_groups() {
  for (EventGroup& group : groups_) compiled_.plan(group.updates, group.plan);
}

SimulationStatus Simulator::handle_events(double time) {
  ++num_event_instants_;
  evaluate_outputs();
  if (groups_.size() == 1) return handle_single_group(time);
  const EventGroup* due = nullptr;  // the one group due, unless groups coincide
  bool coincide = false;            // then due_updates_ lists their updates
  next_event_ = std::numeric_limits<double>::infinity();  // found in the same pass
  for (EventGroup& group : groups_) {
    if (same_instant(group.next_time(), time)) {
      ++group.next;
      record_logs(group, time);
      if (!group.updates.empty() && due == nullptr) {
        due = &group;
      } else if (!group.updates.empty()) {
        if (!coincide) due_updates_.assign(due->updates.begin(), due->updates.end());
        due_updates_.insert(due_updates_.end(), group.updates.begin(), group.updates.end());
        coincide = true;
      }
    }
    next_event_ = std::min(next_event_, group.next_time());
  }
  if (due == nullptr) return SimulationStatus{};
  if (!coincide) return run_updates(due->updates, due->plan);
  // Coinciding groups run in leaf order, each leaf's updates in declaration order (an
  // update's calculation lives in its leaf's array, so the pointers order them).
  std::sort(due_updates_.begin(), due_updates_.end());
  if (options_.schedule == Schedule::kCompiled) compiled_.plan(due_updates_, due_plan_);
  return run_updates(due_updates_, due_plan_);
}

SimulationStatus Simulator::handle_single_group(double time) {
  // A single-rate diagram: its one group is due whenever an instant is.
  EventGroup& group = groups_.front();
  ++group.next;
  next_event_ = group.next_time();
  if (!group.logs.empty()) record_logs(group, time);
  if (group.updates.empty()) return SimulationStatus{};
  return run_updates(group.updates, group.plan);
}

void Simulator::record_logs(const EventGroup& group, double time) {
  for (const int l : group.logs) {
    logs_[static_cast<size_t>(l)].record(
        time, context_->signals().data() + log_offsets_[static_cast<size_t>(l)]);
  }
}

SimulationStatus Simulator::advance_to(double end_time) {
  if (!std::isfinite(end_time)) {
    throw std::invalid_argument("advance_to: the end time must be finite; got " +
                                std::to_string(end_time));
  }
  if (!initialized_) {
    initialize();
  }
  Context& context = *context_;
  while (!terminated_ && context.time() < end_time) {
    poll_interrupt();  // between instants: what it throws leaves the simulation consistent
    const double event_time = next_event_;
    if (same_instant(event_time, context.time())) {
      context.set_time(event_time);
      last_status_ = handle_events(event_time);
      if (last_status_.terminated) {
        terminated_ = true;
        break;
      }
      continue;
    }
    integrate_to(std::min(event_time, end_time));
  }
  last_status_.time = context.time();
  return last_status_;
}

void Simulator::integrate_to(double end_time) {
  Context& context = *context_;
  if (context.continuous_states().size() == 0) {  // a discrete diagram: time only moves on
    context.set_time(end_time);
    return;
  }
  const double start_time = context.time();
  if (options_.schedule == Schedule::kCompiled) {
    // What holds still over the interval, once; the stages compute the rest.
    compiled_.evaluate_interval_inputs();
    if (!diagram_->self_integrating_leaves().empty()) compiled_.evaluate_stage_inputs();
  } else if (!diagram_->self_integrating_leaves().empty()) {
    diagram_->evaluate_continuous_inputs(context);
  }
  for (const int index : diagram_->self_integrating_leaves()) {
    const LeafLayout& leaf = diagram_->leaves()[static_cast<size_t>(index)];
    BlockContext view(context, leaf);
    leaf.block->advance_calculation()(view, end_time);
    context.set_time(start_time);
  }
  if (diagram_->ode_size() > 0) integrate_ode(start_time, end_time);
  context.set_time(end_time);
  check_continuous_state_finite();
}

void Simulator::integrate_ode(double start_time, double end_time) {
  Context& context = *context_;
  Integrator& integrator = *integrator_;
  const Diagram& diagram = *diagram_;
  const int size = diagram.ode_size();
  std::copy_n(context.continuous_states().data(), size, integrator.state.begin());
  // Dormand–Prince reuses the last stage of a step as the first of the next (FSAL); an
  // event may have changed the inputs since, so the first derivative is computed afresh.
  integrator.stepper.reset();

  // The right-hand side writes the trial state into the context, recomputes the outputs the
  // integrated blocks read, and asks each for its derivatives.
  const CompiledSchedule* compiled =
      options_.schedule == Schedule::kCompiled ? &compiled_ : nullptr;
  auto derivatives = [&context, &diagram, compiled, size](const Integrator::State& x,
                                                          Integrator::State& dxdt, double t) {
    // Eigen's copy loop: a call to memmove costs more than these few values.
    VectorView(context.continuous_states().data(), size) = ConstVectorView(x.data(), size);
    context.set_time(t);
    if (compiled != nullptr) {
      compiled->evaluate_stage_inputs();
      compiled->compute_derivatives(dxdt.data());
      return;
    }
    diagram.evaluate_continuous_inputs(context);
    for (const int index : diagram.ode_leaves()) {
      const LeafLayout& leaf = diagram.leaves()[static_cast<size_t>(index)];
      const BlockContext view(context, leaf);
      leaf.block->derivative_calculation()(
          view, VectorView(dxdt.data() + leaf.continuous_offset,
                           leaf.block->initial_continuous_state().size()));
    }
  };

  double t = start_time;
  double step = std::min(integrator.step, end_time - start_time);
  while (t < end_time) {
    const bool last = t + step >= end_time;
    if (last) step = end_time - t;
    const double proposed_before = integrator.step;
    const auto result = integrator.stepper.try_step(derivatives, integrator.state, t, step);
    if (result == odeint::success) {
      if (last) {
        t = end_time;
        // A step shortened to land on the event says nothing about the right step size.
        integrator.step = std::max(step, proposed_before);
      } else {
        integrator.step = step;
      }
    } else if (step < options_.min_step) {
      std::copy_n(integrator.state.begin(), size, context.continuous_states().data());
      std::string blocks;
      for (const int index : diagram.ode_leaves()) {
        blocks += (blocks.empty() ? "'" : ", '") +
                  diagram.leaves()[static_cast<size_t>(index)].block->path() + "'";
      }
      throw SimulationError("the integrator cannot meet accuracy " +
                            std::to_string(options_.accuracy) + " at t = " + std::to_string(t) +
                            ": its step fell below " + std::to_string(options_.min_step) +
                            " s (blocks " + blocks + ")");
    }
  }
  std::copy_n(integrator.state.begin(), size, context.continuous_states().data());
}

void Simulator::check_continuous_state_finite() const {
  const Vector& state = context_->continuous_states();
  if (state.allFinite()) return;
  for (const auto& leaf : diagram_->leaves()) {
    const auto size = leaf.block->initial_continuous_state().size();
    if (size > 0 && !state.segment(leaf.continuous_offset, size).allFinite()) {
      throw SimulationError(
          "block '" + leaf.block->path() +
          "': continuous state became non-finite at t = " + std::to_string(context_->time()));
    }
  }
}

}  // namespace cbbg
