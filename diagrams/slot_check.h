#pragma once
// What a block must offer to fill a slot of a subsystem, and the check of it at build.

#include <string>
#include <vector>

#include "cbbg/framework/block.h"

namespace cbbg::diagrams {

// Throws std::invalid_argument naming `owner` (say "cerebellum 'cb'") and the block unless
// `block` is non-null with exactly one input named `input` (no input when `input` is null)
// and one output named `output` (of size `output_size`, when it is positive).
void check_slot_block(const Block* block, const std::string& owner, const char* input,
                      const char* output, int output_size = 0);

// A port of a slot's contract: its name and size.
struct SlotPort {
  std::string name;
  int size = 1;
};

// A slot's port contract: the inputs the diagram feeds (a block reads any of them and no
// other) and the outputs it reads (a block has each, of that size; more are left unread).
struct SlotContract {
  std::string slot;  // "critic slot", as messages name it
  std::vector<SlotPort> inputs;
  std::vector<SlotPort> outputs;
};

// Throws std::invalid_argument, one line naming the slot, the block, the port and what the
// contract expects, unless `block` is non-null and fits `contract`:
//   critic slot: the block 'critic' has no output "td_error"; it must have outputs
//   "value" (1), "td_error" (1)
//   critic slot: the block 'critic' has an input "features" of size 9; the slot feeds it 49
void check_slot(const Block* block, const SlotContract& contract);

// Connects `source` to the block's input `name` if it reads it (a slot's block reads what
// it needs of what the slot feeds).
template <class Builder, class Port>
void connect_if_read(Builder& builder, const Port& source, const Block& block,
                     const std::string& name) {
  if (const auto* input = block.find_input_port(name)) builder.connect(source, *input);
}

}  // namespace cbbg::diagrams
