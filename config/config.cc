#include "cbbg/config/config.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "cbbg/framework/number_text.h"

namespace cbbg::config {
namespace {

const KeySpec* find_spec(std::string_view path) {
  for (const auto& spec : schema()) {
    if (spec.path == path) return &spec;
  }
  return nullptr;
}

// The keys directly under a section ("plant" -> "kind, wheel_mass, ..."), or "" if none.
std::string section_keys(std::string_view section) {
  std::string keys;
  const std::string prefix = std::string(section) + ".";
  for (const auto& spec : schema()) {
    if (spec.path.rfind(prefix, 0) == 0) {
      keys += (keys.empty() ? "" : ", ") + spec.path.substr(prefix.size());
    }
  }
  return keys;
}

// A node as the user wrote it, on one line, for "got ..." in messages.
std::string shown(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsScalar()) return "'" + shown_text(node.Scalar(), std::string::npos) + "'";
  YAML::Emitter out;
  out.SetSeqFormat(YAML::Flow);
  out.SetMapFormat(YAML::Flow);
  out << node;
  return shown_text(out.c_str(), 57);
}

std::string range_text(const KeySpec& spec) {
  const bool has_min = std::isfinite(spec.min);
  const bool has_max = std::isfinite(spec.max);
  // Integer bounds read as integers: "in [1, 100000]", not "1e+05".
  auto bound = [&spec](double value) {
    return spec.kind == Kind::kInteger ? std::to_string(static_cast<long long>(value))
                                       : format_number(value);
  };
  if (has_min && has_max) {
    return "in " + std::string(spec.min_exclusive ? "(" : "[") + bound(spec.min) + ", " +
           bound(spec.max) + (spec.max_exclusive ? ")" : "]");
  }
  if (has_min) return std::string(spec.min_exclusive ? "> " : ">= ") + bound(spec.min);
  if (has_max) return std::string(spec.max_exclusive ? "< " : "<= ") + bound(spec.max);
  return "any finite number";
}

bool in_range(const KeySpec& spec, double value) {
  const bool above = spec.min_exclusive ? value > spec.min : value >= spec.min;
  const bool below = spec.max_exclusive ? value < spec.max : value <= spec.max;
  return above && below;
}

// What a text of `spec` may be: one of its words, or any name.
std::string words_text(const KeySpec& spec) {
  return spec.choices.empty() ? "a name (" + std::string(kNameRule) + ")"
                              : "one of " + join(spec.choices);
}

YAML::Node load_yaml(const std::string& text, const std::string& source);

class Parser {
 public:
  explicit Parser(std::string source, std::filesystem::path relative_to = {})
      : source_(std::move(source)), relative_to_(std::move(relative_to)) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw ConfigError(source_ + ": " + message);
  }

