#include "cbbg/plant/mujoco/model_drawing.h"

#include <mujoco/mujoco.h>

#include <string>
#include <vector>

namespace cbbg::plant {
namespace {

// Groups 3 to 5 are, by MuJoCo's convention, collision-only shapes its viewer hides.
constexpr int kLastShownGroup = 2;

template <std::size_t N, class Number>
std::array<double, N> array_at(const Number* values, int index) {
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<double>(values[N * index + i]);
  return out;
}

// The signal that logs each joint's angle or position, by joint ("": none).
std::vector<std::string> joint_signals(const mjModel* m, int pitch_joint) {
  std::vector<std::string> signals(static_cast<std::size_t>(m->njnt));
  for (int s = 0; s < m->nsensor; ++s) {
    const char* name = mj_id2name(m, mjOBJ_SENSOR, s);
    if (m->sensor_type[s] == mjSENS_JOINTPOS && name != nullptr) {
      signals[static_cast<std::size_t>(m->sensor_objid[s])] = name;
    }
  }
  for (int j = 0; j < m->njnt && m->nsensor == 0; ++j) {
    const char* name = mj_id2name(m, mjOBJ_JOINT, j);
    if (name != nullptr) signals[static_cast<std::size_t>(j)] = name;
  }
  std::string& pitch = signals[static_cast<std::size_t>(pitch_joint)];
  if (pitch.empty()) pitch = "pitch";
  return signals;
}

DrawnBody drawn_body(const mjModel* m, int body, const std::vector<std::string>& signals) {
  DrawnBody drawn;
  drawn.parent = m->body_parentid[body] - 1;  // the world is no drawn body
  drawn.position = array_at<3>(m->body_pos, body);
  drawn.orientation = array_at<4>(m->body_quat, body);
  for (int j = m->body_jntadr[body]; j < m->body_jntadr[body] + m->body_jntnum[body]; ++j) {
    // A free or ball joint is drawn at rest: no one-number signal can log it.
    if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) continue;
    DrawnJoint joint;
    joint.kind =
        m->jnt_type[j] == mjJNT_HINGE ? DrawnJoint::Kind::kHinge : DrawnJoint::Kind::kSlide;
    joint.axis = array_at<3>(m->jnt_axis, j);
    joint.anchor = array_at<3>(m->jnt_pos, j);
    joint.signal = signals[static_cast<std::size_t>(j)];
    joint.rest = m->qpos0[m->jnt_qposadr[j]];
    drawn.joints.push_back(joint);
  }
  return drawn;
}

bool shown(const mjModel* m, int geom, const float* colour) {
  const int type = m->geom_type[geom];
  return type != mjGEOM_PLANE && type != mjGEOM_HFIELD && m->geom_group[geom] <= kLastShownGroup &&
         colour[3] > 0.0f;
}

DrawnShape::Kind shape_kind(int type) {
  switch (type) {
    case mjGEOM_SPHERE:
      return DrawnShape::Kind::kSphere;
    case mjGEOM_CAPSULE:
      return DrawnShape::Kind::kCapsule;
    case mjGEOM_CYLINDER:
      return DrawnShape::Kind::kCylinder;
    case mjGEOM_ELLIPSOID:
      return DrawnShape::Kind::kEllipsoid;
    default:
      return DrawnShape::Kind::kBox;  // a box, or a mesh as the box fitted to it
  }
}

}  // namespace

ModelDrawing model_drawing(const mjModel_* model, int pitch_joint) {
  const mjModel* m = model;
  const std::vector<std::string> signals = joint_signals(m, pitch_joint);
  ModelDrawing drawing;
  for (int body = 1; body < m->nbody; ++body)
    drawing.bodies.push_back(drawn_body(m, body, signals));
  for (int geom = 0; geom < m->ngeom; ++geom) {
    const int material = m->geom_matid[geom];
    const float* colour = material >= 0 ? m->mat_rgba + 4 * material : m->geom_rgba + 4 * geom;
    if (!shown(m, geom, colour)) continue;
    DrawnShape shape;
    shape.kind = shape_kind(m->geom_type[geom]);
    shape.body = m->geom_bodyid[geom] - 1;
    shape.size = array_at<3>(m->geom_size, geom);
    shape.position = array_at<3>(m->geom_pos, geom);
    shape.orientation = array_at<4>(m->geom_quat, geom);
    shape.colour = array_at<4>(colour, 0);
    drawing.shapes.push_back(shape);
  }
  return drawing;
}

}  // namespace cbbg::plant
