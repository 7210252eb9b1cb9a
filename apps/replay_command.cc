// cbbg replay DIR: a run's trials as one offline HTML page (replay/), and the replays
// `cbbg run` leaves in figures/.

#include <fstream>
#include <iterator>

#include <spdlog/spdlog.h>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/errors.h"
#include "cbbg/apps/figures.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/replay/replay_page.h"
#include "cbbg/store/files.h"
#include "cbbg/store/output_guard.h"

namespace cbbg::app {
namespace {

// The bundled page: $CBBG_REPLAY_PAGE, else share/cbbg/replay.html beside bin/.
std::string page_template() {
  const std::filesystem::path page = shared_file("CBBG_REPLAY_PAGE", "replay.html");
  std::ifstream in(page, std::ios::binary);
  if (!in) {
    throw std::runtime_error("the replay page '" + page.string() +
                             "' is missing: it is bundled at build time with node and npm "
                             "(scripts/setup.sh installs them), or set CBBG_REPLAY_PAGE");
  }
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int replay_command(const ReplayOptions& options) {
  std::string page;
  try {
    if (options.output.empty()) throw config::ConfigError("-o FILE.html is required");
    for (const int trial : options.trials) {
      if (trial < 1) {
        throw config::ConfigError("--trial must be 1 or more; got " + std::to_string(trial));
      }
    }
    check_output_file(options.output, "-o");
    store::check_replaceable_file(options.output, "-o", replay::kGeneratorTag);
    page = replay::replay_of_run(options.directory, {options.arm, options.seed, options.trials},
                                 page_template());
  } catch (const config::ConfigError& error) {
    return report_error(kUserError, error.what());
  } catch (const replay::InputError& error) {
    return report_error(kUserError, error.what());
  } catch (const replay::ChoiceError& error) {
    return report_error(kUserError, error.what());
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  try {
    store::write_atomically(options.output, page);
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
  spdlog::info("replay in {} (open it in a browser; it needs no network)", options.output.string());
  return 0;
}

bool write_run_replays(const std::filesystem::path& directory,
                       const parameters::Parameters& parameters, const std::string& run_name) {
  if (parameters.log.decimation == 0) {
    spdlog::info("no replays: the run logged no ticks (log.decimation: 0)");
    return true;
  }
  try {
    if (replay::read_trial_entries(directory / "trials.csv").empty()) {
      spdlog::info("no replays: the run ran no trials (its evaluation runs are not logged)");
      return true;
    }
    const std::string page = page_template();
    store::Manifest manifest(directory / "figures");
    for (const std::string& arm : run_arms(directory, parameters.run)) {
      manifest.check_writable({replay_figure(arm)}, "the replay");
      manifest.add({replay_figure(arm)});
      store::write_atomically(
          directory / "figures" / replay_figure(arm),
          replay::replay_of_run(directory, {arm, std::nullopt, {}}, page, run_name));
    }
    return true;
  } catch (const std::exception& error) {
    spdlog::warn("the replays could not be written: {}", describe(error));
    return false;
  }
}

}  // namespace cbbg::app
