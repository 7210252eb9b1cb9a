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

// Where a set of weights comes from; recorded in the file, not checked on loading.
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
// Weights are only meaningful in a loop of the same layout (store::check_layout).
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

// Sets the actor's weights in `context`, and the critic's where the loop has one. Throws
// std::invalid_argument when the loop has no actor, or its layout or feature counts differ
// from the weights'; store::check_layout first for a user's message.
void load_learnt_weights(const diagrams::ClosedLoop& loop, Context& context,
                         const LearntWeights& weights);

}  // namespace cbbg::experiments
