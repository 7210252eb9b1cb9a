#pragma once
// A block written in Python: PythonBlock<Base> makes a Block (or a RobotPlant) whose ports,
// state, parameters and events a Python subclass declares with Python callables.
//
// The callables run with the GIL held (the simulator may run in a worker thread with the GIL
// released: each call takes it, so Python calls of parallel runs are serialised). They see a
// CallContext, valid during the call only, and write fresh NumPy arrays that are copied back
// when they return, so nothing a callable keeps can reach a context's memory later.
//
// A callable that is a method of the block itself is kept unbound and called with the block's
// Python object: a bound method would hold the object from inside its own C++ part, a cycle
// Python's collector cannot see.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/plant/robot_plant.h"

namespace cbbg::python {

namespace py = pybind11;

// An exception a Python block raised, or a callable's bad return, while the library ran it:
// the message names the block's path, its type and the callable ("its output 'action'").
// Python sees it as cbbg.BlockError, the exception the block raised as its __cause__.
class BlockCallbackError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  BlockCallbackError(const std::string& message, const py::error_already_set& cause)
      : std::runtime_error(message), cause_(std::make_shared<py::error_already_set>(cause)) {}
  // The Python exception behind it, or null (a bad return).
  const py::error_already_set* cause() const { return cause_.get(); }

 private:
  std::shared_ptr<const py::error_already_set> cause_;  // shared: copies need no GIL
};

// Raises `error` in Python as an exception of `type` (cbbg.BlockError), from its cause.
void raise_block_error(py::handle type, const BlockCallbackError& error);

// The view of one leaf's context a Python callable gets; every method throws once the call
// has returned (std::logic_error: RuntimeError), without touching the block or the context,
// which may be gone by then.
class CallContext {
 public:
  CallContext(const Block& block, BlockContext& context, bool may_draw)
      : block_(&block), context_(&context), may_draw_(may_draw) {}

  double time() const { return context().time(); }
  py::array_t<double> input(const InputPort& port) const;
  py::array_t<double> input_named(const std::string& name) const;
  py::array_t<double> output(const OutputPort& port) const;
  py::array_t<double> discrete_state() const;
  py::array_t<double> state_part(const std::string& name) const;
  py::array_t<double> continuous_state() const;
  py::array_t<double> parameter(const std::string& name) const;
  double random_normal();
  double random_uniform();

  // Called when the callable returns; `kept`: Python holds it still, so it keeps the block's
  // path for its message.
  void expire(bool kept);

 private:
  // The context during the call; throws afterwards.
  BlockContext& context() const;
  void check_own(const Port& port) const;
  // The block's generator, for an update; throws for an output or derivatives.
  RandomGenerator& generator() const;

  const Block* block_;     // null once expired
  BlockContext* context_;  // null once expired
  std::string path_;       // the block's, once expired
  bool may_draw_;          // updates only: outputs and derivatives must not change a generator
};

// A callable a block declared, kept unbound when it is one of the block's own methods.
class BlockCallable {
 public:
  BlockCallable(const Block& block, py::object callable, std::string role);
  // Calls it as callable(context, array) with the GIL held; any Python exception becomes a
  // BlockCallbackError naming the block and the role.
  py::object operator()(BlockContext& context, py::array_t<double>& array, bool may_draw) const;
  const std::string& role() const { return role_; }

 private:
  const Block* block_;
  py::object function_;
  bool method_;  // function_ is the unbound function of a method of the block
  std::string role_;
};

// The Python object of `block` (registered by pybind11 when Python made it).
py::object python_object_of(const Block& block);
// The name Python gives the block's class, for type_name().
std::string python_type_name(const Block& block, const char* fallback);

// Declarations a Python subclass makes, public here; Base is Block or plant::RobotPlant.
template <class Base>
class PythonBlock : public Base {
 public:
  explicit PythonBlock(std::string name) : Base(std::move(name)) {}
  ~PythonBlock() override {
    py::gil_scoped_acquire gil;  // the callables are Python objects
    callables_.clear();
  }

  std::string type_name() const override { return python_type_name(*this, "LeafBlock"); }

  const InputPort& python_input_port(std::string name, int size, std::string description) {
    return this->declare_input_port(std::move(name), size, std::move(description));
  }
  const OutputPort& python_output_port(std::string name, int size, py::object calc,
                                       const std::vector<const InputPort*>& reads,
                                       std::string description, bool holds_between_events);
  StatePart python_discrete_state(std::string name, const Vector& initial, bool per_trial) {
    return this->declare_discrete_state(
        std::move(name), initial,
        per_trial ? StateLifetime::kPerTrial : StateLifetime::kPersistent);
  }
  int python_parameter(std::string name, const Vector& default_value) {
    return this->declare_parameter(std::move(name), default_value);
  }
  void python_periodic_update(double period, double offset, py::object update);
  void python_initialization_update(py::object update);
  void python_continuous_state(const Vector& initial, py::object derivatives);

 private:
  const BlockCallable& keep(py::object callable, std::string role) {
    callables_.push_back(
        std::make_unique<BlockCallable>(*this, std::move(callable), std::move(role)));
    return *callables_.back();
  }

  std::vector<std::unique_ptr<BlockCallable>> callables_;
};

using PythonLeafBlock = PythonBlock<Block>;

// A plant written in Python: reset, and optionally signals, logged_signals and wheel_radius,
// are overridden
// in Python.
class PythonRobotPlant : public PythonBlock<plant::RobotPlant> {
 public:
  using PythonBlock<plant::RobotPlant>::PythonBlock;
  std::string type_name() const override { return python_type_name(*this, "RobotPlant"); }
  void reset(Context& context, double initial_pitch) const override;
  std::vector<std::string> signals() const override;
  std::vector<std::string> logged_signals() const override;
  double wheel_radius() const override;
};

}  // namespace cbbg::python
