#include "cbbg/store/weights_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "cbbg/blocks/learner.h"
#include "cbbg/config/config.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"

namespace cbbg::store {

using records::LearntState;
using records::LearntWeights;
using records::WeightsProvenance;
namespace {

// "weights file 'w.txt'": how every message names the file.
std::string file_name(const std::filesystem::path& path) {
  return "weights file '" + path.string() + "'";
}

std::string format_header(int version) {
  return std::string(kWeightsFormat) + " " + std::to_string(version);
}

// The shortest text that reads back to the same double.
std::string format_number(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

bool is_one_word(const std::string& text) {
  return !text.empty() && text.find_first_of(" \t\r\n#") == std::string::npos;
}

// A line of the file as messages show it: at most 60 characters, printable ones only.
std::string shown(std::string_view text) { return config::shown_text(text); }

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split_words(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t position = 0;
  while (true) {
    const auto start = text.find_first_not_of(" \t", position);
    if (start == std::string_view::npos) break;
    const auto end = text.find_first_of(" \t", start);
    words.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos) break;
    position = end;
  }
  return words;
}

struct Line {
  int number = 0;
  std::string_view text;
  std::vector<std::string_view> words;
};

// Reads a weights file line by line, skipping blank lines and '#' comments, and words every
// error as "weights file '<path>' line <n>: <what>".
class Reader {
 public:
  Reader(const std::filesystem::path& path, std::string_view text) : path_(path), text_(text) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw config::ConfigError(file_name(path_) + " " + what);
  }
  [[noreturn]] void fail(const Line& line, const std::string& what) const {
    fail("line " + std::to_string(line.number) + ": " + what);
  }

  // The next line, blank or not; nullopt at the end of the file.
  std::optional<Line> next_raw() {
    if (position_ >= text_.size()) return std::nullopt;
    const auto end = text_.find('\n', position_);
    const std::string_view raw =
        text_.substr(position_, end == std::string_view::npos ? end : end - position_);
    position_ = end == std::string_view::npos ? text_.size() : end + 1;
    Line line{++line_number_, trim(raw), {}};
    line.words = split_words(line.text);
    return line;
  }

  // The next line that is neither blank nor a comment; nullopt at the end of the file.
  std::optional<Line> next() {
    for (auto line = next_raw(); line; line = next_raw()) {
      if (!line->text.empty() && line->text.front() != '#') return line;
    }
    return std::nullopt;
  }

  // The comments up to the next significant line, each without its '#' and one space; that
  // line stays to be read.
  std::vector<std::string> comments() {
    std::vector<std::string> found;
    while (true) {
      const std::size_t position = position_;
      const int number = line_number_;
      const auto line = next_raw();
      if (!line) return found;
      if (line->text.empty()) continue;
      if (line->text.front() != '#') {
        position_ = position;
        line_number_ = number;
        return found;
      }
      std::string_view note = line->text.substr(1);
      if (!note.empty() && note.front() == ' ') note.remove_prefix(1);
      found.emplace_back(note);
    }
  }

  // The next significant line, which must exist: `expected` says what it should hold.
  Line expect(const std::string& expected) {
    auto line = next();
    if (!line) fail("ends after line " + std::to_string(line_number_) + "; expected " + expected);
    return *line;
  }

  // A line "key value": the value, after checking the key and that there is one value.
  std::string_view keyed(std::string_view key, std::string_view shape) {
    std::string expected = "'";
    expected.append(key).append(" ").append(shape).append("'");
    const Line line = expect(expected);
    if (line.words.size() != 2 || line.words[0] != key) {
      fail(line, "expected " + expected + ", got '" + shown(line.text) + "'");
    }
    last_ = line;
    return line.words[1];
  }

  double number(const Line& line, std::string_view word, const std::string& what) const {
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size()) {
      fail(line, what + " '" + shown(word) + "' is not a number");
    }
    if (!std::isfinite(value)) {
      fail(line, what + " is " + std::string(word) + "; numbers must be finite");
    }
    return value;
  }