  double parse_number(const std::string& label, const YAML::Node& node,
                      const char* what = "a number") const {
    double value = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
      fail(label + " must be " + what + "; got " + shown(node));
    }
    if (!std::isfinite(value)) fail(label + " must be a finite number; got " + shown(node));
    return value;
  }

  double checked_number(const KeySpec& spec, const std::string& label,
                        const YAML::Node& node) const {
    const double value = parse_number(label, node);
    if (!in_range(spec, value)) {
      fail(label + " must be " + range_text(spec) + "; got " + format_number(value));
    }
    return value;
  }

  long long parse_integer(const KeySpec& spec, const std::string& label,
                          const YAML::Node& node) const {
    const std::string wanted = "an integer " + range_text(spec);
    const double value = parse_number(label, node, wanted.c_str());
    if (value != std::floor(value) || std::abs(value) > 9.0e15) {
      fail(label + " must be an integer " + range_text(spec) + "; got " + shown(node));
    }
    if (!in_range(spec, value)) {
      fail(label + " must be an integer " + range_text(spec) + "; got " + format_number(value));
    }
    return static_cast<long long>(value);
  }

  std::string parse_choice(const KeySpec& spec, const std::string& label,
                           const YAML::Node& node) const {
    if (!node.IsScalar()) fail(label + " must be " + words_text(spec) + "; got " + shown(node));
    const std::string& value = node.Scalar();
    if (spec.choices.empty() && !is_name(value)) {
      fail(label + " must be " + words_text(spec) + "; got " + shown(node));
    }
    if (!spec.choices.empty() &&
        std::find(spec.choices.begin(), spec.choices.end(), value) == spec.choices.end()) {
      fail(label + " must be one of " + join(spec.choices) + "; got '" +
           shown_text(value, std::string::npos) + "'");
    }
    return value;
  }

  // A path: one line of text, no control character.
  std::string parse_file(const std::string& key, const YAML::Node& node) const {
    if (node.IsNull()) return "";
    const bool one_line =
        node.IsScalar() && std::none_of(node.Scalar().begin(), node.Scalar().end(), [](char c) {
          return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        });
    if (!one_line) fail(key + " must be a file's path on one line; got " + shown(node));
    const std::filesystem::path path(node.Scalar());
    if (path.empty() || path.is_absolute()) return path.string();
    const std::filesystem::path folder =
        relative_to_.empty() ? std::filesystem::current_path() : relative_to_;
    return (folder / path).lexically_normal().string();
  }

  Value parse(const KeySpec& spec, const YAML::Node& node) const {
    const std::string& key = spec.path;
    switch (spec.kind) {
      case Kind::kNumber:
        return checked_number(spec, key, node);
      case Kind::kInteger:
        return parse_integer(spec, key, node);
      case Kind::kText:
        return parse_choice(spec, key, node);
      case Kind::kNumbers: {
        const std::string wanted = spec.list_size > 0
                                       ? "a list of " + std::to_string(spec.list_size) + " numbers"
                                       : "a non-empty list of numbers";
        if (!node.IsSequence() || node.size() == 0 ||
            (spec.list_size > 0 && static_cast<int>(node.size()) != spec.list_size)) {
          fail(key + " must be " + wanted + "; got " + shown(node));
        }
        std::vector<double> values;
        for (std::size_t i = 0; i < node.size(); ++i) {
          values.push_back(checked_number(spec, key + "[" + std::to_string(i) + "]", node[i]));
        }
        return values;
      }
      case Kind::kNames: {
        if (!node.IsSequence() || node.size() == 0) {
          fail(key + " must be a non-empty list of " +
               (spec.choices.empty() ? "names" : join(spec.choices)) + "; got " + shown(node));
        }
        std::vector<std::string> values;
        for (std::size_t i = 0; i < node.size(); ++i) {
          std::string name = parse_choice(spec, key + "[" + std::to_string(i) + "]", node[i]);
          if (std::find(values.begin(), values.end(), name) != values.end()) {
            fail(key + " lists '" + name + "' twice");
          }
          values.push_back(std::move(name));
        }
        return values;
      }
      case Kind::kAnnealing:
        return parse_annealing(key, node);
      case Kind::kSettings:
        return parse_settings(key, node);
      case Kind::kFile:
        return parse_file(key, node);
    }
    fail(key + ": unknown kind");
  }

  std::vector<std::string> parse_settings(const std::string& key, const YAML::Node& node) const {
    if (!node.IsSequence() || node.size() == 0) {
      fail(key + " must be a non-empty list of settings key=value (several joined by ';'); got " +
           shown(node));
    }
    std::vector<std::string> entries;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const std::string label = key + "[" + std::to_string(i) + "]";
      if (!node[i].IsScalar()) fail(label + " must be key=value; got " + shown(node[i]));
      const std::string& entry = node[i].Scalar();
      if (entry.find_first_of("\r\n") != std::string::npos) {
        fail(label + " must be one line; got " + shown(node[i]));
      }
      check_settings(label, entry);
      if (std::find(entries.begin(), entries.end(), entry) != entries.end()) {
        fail(key + " lists '" + entry + "' twice");
      }
      entries.push_back(entry);
    }
    return entries;
  }

  // Every "key=value" of `entry` names a key of the tree (not a list of settings) and a value
  // that key allows.
  void check_settings(const std::string& label, const std::string& entry) const {
    const std::vector<std::pair<std::string, std::string>> settings = split_settings(entry);
    if (settings.empty()) fail(label + " must be key=value; got '" + entry + "'");
    for (const auto& [path, text] : settings) {
      if (path.empty() || text.empty()) {
        fail(label + " must be key=value (several joined by ';'); got '" + entry + "'");
      }
      const KeySpec* spec = find_spec(path);
      if (spec == nullptr) {
        const std::string suggestion = closest_key(path);
        fail(label + ": unknown key '" + path + "'" +
             (suggestion.empty() ? "" : "; did you mean '" + suggestion + "'?"));
      }
      if (spec->kind == Kind::kSettings) fail(label + ": " + path + " cannot be set here");
      Parser(source_ + ": " + label).parse(*spec, load_yaml(text, source_ + ": " + label));
    }
  }

  std::vector<AnnealingStep> parse_annealing(const std::string& key, const YAML::Node& node) const {
    const std::string shape = " must be a list of {from_trial: integer >= 1, k1: number > 0}";
    if (!node.IsSequence() || node.size() == 0) fail(key + shape + "; got " + shown(node));
    std::vector<AnnealingStep> steps;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const std::string label = key + "[" + std::to_string(i) + "]";
      const YAML::Node& entry = node[i];
      if (!entry.IsMap()) {
        fail(label + " must be a map {from_trial: integer >= 1, k1: number > 0}; got " +
             shown(entry));
      }
      for (const auto& field : entry) {
        const YAML::Node& name = field.first;
        if (!name.IsScalar() || (name.Scalar() != "from_trial" && name.Scalar() != "k1")) {
          fail(label + " has an unknown key " + shown(name) + "; allowed: from_trial, k1");
        }
      }
      if (!entry["from_trial"] || !entry["k1"]) fail(label + " needs both from_trial and k1");
      KeySpec trial_spec;
      trial_spec.min = 1;
      KeySpec k1_spec;
      k1_spec.min = 0;
      k1_spec.min_exclusive = true;
      const AnnealingStep step{
          parse_integer(trial_spec, label + ".from_trial", entry["from_trial"]),
          checked_number(k1_spec, label + ".k1", entry["k1"])};
      if (i == 0 && step.from_trial != 1) {
        fail(key + " must start at from_trial 1; got " + std::to_string(step.from_trial));
      }
      if (i > 0 && step.from_trial <= steps.back().from_trial) {
        fail(key + " must list trials in increasing order; " + label + ".from_trial is " +
             std::to_string(step.from_trial) + " after " + std::to_string(steps.back().from_trial));
      }
      steps.push_back(step);
    }
    return steps;
  }

  // Merges a map node found at `prefix` ("" for the top level) into `values`.
  void merge(const YAML::Node& node, const std::string& prefix,
             std::map<std::string, Value, std::less<>>& values) const {
    std::vector<std::string> seen;
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) fail("keys must be plain names; got " + shown(entry.first));
      const std::string path =
          prefix.empty() ? entry.first.Scalar() : prefix + "." + entry.first.Scalar();
      if (std::find(seen.begin(), seen.end(), path) != seen.end()) {
        fail("key '" + path + "' appears twice (again at line " +
             std::to_string(entry.first.Mark().line + 1) + "); give each key once");
      }
      seen.push_back(path);
      assign(path, entry.second, values);
    }
  }

  void assign(const std::string& path, const YAML::Node& node,
              std::map<std::string, Value, std::less<>>& values) const {
    if (const KeySpec* spec = find_spec(path)) {
      values[path] = parse(*spec, node);
      return;
    }
    const std::string children = section_keys(path);
    if (!children.empty()) {
      if (!node.IsMap()) {
        fail(path + " is a section: give a map of its keys (" + children + "); got " + shown(node));
      }
      merge(node, path, values);
      return;
    }
    const std::string suggestion = closest_key(path);
    fail("unknown key '" + path + "'" +
         (suggestion.empty() ? "; `cbbg list` shows every key"
                             : "; did you mean '" + suggestion + "'?"));
  }

 private:
  std::string source_;
  std::filesystem::path relative_to_;  // empty: the working directory
};

