#include "cbbg/diagrams/slot_check.h"

#include <stdexcept>

namespace cbbg::diagrams {

void check_slot_block(const Block* block, const std::string& owner, const char* input,
                      const char* output, int output_size) {
  if (block == nullptr) throw std::invalid_argument(owner + ": the slot's block is null");
  const bool inputs_fit =
      input == nullptr ? block->num_input_ports() == 0
                       : block->num_input_ports() == 1 && block->input_port(0).name() == input;
  const bool fits = inputs_fit && block->num_output_ports() == 1 &&
                    block->output_port(0).name() == output &&
                    (output_size <= 0 || block->output_port(0).size() == output_size);
  if (fits) return;
  const std::string sized = output_size > 0 ? " of size " + std::to_string(output_size) : "";
  const std::string inputs =
      input == nullptr ? "no input" : "one input \"" + std::string(input) + "\"";
  throw std::invalid_argument(owner + ": the block '" + block->name() + "' must have " + inputs +
                              " and one output \"" + output + "\"" + sized);
}

}  // namespace cbbg::diagrams
