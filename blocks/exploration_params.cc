#include "cbbg/blocks/exploration_params.h"

#include <stdexcept>
#include <string>

namespace cbbg::blocks {

ExplorationKind parse_exploration_kind(std::string_view text) {
  if (text == "boltzmann") return ExplorationKind::kBoltzmann;
  if (text == "gaussian") return ExplorationKind::kGaussian;
  if (text == "ou") return ExplorationKind::kOu;
  throw std::invalid_argument("exploration.kind must be boltzmann, gaussian or ou; got '" +
                              std::string(text) + "'");
}

std::string_view to_string(ExplorationKind kind) {
  switch (kind) {
    case ExplorationKind::kGaussian:
      return "gaussian";
    case ExplorationKind::kOu:
      return "ou";
    case ExplorationKind::kBoltzmann:
      break;
  }
  return "boltzmann";
}

void ExplorationParams::validate() const { check_declared(*this, kSection); }

}  // namespace cbbg::blocks
