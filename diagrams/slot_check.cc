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

namespace cbbg::diagrams {
namespace {

std::string ports_text(const std::vector<SlotPort>& ports) {
  std::string text;
  for (const SlotPort& port : ports) {
    text += (text.empty() ? "\"" : ", \"") + port.name + "\" (" + std::to_string(port.size) + ")";
  }
  return text.empty() ? "none" : text;
}

const SlotPort* find_port(const std::vector<SlotPort>& ports, const std::string& name) {
  for (const SlotPort& port : ports) {
    if (port.name == name) return &port;
  }
  return nullptr;
}

}  // namespace

void check_slot(const Block* block, const SlotContract& contract) {
  if (block == nullptr) throw std::invalid_argument(contract.slot + ": the factory returned null");
  const std::string head = contract.slot + ": the block '" + block->name() + "' ";
  for (int i = 0; i < block->num_input_ports(); ++i) {
    const InputPort& input = block->input_port(i);
    const SlotPort* fed = find_port(contract.inputs, input.name());
    if (fed == nullptr) {
      throw std::invalid_argument(head + "has an input \"" + input.name() +
                                  "\" the slot does not feed; it feeds " +
                                  ports_text(contract.inputs));
    }
    if (input.size() != fed->size) {
      throw std::invalid_argument(head + "has an input \"" + input.name() + "\" of size " +
                                  std::to_string(input.size()) + "; the slot feeds it " +
                                  std::to_string(fed->size));
    }
  }
  for (const SlotPort& wanted : contract.outputs) {
    const OutputPort* output = block->find_output_port(wanted.name);
    if (output == nullptr) {
      throw std::invalid_argument(head + "has no output \"" + wanted.name +
                                  "\"; it must have outputs " + ports_text(contract.outputs));
    }
    if (output->size() != wanted.size) {
      throw std::invalid_argument(head + "has an output \"" + wanted.name + "\" of size " +
                                  std::to_string(output->size()) + "; the slot reads " +
                                  std::to_string(wanted.size));
    }
  }
}

}  // namespace cbbg::diagrams
