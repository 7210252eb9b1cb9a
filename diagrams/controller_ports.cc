#include "cbbg/diagrams/controller_ports.h"

#include <stdexcept>

#include "cbbg/blocks/measured_signals.h"

namespace cbbg::diagrams {
namespace {

std::string path_of(const blocks::Learner& learner) { return learner.learner_block().path(); }
std::string path_of(const Block& block) { return block.path(); }

// Sets `slot` to `found` (the block `block`), refusing a second learner of the same kind.
template <typename L>
void keep_learner(const L*& slot, const L* found, const Block& block, const Diagram& controller,
                  const char* kind) {
  if (slot != nullptr) {
    throw std::invalid_argument("controller '" + controller.name() + "' has two " + kind + "s ('" +
                                path_of(*slot) + "' and '" + block.path() +
                                "'); a closed loop keeps the weights of one");
  }
  slot = found;
}

// Adds what `diagram`, a part of `controller`, holds to `survey`.
void survey_blocks(const Diagram& diagram, const Diagram& controller, ControllerSurvey& survey) {
  LearnerBlocks& found = survey.learner;
  for (const auto& block : diagram.blocks()) {
    if (const auto* shaping = dynamic_cast<const blocks::DescribesLayout*>(block.get())) {
      const blocks::FeatureLayout entries = shaping->layout();
      survey.layout.insert(survey.layout.end(), entries.begin(), entries.end());
      if (std::string note = shaping->layout_note(); !note.empty()) {
        survey.layout_notes.push_back(std::move(note));
      }
    }
    if (block->is_diagram()) {
      survey_blocks(static_cast<const Diagram&>(*block), controller, survey);
    } else if (const auto* learner = dynamic_cast<const blocks::Learner*>(block.get())) {
      const bool critic = learner->learner_role() == blocks::Learner::Role::kCritic;
      keep_learner(critic ? found.critic : found.actor, learner, *block, controller,
                   critic ? "critic" : "actor");
    } else if (const auto* tropism = dynamic_cast<const blocks::Tropism*>(block.get())) {
      keep_learner(found.tropism, tropism, *block, controller, "tropism");
    }
  }
}

void check_port_size(const Diagram& controller, const char* kind, const char* name, int size,
                     int wanted) {
  if (size == wanted) return;
  throw std::invalid_argument("controller '" + controller.name() + "': its " + kind + " \"" + name +
                              "\" has size " + std::to_string(size) + "; it must be " +
                              std::to_string(wanted));
}

}  // namespace

void check_controller_ports(const Diagram& controller) {
  const OutputPort* action = controller.find_output_port("action");
  if (action == nullptr || action->size() != 1) {
    throw std::invalid_argument("controller '" + controller.name() +
                                "' must have an output \"action\" of size 1; its outputs are: " +
                                controller.output_port_names());
  }
  const InputPort* measured = controller.find_input_port("measured");
  if (measured == nullptr) {
    throw std::invalid_argument("controller '" + controller.name() +
                                "' must have an input \"measured\" of size 6; its inputs are: " +
                                controller.input_port_names());
  }
  for (int i = 0; i < controller.num_input_ports(); ++i) {
    const InputPort& input = controller.input_port(i);
    const std::string& name = input.name();
    if (name == "measured") {
      check_port_size(controller, "input", "measured", input.size(), blocks::kMeasuredSize);
    } else if (name == "reward" || name == "failed") {
      check_port_size(controller, "input", name.c_str(), input.size(), 1);
    } else {
      throw std::invalid_argument(
          "controller '" + controller.name() + "' has an input \"" + name +
          "\" the closed loop does not feed; it feeds \"measured\" (6), \"reward\" (1) and "
          "\"failed\" (1)");
    }
  }
  for (const char* name : kControllerDiagnostics) {
    if (const OutputPort* output = controller.find_output_port(name)) {
      check_port_size(controller, "output", name, output->size(), 1);
    }
  }
  if (const OutputPort* own = controller.find_output_port("reward")) {
    check_port_size(controller, "output", "reward", own->size(), 1);
  }
}

ControllerSurvey survey_controller(const Diagram& controller) {
  ControllerSurvey survey;
  survey_blocks(controller, controller, survey);
  return survey;
}

}  // namespace cbbg::diagrams
