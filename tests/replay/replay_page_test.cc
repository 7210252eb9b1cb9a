#include "cbbg/replay/replay_page.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/diagrams/plant_kinds.h"
#include "cbbg/framework/block_context.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::replay {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kTemplate = std::string("<html><head>") + kGeneratorTag +
                              "</head><script type=\"application/json\">__CBBG_REPLAY_DATA__"
                              "</script></html>";

TrialLog one_tick(const std::string& arm) {
  TrialLog log;
  log.entry = {arm, 3, 2, "success"};
  log.t = {0.0, 0.01};
  log.theta_b = {0.1744, 0.1};
  log.phi_l = {0.0, 0.25};
  log.phi_r = {0.0, -0.25};
  log.x = {0.0, 1e-7};
  log.y = {0.0, 0.0};
  log.yaw = {0.0, 0.5};
  log.a = {8.72, std::numeric_limits<double>::infinity()};
  return log;
}

TEST(ReplayPage, WritesTheTrialsInPlaceOfTheDataMarker) {
  const std::string page = replay_page(kTemplate, "exp1", ReplayRobot{}, {one_tick("cbbg")});
  EXPECT_THAT(page, ::testing::StartsWith(std::string("<html><head>") + kGeneratorTag));
  EXPECT_THAT(page, ::testing::EndsWith("</script></html>"));
  EXPECT_EQ(page.find("__CBBG_REPLAY_DATA__"), std::string::npos);
  EXPECT_THAT(page, HasSubstr("{\"title\":\"exp1\",\"robot\":{\"wheel_radius\":0.15,"
                              "\"track_width\":0.44,\"cart_length\":0,\"cart_height\":0,"
                              "\"body_length\":0.8,\"body_thickness\":0.14,\"body_width\":0.308,"
                              "\"com_height\":0.4,\"failure_angle\":0.52,\"torque_limit\":5},"
                              "\"trials\":[{\"arm\":\"cbbg\",\"seed\":3,"
                              "\"trial\":2,\"status\":\"success\",\"stride\":1,\"t\":[0,0.01],"
                              "\"theta_b\":[0.1744,0.1],\"phi_l\":[0,0.25],\"phi_r\":[0,-0.25],"
                              "\"x\":[0,1e-07],\"y\":[0,0],\"yaw\":[0,0.5],\"a\":[8.72,null]}]}"));
}

// A plant's model drawing (a MuJoCo plant's, or a user's) goes to the page with each joint's
// signal turned into the page's column: the pitch is theta_b, one wheel phi_l, a signal
// steps.csv does not keep is null (its joint stays at rest).
TEST(ReplayPage, AModelDrawingCarriesItsBodiesShapesAndTheColumnsItsJointsFollow) {
  ReplayRobot robot;
  plant::DrawnBody rod;
  rod.joints = {{plant::DrawnJoint::Kind::kHinge, {0, 1, 0}, {0, 0, 0.1}, "pitch", 0.0}};
  plant::DrawnBody flywheel;
  flywheel.parent = 0;
  flywheel.position = {0, 0, 0.3};
  flywheel.joints = {{plant::DrawnJoint::Kind::kHinge, {0, 1, 0}, {0, 0, 0}, "wheel", 0.0},
                     {plant::DrawnJoint::Kind::kSlide, {1, 0, 0}, {0, 0, 0}, "extension", 0.5}};
  plant::DrawnShape disc;
  disc.kind = plant::DrawnShape::Kind::kCylinder;
  disc.body = 1;
  disc.size = {0.2, 0.01, 0};
  robot.drawing.model = {{rod, flywheel}, {disc}};
  const std::string page = replay_page(kTemplate, "exp1", robot, {one_tick("cbbg")});
  EXPECT_THAT(
      page,
      HasSubstr("\"torque_limit\":5,\"model\":{\"bodies\":["
                "{\"parent\":-1,\"position\":[0,0,0],\"orientation\":[1,0,0,0],\"joints\":["
                "{\"kind\":\"hinge\",\"axis\":[0,1,0],\"anchor\":[0,0,0.1],\"column\":\"theta_b\","
                "\"rest\":0}]},"
                "{\"parent\":0,\"position\":[0,0,0.3],\"orientation\":[1,0,0,0],\"joints\":["
                "{\"kind\":\"hinge\",\"axis\":[0,1,0],\"anchor\":[0,0,0],\"column\":\"phi_l\","
                "\"rest\":0},"
                "{\"kind\":\"slide\",\"axis\":[1,0,0],\"anchor\":[0,0,0],\"column\":null,\"rest\":"
                "0.5}]}],"
                "\"shapes\":[{\"kind\":\"cylinder\",\"body\":1,\"size\":[0.2,0.01,0],"
                "\"position\":[0,0,0],\"orientation\":[1,0,0,0],\"colour\":[0.5,0.5,0.5,1]}]}},"));
  // A plant without a model drawing sends none.
  EXPECT_THAT(replay_page(kTemplate, "exp1", ReplayRobot{}, {one_tick("cbbg")}),
              ::testing::Not(HasSubstr("\"model\"")));
}

