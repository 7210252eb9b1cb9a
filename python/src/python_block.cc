#include "python_block.h"

#include <pybind11/stl.h>

#include <algorithm>

#include "event_reasons.h"
#include "python_errors.h"

namespace cbbg::python {
namespace {

py::array_t<double> copy_of(const double* data, Eigen::Index size) {
  py::array_t<double> array(static_cast<py::ssize_t>(size));
  std::copy(data, data + size, array.mutable_data());
  return array;
}

std::string describe_block(const Block& block) {
  return "block '" + block.path() + "' (" + block.type_name() + ")";
}

// The array a callable wrote, back into the context, which must have kept its size.
void copy_back(const py::array_t<double>& array, VectorRef destination, const Block& block,
               const std::string& role) {
  if (array.ndim() != 1 || array.shape(0) != destination.size()) {
    throw BlockCallbackError(
        describe_block(block) + ", " + role +
        ": the array it was given changed shape; write into it (out[:] = ...)");
  }
  std::copy(array.data(), array.data() + destination.size(), destination.data());
}

// What a callable that writes an array returned: nothing.
void expect_none(const py::object& result, const Block& block, const std::string& role) {
  if (!result.is_none()) {
    throw BlockCallbackError(describe_block(block) + ", " + role +
                             ": returned a value; write into the array it is given (out[:] = ...)");
  }
}

// What an update returned: None (carry on) or an EventStatus.
EventStatus event_status_of(const py::object& result, const Block& block, const std::string& role) {
  if (result.is_none()) return EventStatus::succeeded();
  if (py::isinstance<EventStatus>(result)) return result.cast<EventStatus>();
  throw BlockCallbackError(describe_block(block) + ", " + role + ": returned " +
                           std::string(py::str(py::type::of(result).attr("__name__"))) +
                           "; an update returns None or cbbg.EventStatus.terminate(reason)");
}

}  // namespace

void CallContext::expire(bool kept) {
  if (kept) path_ = block_->path();
  block_ = nullptr;
  context_ = nullptr;
}

BlockContext& CallContext::context() const {
  if (context_ == nullptr) {
    throw std::logic_error("block '" + path_ +
                           "': a context is valid only during the call it was given to");
  }
  return *context_;
}

void CallContext::check_own(const Port& port) const {
  if (&port.block() != block_) {
    throw std::invalid_argument("block '" + block_->path() + "': port '" + port.path() +
                                "' is not one of its own");
  }
}

// Each method asks for context() first: once the call has returned, the block, its ports
// and the context may all be gone.
py::array_t<double> CallContext::input(const InputPort& port) const {
  const BlockContext& live = context();
  check_own(port);
  const ConstVectorView value = live.input(port);
  return copy_of(value.data(), value.size());
}

py::array_t<double> CallContext::input_named(const std::string& name) const {
  context();
  return input(block_->input_port(name));
}

py::array_t<double> CallContext::output(const OutputPort& port) const {
  const BlockContext& live = context();
  check_own(port);
  const ConstVectorView value = live.output(port);
  return copy_of(value.data(), value.size());
}

py::array_t<double> CallContext::discrete_state() const {
  const ConstVectorView state = context().discrete_state();
  return copy_of(state.data(), state.size());
}

py::array_t<double> CallContext::state_part(const std::string& name) const {
  const ConstVectorView state = context().discrete_state();
  const StatePart& part = block_->discrete_state_part(name);
  return copy_of(state.data() + part.offset, part.size);
}

py::array_t<double> CallContext::continuous_state() const {
  const ConstVectorView state = context().continuous_state();
  return copy_of(state.data(), state.size());
}

py::array_t<double> CallContext::parameter(const std::string& name) const {
  const BlockContext& live = context();
  const ConstVectorView value = live.parameter(block_->parameter_index(name));
  return copy_of(value.data(), value.size());
}

RandomGenerator& CallContext::generator() const {
  BlockContext& live = context();
  if (!may_draw_) {
    throw std::logic_error("block '" + block_->path() +
                           "': only an update draws random numbers (outputs must not change "
                           "the generator)");
  }
  return live.random_generator();
}

double CallContext::random_normal() { return draw_standard_normal(generator()); }

double CallContext::random_uniform() { return draw_uniform(generator()); }

BlockCallable::BlockCallable(const Block& block, py::object callable, std::string role)
    : block_(&block), method_(false), role_(std::move(role)) {
  if (!PyCallable_Check(callable.ptr())) {
    throw std::invalid_argument(describe_block(block) + ", " + role_ + ": " +
                                std::string(py::str(py::repr(callable))) + " is not callable");
  }
  if (py::hasattr(callable, "__self__") && py::hasattr(callable, "__func__") &&
      py::object(callable.attr("__self__")).is(python_object_of(block))) {
    function_ = callable.attr("__func__");
    method_ = true;
  } else {
    function_ = std::move(callable);
  }
}

namespace {

// Expires a CallContext when the call returns or throws. Python holds it still where its
// count is above this one (kept by the callable, or by the frames of a traceback).
class Expiry {
 public:
  explicit Expiry(const std::shared_ptr<CallContext>& context) : context_(context) {}
  ~Expiry() { context_->expire(context_.use_count() > 1); }
  Expiry(const Expiry&) = delete;
  Expiry& operator=(const Expiry&) = delete;

