#include "cbbg/framework/block.h"

#include <cxxabi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <typeinfo>

#include "cbbg/framework/diagram.h"
#include "cbbg/framework/names.h"

namespace cbbg {

std::string Port::path() const { return block_->path() + "." + name_; }

Block::Block(std::string name) : name_(std::move(name)) {
  check_name("block", name_, "block name");
}

Block::~Block() = default;

std::string Block::type_name() const {
  const char* mangled = typeid(*this).name();
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> demangled(
      abi::__cxa_demangle(mangled, nullptr, nullptr, &status), std::free);
  std::string type = status == 0 ? demangled.get() : mangled;
  // Namespaces go, template arguments stay: "cbbg::blocks::Actor" -> "Actor".
  const auto arguments = type.find('<');
  const auto last_scope = type.rfind("::", arguments);
  return last_scope == std::string::npos ? type : type.substr(last_scope + 2);
}

std::string Block::path() const {
  return parent_ == nullptr ? name_ : parent_->path() + "/" + name_;
}

const InputPort& Block::input_port(int index) const {
  if (index < 0 || index >= num_input_ports()) {
    throw std::out_of_range("block '" + path() + "' has no input port with index " +
                            std::to_string(index) + "; it has " +
                            std::to_string(num_input_ports()));
  }
  return inputs_[static_cast<std::size_t>(index)];
}

const OutputPort& Block::output_port(int index) const {
  if (index < 0 || index >= num_output_ports()) {
    throw std::out_of_range("block '" + path() + "' has no output port with index " +
                            std::to_string(index) + "; it has " +
                            std::to_string(num_output_ports()));
  }
  return outputs_[static_cast<std::size_t>(index)];
}

namespace {

template <typename Ports>
std::string list_names(const Ports& ports) {
  if (ports.empty()) return "(none)";
  std::string names;
  for (const auto& port : ports) names += (names.empty() ? "" : ", ") + port.name();
  return names;
}

}  // namespace

const InputPort* Block::find_input_port(std::string_view name) const {
  for (const auto& port : inputs_) {
    if (port.name() == name) return &port;
  }
  return nullptr;
}

const OutputPort* Block::find_output_port(std::string_view name) const {
  for (const auto& port : outputs_) {
    if (port.name() == name) return &port;
  }
  return nullptr;
}

std::string Block::input_port_names() const { return list_names(inputs_); }
std::string Block::output_port_names() const { return list_names(outputs_); }

const InputPort& Block::input_port(std::string_view name) const {
  if (const InputPort* port = find_input_port(name)) return *port;
  throw std::invalid_argument("block '" + path() + "' has no input port '" + std::string(name) +
                              "'; its input ports are: " + list_names(inputs_));
}

const OutputPort& Block::output_port(std::string_view name) const {
  if (const OutputPort* port = find_output_port(name)) return *port;
  throw std::invalid_argument("block '" + path() + "' has no output port '" + std::string(name) +
                              "'; its output ports are: " + list_names(outputs_));
}

const std::vector<int>& Block::output_reads(int output_index) const {
  return output_reads_.at(static_cast<std::size_t>(output_index));
}

int Block::parameter_index(std::string_view name) const {
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    if (parameters_[i].name == name) return static_cast<int>(i);
  }
  std::string names;
  for (const auto& parameter : parameters_) {
    names += (names.empty() ? "" : ", ") + parameter.name;
  }
  throw std::invalid_argument("block '" + path() + "' has no parameter '" + std::string(name) +
                              "'; its parameters are: " + (names.empty() ? "(none)" : names));
}

void Block::check_new_port_name(const std::string& name, int size) const {
  check_name("block '" + path() + "'", name, "port name");
  if (size < 1) {
    throw std::invalid_argument("block '" + path() + "': port '" + name + "' has size " +
                                std::to_string(size) + "; a port has at least 1 element");
  }
}

const InputPort& Block::declare_input_port(std::string name, int size, std::string description) {
  check_new_port_name(name, size);
  for (const auto& port : inputs_) {
    if (port.name() == name) {
      throw std::invalid_argument("block '" + path() + "' already has an input port '" + name +
                                  "'");
    }
  }
  return inputs_.emplace_back(*this, num_input_ports(), std::move(name), size,
                              std::move(description));
}

const OutputPort& Block::declare_output_port(std::string name, int size, OutputFunction calc,
                                             std::vector<const InputPort*> reads,
                                             std::string description, OutputSources sources) {
  return declare_output(std::move(name), size, OutputCalculation::callable(std::move(calc)),
                        std::move(reads), std::move(description), sources);
}

