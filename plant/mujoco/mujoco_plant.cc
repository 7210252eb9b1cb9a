#include "cbbg/plant/mujoco/mujoco_plant.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram.h"
#include "cbbg/framework/number_text.h"
#include "cbbg/framework/simulator.h"
#include "cbbg/plant/mujoco/model_drawing.h"
#include "cbbg/plant/mujoco/two_wheeler_mjcf.h"
#include "cbbg/plant/plant_ports.h"
#include "cbbg/plant/plant_state.h"

namespace cbbg::plant {
namespace {

// MuJoCo's default warning handler writes MUJOCO_LOG.TXT into the working directory: a file
// this program did not ask for. Its warnings are read from mjData's counters instead.
void quiet_warning(const char*) {}

// MuJoCo's default error handler writes MUJOCO_LOG.TXT and exits. Its errors while stepping
// (a model whose <size> leaves its solver too little memory) cannot be turned into an
// exception through its C frames, so this one says so in one line and ends the process as a
// kill would: every finished task is kept, and the run resumes.
[[noreturn]] void fatal_error(const char* message) {
  std::fprintf(stderr,
               "cbbg: MuJoCo stopped the run: %s (for a model file, its <size> may be too "
               "small; the finished seeds are kept, and cbbg run --resume continues the run)\n",
               message);
  std::fflush(stderr);
  std::_Exit(1);
}

// The name the built-in two-wheeler has in MuJoCo's virtual file system.
constexpr const char* kTwoWheelerFile = "two_wheeler.xml";

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// The model text of the built-in two-wheeler, through a virtual file of its own.
mjModel* load_two_wheeler(const RobotParams& robot, char* error, int error_size) {
  const std::string text = two_wheeler_mjcf(robot);
  auto files = std::make_unique<mjVFS>();
  mj_defaultVFS(files.get());
  if (mj_makeEmptyFileVFS(files.get(), kTwoWheelerFile, static_cast<int>(text.size())) != 0) {
    throw std::runtime_error("MuJoCo could not hold the two-wheeler's model in memory");
  }
  const int index = mj_findFileVFS(files.get(), kTwoWheelerFile);
  std::copy(text.begin(), text.end(), static_cast<char*>(files->filedata[index]));
  mjModel* model = mj_loadXML(kTwoWheelerFile, files.get(), error, error_size);
  mj_deleteVFS(files.get());
  return model;
}

mjModel* load(const MujocoParams& p, const RobotParams& robot) {
  static std::once_flag quieted;  // plants may be made on several threads at once
  std::call_once(quieted, [] {    // unless the user set handlers of their own
    if (mju_user_warning == nullptr) mju_user_warning = quiet_warning;
    if (mju_user_error == nullptr) mju_user_error = fatal_error;
  });
  char error[1024] = "";
  if (p.model.empty()) {
    mjModel* model = load_two_wheeler(robot, error, sizeof error);
    if (model == nullptr) {
      throw std::invalid_argument("plant.* make a two-wheeler MuJoCo refuses: " + one_line(error));
    }
    return model;
  }
  if (!std::filesystem::is_regular_file(p.model)) {
    throw std::invalid_argument("mujoco.model '" + p.model + "' is no file");
  }
  mjModel* model = mj_loadXML(p.model.c_str(), nullptr, error, sizeof error);
  if (model == nullptr) {
    throw std::invalid_argument("mujoco.model '" + p.model + "' does not load: " + one_line(error));
  }
  return model;
}

std::string name_of(const mjModel* m, mjtObj type, int id) {
  const char* name = mj_id2name(m, type, id);
  return name != nullptr ? name : "";
}

std::string names_of(const mjModel* m, mjtObj type, int count) {
  std::string names;
  for (int i = 0; i < count; ++i) {
    const std::string name = name_of(m, type, i);
    names += (names.empty() ? "" : ", ") + (name.empty() ? "(unnamed)" : name);
  }
  return names.empty() ? "none" : names;
}

}  // namespace

// The loaded model and where the plant's keys point in it; read only once built.
struct MujocoPlant::Model {
  Model(const MujocoParams& p, const RobotParams& robot, bool pushed);
  ~Model() { mj_deleteModel(m); }
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  // Where a signal is read in MuJoCo's data.
  struct Signal {
    enum Source { kSensor, kPosition, kVelocity } source;
    int index;  // into sensordata, qpos or qvel
  };
  // Where a torque goes: an actuator's control, or a joint's applied force.
  struct Drive {
    bool joint;
    int index;  // into ctrl or qfrc_applied

