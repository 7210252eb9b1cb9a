#include "cbbg/framework/diagram.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cbbg/framework/block_context.h"

namespace cbbg {

Diagram::~Diagram() {
  for (const auto& child : blocks_) child->parent_ = nullptr;
}

const Block& Diagram::block(std::string_view name) const {
  for (const auto& child : blocks_) {
    if (child->name() == name) return *child;
  }
  std::string names;
  for (const auto& child : blocks_) names += (names.empty() ? "" : ", ") + child->name();
  throw std::invalid_argument("diagram '" + path() + "' has no block '" + std::string(name) +
                              "'; its blocks are: " + (names.empty() ? "(none)" : names));
}

int Diagram::leaf_index(const Block& leaf) const {
  const auto found = leaf_index_.find(&leaf);
  if (found == leaf_index_.end()) {
    throw std::invalid_argument("block '" + leaf.path() + "' is not a leaf block of diagram '" +
                                path() + "'");
  }
  return found->second;
}

OutputSlot Diagram::resolve_output(const OutputPort& port) const {
  if (port.block().is_diagram()) {
    const auto& inner = static_cast<const Diagram&>(port.block());
    return resolve_output(*inner.exported_outputs_[static_cast<size_t>(port.index())]);
  }
  return {leaf_index(port.block()), port.index()};
}

int Diagram::signal_offset(const OutputPort& port) const {
  const OutputSlot slot = resolve_output(port);
  return leaves_[static_cast<size_t>(slot.leaf)].output_offsets[static_cast<size_t>(slot.port)];
}

std::unique_ptr<Context> Diagram::create_context(std::uint64_t root_seed) const {
  return std::make_unique<Context>(*this, root_seed);
}

void Diagram::evaluate(Context& context, const std::vector<OutputSlot>& order) const {
  double* signals = context.signals().data();
  for (const OutputSlot& slot : order) {
    const LeafLayout& leaf = leaves_[static_cast<size_t>(slot.leaf)];
    const BlockContext view(context, leaf);
    const auto port = static_cast<size_t>(slot.port);
    leaf.block->output_calculation(slot.port)(
        view, VectorView(signals + leaf.output_offsets[port], leaf.output_sizes[port]));
  }
}

void Diagram::evaluate_outputs(Context& context) const { evaluate(context, evaluation_order_); }

void Diagram::evaluate_continuous_inputs(Context& context) const {
  evaluate(context, continuous_input_order_);
}

ConstVectorView Diagram::eval_output(Context& context, const OutputPort& port) const {
  evaluate_outputs(context);
  return context.signal(port);
}

// ---- Flattening, run once by DiagramBuilder::build --------------------------------------

void Diagram::finalize() {
  leaves_.clear();
  leaf_index_.clear();
  collect_leaves(*this);
  assign_signal_offsets();
  sort_outputs();
  check_continuous_coupling_and_schedule();
  split_continuous_inputs();
  assign_state_offsets();
}

void Diagram::collect_leaves(const Diagram& diagram) {
  for (const auto& child : diagram.blocks_) {
    if (child->is_diagram()) {
      collect_leaves(static_cast<const Diagram&>(*child));
      continue;
    }
    LeafLayout layout;
    layout.block = child.get();
    layout.index = static_cast<int>(leaves_.size());
    layout.stream_name = child->path().substr(path().size() + 1);
    leaf_index_[child.get()] = layout.index;
    leaves_.push_back(std::move(layout));
  }
}

Diagram::InputSource Diagram::resolve_input(const InputPort& port) const {
  const auto& owner = *port.block().parent();
  if (const auto source = owner.source_of_.find(&port); source != owner.source_of_.end()) {
    InputSource result;
    result.output = resolve_output(*source->second);
    return result;
  }
  for (const auto& fixed : owner.fixed_inputs_) {
    if (fixed.port == &port) {
      InputSource result;
      result.fixed = &fixed;
      return result;
    }
  }
  const auto exported = owner.exported_input_of_.find(&port);
  if (exported == owner.exported_input_of_.end()) {
    throw std::logic_error("input '" + port.path() + "' has no source after build");
  }
  if (&owner == this) {
    InputSource result;
    result.root_input = exported->second;
    return result;
  }
  return resolve_input(owner.input_port(exported->second));
}

Diagram::InputOrigin Diagram::origin_of(const InputPort& port) const {
  const InputSource source = resolve_input(port);
  InputOrigin origin;
  if (source.fixed != nullptr) {
    origin.fixed = &source.fixed->value;
  } else if (source.root_input >= 0) {
    origin.diagram_input = source.root_input;
  } else {
    origin.output =
        &leaves_[static_cast<size_t>(source.output.leaf)].block->output_port(source.output.port);
  }
  return origin;
}

void Diagram::assign_signal_offsets() {
  int size = 0;
  first_node_.assign(leaves_.size(), 0);
  num_nodes_ = 0;
  for (auto& leaf : leaves_) {
    first_node_[static_cast<size_t>(leaf.index)] = num_nodes_;
    num_nodes_ += leaf.block->num_output_ports();
    leaf.output_offsets.clear();
    leaf.output_sizes.clear();
    for (int port = 0; port < leaf.block->num_output_ports(); ++port) {
      leaf.output_offsets.push_back(size);
      leaf.output_sizes.push_back(leaf.block->output_port(port).size());
      size += leaf.output_sizes.back();
    }
  }
  root_input_offsets_.clear();
  for (int port = 0; port < num_input_ports(); ++port) {
    root_input_offsets_.push_back(size);
    size += input_port(port).size();
  }
  // Fixed values get a slot each, after the outputs and root inputs.
  std::vector<std::pair<int, const Vector*>> fixed_slots;
  input_sources_.assign(leaves_.size(), {});
  for (auto& leaf : leaves_) {
    auto& sources = input_sources_[static_cast<size_t>(leaf.index)];
    leaf.input_offsets.clear();
    leaf.input_sizes.clear();
    for (int port = 0; port < leaf.block->num_input_ports(); ++port) {
      leaf.input_sizes.push_back(leaf.block->input_port(port).size());
      const InputSource source = resolve_input(leaf.block->input_port(port));
      sources.push_back(source);
      if (source.output.leaf >= 0) {
        leaf.input_offsets.push_back(leaves_[static_cast<size_t>(source.output.leaf)]
                                         .output_offsets[static_cast<size_t>(source.output.port)]);
      } else if (source.root_input >= 0) {
        leaf.input_offsets.push_back(root_input_offsets_[static_cast<size_t>(source.root_input)]);
      } else {
        leaf.input_offsets.push_back(size);
        fixed_slots.emplace_back(size, &source.fixed->value);
        size += static_cast<int>(source.fixed->value.size());
      }
    }
  }
  initial_signals_ = Vector::Zero(size);
  for (int port = 0; port < num_input_ports(); ++port) {
    initial_signals_
        .segment(root_input_offsets_[static_cast<size_t>(port)], input_port(port).size())
        .setConstant(std::numeric_limits<double>::quiet_NaN());
  }
  for (const auto& [offset, value] : fixed_slots) {
    initial_signals_.segment(offset, value->size()) = *value;
  }
}

void Diagram::sort_outputs() {
  // Depth-first search from every output to the outputs it reads through direct
  // feedthrough; post-order is a valid evaluation order, and a grey node reached again closes
  // an algebraic loop.
  enum Colour : char { kWhite, kGrey, kBlack };
  std::vector<char> colour(static_cast<size_t>(num_nodes_), kWhite);
  struct Frame {
    OutputSlot slot;
    size_t next_read;  // position in output_reads of the next dependency to visit
  };
  std::vector<Frame> stack;
  evaluation_order_.clear();

  auto loop_message = [&](size_t first_frame, OutputSlot closing_source) {
    // Frames [first_frame, end) run downstream to upstream; print them in data-flow order.
    std::string message =
        "algebraic loop (outputs that read each other through direct "
        "feedthrough): ";
    const Block* closing_block = leaves_[static_cast<size_t>(closing_source.leaf)].block;
    message += closing_block->output_port(closing_source.port).path();
    for (size_t k = stack.size(); k-- > first_frame;) {
      const Frame& frame = stack[k];
      const Block* block = leaves_[static_cast<size_t>(frame.slot.leaf)].block;
      const int input = block->output_reads(frame.slot.port)[frame.next_read - 1];
      message += " -> " + block->input_port(input).path() + " -> " +
                 block->output_port(frame.slot.port).path();
    }
    return message;
  };

  for (const auto& leaf : leaves_) {
    for (int port = 0; port < leaf.block->num_output_ports(); ++port) {
      const OutputSlot root{leaf.index, port};
      if (colour[static_cast<size_t>(node_of(root))] != kWhite) continue;
      colour[static_cast<size_t>(node_of(root))] = kGrey;
      stack.push_back({root, 0});
      while (!stack.empty()) {
        Frame& frame = stack.back();
        const Block* block = leaves_[static_cast<size_t>(frame.slot.leaf)].block;
        const auto& reads = block->output_reads(frame.slot.port);
        if (frame.next_read == reads.size()) {
          colour[static_cast<size_t>(node_of(frame.slot))] = kBlack;
          evaluation_order_.push_back(frame.slot);
          stack.pop_back();
          continue;
        }
        const int input = reads[frame.next_read++];
        const InputSource& source =
            input_sources_[static_cast<size_t>(frame.slot.leaf)][static_cast<size_t>(input)];
        if (source.output.leaf < 0) continue;  // a fixed value or a root input
        const auto node = static_cast<size_t>(node_of(source.output));
        if (colour[node] == kBlack) continue;
        if (colour[node] == kGrey) {
          size_t first = stack.size() - 1;
          while (stack[first].slot.leaf != source.output.leaf ||
                 stack[first].slot.port != source.output.port) {
            --first;
          }
          throw std::invalid_argument("build: diagram '" + path() +
                                      "': " + loop_message(first, source.output));
        }
        colour[node] = kGrey;
        stack.push_back({source.output, 0});
      }
    }
  }
}

void Diagram::mark_upstream(OutputSlot slot, std::vector<char>& marked) const {
  const auto node = static_cast<size_t>(node_of(slot));
  if (marked[node]) return;
  marked[node] = 1;
  const Block* block = leaves_[static_cast<size_t>(slot.leaf)].block;
  for (const int input : block->output_reads(slot.port)) {
    const InputSource& source =
        input_sources_[static_cast<size_t>(slot.leaf)][static_cast<size_t>(input)];
    if (source.output.leaf >= 0) mark_upstream(source.output, marked);
  }
}

void Diagram::check_continuous_coupling_and_schedule() {
  const auto num_nodes = static_cast<size_t>(num_nodes_);
  std::vector<char> needed(num_nodes, 0);
  for (const auto& leaf : leaves_) {
    const Block& block = *leaf.block;
    if (!block.has_continuous_state()) continue;
    for (int input = 0; input < block.num_input_ports(); ++input) {
      const InputSource& source =
          input_sources_[static_cast<size_t>(leaf.index)][static_cast<size_t>(input)];
      if (source.output.leaf < 0) continue;
      std::vector<char> upstream(num_nodes, 0);
      mark_upstream(source.output, upstream);
      for (const auto& other : leaves_) {
        const Block& other_block = *other.block;
        if (!other_block.has_continuous_state()) continue;
        bool reached = false;
        for (int port = 0; port < other_block.num_output_ports(); ++port) {
          reached = reached || upstream[static_cast<size_t>(node_of({other.index, port}))];
        }
        if (!reached) continue;
        if (block.integrates_itself()) {
          throw std::invalid_argument(
              "build: diagram '" + path() + "': block '" + block.path() +
              "' integrates its own continuous state, so its inputs must hold still between "
              "events, but input '" +
              block.input_port(input).path() +
              "' depends through direct feedthrough on the continuous state of '" +
              other_block.path() + "'; sample it through a discrete block (a zero-order hold)");
        }
        if (other_block.integrates_itself()) {
          throw std::invalid_argument(
              "build: diagram '" + path() + "': input '" + block.input_port(input).path() +
              "' depends through direct feedthrough on '" + other_block.path() +
              "', which integrates its own continuous state and cannot be integrated jointly "
              "with '" +
              block.path() + "'; sample it through a discrete block (a zero-order hold)");
        }
      }
      for (size_t node = 0; node < num_nodes; ++node) needed[node] |= upstream[node];
    }
  }
  continuous_input_order_.clear();
  for (const OutputSlot& slot : evaluation_order_) {
    if (needed[static_cast<size_t>(node_of(slot))]) continuous_input_order_.push_back(slot);
  }
}

void Diagram::split_continuous_inputs() {
  // In evaluation order an output's sources come before it, so one pass decides every node.
  std::vector<char> holds_still(static_cast<size_t>(num_nodes_), 0);
  for (const OutputSlot& slot : evaluation_order_) {
    const Block& block = *leaves_[static_cast<size_t>(slot.leaf)].block;
    bool still = block.output_sources(slot.port) == OutputSources::kDiscreteState;
    for (const int input : block.output_reads(slot.port)) {
      const InputSource& source =
          input_sources_[static_cast<size_t>(slot.leaf)][static_cast<size_t>(input)];
      if (source.output.leaf >= 0)
        still = still && holds_still[static_cast<size_t>(node_of(source.output))];
    }
    holds_still[static_cast<size_t>(node_of(slot))] = still ? 1 : 0;
  }
  interval_input_order_.clear();
  stage_input_order_.clear();
  for (const OutputSlot& slot : continuous_input_order_) {
    (holds_still[static_cast<size_t>(node_of(slot))] ? interval_input_order_ : stage_input_order_)
        .push_back(slot);
  }
}

void Diagram::assign_state_offsets() {
  int discrete = 0;
  int parameters = 0;
  ode_leaves_.clear();
  self_integrating_leaves_.clear();
  for (auto& leaf : leaves_) {
    const Block& block = *leaf.block;
    leaf.discrete_offset = discrete;
    discrete += static_cast<int>(block.initial_discrete_state().size());
    leaf.parameter_offsets.clear();
    for (const auto& parameter : block.parameters()) {
      leaf.parameter_offsets.push_back(parameters);
      parameters += static_cast<int>(parameter.default_value.size());
    }
    if (block.has_continuous_state()) {
      (block.integrates_itself() ? self_integrating_leaves_ : ode_leaves_).push_back(leaf.index);
    }
  }
  // Simulator-integrated states first, so the integrator works on one contiguous prefix.
  int continuous = 0;
  for (const int index : ode_leaves_) {
    leaves_[static_cast<size_t>(index)].continuous_offset = continuous;
    continuous += static_cast<int>(
        leaves_[static_cast<size_t>(index)].block->initial_continuous_state().size());
  }
  ode_size_ = continuous;
  for (const int index : self_integrating_leaves_) {
    leaves_[static_cast<size_t>(index)].continuous_offset = continuous;
    continuous += static_cast<int>(
        leaves_[static_cast<size_t>(index)].block->initial_continuous_state().size());
  }

  initial_discrete_ = Vector::Zero(discrete);
  initial_continuous_ = Vector::Zero(continuous);
  default_parameters_ = Vector::Zero(parameters);
  for (const auto& leaf : leaves_) {
    const Block& block = *leaf.block;
    initial_discrete_.segment(leaf.discrete_offset, block.initial_discrete_state().size()) =
        block.initial_discrete_state();
    initial_continuous_.segment(leaf.continuous_offset, block.initial_continuous_state().size()) =
        block.initial_continuous_state();
    for (size_t p = 0; p < block.parameters().size(); ++p) {
      default_parameters_.segment(leaf.parameter_offsets[p],
                                  block.parameters()[p].default_value.size()) =
          block.parameters()[p].default_value;
    }
  }
}

}  // namespace cbbg
