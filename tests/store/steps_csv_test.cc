// steps.csv from the tasks' rows: one header, the columns of the plant's signals; the header
// alone when no task logged a row.

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/config/config.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/experiments.h"
#include "cbbg/framework/block_context.h"
#include "cbbg/store/results_writer.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::store {
namespace {

using ::testing::ThrowsMessage;
namespace fs = std::filesystem;

config::Config quick_config() {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("seeds=1");
  config.set("max_trials=1");
  config.set("trial.duration=0.05");
  config.set("log.decimation=1");
  config.set("evaluation.angles=[0.1]");
  return config;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A pitch on one wheel, no pose: the signals pitch, pitch_rate, wheel, wheel_rate.
class OneWheel final : public plant::RobotPlant {
 public:
  explicit OneWheel(std::string name) : RobotPlant(std::move(name)) {
    declare_input_port("torque", plant::kTorqueSize);
    declare_output_port("state", 4, [](const BlockContext&, VectorRef y) { y.setZero(); }, {});
  }
  std::vector<std::string> signals() const override {
    return {"pitch", "pitch_rate", "wheel", "wheel_rate"};
  }
  void reset(Context&, double) const override {}
};

TEST(StepsCsv, OneHeaderThenEveryTasksRowsOrTheHeaderAlone) {
  const config::Config config = quick_config();
  experiments::ExperimentResults results =
      experiments::run_exp1(diagrams::validated_parameters(config),
                            {diagrams::preset_arm("pd_only"), diagrams::preset_arm("bg_only")});
  const std::string header = experiments::steps_csv_header();
  ASSERT_TRUE(results.runs[1].steps_csv.starts_with(header));
  const cbbg::testing::ScratchDirectory scratch;
  write_result_files(results, config, run_facts(parameters::read_parameters(config)),
                     scratch.path());
  const std::string written = read(scratch.path() / "steps.csv");
  EXPECT_EQ(written, header + results.runs[0].steps_csv.substr(header.size()) +
                         results.runs[1].steps_csv.substr(header.size()));

  // A protocol that runs no trial (evaluate) logs no row: the header alone.
  EXPECT_EQ(results.steps_header, header);
  for (auto& run : results.runs) run.steps_csv.clear();
  write_result_files(results, config, run_facts(parameters::read_parameters(config)),
                     scratch.path());
  EXPECT_EQ(read(scratch.path() / "steps.csv"), header);
}

TEST(StepsCsv, ArmsWhosePlantsGiveOtherSignalsAreRefused) {
  const config::Config config = quick_config();
  diagrams::ClosedLoopOptions one_wheel;
  one_wheel.plant = [](const std::string& name, const parameters::Parameters&) {
    return std::make_unique<OneWheel>(name);
  };
  const experiments::ExperimentResults results = experiments::run_exp1(
      diagrams::validated_parameters(config),
      {diagrams::preset_arm("pd_only"), diagrams::preset_arm("bg_only", one_wheel)});
  const cbbg::testing::ScratchDirectory scratch;
  const std::string path = (scratch.path() / "steps.csv").string();
  EXPECT_THAT(
      [&] {
        write_result_files(results, config, run_facts(parameters::read_parameters(config)),
                           scratch.path());
      },
      ThrowsMessage<std::runtime_error>(
          "cannot write '" + path +
          "': the arms' plants give different signals "
          "(arm,seed,trial,t,theta_b,dtheta_b,phi_l,phi_r,a_S,a_A,a_E,a,omega,V,delta,T,reward,"
          "x,y,yaw against arm,seed,trial,t,theta_b,dtheta_b,phi_l,phi_r,a_S,a_A,a_E,a,omega,V,"
          "delta,T,reward)"));
}

}  // namespace
}  // namespace cbbg::store