  long long integer(const Line& line, std::string_view word, const std::string& what) const {
    long long value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size()) {
      fail(line, what + " '" + shown(word) + "' is not an integer");
    }
    return value;
  }

  double keyed_number(std::string_view key) {
    const std::string_view word = keyed(key, "<number>");
    return number(last_, word, std::string(key));
  }
  long long keyed_integer(std::string_view key) {
    const std::string_view word = keyed(key, "<integer>");
    return integer(last_, word, std::string(key));
  }
  const Line& last() const { return last_; }
  int line_number() const { return line_number_; }

 private:
  const std::filesystem::path& path_;
  std::string_view text_;
  std::size_t position_ = 0;
  int line_number_ = 0;
  Line last_;
};

std::string read_file(const std::filesystem::path& path) {
  const std::string name = file_name(path);
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw config::ConfigError(name + " does not exist");
  if (std::filesystem::is_directory(status)) {
    throw config::ConfigError(name + " is a directory, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw config::ConfigError(name + " cannot be read");
  return text.str();
}

// The file's version, 1 or 2.
int read_format_line(const Reader& reader, const std::optional<Line>& first) {
  std::string expected = "'";  // appended: GCC 12 misreads "'" + std::string as overlapping
  expected.append(format_header(1)).append("' or '");
  expected.append(format_header(kWeightsFormatVersion)).append("'");
  if (!first) reader.fail("is empty; a weights file starts with the line " + expected);
  if (first->words.size() == 2 && first->words[0] == kWeightsFormat) {
    for (const int version : {1, kWeightsFormatVersion}) {
      if (first->words[1] == std::to_string(version)) return version;
    }
    reader.fail("is format '" + shown(first->text) + "'; this cbbg reads " + expected);
  }
  reader.fail("is not a cbbg weights file: its first line is '" + shown(first->text) +
              "', expected " + expected);
}

// `count` numbers, one per line: `item` names one in messages ("actor weight [3]",
// "critic visits [3]"), `items` them all ("critic weights").
Vector read_numbers(Reader& reader, const std::string& item, const std::string& items,
                    long long count) {
  Vector values(count);
  for (long long k = 0; k < count; ++k) {
    const std::string what = item + " [" + std::to_string(k) + "]";
    const auto line = reader.next();
    if (!line) {
      reader.fail("ends after line " + std::to_string(reader.line_number()) + " with " +
                  std::to_string(k) + " of " + std::to_string(count) + " " + items);
    }
    if (line->words.size() != 1) {
      reader.fail(*line,
                  "expected " + what + " alone on its line, got '" + shown(line->text) + "'");
    }
    values[k] = reader.number(*line, line->words[0], what);
  }
  return values;
}

// How messages name one number of a part: "actor weight", "critic visits".
std::string item_name(const std::string& role, const std::string& part) {
  return role + " " + (part == "weights" ? std::string("weight") : part);
}

// Version 1: "actor <count>" and one weight per line.
LearntState read_weights(Reader& reader, const std::string& role, long long features) {
  const std::string_view count_word = reader.keyed(role, "<count>");
  const long long count = reader.integer(reader.last(), count_word, role + " count");
  if (count != features) {
    reader.fail(reader.last(), role + " has " + std::to_string(count) +
                                   " weights, but features is " + std::to_string(features));
  }
  return LearntState{
      {{"weights", read_numbers(reader, role + " weight", role + " weights", count)}}};
}

// A bound far above any real layout keeps the weight count an int and the file's size sane.
constexpr long long kMaxFeatures = blocks::kMaxFeatures;

// Version 2: "<role> <part> <count>" and one number per line, every part of the actor, then
// every part of the critic.
void read_parts(Reader& reader, LearntWeights& weights) {
  const std::string expected = "'actor <part> <count>' or 'critic <part> <count>'";
  for (auto line = reader.next(); line; line = reader.next()) {
    const bool fits = line->words.size() == 3 &&
                      (line->words[0] == "actor" || line->words[0] == "critic") &&
                      blocks::is_part_name(line->words[1]);
    if (!fits) reader.fail(*line, "expected " + expected + ", got '" + shown(line->text) + "'");
    const std::string role(line->words[0]);
    const std::string part(line->words[1]);
    LearntState& state = role == "actor" ? weights.actor : weights.critic;
    if (role == "actor" && !weights.critic.parts.empty()) {
      reader.fail(*line, "the actor's parts must come before the critic's");
    }
    if (state.find(part) != nullptr) reader.fail(*line, role + " part " + part + " appears twice");
    const long long count = reader.integer(*line, line->words[2], role + " " + part + " count");
    if (count < 1 || count > kMaxFeatures) {
      reader.fail(*line, role + " " + part + " count must be from 1 to " +
                             std::to_string(kMaxFeatures) + "; got " + std::to_string(count));
    }
    state.parts.push_back({part, read_numbers(reader, item_name(role, part),
                                              "numbers of " + role + " " + part, count)});
  }
  // A critic that is no blocks::Learner learns nothing; an actor always learns.
  if (weights.actor.parts.empty()) {
    reader.fail("ends after line " + std::to_string(reader.line_number()) + " with no actor part");
  }
}

// A layout key: one word with a dot inside ("rbf.width"), as blocks/feature_layout.h keys.
bool is_layout_key(const std::string& word) {
  const auto dot = word.find('.');
  return is_one_word(word) && dot != std::string::npos && dot > 0 && word.back() != '.';
}

// "key v1 v2 ...": one entry of the layout its blocks described.
blocks::LayoutEntry read_layout_entry(const Reader& reader, const Line& line,
                                      const blocks::FeatureLayout& before) {
  const std::string key(line.words[0]);
  if (line.words.size() < 2 || !is_layout_key(key)) {
    reader.fail(line,
                "expected a layout line 'kind.parameter <numbers>' or 'features <count>', "
                "got '" +
                    shown(line.text) + "'");
  }
  for (const blocks::LayoutEntry& entry : before) {
    if (entry.key == key) reader.fail(line, key + " appears twice");
  }
  blocks::LayoutEntry entry{key, {}};
  for (std::size_t i = 1; i < line.words.size(); ++i) {
    const std::string what = line.words.size() == 2 ? key : key + "[" + std::to_string(i - 1) + "]";
    entry.values.push_back(reader.number(line, line.words[i], what));
  }
  return entry;
}

LearntWeights parse(const std::filesystem::path& path, std::string_view text) {
  Reader reader(path, text);
  const int version = read_format_line(reader, reader.next_raw());

  LearntWeights weights;
  WeightsProvenance& provenance = weights.provenance;
  provenance.arm = std::string(reader.keyed("arm", "<diagram name>"));
  provenance.seed = reader.keyed_integer("seed");
  provenance.trials = reader.keyed_integer("trials");
  if (provenance.trials < 0) {
    reader.fail(reader.last(), "trials must be >= 0; got " + std::to_string(provenance.trials));
  }
  provenance.plant = std::string(reader.keyed("plant.kind", "<plant kind>"));

  // The layout, line by line, up to the feature count.
  const std::string expected = "a layout line 'kind.parameter <numbers>' or 'features <count>'";
  Line line = reader.expect(expected);
  while (line.words[0] != "features") {
    weights.layout.push_back(read_layout_entry(reader, line, weights.layout));
    line = reader.expect(expected);
  }
  if (line.words.size() != 2) {
    reader.fail(line, "expected 'features <count>', got '" + shown(line.text) + "'");
  }
  const long long features = reader.integer(line, line.words[1], "features");
  if (features < 1 || features > kMaxFeatures) {
    reader.fail(line, "features must be from 1 to " + std::to_string(kMaxFeatures) + "; got " +
                          std::to_string(features));
  }
  weights.features = static_cast<int>(features);
  weights.layout_notes = reader.comments();  // the blocks' notes, kept for a copy of the file
  if (version >= 2) {
    read_parts(reader, weights);
    return weights;
  }
  weights.actor = read_weights(reader, "actor", features);
  weights.critic = read_weights(reader, "critic", features);
  if (const auto extra = reader.next()) {
    reader.fail(*extra, "unexpected '" + shown(extra->text) + "' after the critic weights");
  }
  return weights;
}

void check_finite(const std::string& name, const std::vector<double>& values) {
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values[k])) {
      throw std::invalid_argument("save_weights: " + name + " [" + std::to_string(k) + "] is " +
                                  format_number(values[k]) + "; numbers must be finite");
    }
  }
}

