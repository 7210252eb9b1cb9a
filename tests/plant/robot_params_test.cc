#include "cbbg/plant/robot_params.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cbbg::plant {
namespace {

using ::testing::HasSubstr;

std::string validation_error(const RobotParams& params, bool rigid = false) {
  try {
    rigid ? params.validate_rigid_bodies() : params.validate();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(RobotParams, DefaultsAreTheSpecValues) {
  const RobotParams p;
  EXPECT_EQ(p.wheel_mass, 1.0);
  EXPECT_EQ(p.body_mass, 10.0);
  EXPECT_EQ(p.wheel_radius, 0.15);
  EXPECT_EQ(p.track_width, 0.44);
  EXPECT_EQ(p.com_height, 0.4);
  EXPECT_EQ(p.wheel_inertia, 0.01125);
  EXPECT_EQ(p.body_pitch_inertia, 1.5417);
  EXPECT_EQ(p.body_yaw_inertia, 0.5893);
  EXPECT_EQ(p.gravity, 9.8);
  EXPECT_EQ(p.wheel_ground_friction, 0.1);
  EXPECT_EQ(p.axle_friction, 0.1);
  EXPECT_EQ(p.torque_limit, 5.0);
  EXPECT_EQ(p.accuracy, 1e-6);
  EXPECT_EQ(kDefaultInitialPitch, 0.1744);
  // The two inertias the paper leaves out: a body symmetric about its long axis, a thin disc.
  EXPECT_EQ(p.body_roll_inertia, p.body_pitch_inertia);
  EXPECT_EQ(p.wheel_diametral_inertia, p.wheel_mass * p.wheel_radius * p.wheel_radius / 4.0);
  EXPECT_NO_THROW(p.validate_rigid_bodies());
}

struct Field {
  double RobotParams::*member;
  const char* key;
};

const Field kPositiveFields[] = {
    {&RobotParams::wheel_mass, "wheel_mass"},
    {&RobotParams::body_mass, "body_mass"},
    {&RobotParams::wheel_radius, "wheel_radius"},
    {&RobotParams::track_width, "track_width"},
    {&RobotParams::com_height, "com_height"},
    {&RobotParams::wheel_inertia, "wheel_inertia"},
    {&RobotParams::body_pitch_inertia, "body_pitch_inertia"},
    {&RobotParams::body_yaw_inertia, "body_yaw_inertia"},
    {&RobotParams::body_roll_inertia, "body_roll_inertia"},
    {&RobotParams::torque_limit, "torque_limit"},
};

const Field kNonNegativeFields[] = {
    {&RobotParams::wheel_diametral_inertia, "wheel_diametral_inertia"},
    {&RobotParams::gravity, "gravity"},
    {&RobotParams::wheel_ground_friction, "wheel_ground_friction"},
    {&RobotParams::axle_friction, "axle_friction"},
};

TEST(RobotParams, RejectsANonPositiveOrNonFiniteValueNamingItsKey) {
  for (const Field& field : kPositiveFields) {
    RobotParams p;
    p.*field.member = -1.0;
    EXPECT_EQ(validation_error(p),
              std::string("plant.") + field.key + " must be finite and > 0; got -1");
    p.*field.member = 0.0;
    EXPECT_EQ(validation_error(p),
              std::string("plant.") + field.key + " must be finite and > 0; got 0");
    p.*field.member = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(validation_error(p),
              std::string("plant.") + field.key + " must be finite and > 0; got nan");
    p.*field.member = std::numeric_limits<double>::infinity();
    EXPECT_EQ(validation_error(p),
              std::string("plant.") + field.key + " must be finite and > 0; got inf");
  }
}

TEST(RobotParams, AllowsZeroFrictionAndGravityButNotNegativeOrNonFinite) {
  for (const Field& field : kNonNegativeFields) {
    RobotParams p;
    p.*field.member = 0.0;
    EXPECT_EQ(validation_error(p), "") << field.key;
    p.*field.member = -0.5;
    EXPECT_EQ(validation_error(p),
              std::string("plant.") + field.key + " must be finite and >= 0; got -0.5");
    p.*field.member = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(validation_error(p),
              std::string("plant.") + field.key + " must be finite and >= 0; got nan");
  }
}

TEST(RobotParams, AccuracyMustLieBetweenZeroAndOne) {
  RobotParams p;
  for (const double bad : {0.0, -1e-6, 1.0, std::numeric_limits<double>::quiet_NaN()}) {
    p.accuracy = bad;
    EXPECT_THAT(validation_error(p), HasSubstr("plant.accuracy must be in (0, 1); got "));
  }
  p.accuracy = 1e-12;
  EXPECT_EQ(validation_error(p), "");
}

TEST(RobotParams, RigidBodiesNeedTheTriangleInequalityOfInertias) {
  // the paper's equations read literally (yaw inertia J_z at every pitch) need J_x = J_z, which
  // with the paper's J_y no rigid body has: fine for the equations, not for Simbody.
  RobotParams literal;
  literal.body_roll_inertia = literal.body_yaw_inertia;
  literal.wheel_diametral_inertia = 0.0;
  EXPECT_EQ(validation_error(literal), "");
  EXPECT_EQ(validation_error(literal, true),
            "plant.body_roll_inertia, plant.body_pitch_inertia and plant.body_yaw_inertia "
            "(about the centre of mass) must each be at most the sum of the other two, as for "
            "any rigid body; got 0.5893, 1.5417, 0.5893");

  RobotParams thin_wheel;
  thin_wheel.wheel_diametral_inertia = 0.005;
  EXPECT_EQ(validation_error(thin_wheel, true),
            "plant.wheel_diametral_inertia must be at least half of plant.wheel_inertia, as for "
            "any rigid wheel; got 0.005 with plant.wheel_inertia = 0.01125");

  RobotParams flat_plate;  // the limit case J_x = J_y - J_z is a valid (flat) body
  flat_plate.body_roll_inertia = flat_plate.body_pitch_inertia - flat_plate.body_yaw_inertia;
  EXPECT_EQ(validation_error(flat_plate, true), "");
}

TEST(RobotParams, RigidBodyValidationAlsoChecksEveryKey) {
  RobotParams p;
  p.body_mass = -1.0;
  EXPECT_EQ(validation_error(p, true), "plant.body_mass must be finite and > 0; got -1");
}

}  // namespace
}  // namespace cbbg::plant