TEST(ReplayPage, ALongTrialIsShownEveryNthTickAndItsLast) {
  TrialLog log;
  log.entry = {"cbbg", 1, 1, "success"};
  for (int k = 0; k < 45000; ++k) {
    for (auto* signal :
         {&log.t, &log.theta_b, &log.phi_l, &log.phi_r, &log.x, &log.y, &log.yaw, &log.a}) {
      signal->push_back(k);
    }
  }
  const std::string page = replay_page(kTemplate, "long", ReplayRobot{}, {log});
  // 45000 ticks over 20000 at most: every 3rd, 0, 3, ..., 44997, then the last, 44999.
  EXPECT_THAT(page, HasSubstr("\"stride\":3,\"t\":[0,3,6,"));
  EXPECT_THAT(page, HasSubstr(",44994,44997,44999],\"theta_b\":[0,3,"));
  const std::size_t start = page.find("\"t\":[");
  const std::string times = page.substr(start, page.find(']', start) - start);
  EXPECT_EQ(std::count(times.begin(), times.end(), ','), 15000);  // 15001 ticks
}

TEST(ReplayPage, TextCannotCloseThePagesScript) {
  const std::string page =
      replay_page(kTemplate, "</script><b>\"x\"", ReplayRobot{}, {one_tick("a<b")});
  EXPECT_THAT(page, HasSubstr("\"title\":\"\\u003c/script>\\u003cb>\\\"x\\\"\""));
  EXPECT_THAT(page, HasSubstr("\"arm\":\"a\\u003cb\""));
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
}

TEST(ReplayPage, RefusesATemplateThatIsNotCbbgs) {
  EXPECT_THAT([] { replay_page("<html>__CBBG_REPLAY_DATA__</html>", "t", {}, {}); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "the replay page template is not cbbg's (no generator tag or no data "
                  "marker)"));
}

// A user's plant of another shape: a cart on small wheels and a long thin pole.
class DrawnCart final : public plant::RobotPlant {
 public:
  explicit DrawnCart(std::string name) : RobotPlant(std::move(name)) {
    declare_input_port("torque", plant::kTorqueSize);
    declare_output_port("state", 4, [](const BlockContext&, VectorRef y) { y.setZero(); }, {});
  }
  std::vector<std::string> signals() const override {
    return {"pitch", "pitch_rate", "wheel", "wheel_rate"};
  }
  void reset(Context&, double) const override {}
  plant::PlantDrawing drawing() const override {
    plant::PlantDrawing drawing;
    drawing.wheel_radius = 0.05;
    drawing.track_width = 0.3;
    drawing.cart_length = 0.5;
    drawing.cart_height = 0.12;
    drawing.body_length = 0.9;
    drawing.body_thickness = 0.02;
    drawing.body_width = 0.025;
    drawing.com_height = 0.875;
    return drawing;
  }
};

// plant.kind: drawn_cart, registered once, before its config is made.
void register_drawn_cart() {
  static const bool done = [] {
    diagrams::register_plant_kind(
        {.name = "drawn_cart",
         .description = "a cart and pole that draws itself",
         .make = [](const std::string& name, const parameters::Parameters&) {
           return std::make_unique<DrawnCart>(name);
         }});
    return true;
  }();
  (void)done;
}

// A results directory of one trial of two ticks, with `config` as its config.yaml.
class ReplayOfRun : public ::testing::Test {
 protected:
  fs::path run_with(const std::string& config) const {
    const fs::path run = scratch_.path() / "run";
    fs::create_directories(run);
    std::ofstream(run / "config.yaml") << config;
    std::ofstream(run / "trials.csv") << "arm,seed,trial,status\npd_only,1,1,success\n";
    std::ofstream(run / "steps.csv") << "arm,seed,trial,t,theta_b,phi_l,phi_r,a,x\n"
                                        "pd_only,1,1,0,0.1,0,0,0,0\n"
                                        "pd_only,1,1,0.01,0.09,0.1,0.1,1,0.005\n";
    return run;
  }
  // The page's robot, as its data carries it.
  static std::string robot_of(const std::string& page) {
    const std::size_t start = page.find("\"robot\":");
    return page.substr(start, page.find('}', start) + 1 - start);
  }

  cbbg::testing::ScratchDirectory scratch_;
};

TEST_F(ReplayOfRun, AUsersPlantIsDrawnAsItSaysNotAsTheTwoWheeler) {
  register_drawn_cart();
  const fs::path run = run_with("experiment: pd_only\nplant:\n  kind: drawn_cart\n");
  const std::string page = replay_of_run(run, {}, kTemplate);
  EXPECT_EQ(robot_of(page),
            "\"robot\":{\"wheel_radius\":0.05,\"track_width\":0.3,\"cart_length\":0.5,"
            "\"cart_height\":0.12,\"body_length\":0.9,\"body_thickness\":0.02,"
            "\"body_width\":0.025,\"com_height\":0.875,\"failure_angle\":0.5236,"
            "\"torque_limit\":5}");
  EXPECT_THAT(page, HasSubstr("\"title\":\"pd_only, drawn_cart plant: run\""));
}

TEST_F(ReplayOfRun, ATwoWheelerIsDrawnWithItsOwnParameters) {
  const fs::path run = run_with(
      "experiment: pd_only\nplant:\n  kind: analytic\n  wheel_radius: 0.2\n"
      "  track_width: 0.5\n  com_height: 0.55\n");
  EXPECT_EQ(robot_of(replay_of_run(run, {}, kTemplate)),
            "\"robot\":{\"wheel_radius\":0.2,\"track_width\":0.5,\"cart_length\":0,"
            "\"cart_height\":0,\"body_length\":1.1,\"body_thickness\":0.14,"
            "\"body_width\":0.35,\"com_height\":0.55,\"failure_angle\":0.5236,"
            "\"torque_limit\":5}");
}

}  // namespace
}  // namespace cbbg::replay
