#include "cbbg/config/sweep.h"

#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace cbbg::config {
namespace {

// Splits at commas that are not inside [...] or {...}.
std::vector<std::string> split_values(std::string_view text) {
  std::vector<std::string> values;
  std::string current;
  int depth = 0;
  for (const char c : text) {
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}') --depth;
    if (c == ',' && depth == 0) {
      values.push_back(current);
      current.clear();
      continue;
    }
    current += c;
  }
  values.push_back(current);
  return values;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// A value as YAML reads it, written back in YAML's own flow form: "0.1 # note" becomes
// "0.1", a string that needs quotes gets them. So a sweep's config.yaml always reads back to
// the values swept, whatever a user typed.
// A loaded node keeps the style it was written in; a grid value is one line of flow YAML.
void set_flow_style(YAML::Node node) {
  if (!node.IsSequence() && !node.IsMap()) return;
  node.SetStyle(YAML::EmitterStyle::Flow);
  for (auto entry : node) {
    if (node.IsMap()) {
      set_flow_style(entry.first);
      set_flow_style(entry.second);
    } else {
      set_flow_style(entry);
    }
  }
}

std::string flow_text(const YAML::Node& node) {
  const YAML::Node copy = YAML::Clone(node);
  set_flow_style(copy);
  YAML::Emitter out;
  out << YAML::Flow << copy;
  return out.c_str();
}

std::string canonical_value(const std::string& text, const std::string& source) {
  YAML::Node node;
  try {
    node = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw ConfigError(source + ": '" + text + "' is not a YAML value: " + error.msg);
  }
  if (!node.IsDefined() || node.IsNull()) {
    throw ConfigError(source + ": an empty value; give V1,V2,...");
  }
  return flow_text(node);
}

}  // namespace

void Sweep::add_axis(SweepAxis axis) {
  for (const SweepAxis& existing : axes_) {
    if (existing.key == axis.key) {
      throw ConfigError(axis.source + ": " + axis.key + " is swept twice (also by " +
                        existing.source + ")");
    }
  }
  for (const std::string& value : axis.values) {
    if (value.empty()) throw ConfigError(axis.source + ": an empty value; give V1,V2,...");
  }
  if (points() * axis.values.size() > kMaxSweepPoints) {
    throw ConfigError(axis.source + ": the grid would have more than " +
                      std::to_string(kMaxSweepPoints) + " points");
  }
  axes_.push_back(std::move(axis));
}

void Sweep::add_flag(std::string_view assignment) {
  const std::string source = "--grid " + shown_text(assignment, std::string::npos);
  const auto equals = assignment.find('=');
  if (equals == std::string_view::npos || equals == 0) {
    throw ConfigError(source + ": give KEY=V1,V2,... (e.g. --grid actor.alpha=0.1,0.2)");
  }
  SweepAxis axis{trimmed(std::string(assignment.substr(0, equals))), {}, source};
  for (const std::string& value : split_values(assignment.substr(equals + 1))) {
    const std::string text = trimmed(value);
    if (text.empty()) throw ConfigError(source + ": an empty value; give V1,V2,...");
    axis.values.push_back(canonical_value(text, source));
  }
  add_axis(std::move(axis));
}

void Sweep::add_yaml(const std::string& text, const std::string& source) {
  YAML::Node section;
  try {
    section = YAML::Load(text)["sweep"];
  } catch (const YAML::Exception& error) {
    throw ConfigError(source + ": malformed YAML: " + error.msg);
  }
  if (!section) return;
  if (!section.IsMap()) {
    throw ConfigError(source +
                      ": sweep is a map of keys to lists of values "
                      "(sweep: {actor.alpha: [0.1, 0.2]})");
  }
  for (const auto& entry : section) {
    if (!entry.first.IsScalar()) {
      throw ConfigError(source + ": a sweep's key is a key path such as actor.alpha; got " +
                        flow_text(entry.first));
    }
    const std::string key = entry.first.as<std::string>();
    SweepAxis axis{key, {}, source + ": sweep." + key};
    if (!entry.second.IsSequence() || entry.second.size() == 0) {
      throw ConfigError(axis.source + " must be a list of values, e.g. [0.1, 0.2]");
    }
    for (const auto& value : entry.second) {
      if (value.IsNull()) throw ConfigError(axis.source + ": an empty value; give V1,V2,...");
      axis.values.push_back(flow_text(value));
    }
    add_axis(std::move(axis));
  }
}

void Sweep::add_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  add_yaml(text.str(), path.string());  // Config::merge_file has checked the file already
}

std::size_t Sweep::points() const {
  std::size_t count = 1;
  for (const SweepAxis& axis : axes_) count *= axis.values.size();
  return count;
}

std::vector<std::string> Sweep::values(std::size_t point) const {
  std::vector<std::string> values(axes_.size());
  for (std::size_t a = axes_.size(); a-- > 0;) {
    const std::size_t size = axes_[a].values.size();
    values[a] = axes_[a].values[point % size];
    point /= size;
  }
  return values;
}

Config Sweep::config(const Config& base, std::size_t point) const {
  Config config = base;
  const std::vector<std::string> point_values = values(point);
  for (std::size_t a = 0; a < axes_.size(); ++a) {
    config.set(axes_[a].key + "=" + point_values[a], axes_[a].source);
  }
  return config;
}

void Sweep::check(const Config& base) const {
  for (const SweepAxis& axis : axes_) {
    for (const std::string& value : axis.values) {
      Config copy = base;
      copy.set(axis.key + "=" + value, axis.source);
    }
  }
}

std::string Sweep::to_yaml() const {
  if (axes_.empty()) return {};
  std::string yaml = "sweep:\n";
  for (const SweepAxis& axis : axes_) {
    yaml += "  " + axis.key + ": [";
    for (std::size_t v = 0; v < axis.values.size(); ++v) {
      yaml += (v == 0 ? "" : ", ") + axis.values[v];
    }
    yaml += "]\n";
  }
  return yaml;
}

}  // namespace cbbg::config