YAML::Node load_yaml(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& error) {
    throw ConfigError(source + ": malformed YAML at line " + std::to_string(error.mark.line + 1) +
                      ", column " + std::to_string(error.mark.column + 1) + ": " + error.msg);
  }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string last_segment(std::string_view path) {
  const auto dot = path.rfind('.');
  return std::string(dot == std::string_view::npos ? path : path.substr(dot + 1));
}

// A text as a YAML scalar: plain when YAML reads it back unchanged, else quoted.
std::string yaml_scalar(const std::string& text) {
  YAML::Emitter out;
  out << text;
  return out.c_str();
}

void write_value(std::ostringstream& out, const Value& value) {
  std::visit(
      [&out](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) {
          out << format_number(v);
        } else if constexpr (std::is_same_v<T, long long>) {
          out << v;
        } else if constexpr (std::is_same_v<T, std::string>) {
          out << yaml_scalar(v);
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          out << "[";
          for (std::size_t i = 0; i < v.size(); ++i) out << (i ? ", " : "") << format_number(v[i]);
          out << "]";
        } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          YAML::Emitter list;  // quotes what a flow list needs quoted (a comma, a bracket)
          list << YAML::Flow << v;
          out << list.c_str();
        } else {
          for (const auto& step : v) {
            out << "\n  - {from_trial: " << step.from_trial << ", k1: " << format_number(step.k1)
                << "}";
          }
        }
      },
      value);
}

}  // namespace

