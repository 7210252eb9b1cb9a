#include "replay/replay_page.h"

#include <cmath>
#include <stdexcept>

#include "framework/number_text.h"

namespace cbbg::replay {
namespace {

constexpr std::string_view kDataPlaceholder = "__CBBG_REPLAY_DATA__";

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

std::string trial_json(const TrialLog& log) {
  std::string json = "{\"arm\":" + json_string(log.entry.arm);
  json += ",\"seed\":" + std::to_string(log.entry.seed);
  json += ",\"trial\":" + std::to_string(log.entry.trial);
  json += ",\"status\":" + json_string(log.entry.status);
  append_numbers(json, "t", log.t);
  append_numbers(json, "theta_b", log.theta_b);
  append_numbers(json, "phi_l", log.phi_l);
  append_numbers(json, "phi_r", log.phi_r);
  append_numbers(json, "x", log.x);
  append_numbers(json, "y", log.y);
  append_numbers(json, "yaw", log.yaw);
  append_numbers(json, "a", log.a);
  return json + "}";
}

std::string robot_json(const ReplayRobot& robot) {
  return "{\"wheel_radius\":" + format_number(robot.wheel_radius) +
         ",\"track_width\":" + format_number(robot.track_width) +
         ",\"com_height\":" + format_number(robot.com_height) +
         ",\"failure_angle\":" + format_number(robot.failure_angle) +
         ",\"torque_limit\":" + format_number(robot.torque_limit) + "}";
}

}  // namespace

ReplayRobot replay_robot(const config::Config& config) {
  return {config.number("plant.wheel_radius"), config.number("plant.track_width"),
          config.number("plant.com_height"), config.number("trial.failure_angle"),
          config.number("plant.torque_limit")};
}

std::string replay_page(const std::string& page_template, const std::string& title,
                        const ReplayRobot& robot, const std::vector<TrialLog>& trials) {
  const std::size_t at = page_template.find(kDataPlaceholder);
  if (page_template.find(kGeneratorTag) == std::string::npos || at == std::string::npos) {
    throw std::invalid_argument(
        "the replay page template is not cbbg's (no generator tag or "
        "no data placeholder)");
  }
  std::string data =
      "{\"title\":" + json_string(title) + ",\"robot\":" + robot_json(robot) + ",\"trials\":[";
  for (std::size_t i = 0; i < trials.size(); ++i) {
    if (i > 0) data += ',';
    data += trial_json(trials[i]);
  }
  data += "]}";
  std::string page = page_template.substr(0, at);
  page += data;
  page += page_template.substr(at + kDataPlaceholder.size());
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
  const std::string title = config.text("experiment") + ", " + config.text("plant.kind") +
                            " plant: " + (name.empty() ? run.filename().string() : name);
  return replay_page(page_template, title, replay_robot(config), logs);
}

}  // namespace cbbg::replay