void check_savable(const LearntWeights& weights) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("save_weights: " + what); };
  if (weights.features < 1) fail("the weights have no features");
  if (!is_one_word(weights.provenance.arm) || !is_one_word(weights.provenance.plant)) {
    fail("arm '" + weights.provenance.arm + "' and plant '" + weights.provenance.plant +
         "' must be single words");
  }
  for (const blocks::LayoutEntry& entry : weights.layout) {
    if (!is_layout_key(entry.key) || entry.values.empty()) {
      fail("layout entry '" + entry.key +
           "' must be one word 'kind.parameter' with at least one number");
    }
    check_finite(entry.key, entry.values);
  }
  for (const auto& [role, state] :
       {std::pair<std::string, const LearntState*>{"actor", &weights.actor},
        {"critic", &weights.critic}}) {
    if (role == "actor" && state->parts.empty()) fail("the actor learnt nothing");
    for (const records::LearntPart& part : state->parts) {
      if (!blocks::is_part_name(part.name) || part.values.size() == 0) {
        fail(role + " part '" + part.name + "' must be a name of letters, digits and '_' with " +
             "at least one number");
      }
      check_finite(item_name(role, part.name), {part.values.begin(), part.values.end()});
    }
  }
}

// Version 1 holds the library's shape (one "weights" part per learner, one per feature), so
// the presets' files read as they always have; anything else takes version 2.
int version_for(const LearntWeights& weights) {
  return weights.actor.is_weights_only(weights.features) &&
                 weights.critic.is_weights_only(weights.features)
             ? 1
             : kWeightsFormatVersion;
}

