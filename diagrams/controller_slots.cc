#include "cbbg/diagrams/controller_slots.h"

namespace cbbg::diagrams {

SlotContract critic_contract(int num_features) {
  return {"critic slot",
          {{"features", num_features}, {"reward", 1}, {"failed", 1}},
          {{"value", 1}, {"td_error", 1}}};
}

SlotContract actor_contract(int num_features) {
  return {"actor slot",
          {{"features", num_features},
           {"td_error", 1},
           {"supervisor_action", 1},
           {"omega", 1},
           {"exploration_action", 1}},
          {{"actor_action", 1}}};
}

SlotContract exploration_contract() {
  return {
      "exploration slot", {{"actor_action", 1}, {"temperature", 1}}, {{"exploration_action", 1}}};
}

SlotContract tropism_contract() { return {"tropism slot", {{"value", 1}}, {{"temperature", 1}}}; }

SlotContract entropy_contract() { return {"entropy slot", {{"temperature", 1}}, {{"entropy", 1}}}; }

SlotContract mixer_contract() {
  return {"mixer slot",
          {{"exploration_action", 1}, {"supervisor_action", 1}, {"omega", 1}},
          {{"action", 1}}};
}

}  // namespace cbbg::diagrams
