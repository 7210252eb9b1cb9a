// A user's own project on the installed cbbg, with no edit of the library: a cart-pole plant,
// a supervisor and tile-coded features of its own, four arms over them, and a protocol of
// its own (a curriculum). The program is
// the `cbbg` command line with these registered, so every command knows them:
//
//   cartpole run --set plant.kind=cartpole --set arms=[tiles,tiles_omega_half] --out R
//   cartpole run ... --grid cartpole.pole_length=0.4,0.6     (a sweep over its own key)
//   cartpole eval --set plant.kind=cartpole --load-weights R/weights/tiles_seed1.txt
//   cartpole run --experiment curriculum --set plant.kind=cartpole --out C
//   cartpole plot R                                          (its arms in the figures)
//   cartpole list                                            (its keys, kind and arms)

#include <cbbg/apps/cli.h>
#include <cbbg/diagrams/arms.h>
#include <cbbg/diagrams/presets.h>

#include "cart_pole.h"
#include "curriculum.h"
#include "lean_supervisor.h"
#include "tile_coding.h"

namespace {

// The cbbg controller with the lean PD as its supervisor and tile coding as its features.
cbbg::diagrams::ControllerOptions tiles_controller() {
  cbbg::diagrams::ControllerOptions options = cbbg::diagrams::preset("cbbg").options;
  options.slots.supervisor = cartpole::make_lean_pd;
  options.slots.features = cartpole::make_tiles;
  return options;
}

void register_arms() {
  cbbg::diagrams::register_arm("tiles", "cbbg with the lean PD and tile coding",
                               tiles_controller());

  cbbg::diagrams::ControllerOptions half = tiles_controller();
  half.omega = cbbg::blocks::OmegaMode::kConstant;  // omega held at 0.5
  half.omega_constant = 0.5;
  cbbg::diagrams::register_arm("tiles_omega_half", "as tiles, omega held at 0.5", half);

  cbbg::diagrams::ControllerOptions frozen = tiles_controller();
  frozen.critic_learns = false;  // the actor learns against a critic that never does
  cbbg::diagrams::register_arm("tiles_critic_frozen", "as tiles, the critic frozen", frozen);

  cbbg::diagrams::ControllerOptions lean_alone = cbbg::diagrams::preset("pd_only").options;
  lean_alone.slots.supervisor = cartpole::make_lean_pd;
  cbbg::diagrams::register_arm("lean_pd", "the lean PD alone, no learning", lean_alone);
}

}  // namespace

int main(int argc, char** argv) {
  // Before any config is made: the sections become keys, the plant a plant.kind.
  cartpole::register_cart_pole();
  cartpole::register_lean_pd();
  cartpole::register_tiles();
  cartpole::register_curriculum();
  register_arms();
  return cbbg::app::run_cli(argc, argv);
}
