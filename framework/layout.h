#pragma once
// Where each leaf block's values live in a Context's contiguous storage. Computed once, when
// a root diagram is built; read on every tick.

#include <string>
#include <vector>

namespace cbbg {

class Block;

struct LeafLayout {
  const Block* block = nullptr;
  int index = 0;  // position among the leaves: its generator and scratch
  // The block's path below the root diagram ("controller/basal_ganglia/sampler"): what its
  // random stream is derived from, so diagrams that differ only in their root's name (the
  // arms of a comparison) give a block the same stream.
  std::string stream_name;
  std::vector<int> input_offsets;      // into Context signals, per input port
  std::vector<int> input_sizes;        // per input port (copied here: read on every tick)
  std::vector<int> output_offsets;     // into Context signals, per output port
  std::vector<int> output_sizes;       // per output port
  int discrete_offset = 0;             // into Context discrete state
  int continuous_offset = 0;           // into Context continuous state
  std::vector<int> parameter_offsets;  // into Context parameters, per parameter
};

// One output port of one leaf: a node of the evaluation schedule.
struct OutputSlot {
  int leaf = 0;
  int port = 0;
};

}  // namespace cbbg
