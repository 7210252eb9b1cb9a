#pragma once
// Learnt-weight checkpoints (records/learnt_state.h) saved to and loaded from a text file
// (docs/weights-format.md). A checkpoint lets a run start from weights learnt earlier and
// `cbbg eval` measure a learnt policy without learning again.

#include <filesystem>
#include <string>
#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/records/learnt_state.h"

namespace cbbg::store {

// The first line of a weights file: "cbbg-weights 1" (one weight per feature and learner, the
// library's critic and actor) or "cbbg-weights 2" (any learnt parts); this cbbg reads both.
inline constexpr const char* kWeightsFormat = "cbbg-weights";
inline constexpr int kWeightsFormatVersion = 2;

using records::LearntWeights;

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

}  // namespace cbbg::store
