// The MuJoCo plant as a block: its signals, what it refuses and how it says so, a context
// copied mid-run, pushes and evaluation's changes, and the wheels slipping where the ground's
// friction cannot hold them.

#include "cbbg/plant/mujoco/mujoco_plant.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/plant/mujoco/two_wheeler_mjcf.h"
#include "cbbg/plant/plant_signals.h"
#include "tests/plant/plant_rigs.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::plant::testing {
namespace {

using ::testing::ThrowsMessage;

const std::filesystem::path kShippedModel =
    std::filesystem::path(CBBG_SOURCE_DIR) / "plant" / "mujoco" / "two_wheeler.xml";

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The shipped model with every `from` replaced by `to`, written to `path`.
std::string edited_model(const std::filesystem::path& path, const std::string& from,
                         const std::string& to) {
  std::string text = read(kShippedModel);
  EXPECT_NE(text.find(from), std::string::npos) << from;
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  std::ofstream(path) << text;
  return path.string();
}

// The plant alone in a diagram, its torque input fixed at `torque`; the state log after
// `duration`.
Eigen::MatrixXd run_alone(const MujocoParams& params, double pitch, double torque,
                          double duration) {
  DiagramBuilder builder("robot");
  auto& plant = builder.emplace<MujocoPlant>("plant", params, RobotParams{}, pitch);
  builder.export_input(plant.torque_input(), "torque");
  const auto diagram = builder.build();
  Simulator simulator(*diagram);
  simulator.context().fix_input(diagram->input_port("torque"), Vector::Constant(2, torque));
  const SignalLog& log = simulator.add_log(plant.state_output(), kPeriod);
  simulator.advance_to(duration + kPeriod / 2);
  return log.values();
}

TEST(MujocoPlant, TheShippedModelIsTheTwoWheelerOfTheDefaultParameters) {
  EXPECT_EQ(read(kShippedModel), two_wheeler_mjcf(RobotParams{}));
}

TEST(MujocoPlant, ItsSignalsAreTheModelsSensorsByName) {
  const MujocoPlant plant("plant", MujocoParams{}, RobotParams{});
  EXPECT_EQ(plant.signals(), two_wheeler_signals());
  EXPECT_EQ(plant.state_output().size(), 10);
  EXPECT_EQ(plant.wheel_radius(), RobotParams{}.wheel_radius);
  EXPECT_EQ(plant.timestep(), 0.005);
}

TEST(MujocoPlant, TheShippedFileLoadsToTheSameRobotAsTheBuiltInModel) {
  MujocoParams from_file;
  from_file.model = kShippedModel.string();
  EXPECT_EQ(run_alone(from_file, 0.1, 0.3, 1.0), run_alone(MujocoParams{}, 0.1, 0.3, 1.0));
}

TEST(MujocoPlant, WhatAModelLacksIsRefusedNamingTheKeyAndTheModelsElements) {
  const RobotParams robot;
  MujocoParams p;
  p.model = "/no/such/model.xml";
  EXPECT_THAT([&] { MujocoPlant("plant", p, robot); },
              ThrowsMessage<std::invalid_argument>("mujoco.model '/no/such/model.xml' is no file"));
  p = MujocoParams{};
  p.actuators = {"left_motor", "right_motr"};
  EXPECT_THAT([&] { MujocoPlant("plant", p, robot); },
              ThrowsMessage<std::invalid_argument>(
                  "mujoco.actuators 'right_motr': model the two-wheeler has no actuator or hinge "
                  "or slide joint of that name (it has actuators: left_motor, right_motor; "
                  "joints: x, y, z, yaw, pitch, left_wheel, right_wheel)"));
  p = MujocoParams{};
  p.pitch_joint = "tilt";
  EXPECT_THAT([&] { MujocoPlant("plant", p, robot); },
              ThrowsMessage<std::invalid_argument>(::testing::StartsWith(
                  "mujoco.pitch_joint 'tilt': model the two-wheeler has no joint of that name "
                  "(it has: x, y, z, yaw, pitch, left_wheel")));
  p = MujocoParams{};
  p.body = "chassis";
  EXPECT_NO_THROW(MujocoPlant("plant", p, robot));  // nothing asks for the body
  p.body_mass_scale = 1.3;
  EXPECT_THAT([&] { MujocoPlant("plant", p, robot); },
              ThrowsMessage<std::invalid_argument>(::testing::StartsWith(
                  "mujoco.body 'chassis': model the two-wheeler has no body of that name")));
}

TEST(MujocoPlant, AModelFileMujocoRefusesOrASensorOfManyNumbersIsRefused) {
  const cbbg::testing::ScratchDirectory scratch;
  MujocoParams p;
  p.model = edited_model(scratch.path() / "broken.xml", "<worldbody>", "<worldbody><oops/>");
  EXPECT_THAT([&] { MujocoPlant("plant", p, RobotParams{}); },
              ThrowsMessage<std::invalid_argument>(
                  ::testing::StartsWith("mujoco.model '" + p.model + "' does not load: ")));
  p.model =
      edited_model(scratch.path() / "framepos.xml", "<sensor>",
                   "<sensor>\n    <framepos name=\"where\" objtype=\"body\" objname=\"body\"/>");
  EXPECT_THAT([&] { MujocoPlant("plant", p, RobotParams{}); },
              ThrowsMessage<std::invalid_argument>(
                  "model '" + p.model +
                  "': sensor 'where' gives 3 numbers; each sensor is one signal of one number"));
}

// A copy of the context mid-run continues as the original does: to the byte from one copy to
// the next (runs are reproducible), and within rounding of the original, whose MuJoCo data
// keeps internals beyond the state the context holds (qpos, qvel, act and the solver's warm
// start): measured, the copy's lateral position and yaw, zero but for rounding, differ at
// 1e-17.
TEST(MujocoPlant, ACopiedContextContinuesAsTheOriginalDoes) {
  RobotParams params;
  const Rig rig = make_rig(PlantKind::kMujoco, params, kDefaultInitialPitch, Control::kPd);
  Simulator original(*rig.diagram);
  original.advance_to(1.005);
  Simulator first(*rig.diagram, original.context().clone());
  Simulator second(*rig.diagram, original.context().clone());
  original.advance_to(2.005);
  first.advance_to(2.005);
  second.advance_to(2.005);
  const Vector copied = first.context().continuous_state(*rig.plant);
  EXPECT_EQ(copied, second.context().continuous_state(*rig.plant));
  EXPECT_LT((copied - original.context().continuous_state(*rig.plant)).cwiseAbs().maxCoeff(),
            1e-12);
}

TEST(MujocoPlant, APushAgreesWithTheAnalyticPlants) {
  RobotParams params;
  params.accuracy = 1e-8;
  const Vector push = (Vector(2) << 8.0, 1.5).finished();  // N at the centre of mass; N m
  Eigen::MatrixXd logs[2];
  int i = 0;
  for (const PlantKind kind : {PlantKind::kAnalytic, PlantKind::kMujoco}) {
    const Rig rig = make_rig(kind, params, kDefaultInitialPitch, Control::kPd, 1.0, push);
    auto simulator = make_simulator(rig, params);
    const SignalLog& log = simulator->add_log(rig.state(), kPeriod);
    simulator->advance_to(3.005);
    logs[i++] = log.values();
  }
  EXPECT_GT(logs[1](kX, 300), 0.3);  // pushed forward, it drives forward to stay up
  // Within the agreement test's tolerances (mujoco_agreement_test.cc; measured 1.1e-3 rad).
  EXPECT_LT((logs[0].row(kThetaB) - logs[1].row(kThetaB)).cwiseAbs().maxCoeff(), 2.5e-3);
  EXPECT_LT((logs[0].row(kX) - logs[1].row(kX)).cwiseAbs().maxCoeff(), 8e-3);
}

// On a model file, evaluation.body_mass_scale reaches the body as mujoco.body_mass_scale: the
// same robot as the built-in two-wheeler of a heavier plant.*.
TEST(MujocoPlant, AModelFilesBodyScalesAsPlantParametersDo) {
  MujocoParams from_file;
  from_file.model = kShippedModel.string();
  from_file.body_mass_scale = 1.3;
  from_file.com_height_scale = 1.2;
  RobotParams heavier;
  heavier.body_mass *= 1.3;
  heavier.body_pitch_inertia *= 1.3;
  heavier.body_roll_inertia *= 1.3;
  heavier.body_yaw_inertia *= 1.3;
  heavier.com_height *= 1.2;
  auto run = [](const MujocoParams& p, const RobotParams& robot) {
    DiagramBuilder builder("robot");
    auto& plant = builder.emplace<MujocoPlant>("plant", p, robot, 0.1);
    builder.fix_input(plant.torque_input(), Vector::Constant(2, 0.5));
    const auto diagram = builder.build();
    Simulator simulator(*diagram);
    const SignalLog& log = simulator.add_log(plant.state_output(), kPeriod);
    simulator.advance_to(0.505);
    return Eigen::MatrixXd(log.values());
  };
  const Eigen::MatrixXd scaled = run(from_file, RobotParams{});
  const Eigen::MatrixXd built_in = run(MujocoParams{}, heavier);
  EXPECT_LT((scaled - built_in).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT((scaled - run(MujocoParams{}, RobotParams{})).cwiseAbs().maxCoeff(), 1e-3);
}

// The no-slip plants' assumption holds while the ground's friction can carry the wheels'
// force: full torque on ground of friction 1 rolls (x = R phi to 3 mm; measured 1.5 mm over
// 0.3 s, the soft contact's creep), on ice (friction 0.02) the wheels spin.
TEST(MujocoPlant, TheWheelsRollWhileFrictionHoldsAndSlipOnIce) {
  const cbbg::testing::ScratchDirectory scratch;
  auto slip = [](const Eigen::MatrixXd& log) {
    const double radius = RobotParams{}.wheel_radius;
    return std::abs(radius * log(kPhiLeft, log.cols() - 1) - log(kX, log.cols() - 1));
  };
  EXPECT_LT(slip(run_alone(MujocoParams{}, 0.0, 2.0, 0.3)), 3e-3);
  MujocoParams icy;
  icy.model = edited_model(scratch.path() / "ice.xml", "friction=\"1 ", "friction=\"0.02 ");
  EXPECT_GT(slip(run_alone(icy, 0.0, 2.0, 0.3)), 0.05);
}

// A reaction-wheel pendulum as URDF, which has no sensors and no actuators: its joints are its
// signals (NAME and NAME_rate), and a joint named in mujoco.actuators takes the torque between
// its two links.
constexpr const char* kPendulumUrdf = R"(<robot name="pendulum">
  <link name="base"/>
  <joint name="pitch" type="continuous">
    <parent link="base"/><child link="rod"/><origin xyz="0 0 0.05"/><axis xyz="0 1 0"/>
  </joint>
  <link name="rod">
    <inertial><origin xyz="0 0 0.15"/><mass value="0.5"/>
      <inertia ixx="0.004" iyy="0.004" izz="0.0002" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="wheel" type="continuous">
    <parent link="rod"/><child link="flywheel"/><origin xyz="0 0 0.3"/><axis xyz="0 1 0"/>
  </joint>
  <link name="flywheel">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" iyy="0.02" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
</robot>
)";

TEST(MujocoPlant, AUrdfRobotsJointsAreItsSignalsAndItsDrives) {
  const cbbg::testing::ScratchDirectory scratch;
  MujocoParams p;
  p.model = (scratch.path() / "pendulum.urdf").string();
  std::ofstream(p.model) << kPendulumUrdf;
  p.actuators = {"wheel"};
  p.body = "rod";
  const MujocoPlant plant("plant", p, RobotParams{});
  EXPECT_EQ(plant.signals(),
            (std::vector<std::string>{"pitch", "pitch_rate", "wheel", "wheel_rate"}));
  // Let go at 0.1 rad with no torque, it falls; upright with the torques' sum (1 N m) on the
  // flywheel, the flywheel spins one way and the rod turns the other.
  const Eigen::MatrixXd falling = run_alone(p, 0.1, 0.0, 0.5);
  EXPECT_GT(falling(0, falling.cols() - 1), 0.5);
  const Eigen::MatrixXd driven = run_alone(p, 0.0, 0.5, 0.05);
  EXPECT_GT(driven(3, driven.cols() - 1), 0.0);
  EXPECT_LT(driven(1, driven.cols() - 1), 0.0);
}

// The drawing of the robot of model text `text`, written to `file`, whose rod is its body and
// `actuator` its drive.
ModelDrawing drawing_of(const std::filesystem::path& file, const std::string& text,
                        const std::string& actuator) {
  std::ofstream(file) << text;
  MujocoParams p;
  p.model = file.string();
  p.actuators = {actuator};
  p.body = "rod";
  return MujocoPlant("plant", p, RobotParams{}).drawing().model;
}

// The replay draws a model file's own shapes: the reaction wheel's rod (a capsule) turning with
// the pitch, and its flywheel (a cylinder) on the rod turning with the wheel; the floor (a
// plane) and a collision-only shape (group 3) are not drawn.
TEST(MujocoPlant, AModelFilesDrawingIsItsBodiesAndShapesMovedByTheLoggedJoints) {
  const cbbg::testing::ScratchDirectory scratch;
  std::string text =
      read(std::filesystem::path(CBBG_SOURCE_DIR) / "examples" / "mujoco" / "reaction_wheel.xml");
  const std::string flywheel_body = "<body name=\"flywheel\" pos=\"0 0 0.3\">";
  ASSERT_NE(text.find(flywheel_body), std::string::npos);
  text.insert(text.find(flywheel_body) + flywheel_body.size(),
              "<geom type=\"sphere\" size=\"0.3\" group=\"3\"/>");
  const ModelDrawing drawing = drawing_of(scratch.path() / "reaction_wheel.xml", text, "motor");

  ASSERT_EQ(drawing.bodies.size(), 2u);
  const DrawnBody& rod = drawing.bodies[0];
  const DrawnBody& flywheel = drawing.bodies[1];
  EXPECT_EQ(rod.parent, -1);
  EXPECT_EQ(flywheel.parent, 0);
  EXPECT_EQ(rod.position, (std::array<double, 3>{0.0, 0.0, 0.05}));
  EXPECT_EQ(flywheel.position, (std::array<double, 3>{0.0, 0.0, 0.3}));
  ASSERT_EQ(rod.joints.size(), 1u);
  ASSERT_EQ(flywheel.joints.size(), 1u);
  EXPECT_EQ(rod.joints[0].signal, "pitch");
  EXPECT_EQ(flywheel.joints[0].signal, "wheel");
  EXPECT_EQ(rod.joints[0].kind, DrawnJoint::Kind::kHinge);
  EXPECT_EQ(rod.joints[0].axis, (std::array<double, 3>{0.0, 1.0, 0.0}));

  ASSERT_EQ(drawing.shapes.size(), 2u);
  EXPECT_EQ(drawing.shapes[0].kind, DrawnShape::Kind::kCapsule);
  EXPECT_EQ(drawing.shapes[0].body, 0);
  EXPECT_DOUBLE_EQ(drawing.shapes[0].size[0], 0.015);
  EXPECT_DOUBLE_EQ(drawing.shapes[0].size[1], 0.15);  // half of the rod's 0.3 m
  EXPECT_EQ(drawing.shapes[1].kind, DrawnShape::Kind::kCylinder);
  EXPECT_EQ(drawing.shapes[1].body, 1);
  EXPECT_DOUBLE_EQ(drawing.shapes[1].size[0], 0.2);

  // The built-in two-wheeler is drawn as the other plants' two-wheeler.
  EXPECT_TRUE(MujocoPlant("plant", MujocoParams{}, RobotParams{}).drawing().model.empty());
}

// In a model without sensors (a URDF file), a joint moves with the signal of its own name; a
// link's collision shape is drawn.
TEST(MujocoPlant, AUrdfRobotsJointsAreDrawnMovingWithTheirOwnSignals) {
  const cbbg::testing::ScratchDirectory scratch;
  std::string urdf = kPendulumUrdf;
  const std::string flywheel = "<link name=\"flywheel\">";
  urdf.insert(urdf.find(flywheel) + flywheel.size(),
              "<collision><geometry><cylinder radius=\"0.2\" length=\"0.02\"/></geometry>"
              "</collision>");
  const ModelDrawing drawing = drawing_of(scratch.path() / "pendulum.urdf", urdf, "wheel");
  std::vector<std::string> signals;
  for (const DrawnBody& body : drawing.bodies) {
    for (const DrawnJoint& joint : body.joints) signals.push_back(joint.signal);
  }
  EXPECT_EQ(signals, (std::vector<std::string>{"pitch", "wheel"}));
  ASSERT_EQ(drawing.shapes.size(), 1u);
  EXPECT_EQ(drawing.shapes[0].kind, DrawnShape::Kind::kCylinder);
  EXPECT_EQ(drawing.shapes[0].body, 1);
}

}  // namespace
}  // namespace cbbg::plant::testing
