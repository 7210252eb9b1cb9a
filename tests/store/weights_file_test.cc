#include "cbbg/store/weights_file.h"
#include "tests/support/scratch_directory.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/diagrams/presets.h"
#include "cbbg/experiments/learnt_weights.h"

namespace cbbg::store {
namespace {

using namespace cbbg::diagrams;
using namespace cbbg::experiments;
using namespace cbbg::store;

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class WeightsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_directory_.emplace();
    directory_ = scratch_directory_->path();
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = directory_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  // The message load_weights throws for a file holding `text`.
  std::string load_error(const std::string& text) const {
    const fs::path path = write("w.txt", text);
    try {
      load_weights(path);
    } catch (const config::ConfigError& error) {
      return error.what();
    }
    return "(loaded without an error)";
  }

  std::string prefix() const { return "weights file '" + (directory_ / "w.txt").string() + "' "; }

  std::optional<cbbg::testing::ScratchDirectory> scratch_directory_;
  fs::path directory_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A file written by hand: a 3 x 3 grid (9 features). Line numbers: 1 format, 2 comment,
// 3 arm, 4 seed, 5 trials, 6 plant.kind, 7-9 normaliser, 10 centres, 11 width, 12 features,
// 13 "actor 9", 14-22 actor, 23 "critic 9", 24-32 critic.
std::string small_file() {
  std::string text =
      "cbbg-weights 1\n"
      "# written by hand\n"
      "arm bg_only\n"
      "seed 7\n"
      "trials 3\n"
      "plant.kind analytic\n"
      "normaliser.scale_theta 0.05817764\n"
      "normaliser.scale_dtheta 0.05817764\n"
      "normaliser.saturation 3\n"
      "rbf.centres -1 0 1\n"
      "rbf.width 0.5\n"
      "features 9\n"
      "actor 9\n";
  for (int k = 0; k < 9; ++k) text += std::to_string(k) + ".5\n";
  text += "critic 9\n";
  for (int k = 0; k < 9; ++k) text.append("-").append(std::to_string(k)).append("\n");
  return text;
}

// Replaces line `number` (from 1) of `text`.
std::string with_line(const std::string& text, int number, const std::string& line) {
  std::istringstream in(text);
  std::string result;
  std::string current;
  for (int n = 1; std::getline(in, current); ++n) result += (n == number ? line : current) + "\n";
  return result;
}

// The first `lines` lines of `text`.
std::string first_lines(const std::string& text, int lines) {
  std::istringstream in(text);
  std::string result;
  std::string current;
  for (int n = 1; n <= lines && std::getline(in, current); ++n) result += current + "\n";
  return result;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// The presets' layout at the defaults, as their closed loops describe it.
blocks::FeatureLayout default_layout() {
  return {{"normaliser.scale_theta", {0.05817764}},
          {"normaliser.scale_dtheta", {0.05817764}},
          {"normaliser.saturation", {3}},
          {"rbf.centres", {-3, -2, -1, 0, 1, 2, 3}},
          {"rbf.width", {0.5}}};
}

LearntWeights default_layout_weights() {
  LearntWeights weights;
  weights.layout = default_layout();
  weights.features = 49;
  weights.actor = experiments::LearntState::of_weights(Vector::Zero(49));
  weights.critic = experiments::LearntState::of_weights(Vector::Zero(49));
  return weights;
}

TEST_F(WeightsFile, ReadsAFileWrittenByHand) {
  const LearntWeights weights = load_weights(write("w.txt", small_file()));
  EXPECT_EQ(weights.provenance, (WeightsProvenance{"bg_only", 7, 3, "analytic"}));
  EXPECT_EQ(weights.layout, (blocks::FeatureLayout{{"normaliser.scale_theta", {0.05817764}},
                                                   {"normaliser.scale_dtheta", {0.05817764}},
                                                   {"normaliser.saturation", {3}},
                                                   {"rbf.centres", {-1, 0, 1}},
                                                   {"rbf.width", {0.5}}}));
  ASSERT_EQ(weights.actor.weights("actor").size(), 9);
  ASSERT_EQ(weights.critic.weights("critic").size(), 9);
  EXPECT_EQ(weights.actor.weights("actor")[0], 0.5);
  EXPECT_EQ(weights.actor.weights("actor")[8], 8.5);
  EXPECT_EQ(weights.critic.weights("critic")[8], -8.0);
}

TEST_F(WeightsFile, SaveThenLoadGivesEveryDoubleBackBitForBit) {
  LearntWeights weights;
  weights.layout = {{"rbf.centres", {-3.0, -1.0 / 3.0, 0.1, 0.2 + 0.1, 2.0 / 3.0, 1e-300, 7.25}},
                    {"rbf.width", {0.1 + 0.2}},
                    {"mine.scales", {3.14159265358979 / 54.0, 1.0 / 7.0, 2.9999999999999996}}};
  weights.layout_notes = {"a note for a reader"};
  weights.provenance = {"cbbg_weighted", 123456789012LL, 42, "simbody"};
  // Awkward values first, then random bit patterns (every finite double is allowed).
  const double awkward[] = {-0.0,  5e-324,    -2.2250738585072014e-308, 1.7976931348623157e308,
                            0.1,   1.0 / 3.0, std::nextafter(1.0, 2.0), 123456789.123456789,
                            -1e-17};
  std::mt19937_64 bits(2011);
  weights.features = 49;
  weights.actor = experiments::LearntState::of_weights(Vector(49));
  weights.critic = experiments::LearntState::of_weights(Vector(49));
  for (int k = 0; k < 98; ++k) {
    double value = 0.0;
    if (k < static_cast<int>(std::size(awkward))) {
      value = awkward[k];
    } else {
      do value = std::bit_cast<double>(bits());
      while (!std::isfinite(value));
    }
    (k < 49 ? weights.actor.weights("actor")[k] : weights.critic.weights("critic")[k - 49]) = value;
  }

  const fs::path path = directory_ / "nested" / "w.txt";  // the directory is created
  save_weights(path, weights);
  const LearntWeights loaded = load_weights(path);
  EXPECT_EQ(loaded.provenance, weights.provenance);
  ASSERT_EQ(loaded.layout.size(), weights.layout.size());
  for (std::size_t e = 0; e < weights.layout.size(); ++e) {
    EXPECT_EQ(loaded.layout[e].key, weights.layout[e].key);
    ASSERT_EQ(loaded.layout[e].values.size(), weights.layout[e].values.size());
    for (std::size_t i = 0; i < weights.layout[e].values.size(); ++i) {
      EXPECT_TRUE(same_bits(loaded.layout[e].values[i], weights.layout[e].values[i]))
          << weights.layout[e].key << " " << i;
    }
  }
  ASSERT_EQ(loaded.actor.weights("actor").size(), 49);
  ASSERT_EQ(loaded.critic.weights("critic").size(), 49);
  for (int k = 0; k < 49; ++k) {
    EXPECT_TRUE(same_bits(loaded.actor.weights("actor")[k], weights.actor.weights("actor")[k]))
        << "actor " << k;
    EXPECT_TRUE(same_bits(loaded.critic.weights("critic")[k], weights.critic.weights("critic")[k]))
        << "critic " << k;
  }
  EXPECT_TRUE(loaded == weights);

  const std::string text = read_text(path);
  EXPECT_EQ(text.substr(0, text.find('\n')), "cbbg-weights 1");
  EXPECT_THAT(text, HasSubstr("\nfeatures 49\n# a note for a reader\nactor 49\n"));
  EXPECT_THAT(text, HasSubstr("\n-0\n5e-324\n-2.2250738585072014e-308\n1.7976931348623157e+308\n"
                              "0.1\n0.3333333333333333\n"));
}

TEST_F(WeightsFile, SavingReplacesTheFileWholeAndLeavesNothingElse) {
  LearntWeights first = default_layout_weights();
  first.actor.weights("actor")[3] = 1.0;
  LearntWeights second = default_layout_weights();
  second.actor.weights("actor")[3] = 2.0;
  const fs::path path = directory_ / "w.txt";
  save_weights(path, first);
  save_weights(path, second);
  EXPECT_EQ(load_weights(path).actor.weights("actor")[3], 2.0);
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(directory_)) ++files;
  EXPECT_EQ(files, 1);  // no temporary file left beside it
}

TEST_F(WeightsFile, SavingNeverReplacesAFileThatIsNotAWeightsFile) {
  const fs::path mine = directory_ / "mine.txt";
  std::ofstream(mine) << "my notes\n";
  EXPECT_THAT([&] { save_weights(mine, default_layout_weights()); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "weights file '" + mine.string() +
                  "' exists and cbbg did not write it; cbbg never replaces a file of yours: "
                  "give a new path"));
  std::ifstream in(mine);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "my notes\n");
}

TEST_F(WeightsFile, SavingRefusesWhatTheFormatCannotHold) {
  auto save_error = [this](const LearntWeights& weights) -> std::string {
    try {
      save_weights(directory_ / "w.txt", weights);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "(saved)";
  };
  LearntWeights weights = default_layout_weights();
  weights.actor = experiments::LearntState::of_weights(Vector::Zero(48));
  save_weights(directory_ / "v2.txt", weights);  // not the library's shape: a version-2 file
  EXPECT_EQ(read_text(directory_ / "v2.txt").substr(0, 15), "cbbg-weights 2\n");
  weights = default_layout_weights();
  weights.critic.parts[0].name = "two words";
  EXPECT_EQ(save_error(weights),
            "save_weights: critic part 'two words' must be a name of letters, digits and '_' with "
            "at least one number");
  weights = default_layout_weights();
  weights.actor.parts.clear();
  EXPECT_EQ(save_error(weights), "save_weights: the actor learnt nothing");
  weights = default_layout_weights();
  weights.layout.push_back({"no_dot", {1}});
  EXPECT_EQ(save_error(weights),
            "save_weights: layout entry 'no_dot' must be one word 'kind.parameter' with at least "
            "one number");
  weights = default_layout_weights();
  weights.layout[3].values[1] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(save_error(weights), "save_weights: rbf.centres [1] is inf; numbers must be finite");
  weights = default_layout_weights();
  weights.critic.weights("critic")[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(save_error(weights), "save_weights: critic weight [5] is nan; numbers must be finite");
  weights = default_layout_weights();
  weights.provenance.arm = "bg only";
  EXPECT_EQ(save_error(weights),
            "save_weights: arm 'bg only' and plant 'unknown' must be single words");
  EXPECT_FALSE(fs::exists(directory_ / "w.txt"));
}

TEST_F(WeightsFile, MissingFileAndDirectoryAreNamed) {
  const fs::path missing = directory_ / "nothing.txt";
  try {
    load_weights(missing);
    FAIL() << "loaded a missing file";
  } catch (const config::ConfigError& error) {
    EXPECT_EQ(std::string(error.what()), "weights file '" + missing.string() + "' does not exist");
  }
  try {
    load_weights(directory_);
    FAIL() << "loaded a directory";
  } catch (const config::ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "weights file '" + directory_.string() + "' is a directory, not a file");
  }
}

TEST_F(WeightsFile, OtherFormatsAndVersionsAreNamed) {
  const std::string versions = "'cbbg-weights 1' or 'cbbg-weights 2'";
  EXPECT_EQ(load_error(""), prefix() + "is empty; a weights file starts with the line " + versions);
  EXPECT_EQ(load_error(with_line(small_file(), 1, "cbbg-weights 3")),
            prefix() + "is format 'cbbg-weights 3'; this cbbg reads " + versions);
  EXPECT_EQ(load_error("experiment: exp1\nseeds: 20\n"),
            prefix() +
                "is not a cbbg weights file: its first line is 'experiment: exp1', expected " +
                versions);
  EXPECT_EQ(load_error(std::string("\x7f"
                                   "ELF\x02\x01",
                                   6)),
            prefix() +
                "is not a cbbg weights file: its first line is '?ELF?"
                "?', expected " +
                versions);
}

// The small file as version 2, the critic learning a second part "visits" (line 33, its
// numbers 34-42).
std::string two_part_file() {
  std::string text =
      with_line(with_line(with_line(small_file(), 1, "cbbg-weights 2"), 13, "actor weights 9"), 23,
                "critic weights 9");
  text += "critic visits 9\n";
  for (int k = 0; k < 9; ++k) text += std::to_string(k * k) + "\n";
  return text;
}

TEST_F(WeightsFile, Version2HoldsEveryPartALearnerLearns) {
  const LearntWeights weights = load_weights(write("w.txt", two_part_file()));
  EXPECT_EQ(weights.num_features(), 9);
  ASSERT_EQ(weights.critic.parts.size(), 2u);
  EXPECT_EQ(weights.critic.parts[1].name, "visits");
  EXPECT_EQ(weights.critic.parts[1].values[3], 9.0);
  EXPECT_EQ(weights.actor.weights("actor")[8], 8.5);
  // Saved again, it is version 2, the same bytes but the comment.
  save_weights(directory_ / "again.txt", weights);
  EXPECT_EQ(load_weights(directory_ / "again.txt"), weights);
  EXPECT_EQ(read_text(directory_ / "again.txt").substr(0, 15), "cbbg-weights 2\n");

  const std::string file = two_part_file();
  EXPECT_EQ(load_error(with_line(file, 33, "critic visits")),
            prefix() +
                "line 33: expected 'actor <part> <count>' or 'critic <part> <count>', got "
                "'critic visits'");
  EXPECT_EQ(load_error(with_line(file, 33, "critic weights 9")),
            prefix() + "line 33: critic part weights appears twice");
  EXPECT_EQ(load_error(with_line(file, 33, "actor visits 9")),
            prefix() + "line 33: the actor's parts must come before the critic's");
  EXPECT_EQ(load_error(with_line(file, 33, "critic visits 0")),
            prefix() + "line 33: critic visits count must be from 1 to 1000000; got 0");
  EXPECT_EQ(load_error(first_lines(file, 36)),
            prefix() + "ends after line 36 with 3 of 9 numbers of critic visits");
  EXPECT_EQ(load_error(first_lines(file, 12)), prefix() + "ends after line 12 with no actor part");
}

TEST_F(WeightsFile, MalformedLinesAreNamedWithTheirNumber) {
  const std::string file = small_file();
  EXPECT_EQ(load_error(with_line(file, 4, "sed 7")),
            prefix() + "line 4: expected 'seed <integer>', got 'sed 7'");
  EXPECT_EQ(load_error(with_line(file, 4, "seed seven")),
            prefix() + "line 4: seed 'seven' is not an integer");
  EXPECT_EQ(load_error(with_line(file, 3, "arm bg_only extra")),
            prefix() + "line 3: expected 'arm <diagram name>', got 'arm bg_only extra'");
  EXPECT_EQ(load_error(with_line(file, 5, "trials -1")),
            prefix() + "line 5: trials must be >= 0; got -1");
  EXPECT_EQ(load_error(with_line(file, 11, "rbf.width wide")),
            prefix() + "line 11: rbf.width 'wide' is not a number");
  // The layout's numbers mean something only to the blocks that describe them: loading
  // compares them with a loop's (check_layout), and the file checks their form alone.
  EXPECT_EQ(load_error(with_line(file, 10, "centres -1 0 1")),
            prefix() +
                "line 10: expected a layout line 'kind.parameter <numbers>' or 'features "
                "<count>', got 'centres -1 0 1'");
  EXPECT_EQ(load_error(with_line(file, 10, "rbf.width 0.5")),
            prefix() + "line 11: rbf.width appears twice");
  EXPECT_EQ(load_error(with_line(file, 12, "features 2000000")),
            prefix() + "line 12: features must be from 1 to 1000000; got 2000000");
  EXPECT_EQ(load_error(with_line(file, 15, "1 2")),
            prefix() + "line 15: expected actor weight [1] alone on its line, got '1 2'");
  // Blank lines and comments are skipped but counted.
  EXPECT_EQ(load_error(with_line(with_line(file, 2, ""), 24, "# a comment\nwhat")),
            prefix() + "line 25: critic weight [0] 'what' is not a number");
}

TEST_F(WeightsFile, NonFiniteNumbersAreRefused) {
  const std::string file = small_file();
  EXPECT_EQ(load_error(with_line(file, 11, "rbf.width inf")),
            prefix() + "line 11: rbf.width is inf; numbers must be finite");
  EXPECT_EQ(load_error(with_line(file, 17, "nan")),
            prefix() + "line 17: actor weight [3] is nan; numbers must be finite");
  EXPECT_EQ(load_error(with_line(file, 32, "-inf")),
            prefix() + "line 32: critic weight [8] is -inf; numbers must be finite");
  EXPECT_EQ(load_error(with_line(file, 10, "rbf.centres -1 0 nan")),
            prefix() + "line 10: rbf.centres[2] is nan; numbers must be finite");
}

TEST_F(WeightsFile, WrongCountsAndMissingLinesAreNamed) {
  const std::string file = small_file();
  EXPECT_EQ(load_error(with_line(file, 12, "features 8")),
            prefix() + "line 13: actor has 9 weights, but features is 8");
  EXPECT_EQ(load_error(with_line(file, 13, "actor 8")),
            prefix() + "line 13: actor has 8 weights, but features is 9");
  EXPECT_EQ(load_error(first_lines(file, 27)),
            prefix() + "ends after line 27 with 4 of 9 critic weights");
  EXPECT_EQ(load_error(first_lines(file, 22)),
            prefix() + "ends after line 22; expected 'critic <count>'");
  EXPECT_EQ(load_error(first_lines(file, 6)),
            prefix() +
                "ends after line 6; expected a layout line 'kind.parameter <numbers>' or "
                "'features <count>'");
  EXPECT_EQ(load_error(file + "\n# fine\n1.5\n"),
            prefix() + "line 35: unexpected '1.5' after the critic weights");
}

TEST_F(WeightsFile, LayoutMismatchNamesWhereTheLayoutsDiffer) {
  const LearntWeights weights = default_layout_weights();
  EXPECT_NO_THROW(check_layout(weights, default_layout(), "w.txt"));
  blocks::FeatureLayout other = default_layout();
  other[3].values = {-2, -1, 0, 1, 2};
  EXPECT_THAT([&] { check_layout(weights, other, "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "weights file 'w.txt' was made for rbf.centres [-3, -2, -1, 0, 1, 2, 3]; this "
                  "diagram has rbf.centres [-2, -1, 0, 1, 2]"));
  other = default_layout();
  other[0].values = {0.1};
  EXPECT_THAT([&] { check_layout(weights, other, "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "weights file 'w.txt' was made for normaliser.scale_theta 0.05817764; this "
                  "diagram has normaliser.scale_theta 0.1"));
  // A user's features block describes another layout altogether.
  other = {default_layout()[0], default_layout()[1], default_layout()[2], {"tiles.tilings", {4}}};
  EXPECT_THAT([&] { check_layout(weights, other, "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "weights file 'w.txt' was made for rbf.centres [-3, -2, -1, 0, 1, 2, 3]; this "
                  "diagram has tiles.tilings 4"));
  other.pop_back();
  EXPECT_THAT([&] { check_layout(weights, other, "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "weights file 'w.txt' was made for rbf.centres [-3, -2, -1, 0, 1, 2, 3]; this "
                  "diagram has no rbf.centres"));
  // A file whose layout stops short of the diagram's.
  LearntWeights shorter = weights;
  shorter.layout.pop_back();
  EXPECT_THAT([&] { check_layout(shorter, default_layout(), "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "weights file 'w.txt' was made for no rbf.width; this diagram has rbf.width "
                  "0.5"));
}

// Plant kinds of a user's: a pole, a robot of its own, and a crane modelled twice (a fast and
// an exact model of one robot).
void register_user_kinds() {
  static const bool done = [] {
    const PlantFactory analytic = [](const std::string& name, const parameters::Parameters& p) {
      return plant_kind("analytic").make(name, p);
    };
    register_plant_kind({.name = "pole", .description = "", .make = analytic});
    register_plant_kind(
        {.name = "crane_fast", .description = "", .make = analytic, .robot = "crane"});
    register_plant_kind(
        {.name = "crane_exact", .description = "", .make = analytic, .robot = "crane"});
    return true;
  }();
  (void)done;
}

// `weights`, made on `plant`.
LearntWeights made_on(LearntWeights weights, const std::string& plant) {
  weights.provenance.plant = plant;
  return weights;
}

TEST_F(WeightsFile, WeightsLoadOnlyOntoTheRobotTheyWereLearntOn) {
  register_user_kinds();
  const LearntWeights weights = default_layout_weights();
  config::Config config;
  config.set("plant.kind=analytic");
  const ClosedLoop layout = build_preset("bg_only", parameters::read_parameters(config));
  ASSERT_EQ(layout.layout, default_layout());
  auto refusal = [&](const std::string& made, const std::string& loaded) {
    return "weights file 'w.txt' was made on plant kind '" + made +
           "' and cannot be loaded onto plant kind '" + loaded + "' (plant.kind): another robot";
  };
  EXPECT_NO_THROW(check_weights(made_on(weights, "analytic"), "analytic", layout, "w.txt"));
  // The Simbody and the analytic plant model one robot: each takes the other's weights.
  EXPECT_NO_THROW(check_weights(made_on(weights, "analytic"), "simbody", layout, "w.txt"));
  EXPECT_NO_THROW(check_weights(made_on(weights, "simbody"), "analytic", layout, "w.txt"));
  EXPECT_NO_THROW(check_weights(made_on(weights, "crane_fast"), "crane_exact", layout, "w.txt"));
  EXPECT_NO_THROW(check_weights(made_on(weights, "pole"), "pole", layout, "w.txt"));
  for (const auto& [made, loaded] : std::vector<std::pair<std::string, std::string>>{
           {"pole", "simbody"},
           {"analytic", "pole"},
           {"crane_exact", "simbody"},
           {"pole", "crane_fast"},
           // A kind this program has not registered (another program's): a robot of its own.
           {"cartpole", "analytic"},
           {"simbody", "cartpole"}}) {
    EXPECT_THAT([&] { check_weights(made_on(weights, made), loaded, layout, "w.txt"); },
                ::testing::ThrowsMessage<config::ConfigError>(refusal(made, loaded)))
        << made << " onto " << loaded;
  }
  // The robot is checked first, then the layout.
  config.set("rbf.width=0.7");
  const ClosedLoop other = build_preset("bg_only", parameters::read_parameters(config));
  EXPECT_THAT([&] { check_weights(made_on(weights, "pole"), "simbody", other, "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(refusal("pole", "simbody")));
  EXPECT_THAT([&] { check_weights(made_on(weights, "simbody"), "analytic", other, "w.txt"); },
              ::testing::ThrowsMessage<config::ConfigError>(
                  "weights file 'w.txt' was made for rbf.width 0.5; this diagram has rbf.width "
                  "0.7"));
}

TEST(LearntWeights, MoveFromALearningDiagramIntoTheLearntActor) {
  config::Config config;
  config.set("plant.kind=analytic");
  config.set("rbf.centres=[-1, 0, 1]");
  const ClosedLoop learner = build_preset("bg_only", parameters::read_parameters(config));
  auto learnt = learner.diagram->create_context(1);
  for (int k = 0; k < 9; ++k) {
    learner.learner.actor->mutable_learnt(*learnt, "weights")[k] = 0.5 * k;
    learner.learner.critic->mutable_learnt(*learnt, "weights")[k] = -1.0 * k;
  }
  const LearntWeights weights = learnt_weights(learner, *learnt, {"bg_only", 4, 9, "analytic"});
  EXPECT_EQ(weights.layout, learner.layout);  // what the loop's blocks describe
  EXPECT_EQ(weights.layout[3], (blocks::LayoutEntry{"rbf.centres", {-1, 0, 1}}));
  EXPECT_EQ(weights.layout[1], (blocks::LayoutEntry{"normaliser.scale_dtheta", {0.05817764}}));
  EXPECT_EQ(weights.actor.weights("actor")[4], 2.0);
  EXPECT_EQ(weights.critic.weights("critic")[8], -8.0);
  EXPECT_EQ(weights.provenance.trials, 9);

  const ClosedLoop policy = build_preset(kLearntActor, parameters::read_parameters(config));
  auto evaluated = policy.diagram->create_context(1);
  load_learnt_weights(policy, *evaluated, weights);
  EXPECT_EQ(policy.learner.actor->learnt(*evaluated, "weights")[4], 2.0);

  config::Config grid_of_49;
  grid_of_49.set("plant.kind=analytic");
  const ClosedLoop other = build_preset("cbbg", parameters::read_parameters(grid_of_49));
  auto other_context = other.diagram->create_context(1);
  try {
    load_learnt_weights(other, *other_context, weights);
    FAIL() << "loaded 9 weights into 49 features";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "the weights were made for rbf.centres [-1, 0, 1]; diagram 'cbbg' has rbf.centres "
              "[-3, -2, -1, 0, 1, 2, 3]");
  }
  const ClosedLoop supervisor = build_preset("pd_only", parameters::read_parameters(config));
  auto supervisor_context = supervisor.diagram->create_context(1);
  EXPECT_THAT(([&] { learnt_weights(supervisor, *supervisor_context, {}); }),
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "diagram 'pd_only' has no actor: it learns no weights"));
}

}  // namespace
}  // namespace cbbg::store
