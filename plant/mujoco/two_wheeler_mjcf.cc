#include "cbbg/plant/mujoco/two_wheeler_mjcf.h"

#include <map>
#include <stdexcept>
#include <string>

#include "cbbg/framework/number_text.h"

namespace cbbg::plant {
namespace {

// The model, its numbers as ${names} that two_wheeler_mjcf fills in from plant.*. The ground
// and the tyres have friction 1 (sliding; MuJoCo takes the larger of two geoms'): rubber on a
// floor. A tyre touches the ground as a sphere of the wheel's radius: the wheels cannot roll
// sideways, so the sphere touches where the rim does, in one contact where MuJoCo's cylinder
// takes two (a fifth of a step's cost). The sphere is in group 3, which viewers and the
// replay hide; the cylinder beside it is only drawn. The step, 5 ms, is what the
// cross-validation chose (mujoco_agreement_test.cc).
// Its sizes hold its contacts with room to spare, in 0.8 MB of MuJoCo data per context
// instead of the 10 MB MuJoCo would set aside.
constexpr const char* kModel =
    R"(<!-- cbbg's two-wheeler (plant.kind mujoco), written from plant.* -->
<mujoco model="two_wheeler">
  <compiler angle="radian" inertiafromgeom="false"/>
  <option timestep="0.005" integrator="Euler" gravity="0 0 ${minus_gravity}"/>
  <size njmax="100" nconmax="20" nstack="100000"/>
  <worldbody>
    <geom name="ground" type="plane" size="0 0 1" friction="1 0.005 0.0001"/>
    <body name="base" pos="0 0 ${wheel_radius}">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="y" type="slide" axis="0 1 0"/>
      <joint name="z" type="slide" axis="0 0 1"/>
      <joint name="yaw" type="hinge" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="1e-9" diaginertia="1e-12 1e-12 1e-12"/>
      <body name="body">
        <joint name="pitch" type="hinge" axis="0 1 0"/>
        <inertial pos="0 0 ${com_height}" mass="${body_mass}" diaginertia="${body_roll_inertia} ${body_pitch_inertia} ${body_yaw_inertia}"/>
        <geom name="frame" type="box" size="0.07 ${half_frame_width} ${com_height}" pos="0 0 ${com_height}" contype="0" conaffinity="0" rgba="0.29 0.47 0.71 1"/>
      </body>
      <body name="left_wheel" pos="0 ${half_track} 0">
        <joint name="left_wheel" type="hinge" axis="0 1 0" damping="${wheel_ground_friction}"/>
        <inertial pos="0 0 0" mass="${wheel_mass}" diaginertia="${wheel_diametral_inertia} ${wheel_inertia} ${wheel_diametral_inertia}"/>
        <geom name="left_tyre" type="sphere" size="${wheel_radius}" friction="1 0.005 0.0001" group="3"/>
        <geom name="left_tyre_drawn" type="cylinder" size="${wheel_radius} 0.02" zaxis="0 1 0" contype="0" conaffinity="0" rgba="0.17 0.18 0.2 1"/>
      </body>
      <body name="right_wheel" pos="0 -${half_track} 0">
        <joint name="right_wheel" type="hinge" axis="0 1 0" damping="${wheel_ground_friction}"/>
        <inertial pos="0 0 0" mass="${wheel_mass}" diaginertia="${wheel_diametral_inertia} ${wheel_inertia} ${wheel_diametral_inertia}"/>
        <geom name="right_tyre" type="sphere" size="${wheel_radius}" friction="1 0.005 0.0001" group="3"/>
        <geom name="right_tyre_drawn" type="cylinder" size="${wheel_radius} 0.02" zaxis="0 1 0" contype="0" conaffinity="0" rgba="0.17 0.18 0.2 1"/>
      </body>
    </body>
  </worldbody>
  <tendon>
    <fixed name="left_axle" damping="${axle_friction}">
      <joint joint="left_wheel" coef="1"/>
      <joint joint="pitch" coef="-1"/>
    </fixed>
    <fixed name="right_axle" damping="${axle_friction}">
      <joint joint="right_wheel" coef="1"/>
      <joint joint="pitch" coef="-1"/>
    </fixed>
  </tendon>
  <actuator>
    <motor name="left_motor" tendon="left_axle" ctrllimited="true" ctrlrange="-${torque_limit} ${torque_limit}"/>
    <motor name="right_motor" tendon="right_axle" ctrllimited="true" ctrlrange="-${torque_limit} ${torque_limit}"/>
  </actuator>
  <sensor>
    <jointpos name="pitch" joint="pitch"/>
    <jointvel name="pitch_rate" joint="pitch"/>
    <jointpos name="wheel_left" joint="left_wheel"/>
    <jointpos name="wheel_right" joint="right_wheel"/>
    <jointvel name="wheel_left_rate" joint="left_wheel"/>
    <jointvel name="wheel_right_rate" joint="right_wheel"/>
    <jointpos name="x" joint="x"/>
    <jointpos name="y" joint="y"/>
    <jointpos name="yaw" joint="yaw"/>
    <jointvel name="yaw_rate" joint="yaw"/>
  </sensor>
</mujoco>
)";

}  // namespace

std::string two_wheeler_mjcf(const RobotParams& r) {
  const std::map<std::string, double> values{
      {"minus_gravity", -r.gravity},
      {"wheel_radius", r.wheel_radius},
      {"com_height", r.com_height},
      {"body_mass", r.body_mass},
      {"body_roll_inertia", r.body_roll_inertia},
      {"body_pitch_inertia", r.body_pitch_inertia},
      {"body_yaw_inertia", r.body_yaw_inertia},
      {"half_frame_width", 0.35 * r.track_width},  // the replay's body: 0.7 of the track
      {"half_track", r.track_width / 2.0},
      {"wheel_ground_friction", r.wheel_ground_friction},
      {"wheel_mass", r.wheel_mass},
      {"wheel_inertia", r.wheel_inertia},
      {"wheel_diametral_inertia", r.wheel_diametral_inertia},
      {"axle_friction", r.axle_friction},
      {"torque_limit", r.torque_limit}};
  std::string text = kModel;
  for (auto at = text.find("${"); at != std::string::npos; at = text.find("${", at)) {
    const auto end = text.find('}', at);
    const std::string number = format_number(values.at(text.substr(at + 2, end - at - 2)));
    text.replace(at, end + 1 - at, number);
    at += number.size();
  }
  return text;
}

}  // namespace cbbg::plant
