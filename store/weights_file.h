#pragma once
// Learnt-weight checkpoints (experiments/learnt_weights.h) saved to and loaded from a text file
// (docs/weights-format.md). A checkpoint lets a run start from weights learnt earlier and
// `cbbg eval` measure a learnt policy without learning again.

#include <filesystem>
#include <string>
#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/experiments/learnt_weights.h"

namespace cbbg::store {

// The first line of a weights file: "cbbg-weights 1" (one weight per feature and learner, the
// library's critic and actor) or "cbbg-weights 2" (any learnt parts); this cbbg reads both.
inline constexpr const char* kWeightsFormat = "cbbg-weights";
inline constexpr int kWeightsFormatVersion = 2;

using experiments::LearntWeights;

// Writes `weights` to `path` in the text format, every number in the shortest text that
// reads back to the same double: version 1 when both learners learnt "weights" alone, one
// per feature (so the presets' files are what they always were), else version 2. Writes a temporary
// file beside `path` and renames it, so `path` is never half-written; creates missing parent
// directories. Throws std::invalid_argument for weights the format cannot hold (a learner with no
// part, a part name that is not one word of letters, digits and '_', a provenance word with spaces,
// a non-finite number), config::ConfigError when `path` holds anything but a weights file (a file
// of the user's, a FIFO: never replaced), and std::runtime_error when writing fails.
void save_weights(const std::filesystem::path& path, const LearntWeights& weights);

// Reads a weights file. Every problem (missing file, other format or version, a malformed
// line, a wrong count, a non-finite number) throws config::ConfigError: one line naming the
// file, the line where it applies, and what is wrong.
LearntWeights load_weights(const std::filesystem::path& path);

// Before weights read from the file `source` are loaded into `loop` on plant kind
// `plant_kind` (a run's plant.kind): experiments::check_weights_fit, its messages naming the
// file ("weights file 'w.txt' was made on plant kind 'cartpole' and cannot be loaded onto
// plant kind 'simbody' (plant.kind): another robot"). cbbg eval and cbbg run --load-weights
// check so.
void check_weights(const LearntWeights& weights, const std::string& plant_kind,
                   const diagrams::ClosedLoop& loop, const std::filesystem::path& source);
// Its layout half alone: throws config::ConfigError, naming `source` and where the layouts
// first differ, unless the weights were made for `layout`, the same keys and numbers, bit for
// bit.
void check_layout(const LearntWeights& weights, const blocks::FeatureLayout& layout,
                  const std::filesystem::path& source);

}  // namespace cbbg::store
