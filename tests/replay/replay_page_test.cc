#include "cbbg/replay/replay_page.h"

#include <algorithm>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cbbg::replay {
namespace {

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
                              "\"track_width\":0.44,\"com_height\":0.4,\"failure_angle\":0.52,"
                              "\"torque_limit\":5},\"trials\":[{\"arm\":\"cbbg\",\"seed\":3,"
                              "\"trial\":2,\"status\":\"success\",\"stride\":1,\"t\":[0,0.01],"
                              "\"theta_b\":[0.1744,0.1],\"phi_l\":[0,0.25],\"phi_r\":[0,-0.25],"
                              "\"x\":[0,1e-07],\"y\":[0,0],\"yaw\":[0,0.5],\"a\":[8.72,null]}]}"));
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

}  // namespace
}  // namespace cbbg::replay
