#pragma once
// BlockContext: one leaf block's view of a Context, handed to its output, update, derivative
// and advance functions. Everything is a view into the context's storage: no copies.

#include <cassert>

#include "cbbg/framework/context.h"
#include "cbbg/framework/layout.h"
#include "cbbg/framework/port.h"
#include "cbbg/framework/types.h"

namespace cbbg {

class BlockContext {
 public:
  BlockContext(Context& context, const LeafLayout& layout) : context_(&context), layout_(&layout) {}

  double time() const { return context_->time(); }

  ConstVectorView input(int index) const {
    const auto i = static_cast<size_t>(index);
    return ConstVectorView(context_->signals().data() + layout_->input_offsets[i],
                           layout_->input_sizes[i]);
  }
  ConstVectorView input(const InputPort& port) const { return input(port.index()); }
  // The same with the size fixed at compile time, for a port the block declared of that size:
  // Eigen then unrolls what reads it (a plant's torques). The size is the block's promise,
  // checked in debug builds only.
  template <int Size>
  Eigen::Map<const Eigen::Matrix<double, Size, 1>> input(const InputPort& port) const {
    const auto i = static_cast<size_t>(port.index());
    assert(layout_->input_sizes[i] == Size);
    return Eigen::Map<const Eigen::Matrix<double, Size, 1>>(context_->signals().data() +
                                                            layout_->input_offsets[i]);
  }

  // In an update: this block's own output `port` as evaluated at this instant (every output
  // is evaluated before any update runs, simulator.h step 2), so an update can use a value
  // its outputs already computed instead of computing it again.
  ConstVectorView output(const OutputPort& port) const {
    const auto i = static_cast<size_t>(port.index());
    return ConstVectorView(context_->signals().data() + layout_->output_offsets[i],
                           layout_->output_sizes[i]);
  }

  ConstVectorView discrete_state() const {
    return ConstVectorView(context_->discrete_states().data() + layout_->discrete_offset,
                           layout_->block->initial_discrete_state().size());
  }
  ConstVectorView continuous_state() const {
    return ConstVectorView(context_->continuous_states().data() + layout_->continuous_offset,
                           layout_->block->initial_continuous_state().size());
  }
  // The same with the size fixed at compile time (checked in debug builds only).
  template <int Size>
  Eigen::Map<const Eigen::Matrix<double, Size, 1>> continuous_state() const {
    assert(layout_->block->initial_continuous_state().size() == Size);
    return Eigen::Map<const Eigen::Matrix<double, Size, 1>>(context_->continuous_states().data() +
                                                            layout_->continuous_offset);
  }
  ConstVectorView parameter(int index) const {
    const auto size = layout_->block->parameters()[static_cast<size_t>(index)].default_value.size();
    return ConstVectorView(
        context_->parameters().data() + layout_->parameter_offsets[static_cast<size_t>(index)],
        size);
  }

  // For updates and self-integrating blocks only (their BlockContext is not const).
  RandomGenerator& random_generator() { return context_->random_generator(layout_->index); }
  VectorView mutable_continuous_state() {
    return VectorView(context_->continuous_states().data() + layout_->continuous_offset,
                      layout_->block->initial_continuous_state().size());
  }
  // The block's scratch, of the type its make_scratch returns.
  template <typename Scratch>
  Scratch& scratch() {
    return static_cast<Scratch&>(*context_->scratch(layout_->index));
  }

 private:
  Context* context_;
  const LeafLayout* layout_;
};

}  // namespace cbbg