const OutputPort& Block::declare_output(std::string name, int size, OutputCalculation calc,
                                        std::vector<const InputPort*> reads,
                                        std::string description, OutputSources sources) {
  check_new_port_name(name, size);
  for (const auto& port : outputs_) {
    if (port.name() == name) {
      throw std::invalid_argument("block '" + path() + "' already has an output port '" + name +
                                  "'");
    }
  }
  std::vector<int> read_indices;
  for (const InputPort* input : reads) {
    if (input == nullptr || &input->block() != this) {
      throw std::invalid_argument("block '" + path() + "': output '" + name +
                                  "' lists as read an input port of another block");
    }
    read_indices.push_back(input->index());
  }
  output_calculations_.push_back(std::move(calc));
  output_reads_.push_back(std::move(read_indices));
  output_sources_.push_back(sources);
  return outputs_.emplace_back(*this, num_output_ports(), std::move(name), size,
                               std::move(description));
}

int Block::declare_parameter(std::string name, Vector default_value) {
  check_name("block '" + path() + "'", name, "parameter name");
  for (const auto& parameter : parameters_) {
    if (parameter.name == name) {
      throw std::invalid_argument("block '" + path() + "' already has a parameter '" + name + "'");
    }
  }
  parameters_.push_back({std::move(name), std::move(default_value)});
  return static_cast<int>(parameters_.size()) - 1;
}

StatePart Block::declare_discrete_state(std::string name, Vector initial_value,
                                        StateLifetime lifetime) {
  check_name("block '" + path() + "'", name, "state part name");
  for (const auto& part : state_parts_) {
    if (part.name == name) {
      throw std::invalid_argument("block '" + path() + "' already has a state part '" + name + "'");
    }
  }
  const auto offset = initial_discrete_state_.size();
  const auto size = initial_value.size();
  initial_discrete_state_.conservativeResize(offset + size);
  initial_discrete_state_.tail(size) = initial_value;
  state_parts_.push_back(
      {std::move(name), static_cast<int>(offset), static_cast<int>(size), lifetime});
  return state_parts_.back();
}

const StatePart& Block::discrete_state_part(std::string_view name) const {
  std::string known;
  for (const auto& part : state_parts_) {
    if (part.name == name) return part;
    known += (known.empty() ? "" : ", ") + part.name;
  }
  throw std::invalid_argument("block '" + path() + "' has no state part '" + std::string(name) +
                              "'; it has: " + (known.empty() ? "none" : known));
}

void Block::declare_periodic_update(double period, double offset, UpdateFunction update,
                                    UpdateWrites writes) {
  declare_periodic(period, offset, UpdateCalculation::callable(std::move(update)), writes);
}

void Block::declare_periodic(double period, double offset, UpdateCalculation update,
                             UpdateWrites writes) {
  if (!std::isfinite(period) || period <= 0.0) {
    throw std::invalid_argument("block '" + path() +
                                "': a periodic update needs a positive, finite period; got " +
                                std::to_string(period));
  }
  if (!std::isfinite(offset) || offset < 0.0) {
    throw std::invalid_argument("block '" + path() +
                                "': a periodic update needs a finite offset >= 0; got " +
                                std::to_string(offset));
  }
  if (writes == UpdateWrites::kInPlace && !periodic_updates_.empty()) {
    throw std::invalid_argument("block '" + path() +
                                "': an update that writes in place must be the block's only "
                                "periodic update");
  }
  if (std::any_of(periodic_updates_.begin(), periodic_updates_.end(),
                  [](const PeriodicUpdate& u) { return u.writes == UpdateWrites::kInPlace; })) {
    throw std::invalid_argument("block '" + path() +
                                "': its update writes in place, so it can have no other "
                                "periodic update");
  }
  periodic_updates_.push_back({period, offset, std::move(update), writes});
}

void Block::declare_initialization_update(UpdateFunction update) {
  init_updates_.push_back(UpdateCalculation::callable(std::move(update)));
}

void Block::check_no_continuous_state() const {
  if (has_continuous_state()) {
    throw std::logic_error("block '" + path() + "' declares its continuous state twice");
  }
}

void Block::declare_continuous_state(Vector initial_value, DerivativeFunction derivatives) {
  declare_derivatives(std::move(initial_value),
                      DerivativeCalculation::callable(std::move(derivatives)));
}

void Block::declare_derivatives(Vector initial_value, DerivativeCalculation derivatives) {
  check_no_continuous_state();
  initial_continuous_state_ = std::move(initial_value);
  derivatives_ = std::move(derivatives);
}

void Block::declare_self_integrated_state(Vector initial_value, AdvanceFunction advance) {
  declare_advance(std::move(initial_value), AdvanceCalculation::callable(std::move(advance)));
}

void Block::declare_advance(Vector initial_value, AdvanceCalculation advance) {
  check_no_continuous_state();
  initial_continuous_state_ = std::move(initial_value);
  advance_ = std::move(advance);
}

}  // namespace cbbg
