#pragma once
// Features of the user's own in the basal ganglia's features slot: tile coding of the
// normalised (theta, theta') over [-3, 3]^2, `tilings` grids of per_axis x per_axis tiles,
// each offset by 1/tilings of a tile. Its layout (tiles.*) goes with its learnt weights, so a
// weights file is loaded only into the same tiles.

#include <algorithm>
#include <memory>
#include <string>

#include <cbbg/blocks/feature_layout.h>
#include <cbbg/config/declared_keys.h>
#include <cbbg/framework/block.h>
#include <cbbg/framework/block_context.h>

namespace cartpole {

struct TileParams {
  long long tilings = 4;
  long long per_axis = 6;

  static constexpr const char* kSection = "tiles";
  template <class Archive>
  void describe(Archive& a) {
    a.integer("tilings", tilings, "offset grids of tiles", cbbg::interval(1, 32));
    a.integer("per_axis", per_axis, "tiles per axis of each grid", cbbg::interval(1, 64));
  }
};

/// TileCoding: input "x" (2, the normaliser's output), output "features" (tilings per_axis^2):
/// in each grid, the tile holding x is 1 / tilings, the rest 0.
class TileCoding final : public cbbg::Block, public cbbg::blocks::DescribesLayout {
 public:
  TileCoding(std::string name, const TileParams& p)
      : Block(std::move(name)),
        p_(p),
        n_(static_cast<int>(p.per_axis)),
        grids_(static_cast<int>(p.tilings)) {
    x_ = &declare_input_port("x", 2);
    declare_output_port<&TileCoding::calc_features>("features", grids_ * n_ * n_, {x_});
  }

  cbbg::blocks::FeatureLayout layout() const override { return cbbg::blocks::declared_layout(p_); }

 private:
  // "features": in each grid, 1 / tilings at the tile holding x.
  void calc_features(const cbbg::BlockContext& context, cbbg::VectorRef phi) const {
    const int n = n_, grids = grids_;
    const auto v = context.input(*x_);
    phi.setZero();
    for (int g = 0; g < grids; ++g) {
      const double offset = static_cast<double>(g) / grids;  // in tiles
      auto tile = [n, offset](double value) {
        const int i = static_cast<int>((value + 3.0) / 6.0 * n + offset);
        return std::clamp(i, 0, n - 1);
      };
      phi[g * n * n + tile(v[0]) * n + tile(v[1])] = 1.0 / grids;
    }
  }

  TileParams p_;
  int n_;      // tiles per axis
  int grids_;  // tilings
  const cbbg::InputPort* x_;
};

inline void register_tiles() { cbbg::config::register_section<TileParams>(TileParams::kSection); }

inline std::unique_ptr<cbbg::Block> make_tiles(const std::string& name,
                                               const cbbg::parameters::Parameters& p) {
  return std::make_unique<TileCoding>(
      name, cbbg::config::read_section<TileParams>(p.own, TileParams::kSection));
}

}  // namespace cartpole