void check_default(const KeySpec& spec) {
  std::ostringstream text;
  write_value(text, spec.default_value);
  const std::string source = "config key '" + spec.path + "' has a default outside its declaration";
  Parser(source).parse(spec, load_yaml(text.str(), source));
}

std::string allowed_values(const KeySpec& spec) {
  switch (spec.kind) {
    case Kind::kNumber:
      return range_text(spec);
    case Kind::kInteger:
      return "an integer " + range_text(spec);
    case Kind::kText:
    case Kind::kNames:
      if (spec.kind == Kind::kText) return words_text(spec);
      return spec.choices.empty() ? "a list of names (" + std::string(kNameRule) + ")"
                                  : "a list of " + join(spec.choices);
    case Kind::kNumbers: {
      const std::string count =
          spec.list_size > 0 ? std::to_string(spec.list_size) + " numbers" : "a list of numbers";
      return std::isfinite(spec.min) ? count + ", each " + range_text(spec) : count;
    }
    case Kind::kAnnealing:
      return "a list of {from_trial, k1}";
    case Kind::kSettings:
      return "a list of key=value (several joined by ';')";
    case Kind::kFile:
      return "a file's path (empty: none)";
  }
  return "";
}

bool is_name(std::string_view text) {
  if (text.empty() || text.size() > 100 || text.front() == '-' || text.front() == '.') {
    return false;
  }
  return std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
  });
}

std::string closest_key(std::string_view unknown) {
  std::string best;
  std::size_t best_distance = 4;  // suggest only keys within three edits
  for (const auto& spec : schema()) {
    std::size_t distance = edit_distance(unknown, spec.path);
    // A key written without its section ("gamma") matches by its last segment.
    if (last_segment(spec.path) == unknown) distance = 1;
    if (distance < best_distance) {
      best_distance = distance;
      best = spec.path;
    }
  }
  return best;
}

Config::Config() {
  for (const auto& spec : schema()) values_[spec.path] = spec.default_value;
}

void Config::merge_yaml(const std::string& text, const std::string& source,
                        const std::filesystem::path& relative_to) {
  YAML::Node document = load_yaml(text, source);
  if (!document.IsDefined() || document.IsNull()) return;  // an empty file changes nothing
  const Parser parser(source, relative_to);
  if (!document.IsMap()) parser.fail("a config is a map of keys; got " + shown(document));
  if (document["sweep"]) {  // a sweep's grid, which config::Sweep reads (config/sweep.h)
    document = YAML::Clone(document);
    document.remove("sweep");
  }
  auto merged = values_;  // all or nothing
  parser.merge(document, "", merged);
  values_ = std::move(merged);
}

void Config::merge_file(const std::filesystem::path& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw ConfigError("config file '" + path.string() + "' is not a regular file");
  }
  if (std::filesystem::exists(status) &&
      std::filesystem::file_size(path, error) > kMaxConfigFileBytes) {
    throw ConfigError("config file '" + path.string() + "' is larger than " +
                      std::to_string(kMaxConfigFileBytes / 1024) + " KiB; a config is a few keys");
  }
  std::ifstream in(path);
  if (!in) {
    throw ConfigError("config file '" + path.string() + "' cannot be read (missing or unreadable)");
  }
  std::stringstream text;
  text << in.rdbuf();
  merge_yaml(text.str(), path.string(), std::filesystem::absolute(path).parent_path());
}

