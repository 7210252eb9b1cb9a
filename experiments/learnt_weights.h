#pragma once
// What a learning arm has learnt: the critic's and the actor's weights with the feature
// layout they were learnt on and where they come from; read from and written into a closed
// loop's context. store/weights_file.h keeps them in files.

#include <string>
#include <vector>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/types.h"

namespace cbbg::experiments {

// Where a set of weights comes from, recorded in the file. The plant kind is checked before
// they are loaded from elsewhere (check_weights_fit).
struct WeightsProvenance {
  std::string arm = "unknown";    // the arm that learnt them (one word)
  long long seed = 0;             // its root seed
  long long trials = 0;           // trials it learnt over
  std::string plant = "unknown";  // plant.kind it learnt on (one word)
  bool operator==(const WeightsProvenance&) const = default;
};

// The weights of the critic (V = w . phi) and the actor (a_A = theta . phi), and the layout
// that gives phi its meaning, as the loop's blocks describe it (blocks/feature_layout.h: the
// normaliser's scales and the RBF grid for the presets, a user's features block's own).
// Weights are only meaningful on the same robot, in a loop of the same layout
// (check_weights_fit).
struct LearntWeights {
  blocks::FeatureLayout layout;
  std::vector<std::string> layout_notes;  // the blocks' notes, for a reader of the file
  Vector actor;                           // theta, one per feature
  Vector critic;                          // w, as many
  WeightsProvenance provenance;

  // The feature count: the actor's weights.
  int num_features() const;
  // The same layout, weights and provenance (the notes are a reader's help only).
  bool operator==(const LearntWeights& other) const;
};

// The weights `loop` has learnt in `context`, with the loop's layout. Throws
// std::invalid_argument when the loop has no critic and actor.
LearntWeights learnt_weights(const diagrams::ClosedLoop& loop, const Context& context,
                             const WeightsProvenance& provenance);

// The one check of weights from elsewhere (a file, a run before) before they are loaded into
// a loop on plant kind `plant_kind` whose blocks describe `layout`. Throws config::ConfigError,
// a line that starts with `what` (store::check_weights: "weights file 'w.txt'"), unless they
// were learnt on the same robot (diagrams::same_robot: the Simbody and the analytic plant are
// one) and for the same layout, every key and number bit for bit:
//   <what> was made on plant kind 'cartpole' and cannot be loaded onto plant kind 'simbody'
//   (plant.kind): another robot
//   <what> was made for rbf.centres [-1, 0, 1]; this diagram has rbf.centres [-2, 0, 2]
void check_weights_fit(const LearntWeights& weights, const std::string& plant_kind,
                       const blocks::FeatureLayout& layout, const std::string& what);
// Its second half: the layout alone.
void check_layout_fit(const LearntWeights& weights, const blocks::FeatureLayout& layout,
                      const std::string& what);

// Sets the actor's weights in `context`, and the critic's where the loop has one. Throws
// std::invalid_argument when the loop has no actor, or its layout or feature counts differ
// from the weights'; check_weights_fit first for a user's message.
void load_learnt_weights(const diagrams::ClosedLoop& loop, Context& context,
                         const LearntWeights& weights);

}  // namespace cbbg::experiments
