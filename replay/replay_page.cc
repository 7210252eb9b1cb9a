#include "cbbg/replay/replay_page.h"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/framework/number_text.h"

namespace cbbg::replay {
namespace {

constexpr std::string_view kDataMarker = "__CBBG_REPLAY_DATA__";

// A JSON string of plain text: arm names, statuses and titles, with '<' escaped so that the
// text cannot close the page's script element.
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '<') {
      out += "\\u003c";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// Appends ,"name":value (the first member without its comma), piece by piece: GCC 12 warns
// falsely (-Wrestrict) on chains of operator+.
void append_member(std::string& json, const char* name, const std::string& value) {
  if (json.size() > 1) json += ',';
  json += '"';
  json += name;
  json += "\":";
  json += value;
}

void append_numbers(std::string& json, const char* name, const std::vector<double>& values) {
  json += ",\"";
  json += name;
  json += "\":[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) json += ',';
    // Not finite (a commanded torque that diverged): JSON has only null for it.
    json += std::isfinite(values[i]) ? format_number(values[i]) : std::string("null");
  }
  json += ']';
}

// Every stride-th of `values`, and the last.
std::vector<double> every(const std::vector<double>& values, std::size_t stride) {
  std::vector<double> kept;
  for (std::size_t i = 0; i < values.size(); i += stride) kept.push_back(values[i]);
  if ((values.size() - 1) % stride != 0) kept.push_back(values.back());
  return kept;
}

std::string trial_json(const TrialLog& log) {
  // A long trial is shown every stride-th tick, so the page stays a few megabytes.
  const std::size_t stride = (log.t.size() + kMaxTicksShown - 1) / kMaxTicksShown;
  std::string json = "{";
  append_member(json, "arm", json_string(log.entry.arm));
  append_member(json, "seed", std::to_string(log.entry.seed));
  append_member(json, "trial", std::to_string(log.entry.trial));
  append_member(json, "status", json_string(log.entry.status));
  append_member(json, "stride", std::to_string(stride));
  for (int c = 0; c < TrialLog::kColumns; ++c) {
    append_numbers(json, TrialLog::kColumnNames[c], every(log.column(c), stride));
  }
  return json + "}";
}

template <std::size_t N>
std::string json_numbers(const std::array<double, N>& values) {
  std::string json = "[";
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) json += ',';
    json += format_number(values[i]);
  }
  return json + "]";
}

// A JSON array of `items`, each written by `to_json`.
template <class Item, class ToJson>
std::string json_array(const std::vector<Item>& items, ToJson to_json) {
  std::string json = "[";
  for (const Item& item : items) {
    if (json.size() > 1) json += ',';
    json += to_json(item);
  }
  return json + "]";
}

// The page's column (TrialLog::kColumnNames) that a plant signal is logged in, or null for
// a signal steps.csv does not keep: its joint is drawn at rest.
std::string column_of(const std::string& signal) {
  static const std::map<std::string, std::string> columns = {{"pitch", "theta_b"},
                                                             {"wheel_left", "phi_l"},
                                                             {"wheel_right", "phi_r"},
                                                             {"wheel", "phi_l"},
                                                             {"x", "x"},
                                                             {"y", "y"},
                                                             {"yaw", "yaw"}};
  const auto found = columns.find(signal);
  return found == columns.end() ? "null" : json_string(found->second);
}

std::string joint_json(const plant::DrawnJoint& joint) {
  std::string json = "{";
  append_member(json, "kind",
                json_string(joint.kind == plant::DrawnJoint::Kind::kHinge ? "hinge" : "slide"));
  append_member(json, "axis", json_numbers(joint.axis));
  append_member(json, "anchor", json_numbers(joint.anchor));
  append_member(json, "column", column_of(joint.signal));
  append_member(json, "rest", format_number(joint.rest));
  return json + "}";
}

std::string body_json(const plant::DrawnBody& body) {
  std::string json = "{";
  append_member(json, "parent", std::to_string(body.parent));
  append_member(json, "position", json_numbers(body.position));
  append_member(json, "orientation", json_numbers(body.orientation));
  append_member(json, "joints", json_array(body.joints, joint_json));
  return json + "}";
}