    // `torque` held for the tick.
    void apply(mjData* data, double torque) const {
      (joint ? data->qfrc_applied : data->ctrl)[index] = torque;
    }
  };

  int id(mjtObj type, const std::string& name, const char* key, const char* what) const;
  void scale_body(const MujocoParams& p);
  void read_sensors();
  void read_joints();
  Drive drive(const std::string& name) const;

  std::string source;  // for messages: the file, or "the two-wheeler"
  mjModel* m = nullptr;
  std::vector<Drive> drives;
  std::vector<std::string> signal_names;
  std::vector<Signal> signal_sources;
  int pitch_joint = -1;
  bool sensors_need_acceleration = false;  // an accelerometer, a force or touch sensor
  // Whether a step can be split in MuJoCo's two halves (mj_step2, then mj_step1 at the new
  // state, which gives the sensors): not with Runge-Kutta, nor for sensors of accelerations.
  bool split_steps = false;
  int body = -1;  // -1: the model has no mujoco.body, and nothing asked for it
  // The continuous state's layout: signals, qpos, qvel, act, warm start.
  int signals = 0;
  int qpos = 0, qvel = 0, act = 0, warm = 0, size = 0;
};

MujocoPlant::Model::Model(const MujocoParams& p, const RobotParams& robot, bool pushed)
    : source(p.model.empty() ? "the two-wheeler" : "'" + p.model + "'"), m(load(p, robot)) {
  try {
    if (p.timestep > 0.0) m->opt.timestep = p.timestep;
    if (p.integrator != MujocoIntegrator::kModel) {
      m->opt.integrator = p.integrator == MujocoIntegrator::kEuler         ? mjINT_EULER
                          : p.integrator == MujocoIntegrator::kRungeKutta4 ? mjINT_RK4
                                                                           : mjINT_IMPLICIT;
    }
    if (p.actuators.empty() || p.actuators.size() > 2) {
      throw std::invalid_argument("mujoco.actuators names one or two actuators; got " +
                                  std::to_string(p.actuators.size()));
    }
    for (const std::string& name : p.actuators) drives.push_back(drive(name));
    const int pitch = id(mjOBJ_JOINT, p.pitch_joint, "mujoco.pitch_joint", "joint");
    if (m->jnt_type[pitch] != mjJNT_HINGE && m->jnt_type[pitch] != mjJNT_SLIDE) {
      throw std::invalid_argument("mujoco.pitch_joint '" + p.pitch_joint + "' of model " + source +
                                  " is no hinge or slide joint");
    }
    pitch_joint = pitch;
    const bool changed = p.body_mass_scale != 1.0 || p.com_height_scale != 1.0;
    body = pushed || changed ? id(mjOBJ_BODY, p.body, "mujoco.body", "body")
                             : mj_name2id(m, mjOBJ_BODY, p.body.c_str());
    if (changed) scale_body(p);
    if (m->nsensor > 0) {
      read_sensors();
    } else {
      read_joints();
    }
  } catch (...) {
    mj_deleteModel(m);
    throw;
  }
  for (int s = 0; s < m->nsensor; ++s) {
    sensors_need_acceleration |= m->sensor_needstage[s] == mjSTAGE_ACC;
  }
  split_steps = !sensors_need_acceleration && m->opt.integrator != mjINT_RK4;
  signals = static_cast<int>(signal_names.size());
  qpos = signals;
  qvel = qpos + m->nq;
  act = qvel + m->nv;
  warm = act + m->na;
  size = warm + m->nv;
}

int MujocoPlant::Model::id(mjtObj type, const std::string& name, const char* key,
                           const char* what) const {
  const int found = mj_name2id(m, type, name.c_str());
  if (found >= 0) return found;
  const int count = type == mjOBJ_JOINT ? m->njnt : m->nbody;
  throw std::invalid_argument(std::string(key) + " '" + name + "': model " + source + " has no " +
                              what + " of that name (it has: " + names_of(m, type, count) + ")");
}

// Each sensor is one named signal of one number.
void MujocoPlant::Model::read_sensors() {
  for (int s = 0; s < m->nsensor; ++s) {
    const std::string name = name_of(m, mjOBJ_SENSOR, s);
    if (name.empty()) {
      throw std::invalid_argument("model " + source + ": sensor " + std::to_string(s + 1) +
                                  " has no name; a sensor's name is its signal's");
    }
    if (m->sensor_dim[s] != 1) {
      throw std::invalid_argument("model " + source + ": sensor '" + name + "' gives " +
                                  std::to_string(m->sensor_dim[s]) +
                                  " numbers; each sensor is one signal of one number");
    }
    signal_names.push_back(name);
    signal_sources.push_back({Signal::kSensor, m->sensor_adr[s]});
  }
}

// A model without sensors (a URDF file has none): each hinge or slide joint is two signals,
// its angle or position under its name and its rate as NAME_rate.
void MujocoPlant::Model::read_joints() {
  for (int j = 0; j < m->njnt; ++j) {
    const std::string name = name_of(m, mjOBJ_JOINT, j);
    if (name.empty() || (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE)) continue;
    signal_names.push_back(name);
    signal_sources.push_back({Signal::kPosition, m->jnt_qposadr[j]});
    signal_names.push_back(name + "_rate");
    signal_sources.push_back({Signal::kVelocity, m->jnt_dofadr[j]});
  }
}

// An actuator of that name takes the torque as its control; else a hinge or slide joint of
// that name takes it as a force between its body and the parent (a URDF file has no
// actuators).
MujocoPlant::Model::Drive MujocoPlant::Model::drive(const std::string& name) const {
  const int actuator = mj_name2id(m, mjOBJ_ACTUATOR, name.c_str());
  if (actuator >= 0) return {false, actuator};
  const int joint = mj_name2id(m, mjOBJ_JOINT, name.c_str());
  if (joint >= 0 && (m->jnt_type[joint] == mjJNT_HINGE || m->jnt_type[joint] == mjJNT_SLIDE)) {
    return {true, m->jnt_dofadr[joint]};
  }
  throw std::invalid_argument("mujoco.actuators '" + name + "': model " + source +
                              " has no actuator or hinge or slide joint of that name (it has "
                              "actuators: " +
                              names_of(m, mjOBJ_ACTUATOR, m->nu) +
                              "; joints: " + names_of(m, mjOBJ_JOINT, m->njnt) + ")");
}

// evaluation's changes of the body, on a model file: its mass and inertia, and its centre of
// mass's offset from its frame, scaled; then MuJoCo's derived constants made anew.
void MujocoPlant::Model::scale_body(const MujocoParams& p) {
  m->body_mass[body] *= p.body_mass_scale;
  for (int i = 0; i < 3; ++i) {
    m->body_inertia[3 * body + i] *= p.body_mass_scale;
    m->body_ipos[3 * body + i] *= p.com_height_scale;
  }
  mjData* data = mj_makeData(m);
  mj_setConst(m, data);
  mj_deleteData(data);
}

// One context's MuJoCo model and data, and the time and state at which they last matched the
// context. The model is a copy of the plant's: a last step shorter than the others (an
// interval that is no whole number of steps) changes its timestep, which contexts running in
// parallel must not see.
class MujocoPlant::Scratch final : public BlockScratch {
 public:
  explicit Scratch(std::shared_ptr<const Model> model)
      : model_(std::move(model)),
        own_(mj_copyModel(nullptr, model_->m)),
        data_(mj_makeData(own_)) {}
  ~Scratch() override {
    mj_deleteData(data_);
    mj_deleteModel(own_);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  std::unique_ptr<BlockScratch> clone() const override {
    auto copy = std::make_unique<Scratch>(model_);
    copy->synced_time = synced_time;
    copy->synced_state = synced_state;
    if (std::isfinite(synced_time)) copy->restore(synced_time, synced_state);
    return copy;
  }

  // Puts the data at the context's state unless it is still where it left it.
  void sync(double time, const Eigen::Ref<const Eigen::VectorXd>& state) {
    if (time == synced_time && state == synced_state) return;
    restore(time, state);
    synced_time = time;
    synced_state = state;
  }

  // Every joint at qpos0 but the pitch joint at `pitch`, at rest; the sensors computed.
  void rest(double pitch) {
    mj_resetData(own_, data_);
    data_->qpos[own_->jnt_qposadr[model_->pitch_joint]] = pitch;
    compute_signals();
  }

  // MuJoCo's steps through `duration` with the inputs held (the last one shorter where the
  // duration is no whole number of steps), then the sensors at the end.
  void step_through(double duration) {
    const double step = model_->m->opt.timestep;
    const auto whole = static_cast<long long>(std::floor(duration / step + 1e-9));
    for (long long i = 0; i < whole; ++i) one_step();
    const double rest = duration - static_cast<double>(whole) * step;
    if (rest > 1e-9 * step) {
      own_->opt.timestep = rest;
      one_step();
      own_->opt.timestep = step;
    }
    if (!model_->split_steps) compute_signals();
  }

  // The data's state in the layout of the continuous state.
  void pack(VectorRef state) const {
    const mjModel* m = model_->m;
    for (int i = 0; i < model_->signals; ++i) {
      const Model::Signal& signal = model_->signal_sources[static_cast<std::size_t>(i)];
      state[i] = signal.source == Model::Signal::kSensor     ? data_->sensordata[signal.index]
                 : signal.source == Model::Signal::kPosition ? data_->qpos[signal.index]
                                                             : data_->qvel[signal.index];
    }
    std::copy_n(data_->qpos, m->nq, state.data() + model_->qpos);
    std::copy_n(data_->qvel, m->nv, state.data() + model_->qvel);
    std::copy_n(data_->act, m->na, state.data() + model_->act);
    std::copy_n(data_->qacc_warmstart, m->nv, state.data() + model_->warm);
  }

  mjData* data() { return data_; }

  double synced_time = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd synced_state{};

 private:
  void restore(double time, const Eigen::Ref<const Eigen::VectorXd>& state) {
    const mjModel* m = own_;
    mj_resetData(m, data_);
    data_->time = time;
    std::copy_n(state.data() + model_->qpos, m->nq, data_->qpos);
    std::copy_n(state.data() + model_->qvel, m->nv, data_->qvel);
    std::copy_n(state.data() + model_->act, m->na, data_->act);
    std::copy_n(state.data() + model_->warm, m->nv, data_->qacc_warmstart);
    compute_signals();  // and the body frames a push is applied in
  }

  // One step of MuJoCo. Split, the data holds its position and velocity stages (mj_step1,
  // which computes the sensors) at its state between steps, and the inputs, which only the
  // second half reads, may change there: a step is that half (mj_step2) and mj_step1 at the
  // new state, the same numbers as mj_step's with no pass of the sensors' own after it.
  void one_step() {
    if (model_->split_steps) {
      mj_step2(own_, data_);
      mj_step1(own_, data_);
    } else {
      mj_step(own_, data_);
    }
  }

  // The sensors (and the body frames) at the data's state: only as far as they need, for a
  // model's joint sensors not the contact forces and accelerations MuJoCo's next step
  // computes anew (a whole mj_forward costs about a step).
  void compute_signals() {
    if (model_->sensors_need_acceleration) {
      mj_forward(own_, data_);
    } else if (model_->split_steps) {
      mj_step1(own_, data_);
    } else {
      mj_fwdPosition(own_, data_);
      mj_sensorPos(own_, data_);
      mj_fwdVelocity(own_, data_);
      mj_sensorVel(own_, data_);
    }
  }

  std::shared_ptr<const Model> model_;
  mjModel* own_;
  mjData* data_;
};

namespace {

// MuJoCo's count of the warnings that mean a step went wrong: it reset a diverged simulation,
// or dropped contacts or constraints its <size> had no room for.
int divergences(const mjData* data) {
  int count = 0;
  for (const mjtWarning warning :
       {mjWARN_BADQACC, mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_CONTACTFULL, mjWARN_CNSTRFULL}) {
    count += data->warning[warning].number;
  }
  return count;
}

// A push held for the tick: a force along the body's heading at its centre of mass, and a
// torque about the horizontal across the heading (> 0 leans it forward).
void apply_push(mjData* data, int body, double force, double pitch_torque) {
  const mjtNum* frame = data->xmat + 9 * body;  // the body's axes, row-major
  double heading_x = frame[0];
  double heading_y = frame[3];
  const double length = std::hypot(heading_x, heading_y);
  if (length > 0.0) {
    heading_x /= length;
    heading_y /= length;
  }
  mjtNum* applied = data->xfrc_applied + 6 * body;
  applied[0] = force * heading_x;
  applied[1] = force * heading_y;
  applied[2] = 0.0;
  applied[3] = -pitch_torque * heading_y;  // about z x heading
  applied[4] = pitch_torque * heading_x;
  applied[5] = 0.0;
}

}  // namespace

MujocoPlant::MujocoPlant(std::string name, const MujocoParams& params, const RobotParams& robot,
                         double initial_pitch, DisturbanceInput disturbance)
    : RobotPlant(std::move(name)),
      model_(
          std::make_shared<const Model>(params, robot, disturbance == DisturbanceInput::kDeclared)),
      wheel_radius_(params.wheel_radius > 0.0 ? params.wheel_radius
                    : params.model.empty()    ? robot.wheel_radius
                                              : std::numeric_limits<double>::quiet_NaN()),
      drawing_(params.model.empty() ? two_wheeler_drawing(robot) : PlantDrawing{}) {
  // A model file's robot is drawn from its own shapes; the built-in two-wheeler as the other
  // plants' two-wheeler is.
  if (!params.model.empty()) drawing_.model = model_drawing(model_->m, model_->pitch_joint);
  check_initial_pitch(initial_pitch);
  signals_ = model_->signal_names;
  torque_ = &declare_input_port("torque", kTorqueSize,
                                "tau_l, tau_r: motor torques, N m, to mujoco.actuators");
  disturbance_ = declare_disturbance_input(disturbance);
  declare_output_port<&MujocoPlant::calc_state>("state", model_->signals, {},
                                                "the model's sensors (or joints), by name");
  Scratch scratch(model_);
  scratch.rest(initial_pitch);
  Vector initial(model_->size);
  scratch.pack(initial);
  declare_self_integrated_state<&MujocoPlant::advance>(initial);
}

void MujocoPlant::calc_state(const BlockContext& context, VectorRef y) const {
  y = context.continuous_state().head(model_->signals);
}

void MujocoPlant::advance(BlockContext& context, double end_time) const {
  const ConstVectorView tau = context.input(*torque_);
  check_torque_finite(*this, tau);
  Scratch& scratch = context.scratch<Scratch>();
  VectorView state = context.mutable_continuous_state();
  const double start_time = context.time();
  scratch.sync(start_time, state);
  mjData* data = scratch.data();
  const std::vector<Model::Drive>& drives = model_->drives;
  if (drives.size() == 2) {
    drives[0].apply(data, tau[kTauLeft]);
    drives[1].apply(data, tau[kTauRight]);
  } else {
    drives[0].apply(data, tau[kTauLeft] + tau[kTauRight]);
  }
  if (disturbance_ != nullptr) {
    const ConstVectorView push = context.input(*disturbance_);
    check_disturbance_finite(*this, push);
    apply_push(data, model_->body, push[kPushForce], push[kPushPitchTorque]);
  }
  const int diverged = divergences(data);
  scratch.step_through(end_time - start_time);
  if (divergences(data) != diverged) {
    scratch.synced_time = std::numeric_limits<double>::quiet_NaN();
    throw SimulationError(
        "block '" + path() + "': MuJoCo's step failed between t = " + format_number(start_time) +
        " and " + format_number(end_time) +
        ": it diverged (a smaller mujoco.timestep may hold it) or had no room for its "
        "contacts (the model's <size nconmax njmax>)");
  }
  data->time = end_time;
  scratch.pack(state);
  if (!state.allFinite()) {
    throw SimulationError("block '" + path() +
                          "': state is not finite at t = " + format_number(end_time));
  }
  scratch.synced_time = end_time;
  scratch.synced_state = state;
}

MujocoPlant::~MujocoPlant() = default;

double MujocoPlant::timestep() const { return model_->m->opt.timestep; }

std::unique_ptr<BlockScratch> MujocoPlant::make_scratch() const {
  return std::make_unique<Scratch>(model_);
}

void MujocoPlant::reset(Context& context, double initial_pitch) const {
  check_initial_pitch(initial_pitch);
  auto& scratch = static_cast<Scratch&>(*context.scratch(context.diagram().leaf_index(*this)));
  scratch.rest(initial_pitch);
  VectorView state = context.continuous_state(*this);
  scratch.pack(state);
  scratch.synced_time = context.time();
  scratch.synced_state = state;
}

}  // namespace cbbg::plant