std::string format_weights(const LearntWeights& weights) {
  const WeightsProvenance& provenance = weights.provenance;
  // Appended piece by piece: one line per key, then one weight per line.
  std::string text;
  auto line = [&text](std::string_view key, const std::string& value) {
    text.append(key).append(" ").append(value).append("\n");
  };
  const int version = version_for(weights);
  text.append(format_header(version)).append("\n");
  text.append("# Learnt cbbg weights (docs/weights-format.md).\n");
  line("arm", provenance.arm);
  line("seed", std::to_string(provenance.seed));
  line("trials", std::to_string(provenance.trials));
  line("plant.kind", provenance.plant);
  for (const blocks::LayoutEntry& entry : weights.layout) {
    text.append(entry.key);
    for (const double value : entry.values) text.append(" ").append(format_number(value));
    text.append("\n");
  }
  line("features", std::to_string(weights.num_features()));
  for (const std::string& note : weights.layout_notes) text.append("# ").append(note).append("\n");
  for (const auto& [role, state] :
       {std::pair<std::string, const LearntState*>{"actor", &weights.actor},
        {"critic", &weights.critic}}) {
    for (const records::LearntPart& part : state->parts) {
      const std::string count = std::to_string(part.values.size());
      line(role, version == 1 ? count : part.name + " " + count);
      for (const double value : part.values) text.append(format_number(value)).append("\n");
    }
  }
  return text;
}

}  // namespace

void save_weights(const std::filesystem::path& path, const LearntWeights& weights) {
  check_savable(weights);
  check_replaceable_file(path, "weights file", kWeightsFormat);  // never a file of the user's
  const std::string text = format_weights(weights);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  write_atomically(path, text);
}

LearntWeights load_weights(const std::filesystem::path& path) {
  const std::string text = read_file(path);
  return parse(path, text);
}

}  // namespace cbbg::store
