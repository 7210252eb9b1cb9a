#pragma once
// What a learning arm has learnt: the critic's and the actor's weights with the feature
// layout they were learnt on and where they come from; read from and written into a closed
// loop's context. store/weights_file.h keeps them in files.

#include <string>
#include <string_view>
#include <vector>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/blocks/learner.h"
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

// One part of what a learner learnt (blocks::Learner::learnt_parts): its name ("weights",
// or a user's learner's own: "trace", "second_weights") and its numbers.
struct LearntPart {
  std::string name;
  Vector values;
};

// What one learner learnt: its parts, in the order it declares them.
struct LearntState {
  std::vector<LearntPart> parts;

  // The part `name`; null when there is none.
  const Vector* find(std::string_view name) const;
  // The library's shape: one part, "weights".
  static LearntState of_weights(Vector weights);
  // The part "weights" (the library's critic's w, its actor's theta). Throws
  // std::invalid_argument naming `role` ("actor") when there is none.
  const Vector& weights(const char* role) const;
  Vector& weights(const char* role);
  // Whether it is the library's shape: one part, "weights", of `features` numbers.
  bool is_weights_only(int features) const;
  bool all_finite() const;
  bool operator==(const LearntState& other) const;
};

// What the critic and the actor learnt (the library's: w with V = w . phi, theta with
// a_A = theta . phi; a user's learner's: whatever parts it declares), and the layout that
// gives phi its meaning, as the loop's blocks describe it (blocks/feature_layout.h: the
// normaliser's scales and the RBF grid for the presets, a user's features block's own).
// Weights are only meaningful on the same robot, in a loop of the same layout
// (check_weights_fit).
struct LearntWeights {
  blocks::FeatureLayout layout;
  std::vector<std::string> layout_notes;  // the blocks' notes, for a reader of the file
  int features = 0;                       // n, the features the learners read
  LearntState actor;
  LearntState critic;
  WeightsProvenance provenance;

  int num_features() const { return features; }
  // The role's state: `role` is "actor" or "critic".
  const LearntState& of(blocks::Learner::Role role) const;
  // The same layout, feature count, parts and provenance (the notes are a reader's help only).
  bool operator==(const LearntWeights& other) const;
};

// What `loop`'s learners have learnt in `context` (every part they declare; none for a critic
// that is no blocks::Learner), with the loop's layout. Throws std::invalid_argument when the
// loop has no actor.
LearntWeights learnt_weights(const diagrams::ClosedLoop& loop, const Context& context,
                             const WeightsProvenance& provenance);

// The one check of weights from elsewhere (a file, a run before) before they are loaded into
// `loop` on plant kind `plant_kind`. Throws config::ConfigError, a line that starts with
// `what` (store::check_weights: "weights file 'w.txt'"), unless they were learnt on the same
// robot (diagrams::same_robot: the Simbody and the analytic plant are one), for the same
// layout, every key and number bit for bit, and hold the parts the loop's learners declare:
//   <what> was made on plant kind 'cartpole' and cannot be loaded onto plant kind 'simbody'
//   (plant.kind): another robot
//   <what> was made for rbf.centres [-1, 0, 1]; this diagram has rbf.centres [-2, 0, 2]
//   <what> holds critic parts weights (49); the critic 'controller/basal_ganglia/critic'
//   learns weights (49), trace (49)
void check_weights_fit(const LearntWeights& weights, const std::string& plant_kind,
                       const diagrams::ClosedLoop& loop, const std::string& what);
// Its layout half alone.
void check_layout_fit(const LearntWeights& weights, const blocks::FeatureLayout& layout,
                      const std::string& what);

// Sets every part the actor declares in `context`, and the critic's where the loop has one.
// Throws std::invalid_argument when the loop has no actor, or its layout, feature count or
// learnt parts (names and sizes) differ from the weights'; check_weights_fit first for a
// user's message.
void load_learnt_weights(const diagrams::ClosedLoop& loop, Context& context,
                         const LearntWeights& weights);

}  // namespace cbbg::experiments
