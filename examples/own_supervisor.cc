// A user's ablation, from the installed library alone: the paper's PD cerebellum replaced by
// a supervisor of our own (a PD law on pitch and wheel speed whose torque saturates), run
// through experiment 1 against the built-in cbbg preset. Seed k gives both arms the same
// random streams (common random numbers), so the comparison is paired seed by seed.
//
//   own_supervisor OUTPUT_DIR [SEEDS [KEY=VALUE | --grid=KEY=V1,V2 ...]]
//
// Writes a results directory (config.yaml, summary.json, trials.csv, evaluation.csv,
// steps.csv, weights/) and figures/diagram.svg (diagram.dot without Graphviz) there; with
// --grid axes (the supervisor's own keys too), one such directory per grid point,
// OUTPUT_DIR/point_NNN. The config is read once, here: below, everything takes the typed
// parameters, the supervisor its own section of them.

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <cbbg/blocks/measured_signals.h>
#include <cbbg/config/declared_keys.h>
#include <cbbg/config/sweep.h>
#include <cbbg/diagrams/presets.h>
#include <cbbg/diagrams/validated_parameters.h>
#include <cbbg/experiments/experiments.h>
#include <cbbg/framework/block_context.h>
#include <cbbg/framework/graphviz.h>
#include <cbbg/parameters/parameters.h>
#include <cbbg/store/results_writer.h>
#include <cbbg/store/run_directory.h>
#include <cbbg/store/sweep_directory.h>
#include <cbbg/store/task_store.h>

namespace {

using namespace cbbg;

// [docs saturated-pd-params]
// The supervisor's own parameters: config keys saturated_pd.*, declared once, here.
struct SaturatedPdParams {
  double k_theta = 60.0;
  double k_dtheta = 12.0;
  double k_v = 1.0;

  template <class Archive>
  void describe(Archive& a) {
    a.number("k_theta", k_theta, "gain on the pitch, N m/rad", kFinite);
    a.number("k_dtheta", k_dtheta, "gain on the pitch rate, N m s/rad", kFinite);
    a.number("k_v", k_v, "gain on the mean wheel speed, N m s/rad", kFinite);
  }
};
// [docs saturated-pd-params end]

/// SaturatedPd: a_S = clamp(k_theta theta_b + k_dtheta theta_b' + k_v (phi_l' + phi_r') / 2,
/// -limit, limit). Input "measured" (6), output "action" (1): the cerebellum's slot.
class SaturatedPd final : public Block {
 public:
  SaturatedPd(std::string name, const SaturatedPdParams& gains, double limit)
      : Block(std::move(name)), gains_(gains), limit_(limit) {
    measured_ = &declare_input_port("measured", blocks::kMeasuredSize);
    declare_output_port<&SaturatedPd::calc_action>("action", 1, {measured_});
  }

 private:
  // "action": the PD law above, clamped to the limit.
  void calc_action(const BlockContext& context, VectorRef action) const {
    const auto y = context.input(*measured_);
    const double wheel_speed =
        (y[blocks::kMeasuredPhiLeftDot] + y[blocks::kMeasuredPhiRightDot]) / 2.0;
    const double law = gains_.k_theta * y[blocks::kMeasuredThetaB] +
                       gains_.k_dtheta * y[blocks::kMeasuredThetaBDot] + gains_.k_v * wheel_speed;
    action[0] = std::clamp(law, -limit_, limit_);
  }

