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

// The first line of every weights file this cbbg writes and the only one it reads.
inline constexpr const char* kWeightsFormat = "cbbg-weights";
inline constexpr int kWeightsFormatVersion = 1;

using experiments::LearntWeights;

// Writes `weights` to `path` in the text format, every number in the shortest text that
// reads back to the same double. Writes a temporary file beside `path` and renames it, so
// `path` is never half-written; creates missing parent directories. Throws
// std::invalid_argument for weights the format cannot hold (critic and actor counts that
// differ, a provenance word with spaces, a non-finite number), config::ConfigError when `path`
// holds anything but a weights file (a file of the user's, a FIFO: never replaced), and
// std::runtime_error when writing fails.
void save_weights(const std::filesystem::path& path, const LearntWeights& weights);

// Reads a weights file. Every problem (missing file, other format or version, a malformed
// line, a wrong count, a non-finite number) throws config::ConfigError: one line naming the
// file, the line where it applies, and what is wrong.
LearntWeights load_weights(const std::filesystem::path& path);

// Throws config::ConfigError, naming `source` and where the layouts first differ, unless the
// weights were made for `layout` (a closed loop's: diagrams::ClosedLoop::layout), the same
// keys and numbers, bit for bit.
void check_layout(const LearntWeights& weights, const blocks::FeatureLayout& layout,
                  const std::filesystem::path& source);

}  // namespace cbbg::store
