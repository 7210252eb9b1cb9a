#pragma once
// The configuration of a cbbg run: every registered key (config/declared_keys.h: the run's
// tree registers the blocks' and plants' sections, parameters/parameters.h; each protocol its
// own; a user's the same way), merged from their defaults, a YAML file and `--set key.path=value`
// overrides, in that order. Types, choices and ranges are checked here, as each value arrives;
// invariants a block owns beyond its ranges, and rules across keys, by
// diagrams::validated_parameters.

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace cbbg::config {

// A user's mistake in a config: one line naming the key path and what is allowed.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A config file larger than this is refused before it is read.
inline constexpr std::uintmax_t kMaxConfigFileBytes = 1024 * 1024;
// Bounds of the run's size: seeds per arm, the root seed, trials per seed (max_trials,
// exp2.trials); what a run may ask for before it is refused as a typing slip.
inline constexpr double kMaxSeeds = 10000;
inline constexpr double kMaxSeed = 1e12;
inline constexpr double kMaxTrials = 100000;

// exp2's schedule: k1 from trial `from_trial` on (trials count from 1).
struct AnnealingStep {
  long long from_trial;
  double k1;
  bool operator==(const AnnealingStep&) const = default;
};

using Value = std::variant<double, long long, std::string, std::vector<double>,
                           std::vector<std::string>, std::vector<AnnealingStep>>;

// kSettings: a list of texts, each "key=value" (several joined by ';'), every key another of
// the tree and every value one that key allows: a list of conditions (transfer.conditions).
// kFile: a path to a file, any text on one line (empty: none), not a name.
enum class Kind { kNumber, kInteger, kText, kNumbers, kNames, kAnnealing, kSettings, kFile };

// One key of the tree.
struct KeySpec {
  std::string path;  // "critic.gamma"
  Kind kind;
  Value default_value;
  std::string meaning;               // one line, for `cbbg list`
  std::vector<std::string> choices;  // allowed texts (kText, kNames); empty: any
  // Numeric range (kNumber, kInteger, each element of kNumbers).
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  bool max_exclusive = false;
  int list_size = 0;  // kNumbers: exact length when > 0
};

// Every key, in the order `cbbg list` and config.yaml show them: the run's tree, each
// protocol's sections where it placed them, then the sections registered since.
const std::vector<KeySpec>& schema();
// What `spec` allows, as messages and the docs' table say it: "in (0, 1]", "> 0", "one of
// pd, lqr", "6 numbers >= 0".
std::string allowed_values(const KeySpec& spec);
// Throws ConfigError when the default of `spec` is not a value `spec` allows (so a config.yaml
// that records it would not read back), naming the key and what it allows.
void check_default(const KeySpec& spec);

class Config {
 public:
  // The defaults of every key registered so far.
  Config();

  // Merges a YAML document; `source` names it in error messages (a file name). A file's path
  // (a key of kind kFile) is kept absolute: a relative one is read from `relative_to`, by
  // default the working directory; merge_file reads it from the config file's folder.
  void merge_yaml(const std::string& text, const std::string& source,
                  const std::filesystem::path& relative_to = {});
  void merge_file(const std::filesystem::path& path);
  // Applies one "key.path=value" override (value in YAML syntax: 3, [1, 2], {a: 1}).
  // Errors start with `source`, by default "--set key.path=value".
  void set(std::string_view assignment, std::string source = {});
  // Sets a registered key to a value of its kind, with no text in between; the caller has
  // checked it against its declaration (write_parameters does).
  void assign(std::string_view key, Value value);

  double number(std::string_view key) const;
  long long integer(std::string_view key) const;
  const std::string& text(std::string_view key) const;
  const std::vector<double>& numbers(std::string_view key) const;
  const std::vector<std::string>& names(std::string_view key) const;  // kNames, kSettings
  const std::vector<AnnealingStep>& annealing(std::string_view key) const;
  // The value of `key` whatever its kind; std::logic_error for a key no declaration made.
  const Value& value(std::string_view key) const;

  // The fully resolved tree as YAML, in schema order; it loads back to the same Config.
  std::string to_yaml() const;
  bool operator==(const Config&) const = default;

 private:
  std::map<std::string, Value, std::less<>> values_;
};

// The "key=value" pairs of one entry of a kSettings key ("a=1; b=2"), each key and value
// trimmed, in order. The entry was checked when it arrived.
std::vector<std::pair<std::string, std::string>> split_settings(std::string_view entry);

// The key closest to `unknown` by edit distance, or "" when none is close.
std::string closest_key(std::string_view unknown);

// What a name is, where a key takes any name (`arms`, `experiment`, a user's word): 1 to 100
// letters, digits, '_', '-' and '.', not starting with '-' or '.'. Names become file names
// (weights/<arm>_seed<k>.txt) and columns, so nothing else is one.
inline constexpr const char* kNameRule =
    "1 to 100 letters, digits, '_', '-' and '.', not starting with '-' or '.'";
bool is_name(std::string_view text);

// A text as a one-line message shows it: '?' for a newline or any other control character,
// at most `max_size` bytes, then "...".
std::string shown_text(std::string_view text, std::size_t max_size = 60);

// "a, b, c": a list of names in a message.
std::string join(const std::vector<std::string>& items);

// Before a registration (a plant kind, an arm, a protocol): `name` is a name and none of
// `taken`. Throws std::invalid_argument "<what> '<name>': a name is ..." or "<what> '<name>'
// is registered twice".
void check_new_name(std::string_view what, const std::string& name,
                    const std::vector<std::string>& taken);

}  // namespace cbbg::config