std::string shape_json(const plant::DrawnShape& shape) {
  static const std::map<plant::DrawnShape::Kind, const char*> kinds = {
      {plant::DrawnShape::Kind::kBox, "box"},
      {plant::DrawnShape::Kind::kSphere, "sphere"},
      {plant::DrawnShape::Kind::kCapsule, "capsule"},
      {plant::DrawnShape::Kind::kCylinder, "cylinder"},
      {plant::DrawnShape::Kind::kEllipsoid, "ellipsoid"}};
  std::string json = "{";
  append_member(json, "kind", json_string(kinds.at(shape.kind)));
  append_member(json, "body", std::to_string(shape.body));
  append_member(json, "size", json_numbers(shape.size));
  append_member(json, "position", json_numbers(shape.position));
  append_member(json, "orientation", json_numbers(shape.orientation));
  append_member(json, "colour", json_numbers(shape.colour));
  return json + "}";
}

// A model's own drawing: {"bodies": [...], "shapes": [...]}.
std::string model_json(const plant::ModelDrawing& model) {
  std::string json = "{";
  append_member(json, "bodies", json_array(model.bodies, body_json));
  append_member(json, "shapes", json_array(model.shapes, shape_json));
  return json + "}";
}

std::string robot_json(const ReplayRobot& robot) {
  const plant::PlantDrawing& drawing = robot.drawing;
  std::string json = "{";
  append_member(json, "wheel_radius", format_number(drawing.wheel_radius));
  append_member(json, "track_width", format_number(drawing.track_width));
  append_member(json, "cart_length", format_number(drawing.cart_length));
  append_member(json, "cart_height", format_number(drawing.cart_height));
  append_member(json, "body_length", format_number(drawing.body_length));
  append_member(json, "body_thickness", format_number(drawing.body_thickness));
  append_member(json, "body_width", format_number(drawing.body_width));
  append_member(json, "com_height", format_number(drawing.com_height));
  append_member(json, "failure_angle", format_number(robot.failure_angle));
  append_member(json, "torque_limit", format_number(robot.torque_limit));
  if (!drawing.model.empty()) append_member(json, "model", model_json(drawing.model));
  return json + "}";
}

}  // namespace

ReplayRobot replay_robot(const parameters::Parameters& parameters) {
  const auto plant = diagrams::plant_kind(parameters.plant.kind).make("plant", parameters);
  return {plant->drawing(), parameters.trial.failure_angle, parameters.plant.robot.torque_limit};
}

std::string replay_page(const std::string& page_template, const std::string& title,
                        const ReplayRobot& robot, const std::vector<TrialLog>& trials) {
  const std::size_t at = page_template.find(kDataMarker);
  if (page_template.find(kGeneratorTag) == std::string::npos || at == std::string::npos) {
    throw std::invalid_argument(
        "the replay page template is not cbbg's (no generator tag or "
        "no data marker)");
  }
  std::string data = "{";
  append_member(data, "title", json_string(title));
  append_member(data, "robot", robot_json(robot));
  append_member(data, "trials", "[");
  for (std::size_t i = 0; i < trials.size(); ++i) {
    if (i > 0) data += ',';
    data += trial_json(trials[i]);
  }
  data += "]}";
  std::string page = page_template.substr(0, at);
  page += data;
  page += page_template.substr(at + kDataMarker.size());
  return page;
}

std::string replay_of_run(const std::filesystem::path& run, const TrialChoice& choice,
                          const std::string& page_template, const std::string& name) {
  config::Config config;
  const std::filesystem::path config_file = run / "config.yaml";
  std::error_code error;
  if (!std::filesystem::is_regular_file(config_file, error)) {
    throw InputError("'" + run.string() + "' is not a results directory (it has no config.yaml)");
  }
  config.merge_file(config_file);
  const std::vector<TrialEntry> chosen =
      choose_trials(read_trial_entries(run / "trials.csv"), choice);
  const std::vector<TrialLog> logs = read_trial_logs(run / "steps.csv", chosen);
  const parameters::Parameters parameters = parameters::read_parameters(config);
  const std::string title = parameters.run.experiment + ", " + parameters.plant.kind +
                            " plant: " + (name.empty() ? run.filename().string() : name);
  return replay_page(page_template, title, replay_robot(parameters), logs);
}

}  // namespace cbbg::replay
