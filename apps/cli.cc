#include "cbbg/apps/cli.h"

#include <charconv>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cbbg/apps/commands.h"
#include "cbbg/apps/drive_command.h"
#include "cbbg/apps/errors.h"
#include "cbbg/apps/eval_command.h"
#include "cbbg/apps/export_command.h"
#include "cbbg/apps/figures.h"
#include "cbbg/apps/robot_command.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/run_names.h"

namespace {

// A number as --set reads one: decimal (1.5, -2, 1e3, nan, inf), never hexadecimal or octal,
// which CLI11 alone would take ("0x10" as 16).
const CLI::Validator kDecimal(
    [](std::string& text) {
      double value = 0.0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      const bool decimal = error == std::errc() && end == text.data() + text.size();
      return decimal ? std::string() : "must be a decimal number; got '" + text + "'";
    },
    "DECIMAL");

// --jobs as typed: an integer from 1 to 1024.
bool parse_jobs(const std::string& text, int& jobs) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > 1024) {
    return false;
  }
  jobs = value;
  return true;
}

// "a | b | c": names for a flag's help, from their tables.
std::string alternatives(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : " | ") + name;
  return text;
}

std::string experiment_help() {
  std::vector<std::string> names;
  for (const auto& protocol : cbbg::experiments::protocol_names()) names.push_back(protocol.name);
  return alternatives(names) + " | a diagram name (default: the config's, exp1)";
}

std::string diagram_help() { return alternatives(cbbg::diagrams::diagram_names()); }

// The first word of the command line when it names no subcommand of `app` ("" when it does,
// or there is none): the words before it are the main options (--log-level and its value).
std::string unknown_command(const CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--log-level") {
      ++i;  // its value
      continue;
    }
    if (word.starts_with("-")) continue;
    for (const CLI::App* command : app.get_subcommands({})) {
      if (command->get_name() == word) return "";
    }
    return word;
  }
  return "";
}

}  // namespace

