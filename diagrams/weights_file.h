#pragma once
// Learnt-weight checkpoints: the critic's and the actor's weights with the feature layout they
// were learnt on and where they come from, saved to and loaded from a text file
// (docs/weights-format.md). A checkpoint lets a run start from weights learnt earlier and
// `cbbg eval` measure a learnt policy without learning again.

#include <filesystem>
#include <string>
#include <vector>

#include "blocks/normaliser.h"
#include "config/config.h"
#include "diagrams/controller_diagram.h"
#include "framework/context.h"
#include "framework/types.h"

namespace cbbg::diagrams {

// The first line of every weights file this cbbg writes and the only one it reads.
inline constexpr const char* kWeightsFormat = "cbbg-weights";
inline constexpr int kWeightsFormatVersion = 1;

// Where a set of weights comes from; recorded in the file, not checked on loading.
struct WeightsProvenance {
  std::string arm = "unknown";    // the diagram that learnt them (one word)
  long long seed = 0;             // its root seed
  long long trials = 0;           // trials it learnt over
  std::string plant = "unknown";  // plant.kind it learnt on (one word)
  bool operator==(const WeightsProvenance&) const = default;
};

// The weights of the critic (V = w . phi) and the actor (a_A = theta . phi), and the layout
// that gives phi its meaning: the normaliser's scales and the RBF grid. Weights are only
// meaningful with the same layout (check_layout).
struct LearntWeights {
  std::vector<double> centres;          // rbf.centres
  double width = 0.0;                   // rbf.width
  blocks::NormaliserParams normaliser;  // normaliser.*
  Vector actor;                         // theta, centres.size()^2 of them
  Vector critic;                        // w, as many
  WeightsProvenance provenance;

  // The feature count of the layout: centres.size() squared.
  int num_features() const;
  bool operator==(const LearntWeights& other) const;
};

// Writes `weights` to `path` in the text format, every number in the shortest text that
// reads back to the same double. Writes a temporary file beside `path` and renames it, so
// `path` is never half-written; creates missing parent directories. Throws
// std::invalid_argument for weights the format cannot hold (a weight count that does not
// match the layout, a provenance word with spaces) and std::runtime_error when writing fails.
void save_weights(const std::filesystem::path& path, const LearntWeights& weights);

// Reads a weights file. Every problem (missing file, other format or version, a malformed
// line, a wrong count, a non-finite number) throws config::ConfigError: one line naming the
// file, the line where it applies, and what is wrong.
LearntWeights load_weights(const std::filesystem::path& path);

// Throws config::ConfigError, naming `source` and both layouts, unless the weights were made
// for the normaliser and RBF grid of `config` (the same numbers, bit for bit).
void check_layout(const LearntWeights& weights, const config::Config& config,
                  const std::filesystem::path& source);

// The weights `controller` has learnt in `context`, with the layout of `config` (which
// built `controller`). Throws std::invalid_argument when the diagram has no critic and actor.
LearntWeights learnt_weights(const ControllerDiagram& controller, const Context& context,
                             const config::Config& config, const WeightsProvenance& provenance);

// Sets the actor's weights in `context`, and the critic's where the diagram has one.
// Throws std::invalid_argument when the diagram has no actor or the feature counts differ;
// check_layout first for a user's message.
void load_learnt_weights(const ControllerDiagram& controller, Context& context,
                         const LearntWeights& weights);

}  // namespace cbbg::diagrams