 private:
  const std::shared_ptr<CallContext>& context_;
};

}  // namespace

py::object BlockCallable::operator()(BlockContext& context, py::array_t<double>& array,
                                     bool may_draw) const {
  const auto call_context = std::make_shared<CallContext>(*block_, context, may_draw);
  const Expiry expiry(call_context);
  try {
    return method_ ? function_(python_object_of(*block_), call_context, array)
                   : function_(call_context, array);
  } catch (const py::error_already_set& error) {
    throw_if_interrupt(error);  // KeyboardInterrupt, SystemExit: as they are
    throw BlockCallbackError(
        describe_block(*block_) + ", " + role_ + ": " + python_error_text(error), error);
  }
}

void raise_block_error(py::handle type, const BlockCallbackError& error) {
  PyErr_SetString(type.ptr(), error.what());
  const py::error_already_set* cause = error.cause();
  if (cause == nullptr) return;
  // As `raise BlockError(...) from cause` does: the cause with its traceback, the new
  // exception's __cause__ (and __context__).
  PyObject* raised_type = nullptr;
  PyObject* raised = nullptr;
  PyObject* trace = nullptr;
  PyErr_Fetch(&raised_type, &raised, &trace);
  PyErr_NormalizeException(&raised_type, &raised, &trace);
  const py::object value = cause->value();
  if (cause->trace()) PyException_SetTraceback(value.ptr(), cause->trace().ptr());
  PyException_SetCause(raised, value.inc_ref().ptr());  // each steals a reference
  PyException_SetContext(raised, value.inc_ref().ptr());
  PyErr_Restore(raised_type, raised, trace);
}

py::object python_object_of(const Block& block) {
  return py::cast(&block, py::return_value_policy::reference);
}

std::string python_type_name(const Block& block, const char* fallback) {
  py::gil_scoped_acquire gil;
  const py::object object = python_object_of(block);
  if (!object) return fallback;
  return py::str(py::type::of(object).attr("__name__"));
}

template <class Base>
const OutputPort& PythonBlock<Base>::python_output_port(std::string name, int size, py::object calc,
                                                        const std::vector<const InputPort*>& reads,
                                                        std::string description,
                                                        bool holds_between_events) {
  const BlockCallable& callable = keep(std::move(calc), "its output '" + name + "'");
  OutputFunction output = [this, &callable](const BlockContext& context, VectorRef value) {
    py::gil_scoped_acquire gil;
    py::array_t<double> array = copy_of(value.data(), value.size());
    expect_none(callable(const_cast<BlockContext&>(context), array, false), *this, callable.role());
    copy_back(array, value, *this, callable.role());
  };
  return this->declare_output_port(
      std::move(name), size, std::move(output), reads, std::move(description),
      holds_between_events ? OutputSources::kDiscreteState : OutputSources::kAnything);
}

namespace {

// An update that calls `callable` with a copy of the next state and writes back what it wrote.
UpdateFunction calling_update(const Block& block, const BlockCallable& callable) {
  return [&block, &callable](BlockContext& context, VectorRef next_state) {
    py::gil_scoped_acquire gil;
    py::array_t<double> array = copy_of(next_state.data(), next_state.size());
    const EventStatus status =
        event_status_of(callable(context, array, true), block, callable.role());
    copy_back(array, next_state, block, callable.role());
    return status;
  };
}

}  // namespace

template <class Base>
void PythonBlock<Base>::python_periodic_update(double period, double offset, py::object update) {
  const BlockCallable& callable = keep(std::move(update), "its periodic update");
  this->declare_periodic_update(period, offset, calling_update(*this, callable));
}

template <class Base>
void PythonBlock<Base>::python_initialization_update(py::object update) {
  const BlockCallable& callable = keep(std::move(update), "its initialization update");
  this->declare_initialization_update(calling_update(*this, callable));
}

template <class Base>
void PythonBlock<Base>::python_continuous_state(const Vector& initial, py::object derivatives) {
  const BlockCallable& callable = keep(std::move(derivatives), "its derivatives");
  this->declare_continuous_state(initial, [this, &callable](const BlockContext& context,
                                                            VectorRef derivative) {
    py::gil_scoped_acquire gil;
    py::array_t<double> array = copy_of(derivative.data(), derivative.size());
    expect_none(callable(const_cast<BlockContext&>(context), array, false), *this, callable.role());
    copy_back(array, derivative, *this, callable.role());
  });
}

template class PythonBlock<Block>;
template class PythonBlock<plant::RobotPlant>;

void PythonRobotPlant::reset(Context& context, double initial_pitch) const {
  try {
    PYBIND11_OVERRIDE_PURE(void, plant::RobotPlant, reset, &context, initial_pitch);
  } catch (const py::error_already_set& error) {
    const py::gil_scoped_acquire gil;
    throw_if_interrupt(error);
    throw BlockCallbackError(describe_block(*this) + ", its reset: " + python_error_text(error),
                             error);
  }
}

// An exception of signals(), logged_signals() or wheel_radius() crosses as it is, an interrupt
// as one.
std::vector<std::string> PythonRobotPlant::signals() const {
  try {
    PYBIND11_OVERRIDE(std::vector<std::string>, plant::RobotPlant, signals, );
  } catch (const py::error_already_set& error) {
    const py::gil_scoped_acquire gil;
    throw_if_interrupt(error);
    throw;
  }
}

std::vector<std::string> PythonRobotPlant::logged_signals() const {
  try {
    PYBIND11_OVERRIDE(std::vector<std::string>, plant::RobotPlant, logged_signals, );
  } catch (const py::error_already_set& error) {
    const py::gil_scoped_acquire gil;
    throw_if_interrupt(error);
    throw;
  }
}

double PythonRobotPlant::wheel_radius() const {
  try {
    PYBIND11_OVERRIDE(double, plant::RobotPlant, wheel_radius, );
  } catch (const py::error_already_set& error) {
    const py::gil_scoped_acquire gil;
    throw_if_interrupt(error);
    throw;
  }
}

}  // namespace cbbg::python
