#include "cbbg/framework/context.h"

#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>

#include "cbbg/framework/diagram.h"
#include "cbbg/framework/layout.h"

namespace cbbg {

Context::Context(const Diagram& diagram, std::uint64_t root_seed)
    : diagram_(&diagram),
      root_seed_(root_seed),
      signals_(diagram.initial_signals()),
      discrete_(diagram.initial_discrete_states()),
      next_discrete_(diagram.initial_discrete_states()),
      continuous_(diagram.initial_continuous_states()),
      parameters_(diagram.default_parameters()) {
  for (const auto& leaf : diagram.leaves()) {
    generators_.emplace_back(derive_seed(root_seed, leaf.stream_name));
    scratch_.push_back(leaf.block->make_scratch());
  }
}

Context::~Context() = default;

std::unique_ptr<Context> Context::clone() const {
  auto copy = std::make_unique<Context>(*diagram_, root_seed_);
  copy->assign_from(*this);
  return copy;
}

void Context::assign_from(const Context& other) {
  if (other.diagram_ != diagram_) {
    throw std::invalid_argument(
        "assign_from: the source context belongs to another diagram than this one ('" +
        diagram_->path() + "')");
  }
  root_seed_ = other.root_seed_;
  time_ = other.time_;
  signals_ = other.signals_;
  discrete_ = other.discrete_;
  next_discrete_ = other.next_discrete_;
  continuous_ = other.continuous_;
  parameters_ = other.parameters_;
  generators_ = other.generators_;
  for (size_t leaf = 0; leaf < scratch_.size(); ++leaf) {
    scratch_[leaf] = other.scratch_[leaf] ? other.scratch_[leaf]->clone() : nullptr;
  }
}

const LeafLayout& Context::layout_of(const Block& block) const {
  return diagram_->leaves()[static_cast<size_t>(diagram_->leaf_index(block))];
}

VectorView Context::discrete_state(const Block& block) {
  return VectorView(discrete_.data() + layout_of(block).discrete_offset,
                    block.initial_discrete_state().size());
}

ConstVectorView Context::discrete_state(const Block& block) const {
  return ConstVectorView(discrete_.data() + layout_of(block).discrete_offset,
                         block.initial_discrete_state().size());
}

VectorView Context::continuous_state(const Block& block) {
  return VectorView(continuous_.data() + layout_of(block).continuous_offset,
                    block.initial_continuous_state().size());
}

ConstVectorView Context::continuous_state(const Block& block) const {
  return ConstVectorView(continuous_.data() + layout_of(block).continuous_offset,
                         block.initial_continuous_state().size());
}

ConstVectorView Context::parameter(const Block& block, std::string_view name) const {
  const int index = block.parameter_index(name);
  return ConstVectorView(
      parameters_.data() + layout_of(block).parameter_offsets[static_cast<size_t>(index)],
      block.parameters()[static_cast<size_t>(index)].default_value.size());
}

void Context::set_parameter(const Block& block, std::string_view name, const Vector& value) {
  const int index = block.parameter_index(name);
  const auto size = block.parameters()[static_cast<size_t>(index)].default_value.size();
  if (value.size() != size) {
    throw std::invalid_argument("parameter '" + std::string(name) + "' of block '" + block.path() +
                                "' has size " + std::to_string(size) + ", got a value of size " +
                                std::to_string(value.size()));
  }
  parameters_.segment(layout_of(block).parameter_offsets[static_cast<size_t>(index)], size) = value;
}

RandomGenerator& Context::random_generator(const Block& block) {
  return generators_[static_cast<size_t>(layout_of(block).index)];
}

const RandomGenerator& Context::random_generator(const Block& block) const {
  return generators_[static_cast<size_t>(layout_of(block).index)];
}

void Context::reset_state(const Block& block) {
  discrete_state(block) = block.initial_discrete_state();
  continuous_state(block) = block.initial_continuous_state();
}

void Context::reset_all_state() {
  time_ = 0.0;
  discrete_ = diagram_->initial_discrete_states();
  continuous_ = diagram_->initial_continuous_states();
}

void Context::reset_trial_state() {
  time_ = 0.0;
  for (const auto& leaf : diagram_->leaves()) {
    const Vector& initial = leaf.block->initial_discrete_state();
    for (const auto& part : leaf.block->discrete_state_parts()) {
      if (part.lifetime != StateLifetime::kPerTrial) continue;
      discrete_.segment(leaf.discrete_offset + part.offset, part.size) = part.of(initial);
    }
  }
}

namespace {

// Whether two lists of declarations (state parts, parameters) have the same names and sizes,
// in order; `size_of` gives a declaration's size.
template <class List, class SizeOf>
bool same_names_and_sizes(const List& left, const List& right, SizeOf size_of) {
  if (left.size() != right.size()) return false;
  for (std::size_t i = 0; i < left.size(); ++i) {
    if (left[i].name != right[i].name || size_of(left[i]) != size_of(right[i])) return false;
  }
  return true;
}

bool same_parts(const Block& a, const Block& b) {
  return same_names_and_sizes(a.discrete_state_parts(), b.discrete_state_parts(),
                              [](const auto& part) { return part.size; });
}

bool same_parameters(const Block& a, const Block& b) {
  return same_names_and_sizes(a.parameters(), b.parameters(),
                              [](const Parameter& p) { return p.default_value.size(); });
}

// The leaves of `diagram` by their path below its root (LeafLayout::stream_name).
std::unordered_map<std::string_view, const LeafLayout*> leaves_by_path(const Diagram& diagram) {
  std::unordered_map<std::string_view, const LeafLayout*> leaves;
  for (const auto& leaf : diagram.leaves()) leaves[leaf.stream_name] = &leaf;
  return leaves;
}

// Whether the block at `path` is the block at `outer` or inside it.
bool is_within(const std::string& path, const std::string& outer) {
  return path.size() >= outer.size() && path.compare(0, outer.size(), outer) == 0 &&
         (path.size() == outer.size() || path[outer.size()] == '/');
}

}  // namespace

void Context::continue_from(const Context& other) {
  const auto theirs = leaves_by_path(*other.diagram_);
  for (const auto& leaf : diagram_->leaves()) {
    const auto match = theirs.find(leaf.stream_name);
    if (match == theirs.end() || !same_parts(*leaf.block, *match->second->block)) continue;
    const LeafLayout& source = *match->second;
    for (const auto& part : leaf.block->discrete_state_parts()) {
      if (part.lifetime != StateLifetime::kPersistent) continue;
      discrete_.segment(leaf.discrete_offset + part.offset, part.size) =
          other.discrete_.segment(source.discrete_offset + part.offset, part.size);
    }
    generators_[static_cast<size_t>(leaf.index)] =
        other.generators_[static_cast<size_t>(source.index)];
  }
}

void Context::copy_parameters_from(const Context& other, const Block* own) {
  const auto theirs = leaves_by_path(*other.diagram_);
  const std::string own_path = own == nullptr ? std::string() : own->path();
  for (const auto& leaf : diagram_->leaves()) {
    if (own != nullptr && is_within(leaf.block->path(), own_path)) continue;
    const auto match = theirs.find(leaf.stream_name);
    if (match == theirs.end() || !same_parameters(*leaf.block, *match->second->block)) continue;
    const LeafLayout& source = *match->second;
    for (std::size_t i = 0; i < leaf.parameter_offsets.size(); ++i) {
      const auto size = leaf.block->parameters()[i].default_value.size();
      parameters_.segment(leaf.parameter_offsets[i], size) =
          other.parameters_.segment(source.parameter_offsets[i], size);
    }
  }
}

void Context::reseed(std::uint64_t root_seed) {
  root_seed_ = root_seed;
  for (const auto& leaf : diagram_->leaves()) {
    generators_[static_cast<size_t>(leaf.index)].seed(derive_seed(root_seed, leaf.stream_name));
  }
}

bool Context::generators_at_seed() const {
  for (const auto& leaf : diagram_->leaves()) {
    const RandomGenerator seeded(derive_seed(root_seed_, leaf.stream_name));
    if (generators_[static_cast<size_t>(leaf.index)] != seeded) return false;
  }
  return true;
}

void Context::fix_input(const InputPort& diagram_input, const Vector& value) {
  if (&diagram_input.block() != diagram_) {
    throw std::invalid_argument("fix_input: '" + diagram_input.path() +
                                "' is not an input port of the root diagram '" + diagram_->path() +
                                "'");
  }
  if (value.size() != diagram_input.size()) {
    throw std::invalid_argument("fix_input: input '" + diagram_input.path() + "' has size " +
                                std::to_string(diagram_input.size()) + ", got a value of size " +
                                std::to_string(value.size()));
  }
  signals_.segment(diagram_->root_input_offset(diagram_input.index()), value.size()) = value;
}

ConstVectorView Context::signal(const OutputPort& port) const {
  return ConstVectorView(signals_.data() + diagram_->signal_offset(port), port.size());
}

}  // namespace cbbg
