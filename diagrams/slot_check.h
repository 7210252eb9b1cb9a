#pragma once
// What a block must offer to fill a slot of a subsystem: one input (or none) and one output
// of the names the slot wires.

#include <string>

#include "cbbg/framework/block.h"

namespace cbbg::diagrams {

// Throws std::invalid_argument naming `owner` (say "cerebellum 'cb'") and the block unless
// `block` is non-null with exactly one input named `input` (no input when `input` is null)
// and one output named `output` (of size `output_size`, when it is positive).
void check_slot_block(const Block* block, const std::string& owner, const char* input,
                      const char* output, int output_size = 0);

}  // namespace cbbg::diagrams
