#pragma once
// What a learning arm has learnt (records/learnt_state.h), read from and written into a
// closed loop's context, and checked before it is loaded into one. store/weights_file.h keeps
// it in files.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "cbbg/blocks/feature_layout.h"
#include "cbbg/blocks/learner.h"
#include "cbbg/diagrams/closed_loop.h"
#include "cbbg/framework/context.h"
#include "cbbg/framework/types.h"
#include "cbbg/records/learnt_state.h"

namespace cbbg::experiments {

using records::LearntPart;
using records::LearntState;
using records::LearntWeights;
using records::WeightsProvenance;

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

// check_weights_fit for weights read from the file `source` (cbbg eval, cbbg run
// --load-weights), its messages naming the file: "weights file 'w.txt' was made on plant kind
// 'cartpole' and cannot be loaded onto plant kind 'simbody' (plant.kind): another robot".
void check_weights(const LearntWeights& weights, const std::string& plant_kind,
                   const diagrams::ClosedLoop& loop, const std::filesystem::path& source);
// Its layout half alone: throws config::ConfigError, naming `source` and where the layouts
// first differ, unless the weights were made for `layout`, the same keys and numbers, bit for
// bit.
void check_layout(const LearntWeights& weights, const blocks::FeatureLayout& layout,
                  const std::filesystem::path& source);

// Sets every part the actor declares in `context`, and the critic's where the loop has one.
// Throws std::invalid_argument when the loop has no actor, or its layout, feature count or
// learnt parts (names and sizes) differ from the weights'; check_weights_fit first for a
// user's message.
void load_learnt_weights(const diagrams::ClosedLoop& loop, Context& context,
                         const LearntWeights& weights);

}  // namespace cbbg::experiments