namespace cbbg::app {

int run_cli(int argc, char** argv, const std::filesystem::path& share) {
  set_share_directory(share);
  if (argc > 0 && argv[0] != nullptr && *argv[0] != '\0') {
    set_program_name(std::filesystem::path(argv[0]).filename().string());
  }
  CLI::App app{"cbbg: cerebellum-basal-ganglia motor learning on a two-wheeled robot"};
  app.require_subcommand(0, 1);
  app.fallthrough();  // --log-level after the command too: `cbbg run --log-level warn`
  std::string log_level = "info";
  app.add_option("--log-level", log_level, "trace | debug | info | warn | error | off")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));

  RunOptions run;
  run.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App* run_app = app.add_subcommand("run", "run an experiment over many seeds (the default)");
  std::string experiment;
  std::string seeds;
  std::string seed;
  std::filesystem::path resume;
  auto* experiment_option = run_app->add_option("--experiment", experiment, experiment_help());
  run_app->add_option("--config", run.config_file, "a YAML config (keys: `cbbg list`)");
  run_app->add_option("--set", run.sets, "override one key: --set critic.gamma=0.9 (repeatable)");
  // Numbers are checked by the config's schema, with the project's messages and limits.
  auto* seeds_option = run_app->add_option("--seeds", seeds, "independent runs per arm");
  auto* seed_option = run_app->add_option("--seed", seed, "root seed; run k uses seed + k");
  std::string jobs;
  auto* jobs_option = run_app->add_option(
      "--jobs,-j", jobs, "threads, 1 to 1024 (results are the same for any count)");
  auto* out_option =
      run_app->add_option("--out,-o", run.out, "results directory (a new path, or --replace)");
  auto* resume_option =
      run_app
          ->add_option("--resume", resume,
                       "continue the interrupted run into DIR (its DIR.partial), redoing only "
                       "the unfinished seeds")
          ->excludes(out_option);
  run_app->add_flag("--replace", run.replace,
                    "replace the results of an earlier run at --out (kept until the new ones "
                    "are complete)");
  run_app->add_flag("--check", run.check,
                    "check the config, the arms, the weights and the options as a run would "
                    "before any work, then stop (nothing is written; --out is not looked at)");
  run_app->add_flag("!--no-figures", run.figures, "skip the figures");
  run_app->add_flag("!--no-replay", run.replays,
                    "skip the replay pages in figures/ (cbbg replay makes one of any trial)");
  run_app->add_option("--load-weights", run.load_weights,
                      "start learning from a weights file (docs/weights-format.md)");
  run_app->add_option("--save-weights", run.save_weights,
                      "write the learnt weights (a run with one learning arm and one seed)");
  run_app->add_option("--grid", run.grid,
                      "sweep a key over values: --grid actor.alpha=0.1,0.2 (repeatable: the "
                      "grid is their product)");
  std::string shard;
  auto* shard_option = run_app->add_option(
      "--shard", shard, "run only shard K of N of the sweep's tasks (then: cbbg merge DIR)");

  std::filesystem::path merge_directory;
  CLI::App* merge_app =
      app.add_subcommand("merge", "merge the shards of a sweep into one results directory");
  merge_app->add_option("DIR", merge_directory, "the sweep's --out")->required();
  std::filesystem::path status_directory;
  CLI::App* status_app = app.add_subcommand(
      "status", "how far a run or a sweep got: tasks done and missing, failed shards");
  status_app->add_option("DIR", status_directory, "the run's or the sweep's --out")->required();

  GraphOptions graph;
  CLI::App* graph_app = app.add_subcommand("graph", "draw a diagram (.dot, .svg or .png)");
  auto* diagram_option = graph_app->add_option("--diagram", graph.diagram, diagram_help());
  graph_app->add_option("--config", graph.config_file, "a YAML config")->excludes(diagram_option);
  graph_app->add_option("--set", graph.sets, "override one key (repeatable)");
  graph_app->add_option("--depth", graph.max_depth, "nesting levels to expand (default: all)");
  graph_app->add_option("-o,--output", graph.output, "FILE.dot | FILE.svg | FILE.png")->required();
  graph_app->add_flag("--show-telemetry", graph.show_telemetry,
                      "draw the telemetry multiplexer and its wires too");

  std::filesystem::path plot_directory;
  CLI::App* plot_app = app.add_subcommand("plot", "draw the figures of a results directory");
  plot_app->add_option("DIR", plot_directory, "a results directory")->required();

  ReplayOptions replay;
  CLI::App* replay_app = app.add_subcommand(
      "replay", "a 3-D replay of trials in one offline HTML file (open it in a browser)");
  replay_app->add_option("DIR", replay.directory, "a results directory")->required();
  replay_app->add_option("--arm", replay.arm, "the arm (default: the run's first)");
  replay_app->add_option("--seed", replay.seed, "the seed (default: the arm's first)");
  replay_app->add_option("--trial", replay.trials,
                         "trials to show, from 1 (default: the first, the first successful "
                         "and the last)");
  replay_app->add_option("-o,--out", replay.output, "the page to write, FILE.html")->required();

  EvalOptions eval;
  CLI::App* eval_app =
      app.add_subcommand("eval", "evaluate learnt weights: the actor alone, frozen, per angle");
  eval_app
      ->add_option("--load-weights", eval.weights_file, "a weights file (cbbg run --save-weights)")
      ->required();
  eval_app->add_option("--config", eval.config_file, "a YAML config (keys: `cbbg list`)");
  eval_app->add_option("--set", eval.sets,
                       "override one key: --set plant.kind=analytic (repeatable)");
  eval_app->add_option("--angles", eval.angles,
                       "initial pitches, rad, comma-separated (default: evaluation.angles)");
  eval_app->add_option("--repeats", eval.repeats, "runs per angle, seeds seed, seed + 1, ...")
      ->check(kDecimal);
  const std::tuple<const char*, std::optional<double>*, const char*> push_flags[] = {
      {"--push-time", &eval.push_time, "push start, s (with --push-duration and a push size)"},
      {"--push-torque", &eval.push_torque,
       "push through the motors: N m added to both wheels' torque"},
      {"--push-force", &eval.push_force,
       "push from outside: N at the body's centre of mass, along the heading"},
      {"--push-pitch-torque", &eval.push_pitch_torque,
       "push from outside: N m on the body about the axle"},
      {"--push-duration", &eval.push_duration, "push length, s"}};
  for (const auto& [flag, value, help] : push_flags) {
    eval_app->add_option(flag, *value, help)->check(kDecimal);
  }
  eval_app->add_flag("--linearise", eval.linearise,
                     "also print the actor's slopes at rest and the closed loop's modes");
  eval_app->add_option("--out,-o", eval.out, "write DIR/evaluation.csv");

  ExportOptions export_options;
  CLI::App* export_app = app.add_subcommand(
      "export", "write learnt weights' policy as dependency-free C99: DIR/NAME.h, DIR/NAME.c");
  export_app
      ->add_option("--load-weights", export_options.weights_file,
                   "a weights file (cbbg run --save-weights)")
      ->required();
  export_app->add_option("--config", export_options.config_file,
                         "a YAML config (keys: `cbbg list`)");
  export_app->add_option("--set", export_options.sets, "override one key (repeatable)");
  export_app->add_option("--out,-o", export_options.out, "the directory to write into")->required();
  export_app->add_option("--name", export_options.name,
                         "prefix of the files and of the C identifiers (default: cbbg_policy, "
                         "with --learner cbbg_learner)");
  export_app->add_option("--scalar", export_options.scalar, "double (default) or float");
  export_app
      ->add_option("--omega", export_options.omega,
                   "with the supervisor and the mixer at this omega, 0 to 1, no exploration")
      ->check(kDecimal);
  export_app->add_flag("--learner", export_options.learner,
                       "the whole online learner, which goes on learning (its generators as "
                       "run.seed's)");

  DriveOptions drive;
  CLI::App* drive_app = app.add_subcommand(
      "drive", "drive a robot over UDP in real time (cbbg robot, or a real one): a run's results");
  drive_app->add_option("--controller", drive.controller,
                        "an arm: cbbg (learns on; default), pd_only, bg_only, a registered one");
  drive_app->add_flag("--policy", drive.policy,
                      "the arm's learnt actor alone, frozen, with the weights of --load-weights");
  drive_app->add_option("--load-weights", drive.weights_file,
                        "weights to start learning from, or (--policy) to run");
  drive_app->add_option("--config", drive.config_file, "a YAML config (keys: `cbbg list`)");
  drive_app->add_option("--set", drive.sets, "override one key (repeatable)");
  drive_app->add_option("--robot", drive.robot,
                        "the robot's HOST:PORT (default remote.host:remote.port, 127.0.0.1:5005)");
  drive_app->add_option("--bind", drive.bind,
                        "this end's HOST:PORT (default remote.bind_host:bind_port, 127.0.0.1:0)");
  drive_app->add_option("--key-file", drive.key_file,
                        "a file holding the key shared with the robot");
  drive_app->add_option("--duration", drive.duration, "s per trial (trial.duration)")
      ->check(kDecimal);
  drive_app->add_option("--trials", drive.trials, "trials in all (realtime.trials; default 1)");
  drive_app->add_option("--out,-o", drive.out, "results directory (default: drive)");
  drive_app->add_flag("--replace", drive.replace, "replace an earlier run's results at --out");
  drive_app->add_flag("!--no-figures", drive.figures, "skip the figures");

  RobotOptions robot;
  CLI::App* robot_app = app.add_subcommand(
      "robot", "serve a simulated robot (plant.kind's) over UDP in real time, for cbbg drive");
  robot_app->add_option("--config", robot.config_file, "a YAML config: plant.*, trial.period");
  robot_app->add_option("--set", robot.sets, "override one key (repeatable)");
  robot_app->add_option("--bind", robot.bind,
                        "HOST:PORT to serve on (default 127.0.0.1:5005; port 0: any, printed)");
  robot_app->add_option("--key-file", robot.key_file, "a file holding the key shared with drive");
  robot_app
      ->add_option("--deadline", robot.deadline,
                   "a torque must come within this fraction of a period (default 0.5)")
      ->check(kDecimal);
  robot_app->add_flag("--lockstep", robot.lockstep,
                      "wait for each torque instead of holding the last (a simulator in the "
                      "loop: the trial is the simulated one, its pace not real)");
  robot_app->add_option("--timeout-periods", robot.timeout_periods,
                        "periods without a torque that end a session (default 10)");
  robot_app->add_option("--sessions", robot.sessions,
                        "sessions to serve, then exit (default 0: until SIGINT)");

  CLI::App* list_app =
      app.add_subcommand("list", "list the diagrams, the blocks and every config key");
  bool keys_markdown = false;
  list_app->add_flag("--keys-markdown", keys_markdown,
                     "only the config keys, as a Markdown table (docs/parameters.md)");

  if (const std::string word = unknown_command(app, argc, argv); !word.empty()) {
    // Before CLI11 reads a --help after it as the main help's.
    return report_error(kUserError, "unknown command '" + config::shown_text(word) + "' (" +
                                        program_name() + " --help lists the commands)");
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    // Command-line misuse, like a bad config: one line, exit 2.
    return report_error(kUserError, std::string(error.what()) + " (" + program_name() +
                                        " --help lists the commands and options)");
  }
  if (jobs_option->count() > 0 && !parse_jobs(jobs, run.jobs)) {
    return report_error(kUserError, "--jobs must be an integer from 1 to 1024; got '" + jobs + "'");
  }
  if (experiment_option->count() > 0) run.experiment = experiment;
  if (seeds_option->count() > 0) run.seeds = seeds;
  if (seed_option->count() > 0) run.seed = seed;
  if (resume_option->count() > 0) run.resume = resume;
  if (shard_option->count() > 0) run.shard = shard;
  spdlog::set_level(spdlog::level::from_str(log_level));
  spdlog::set_pattern("[%H:%M:%S] %^%l%$ %v");

  // Each command reports its own errors; this catches what slips past them, so nothing ends
  // in std::terminate.
  try {
    if (eval_app->parsed()) return eval_command(eval);
    if (export_app->parsed()) return export_command(export_options);
    if (drive_app->parsed()) return drive_command(drive);
    if (robot_app->parsed()) return robot_command(robot);
    if (graph_app->parsed()) return graph_command(graph);
    if (plot_app->parsed()) return plot_command(plot_directory);
    if (replay_app->parsed()) return replay_command(replay);
    if (list_app->parsed()) return list_command(keys_markdown);
    if (merge_app->parsed()) return merge_command(merge_directory);
    if (status_app->parsed()) return status_command(status_directory);
    return run_command(run);  // `cbbg` alone runs exp1 with the paper's defaults
  } catch (const std::exception& error) {
    return report_error(kMachineError, describe(error));
  }
}

}  // namespace cbbg::app
