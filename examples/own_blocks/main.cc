// Three ablations of the paper's controller from the installed library, each a block of our
// own in one slot, with no rewiring: the critic (visit_critic.h: two learnt parts), the
// exploration (uniform_exploration.h) and the task's reward (pitch_cost_reward.h). The
// program is the `cbbg` command line with the three arms registered, so every command knows
// them:
//
//   own_blocks run --set plant.kind=analytic --set arms=[cbbg,own_critic] --out R
//   own_blocks run --experiment exp3 --set arms=[own_exploration] --out E
//   own_blocks run --resume R
//   own_blocks eval --load-weights R/weights/own_critic_seed1.txt
//
// Each arm keeps the library's block paths, so seed k gives every arm the same random
// streams (common random numbers): the comparisons are paired seed by seed.

#include <memory>

#include <cbbg/apps/cli.h>
#include <cbbg/diagrams/arms.h>
#include <cbbg/diagrams/presets.h>

#include "pitch_cost_reward.h"
#include "uniform_exploration.h"
#include "visit_critic.h"

namespace {

using cbbg::diagrams::ControllerOptions;
using cbbg::diagrams::SlotRequest;

// [docs own-critic]
ControllerOptions paper() { return cbbg::diagrams::preset("cbbg").options; }

void register_own_critic() {
  ControllerOptions options = paper();
  options.slots.critic = [](const SlotRequest& r) {
    return std::make_shared<own_blocks::VisitCritic>(r.name, r.num_features, r.parameters,
                                                     r.learns);
  };
  cbbg::diagrams::register_arm("own_critic", "cbbg with a visit-count TD(0) critic", options);
}
// [docs own-critic end]

// [docs own-exploration-and-reward]
void register_own_exploration() {
  ControllerOptions options = paper();
  options.slots.exploration = [](const std::string& name, const cbbg::parameters::Parameters& p) {
    return std::make_shared<own_blocks::UniformExploration>(name, p);
  };
  cbbg::diagrams::register_arm("own_exploration", "cbbg with uniform exploration", options);
}

void register_own_reward() {
  cbbg::diagrams::TaskSlots task;
  task.reward = [](const std::string& name, const cbbg::parameters::Parameters& p) {
    return std::make_shared<own_blocks::PitchCostReward>(name, p);
  };
  cbbg::diagrams::register_arm("own_reward", "cbbg learning from a pitch cost", paper(), task);
}
// [docs own-exploration-and-reward end]

}  // namespace

int main(int argc, char** argv) {
  register_own_critic();
  register_own_exploration();
  register_own_reward();
  return cbbg::app::run_cli(argc, argv);
}
