#include "cbbg/framework/diagram_builder.h"

#include <stdexcept>

namespace cbbg {

DiagramBuilder::DiagramBuilder(std::string diagram_name)
    : owned_(new Diagram(std::move(diagram_name))), diagram_(owned_.get()) {}

DiagramBuilder::DiagramBuilder(Diagram& target) : diagram_(&target) {
  if (!target.blocks_.empty() || target.num_input_ports() > 0 || target.num_output_ports() > 0) {
    throw std::logic_error("DiagramBuilder: diagram '" + target.path() +
                           "' is already built; a builder builds into an empty diagram");
  }
}

Diagram& DiagramBuilder::diagram() const {
  if (diagram_ == nullptr) {
    throw std::logic_error("this DiagramBuilder has already built its diagram");
  }
  return *diagram_;
}

void DiagramBuilder::add_block(std::shared_ptr<Block> block) {
  Diagram& parent = diagram();
  if (!block) {
    throw std::invalid_argument("diagram '" + parent.path() + "': cannot add a null block");
  }
  if (block->parent_ != nullptr) {
    throw std::invalid_argument("diagram '" + parent.path() + "': block '" + block->path() +
                                "' is in a diagram already; a block belongs to one diagram");
  }
  for (const auto& child : parent.blocks_) {
    if (child->name() == block->name()) {
      throw std::invalid_argument("diagram '" + parent.path() + "': a block named '" +
                                  block->name() + "' already exists; names must be unique");
    }
  }
  block->parent_ = &parent;
  parent.blocks_.push_back(std::move(block));
}

void DiagramBuilder::check_child(const Block& block, const char* action) const {
  if (block.parent() != &diagram()) {
    throw std::invalid_argument(std::string(action) + ": block '" + block.path() +
                                "' is not in diagram '" + diagram().path() +
                                "'; add it to this builder first");
  }
}

void DiagramBuilder::check_input_free(const InputPort& port, const char* action) const {
  const Diagram& parent = diagram();
  if (const auto source = parent.source_of_.find(&port); source != parent.source_of_.end()) {
    throw std::invalid_argument(std::string(action) + ": input '" + port.path() +
                                "' is already connected from '" + source->second->path() + "'");
  }
  if (const auto exported = parent.exported_input_of_.find(&port);
      exported != parent.exported_input_of_.end()) {
    throw std::invalid_argument(std::string(action) + ": input '" + port.path() +
                                "' is already exported as '" +
                                parent.input_port(exported->second).path() + "'");
  }
  for (const auto& fixed : parent.fixed_inputs_) {
    if (fixed.port == &port) {
      throw std::invalid_argument(std::string(action) + ": input '" + port.path() +
                                  "' is already fixed to a value");
    }
  }
}

void DiagramBuilder::connect(const OutputPort& source, const InputPort& destination) {
  check_child(source.block(), "connect");
  check_child(destination.block(), "connect");
  if (source.size() != destination.size()) {
    throw std::invalid_argument("connect: size mismatch: output '" + source.path() + "' has size " +
                                std::to_string(source.size()) + " but input '" +
                                destination.path() + "' has size " +
                                std::to_string(destination.size()));
  }
  check_input_free(destination, "connect");
  diagram().connections_.push_back({&source, &destination});
  diagram().source_of_[&destination] = &source;
}

void DiagramBuilder::connect(const Block& source, std::string_view output, const Block& destination,
                             std::string_view input) {
  connect(source.output_port(output), destination.input_port(input));
}

const InputPort& DiagramBuilder::export_input(const InputPort& inner, std::string name) {
  check_child(inner.block(), "export_input");
  check_input_free(inner, "export_input");
  Diagram& parent = diagram();
  if (name.empty()) name = inner.name();
  int index = -1;
  for (int port = 0; port < parent.num_input_ports(); ++port) {
    if (parent.input_port(port).name() == name) index = port;
  }
  if (index < 0) {
    index = parent.declare_input_port(name, inner.size(), inner.description()).index();
  } else if (parent.input_port(index).size() != inner.size()) {
    throw std::invalid_argument("export_input: size mismatch: diagram input '" +
                                parent.input_port(index).path() + "' has size " +
                                std::to_string(parent.input_port(index).size()) + " but input '" +
                                inner.path() + "' has size " + std::to_string(inner.size()));
  }
  parent.exported_inputs_.push_back({index, &inner});
  parent.exported_input_of_[&inner] = index;
  return parent.input_port(index);
}

const OutputPort& DiagramBuilder::export_output(const OutputPort& inner, std::string name) {
  check_child(inner.block(), "export_output");
  Diagram& parent = diagram();
  if (name.empty()) name = inner.name();
  for (int port = 0; port < parent.num_output_ports(); ++port) {
    if (parent.output_port(port).name() == name) {
      throw std::invalid_argument("export_output: diagram '" + parent.path() +
                                  "' already has an output port '" + name + "'");
    }
  }
  const OutputPort& port =
      parent.declare_output_port(name, inner.size(), {}, {}, inner.description());
  parent.exported_outputs_.push_back(&inner);
  return port;
}

void DiagramBuilder::fix_input(const InputPort& inner, Vector value) {
  check_child(inner.block(), "fix_input");
  check_input_free(inner, "fix_input");
  if (value.size() != inner.size()) {
    throw std::invalid_argument("fix_input: input '" + inner.path() + "' has size " +
                                std::to_string(inner.size()) + ", got a value of size " +
                                std::to_string(value.size()));
  }
  diagram().fixed_inputs_.push_back({&inner, std::move(value)});
}

std::unique_ptr<Diagram> DiagramBuilder::build() {
  if (!owned_) {
    throw std::logic_error("DiagramBuilder: this builder builds into diagram '" + diagram().path() +
                           "'; call build_into()");
  }
  check_and_finalize();
  return std::move(owned_);
}

void DiagramBuilder::build_into() {
  if (owned_) {
    throw std::logic_error("DiagramBuilder: this builder makes its own diagram; call build()");
  }
  check_and_finalize();
}

void DiagramBuilder::check_and_finalize() {
  Diagram& built = diagram();
  std::string open_inputs;
  for (const auto& child : built.blocks_) {
    for (int index = 0; index < child->num_input_ports(); ++index) {
      const InputPort& port = child->input_port(index);
      bool has_source =
          built.source_of_.count(&port) > 0 || built.exported_input_of_.count(&port) > 0;
      for (const auto& fixed : built.fixed_inputs_) has_source = has_source || fixed.port == &port;
      if (!has_source) {
        open_inputs += (open_inputs.empty() ? "" : "; ") + std::string("input '") + port.path() +
                       "' (size " + std::to_string(port.size()) +
                       ") is neither connected, exported nor fixed";
      }
    }
  }
  if (!open_inputs.empty()) {
    throw std::invalid_argument("build: diagram '" + built.path() + "': " + open_inputs);
  }
  built.finalize();
  diagram_ = nullptr;
}

}  // namespace cbbg