void Config::set(std::string_view assignment, std::string source) {
  if (source.empty()) source = "--set " + shown_text(assignment, std::string::npos);
  const auto equals = assignment.find('=');
  if (equals == std::string_view::npos || equals == 0) {
    throw ConfigError(source + ": expected key.path=value");
  }
  const std::string key(assignment.substr(0, equals));
  const std::string text(assignment.substr(equals + 1));
  if (text.empty()) throw ConfigError(source + ": " + key + " has no value after '='");
  const YAML::Node node = load_yaml(text, source);
  const Parser parser(source);
  auto merged = values_;
  parser.assign(key, node, merged);
  values_ = std::move(merged);
}

void Config::assign(std::string_view key, Value value) {
  const KeySpec* spec = find_spec(key);
  if (spec == nullptr || spec->default_value.index() != value.index()) {
    throw std::logic_error("config key '" + std::string(key) + "' does not take this value");
  }
  values_[std::string(key)] = std::move(value);
}

const Value& Config::value(std::string_view key) const {
  const auto found = values_.find(key);
  if (found != values_.end()) return found->second;
  // A key registered after this config was made still has its default.
  if (const KeySpec* spec = find_spec(key)) return spec->default_value;
  throw std::logic_error("config has no key '" + std::string(key) + "'");
}

double Config::number(std::string_view key) const { return std::get<double>(value(key)); }
long long Config::integer(std::string_view key) const { return std::get<long long>(value(key)); }
const std::string& Config::text(std::string_view key) const {
  return std::get<std::string>(value(key));
}
const std::vector<double>& Config::numbers(std::string_view key) const {
  return std::get<std::vector<double>>(value(key));
}
const std::vector<std::string>& Config::names(std::string_view key) const {
  return std::get<std::vector<std::string>>(value(key));
}
const std::vector<AnnealingStep>& Config::annealing(std::string_view key) const {
  return std::get<std::vector<AnnealingStep>>(value(key));
}

std::string Config::to_yaml() const {
  std::ostringstream out;
  std::string section;
  for (const auto& spec : schema()) {
    const auto dot = spec.path.find('.');
    const std::string head = dot == std::string::npos ? "" : spec.path.substr(0, dot);
    if (head != section) {
      section = head;
      if (!head.empty()) out << head << ":\n";
    }
    out << (head.empty() ? "" : "  ") << spec.path.substr(head.empty() ? 0 : dot + 1) << ":"
        << (spec.kind == Kind::kAnnealing ? "" : " ");
    write_value(out, value(spec.path));
    out << "\n";
  }
  return out.str();
}

std::vector<std::pair<std::string, std::string>> split_settings(std::string_view entry) {
  auto trimmed = [](std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) return std::string();
    return std::string(text.substr(first, text.find_last_not_of(" \t") - first + 1));
  };
  std::vector<std::pair<std::string, std::string>> settings;
  std::size_t start = 0;
  while (start <= entry.size()) {
    const std::size_t end = std::min(entry.find(';', start), entry.size());
    const std::string_view part = entry.substr(start, end - start);
    const std::size_t equals = part.find('=');
    settings.emplace_back(trimmed(part.substr(0, equals)),
                          equals == std::string_view::npos ? "" : trimmed(part.substr(equals + 1)));
    start = end + 1;
  }
  return settings;
}

std::string shown_text(std::string_view text, std::size_t max_size) {
  std::string shown;
  for (const char c : text.substr(0, std::min(text.size(), max_size))) {
    const auto byte = static_cast<unsigned char>(c);
    shown += (byte < 0x20 || byte == 0x7f) ? '?' : c;  // UTF-8 passes; controls do not
  }
  if (text.size() > max_size) shown += "...";
  return shown;
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

void check_new_name(std::string_view what, const std::string& name,
                    const std::vector<std::string>& taken) {
  const std::string named = std::string(what) + " '" + name + "'";
  if (!is_name(name)) {
    throw std::invalid_argument(named + ": a name is letters, digits, '_', '-' and '.'");
  }
  if (std::find(taken.begin(), taken.end(), name) != taken.end()) {
    throw std::invalid_argument(named + " is registered twice");
  }
}

}  // namespace cbbg::config
