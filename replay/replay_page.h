#pragma once
// The replay page: one self-contained HTML file (share/cbbg/replay.html, the page with
// three.js bundled at build time) with a run's chosen trials written into it. It needs no
// network when opened.

#include <filesystem>
#include <string>
#include <vector>

#include "cbbg/parameters/parameters.h"
#include "cbbg/plant/plant_drawing.h"
#include "cbbg/replay/trial_log.h"

namespace cbbg::replay {

// The page's generator tag: a file holding it was written by cbbg replay.
inline constexpr const char* kGeneratorTag = "<meta name=\"generator\" content=\"cbbg replay\">";

// Ticks a trial keeps on the page at most: a longer one is shown every n-th logged tick
// (and its last), n the smallest that fits.
inline constexpr std::size_t kMaxTicksShown = 20000;

// What the page draws of the robot and of its limits.
struct ReplayRobot {
  plant::PlantDrawing drawing;  // the plant's own (RobotPlant::drawing)
  double failure_angle = 0.52;  // trial.failure_angle, rad
  double torque_limit = 5.0;    // plant.torque_limit, N m
};

// The robot of a run's parameters: the drawing of the plant plant.kind's kind builds from them
// (a user's kind's plant states its own), and the limits.
ReplayRobot replay_robot(const parameters::Parameters& parameters);

// `page_template` with `trials` in it. Throws std::invalid_argument when the template is not
// a replay page (no generator tag or no data marker).
std::string replay_page(const std::string& page_template, const std::string& title,
                        const ReplayRobot& robot, const std::vector<TrialLog>& trials);

// The page of the chosen trials of the results directory `run` (its config.yaml, trials.csv
// and steps.csv), titled with `name` (empty: the directory's name). Throws InputError naming
// a missing or malformed file and ChoiceError for a choice the run does not have.
std::string replay_of_run(const std::filesystem::path& run, const TrialChoice& choice,
                          const std::string& page_template, const std::string& name = {});

}  // namespace cbbg::replay
