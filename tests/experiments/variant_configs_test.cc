// The configs of configs/ (the teacher study's variants) through every protocol, small: each
// is valid, trains, evaluates, transfers, and its learnt weights carry the view they were
// learnt on and are refused on another.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/presets.h"
#include "cbbg/diagrams/validated_parameters.h"
#include "cbbg/experiments/protocols.h"
#include "cbbg/store/weights_file.h"

namespace cbbg::experiments {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> variant_configs() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(CBBG_SOURCE_DIR) / "configs")) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  return files;
}

config::Config small(const fs::path& file, const std::string& experiment) {
  config::Config config;
  config.merge_file(file);
  config.set("plant.kind=analytic");
  config.set("experiment=" + experiment);
  config.set("arms=[cbbg]");
  config.set("seeds=1");
  config.set("max_trials=3");
  config.set("trial.duration=2");
  config.set("exp2.trials=3");
  config.set("evaluation.angles=[0.05]");
  config.set("exp3.angles=[0.05]");
  config.set("transfer.conditions=[evaluation.push_force=20]");
  return config;
}

TEST(VariantConfigs, EachRunsThroughEveryProtocol) {
  const std::vector<fs::path> files = variant_configs();
  ASSERT_GE(files.size(), 5u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    std::optional<LearntWeights> learnt;
    for (const char* experiment : {"exp1", "exp2", "exp3", "transfer"}) {
      const ExperimentResults results =
          run_experiment(diagrams::validated_parameters(small(file, experiment)));
      ASSERT_EQ(results.runs.size(), 1u) << experiment;
      EXPECT_FALSE(results.runs[0].trials.empty()) << experiment;
      if (!learnt) learnt = results.runs[0].weights;
    }
    ASSERT_TRUE(learnt.has_value());
    const config::Config evaluate = small(file, "evaluate");
    ExperimentOptions options;
    options.initial_weights = &*learnt;
    const ExperimentResults evaluated =
        run_experiment(diagrams::validated_parameters(evaluate), options);
    EXPECT_EQ(evaluated.runs[0].evaluation.size(), 1u);
  }
}

// Weights learnt seeing the wheels say so, and the paper's view refuses them.
TEST(VariantConfigs, WeightsLearntSeeingTheWheelsAreRefusedOnThePapersView) {
  const fs::path file = fs::path(CBBG_SOURCE_DIR) / "configs" / "wheel_rate_features.yaml";
  const ExperimentResults results =
      run_experiment(diagrams::validated_parameters(small(file, "exp1")));
  const LearntWeights& weights = *results.runs[0].weights;
  EXPECT_EQ(weights.num_features(), 343);
  EXPECT_TRUE(std::any_of(weights.layout.begin(), weights.layout.end(), [](const auto& entry) {
    return entry.key == "normaliser.scale_dphi" && entry.values == std::vector<double>{2.0};
  }));
  config::Config paper;
  paper.set("plant.kind=analytic");
  const diagrams::ClosedLoop policy =
      diagrams::build_preset(diagrams::kLearntActor, parameters::read_parameters(paper));
  EXPECT_THAT([&] { experiments::check_layout(weights, policy.layout, "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  ::testing::HasSubstr("weights file 'w.txt' was made for")));
}

}  // namespace
}  // namespace cbbg::experiments