  SaturatedPdParams gains_;
  double limit_;
  const InputPort* measured_;
};

void render(const diagrams::Arm& arm, const parameters::Parameters& parameters,
            const std::filesystem::path& figures) {
  std::filesystem::create_directories(figures);
  const std::string dot =
      to_dot(*arm.learner(parameters).diagram, {.hidden_blocks = {arm.name + "/telemetry"}});
  try {
    render_dot(dot, figures / "diagram.svg");
  } catch (const std::runtime_error& error) {  // no Graphviz: the DOT text still tells
    std::fprintf(stderr, "own_supervisor: %s; writing diagram.dot\n", error.what());
    render_dot(dot, figures / "diagram.dot");
  }
}

// One grid point: the run's config (what its directory records) and its typed parameters.
struct Point {
  config::Config config;
  parameters::Parameters parameters;
};

// The edge of the program: the config made from the arguments, and every grid point's
// parameters checked, before anything runs. Throws config::ConfigError.
std::vector<Point> read_points(int argc, char** argv) {
  config::Config config;
  config::Sweep sweep;
  config.set("plant.kind=analytic");
  config.set("seeds=" + std::string(argc > 2 ? argv[2] : "3"));
  config.set("log.decimation=10");
  for (int i = 3; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.starts_with("--grid=")) {
      sweep.add_flag(argument.substr(7));  // --grid=saturated_pd.k_theta=50,70
    } else {
      config.set(argument);  // saturated_pd.k_theta=70
    }
  }
  sweep.check(config);
  std::vector<Point> points;
  for (std::size_t p = 0; p < sweep.points(); ++p) {
    config::Config point = sweep.config(config, p);
    points.push_back({point, diagrams::validated_parameters(point)});
  }
  return points;
}

// Experiment 1 of both arms at one point, into the results directory `out`.
void run_point(const Point& point, const std::filesystem::path& out) {
  // [docs own-supervisor]
  diagrams::ControllerOptions mine = diagrams::preset("cbbg").options;
  mine.slots.supervisor = [](const diagrams::SlotRequest& request) {
    return std::make_unique<SaturatedPd>(request.name,
                                         request.section<SaturatedPdParams>("saturated_pd"),
                                         request.parameters.plant.robot.torque_limit);
  };
  const std::vector<diagrams::Arm> arms{diagrams::preset_arm("cbbg"),
                                        diagrams::make_arm("cbbg_saturated_pd", mine)};

  store::RunDirectory directory = store::RunDirectory::create(out, point.config, {});
  const store::TaskStore tasks(directory.tasks());
  const experiments::ExperimentResults results =
      experiments::run_exp1(point.parameters, arms, {.jobs = 2, .store = &tasks});
  // config.yaml records the arms that ran and saturated_pd.*, with every other key.
  store::write_result_files(results, point.config, store::run_facts(point.parameters),
                            directory.work(), &tasks);
  render(arms[1], point.parameters, directory.work() / "figures");
  directory.commit();
  // [docs own-supervisor end]

  std::printf("%s\n%-6s %22s %22s\n", out.string().c_str(), "seed", "cbbg failures",
              "cbbg_saturated_pd failures");
  for (std::size_t s = 0; s < results.seeds.size(); ++s) {
    std::printf("%-6lld %22d %22d\n", results.seeds[s], results.run(0, s).failures_before_success,
                results.run(1, s).failures_before_success);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: own_supervisor OUTPUT_DIR [SEEDS [KEY=VALUE | --grid=KEY=V1,V2 ...]]\n");
    return 2;
  }
  // [docs register-section]
  // Before any config is made: saturated_pd.* become keys like the built-in ones.
  config::register_section<SaturatedPdParams>("saturated_pd");
  // [docs register-section end]
  std::vector<Point> points;
  try {
    points = read_points(argc, argv);
  } catch (const config::ConfigError& error) {
    std::fprintf(stderr, "own_supervisor: %s\n", error.what());
    return 2;
  }
  try {
    const std::filesystem::path out = argv[1];
    if (points.size() == 1) {
      run_point(points.front(), out);
      return 0;
    }
    std::filesystem::create_directories(out);  // a grid: one results directory per point
    for (std::size_t p = 0; p < points.size(); ++p) {
      run_point(points[p], out / ("point_" + store::point_name(p, points.size())));
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "own_supervisor: %s\n", error.what());
    return 1;
  }
  return 0;
}
