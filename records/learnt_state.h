#pragma once
// What a learning arm has learnt: the critic's and the actor's parts with the feature layout
// they were learnt on and where they come from. experiments/learnt_weights.h reads it from a
// closed loop and loads it into one; store/weights_file.h keeps it in files.

#include <string>
#include <string_view>
#include <vector>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/blocks/learner.h"
#include "cbbg/framework/types.h"

namespace cbbg::records {

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

// "weights (49), trace (49)": a learner's parts in messages; "nothing" for none.
std::string parts_text(const LearntState& state);

}  // namespace cbbg::records
