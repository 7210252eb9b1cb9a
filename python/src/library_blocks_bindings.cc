// The library's blocks in Python: the CB-BG controller's blocks (blocks/), the two robot
// plants (plant/), and their params structs, each bound from its describe() declarations
// (params_binding.h).

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "cbbg/blocks/actor.h"
#include "cbbg/blocks/boltzmann_sampler.h"
#include "cbbg/blocks/critic.h"
#include "cbbg/blocks/entropy.h"
#include "cbbg/blocks/exploration_params.h"
#include "cbbg/blocks/external_push.h"
#include "cbbg/blocks/failure_detector.h"
#include "cbbg/blocks/gaussian_exploration.h"
#include "cbbg/blocks/lqr_supervisor.h"
#include "cbbg/blocks/mixer.h"
#include "cbbg/blocks/normaliser.h"
#include "cbbg/blocks/omega_schedule.h"
#include "cbbg/blocks/ou_exploration.h"
#include "cbbg/blocks/pd_supervisor.h"
#include "cbbg/blocks/quadratic_reward.h"
#include "cbbg/blocks/rbf_features.h"
#include "cbbg/blocks/reward.h"
#include "cbbg/blocks/sensors.h"
#include "cbbg/blocks/torque_push.h"
#include "cbbg/blocks/tropism.h"
#include "cbbg/plant/analytic_plant.h"
#include "cbbg/plant/linearization.h"
#include "cbbg/plant/plant_signals.h"
#include "cbbg/plant/robot_params.h"
#include "cbbg/plant/simbody_plant.h"
#include "cbbg_docstrings.h"
#include "params_binding.h"

namespace cbbg::python {

// Structs without describe(), and fields describe() leaves out because they are controller
// options rather than config keys: declared here, as their headers comment them.
template <>
struct ParamsDeclarations<blocks::EntropyParams> {
  template <class Archive>
  static void describe(Archive& a, blocks::EntropyParams& params) {
    a.number("k_b", params.k_b, "sampler.k_b: K_B, as the BoltzmannSampler uses it", kPositive);
  }
};

template <>
struct ParamsDeclarations<blocks::FailureDetectorParams> {
  template <class Archive>
  static void describe(Archive& a, blocks::FailureDetectorParams& params) {
    a.number("failure_angle", params.failure_angle,
             "trial.failure_angle: |theta_b| beyond it fails, rad", kPositive);
  }
};

template <>
struct ParamsDeclarations<blocks::CriticParams> {
  template <class Archive>
  static void describe(Archive& a, blocks::CriticParams& params) {
    params.describe(a);
    a.flag("frozen", params.frozen,
           "not a config key: a frozen critic computes V and delta but never changes w");
  }
};

template <>
struct ParamsDeclarations<blocks::ActorParams> {
  template <class Archive>
  static void describe(Archive& a, blocks::ActorParams& params) {
    params.describe(a);
    a.flag("frozen", params.frozen,
           "not a config key: a frozen actor acts but never changes theta");
  }
};

template <>
struct ParamsDeclarations<blocks::OmegaParams> {
  template <class Archive>
  static void describe(Archive& a, blocks::OmegaParams& params) {
    using blocks::OmegaMode;
    params.describe(a);
    a.choice("mode", params.mode,
             "not a config key: where omega comes from (the controller's option)",
             Choices<OmegaMode>{{"schedule", OmegaMode::kSchedule},
                                {"zero", OmegaMode::kZero},
                                {"one", OmegaMode::kOne},
                                {"constant", OmegaMode::kConstant}});
    a.number("constant", params.constant, "mode constant's omega", interval(0.0, 1.0));
  }
};

namespace {

// A struct's docstring is its header's comment (cbbg_docstrings.h), unless the binding
// declares more than the struct's describe() (frozen, mode, constant) or the struct has no
// comment of its own.
void bind_all_params(py::module_& m) {
  bind_params<plant::RobotParams>(
      m, "RobotParams", "The two-wheeled robot's physical parameters, config keys plant.*.");
  bind_params<blocks::PdSupervisorParams>(m, "PdSupervisorParams", kPdSupervisorParamsDoc);
  bind_params<blocks::LqrSupervisorParams>(m, "LqrSupervisorParams", kLqrSupervisorParamsDoc);
  bind_params<blocks::NormaliserParams>(m, "NormaliserParams", kNormaliserParamsDoc);
  bind_params<blocks::RbfParams>(m, "RbfParams", kRbfParamsDoc);
  bind_params<blocks::CriticParams>(m, "CriticParams", "Config keys critic.*, and frozen.");
  bind_params<blocks::ActorParams>(m, "ActorParams", "Config keys actor.*, and frozen.");
  bind_params<blocks::SamplerParams>(m, "SamplerParams", kSamplerParamsDoc);
  bind_params<blocks::ExplorationParams>(
      m, "ExplorationParams",
      "Config keys exploration.*: the exploration block's kind and the alternatives' noise.");
  bind_params<blocks::EntropyParams>(m, "EntropyParams", kEntropyParamsDoc);
  bind_params<blocks::OmegaParams>(m, "OmegaParams", "Config keys omega.*, and mode and constant.");
  bind_params<blocks::RewardParams>(m, "RewardParams", kRewardParamsDoc);
  bind_params<blocks::FailureDetectorParams>(m, "FailureDetectorParams", kFailureDetectorParamsDoc);
  bind_params<blocks::SensorsParams>(m, "SensorsParams", kSensorsParamsDoc);
  bind_params<blocks::PushParams>(m, "PushParams", "A push on the robot: config keys push.*.");
  bind_params<blocks::TropismParams>(m, "TropismParams", kTropismParamsDoc);
}

// What the supervisors and the sensors are designed for: the robot's linearisation and the
// names of a plant's signals.
void bind_plant_models(py::module_& m) {
  py::class_<plant::LinearModel>(m, "LinearModel", kLinearModelDoc)
      .def(py::init([](Eigen::MatrixXd A, Eigen::MatrixXd B) {
             return plant::LinearModel{std::move(A), std::move(B)};
           }),
           py::arg("A"), py::arg("B"))
      .def_readwrite("A", &plant::LinearModel::A)
      .def_readwrite("B", &plant::LinearModel::B);
  m.def("linearize_upright", &plant::linearize_upright, py::arg("params"),
        "The robot upright at rest: x = (theta_b, phi_l, phi_r, theta_b', phi_l', phi_r'), "
        "u = (tau_l, tau_r).");
  m.def("linearize_planar_upright", &plant::linearize_planar_upright, py::arg("params"),
        "Both wheels driven by one command a: x = (theta_b, phi, theta_b', phi') with phi = "
        "(phi_l + phi_r) / 2, u = a.");

  using plant::SignalIndex;
  py::class_<SignalIndex>(m, "SignalIndex",
                          "Where each signal the closed loop reads sits in a plant's state "
                          "output; -1: the plant has no such signal.")
      .def(py::init<>())
      .def_readwrite("pitch", &SignalIndex::pitch)
      .def_readwrite("pitch_rate", &SignalIndex::pitch_rate)
      .def_readwrite("wheel_left", &SignalIndex::wheel_left)
      .def_readwrite("wheel_right", &SignalIndex::wheel_right)
      .def_readwrite("wheel_left_rate", &SignalIndex::wheel_left_rate)
      .def_readwrite("wheel_right_rate", &SignalIndex::wheel_right_rate)
      .def_readwrite("x", &SignalIndex::x)
      .def_readwrite("y", &SignalIndex::y)
      .def_readwrite("yaw", &SignalIndex::yaw)
      .def_property_readonly("logged",
                             [](const SignalIndex& index) {
                               std::vector<std::pair<std::string, int>> logged;
                               for (const auto& [name, at] : index.logged) {
                                 logged.emplace_back(name, at);
                               }
                               return logged;
                             })
      .def_property_readonly("has_pose", &SignalIndex::has_pose);
  m.def("index_signals", &plant::index_signals, py::arg("plant"), py::arg("signals"),
        py::arg("logged") = std::vector<std::string>{},
        "The indices of `signals`, the names of plant `plant`'s state output, and of "
        "`logged`, those it logs into steps.csv: (name, index) pairs.");
  m.def("two_wheeler_index", &plant::two_wheeler_index, py::return_value_policy::copy);
  m.def("two_wheeler_signals", &plant::two_wheeler_signals, py::return_value_policy::copy);
}

// A library plant's constructor; disturbance_input=True declares its input "disturbance"
// (force N, pitch torque N m).
template <class Plant>
auto plant_init() {
  return py::init([](std::string name, const plant::RobotParams& params, double initial_pitch,
                     bool disturbance_input) {
    return std::make_unique<Plant>(
        std::move(name), params, initial_pitch,
        disturbance_input ? plant::DisturbanceInput::kDeclared : plant::DisturbanceInput::kNone);
  });
}

void bind_plants(py::module_& m) {
  using plant::AnalyticPlant;
  using plant::SimbodyPlant;
  // Copies of params: a block's own parameters never change once it is made.
  py::class_<AnalyticPlant, plant::RobotPlant>(m, "AnalyticPlant", kAnalyticPlantDoc)
      .def(plant_init<AnalyticPlant>(), py::arg("name"), py::arg("params"),
           py::arg("initial_pitch") = plant::kDefaultInitialPitch,
           py::arg("disturbance_input") = false)
      .def_property_readonly("params", [](const AnalyticPlant& p) { return p.params(); })
      .def("set_state", &AnalyticPlant::set_state, py::arg("context"), py::arg("state"),
           "Sets the whole state from a vector in the output layout; the yaw rate is not "
           "stored.");
  py::class_<SimbodyPlant, plant::RobotPlant>(m, "SimbodyPlant", kSimbodyPlantDoc)
      .def(plant_init<SimbodyPlant>(), py::arg("name"), py::arg("params"),
           py::arg("initial_pitch") = plant::kDefaultInitialPitch,
           py::arg("disturbance_input") = false)
      .def_property_readonly("params", [](const SimbodyPlant& p) { return p.params(); })
      .def("set_state", &SimbodyPlant::set_state, py::arg("context"), py::arg("state"),
           "Sets the whole state from a vector in the output layout; the yaw rate is not read.")
      .def("multibody_energy", &SimbodyPlant::multibody_energy, py::arg("context"),
           "Simbody's kinetic plus gravitational energy of the robot in `context`.");
}

void bind_supervisors(py::module_& m) {
  using blocks::LqrSupervisor;
  using blocks::LqrSupervisorParams;
  py::class_<blocks::PdSupervisor, Block>(m, "PdSupervisor", kPdSupervisorDoc)
      .def(py::init<std::string, const blocks::PdSupervisorParams&>(), py::arg("name"),
           py::arg("params"));
  py::class_<LqrSupervisor, Block>(m, "LqrSupervisor", kLqrSupervisorDoc)
      .def(py::init<std::string, const plant::LinearModel&, const LqrSupervisorParams&>(),
           py::arg("name"), py::arg("planar"), py::arg("params"),
           "Designed for `planar`, a plant linearised as linearize_planar_upright is.")
      .def(py::init<std::string, const plant::RobotParams&, const LqrSupervisorParams&>(),
           py::arg("name"), py::arg("robot"), py::arg("params"),
           "Designed for the two-wheeler `robot`.")
      .def_property_readonly(
          "gain", [](const LqrSupervisor& s) { return Eigen::RowVector4d(s.gain()); },
          "K on (theta_b, phi, theta_b', phi').");
}

// A layout (feature_layout.h) as a dict, key -> values, in its order.
py::dict layout_dict(const blocks::FeatureLayout& layout) {
  py::dict dict;
  for (const blocks::LayoutEntry& entry : layout) dict[py::str(entry.key)] = py::cast(entry.values);
  return dict;
}

void bind_features(py::module_& m) {
  py::class_<blocks::Normaliser, Block>(m, "Normaliser", kNormaliserDoc)
      .def(py::init<std::string, const blocks::NormaliserParams&>(), py::arg("name"),
           py::arg("params"))
      .def("layout", [](const blocks::Normaliser& b) { return layout_dict(b.layout()); });
  py::class_<blocks::RbfFeatures, Block>(m, "RbfFeatures", kRbfFeaturesDoc)
      .def(py::init<std::string, const blocks::RbfParams&, int>(), py::arg("name"),
           py::arg("params"), py::arg("dimensions") = 2)
      .def_property_readonly("num_features", &blocks::RbfFeatures::num_features)
      .def("layout", [](const blocks::RbfFeatures& b) { return layout_dict(b.layout()); })
      .def("layout_note", &blocks::RbfFeatures::layout_note);
}

// A learner's weights, copied out and checked in.
template <class Learner>
void def_weights(py::class_<Learner, Block>& cls) {
  cls.def_property_readonly("num_features", &Learner::num_features)
      .def(
          "weights", [](const Learner& l, const Context& c) { return Vector(l.weights(c)); },
          py::arg("context"), "A copy of the learnt weights in `context`.")
      .def(
          "set_weights",
          [](const Learner& l, Context& c, const Vector& weights) {
            VectorView stored = l.mutable_weights(c);
            if (weights.size() != stored.size()) {
              throw std::invalid_argument("set_weights: block '" + l.path() + "' has " +
                                          std::to_string(stored.size()) + " weights, got " +
                                          std::to_string(weights.size()));
            }
            stored = weights;
          },
          py::arg("context"), py::arg("weights"));
}

void bind_learners(py::module_& m) {
  py::class_<blocks::Critic, Block> critic(m, "Critic", kCriticDoc);
  critic.def(py::init<std::string, int, const blocks::CriticParams&, double>(), py::arg("name"),
             py::arg("num_features"), py::arg("params"), py::arg("period"));
  def_weights(critic);
  py::class_<blocks::Actor, Block> actor(m, "Actor", kActorDoc);
  actor.def(py::init<std::string, int, const blocks::ActorParams&, double>(), py::arg("name"),
            py::arg("num_features"), py::arg("params"), py::arg("period"));
  def_weights(actor);
}

void bind_exploration(py::module_& m) {
  py::class_<blocks::BoltzmannSampler, Block>(m, "BoltzmannSampler", kBoltzmannSamplerDoc)
      .def(py::init<std::string, const blocks::SamplerParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"));
  py::class_<blocks::GaussianExploration, Block>(m, "GaussianExploration", kGaussianExplorationDoc)
      .def(py::init<std::string, const blocks::ExplorationParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"))
      .def("sigma_at", &blocks::GaussianExploration::sigma_at, py::arg("elapsed"),
           "sigma after `elapsed` s of learning.")
      .def("elapsed", &blocks::GaussianExploration::elapsed, py::arg("context"),
           "The learning time elapsed in `context`, s.");
  py::class_<blocks::OuExploration, Block>(m, "OuExploration", kOuExplorationDoc)
      .def(py::init<std::string, const blocks::ExplorationParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"));
  py::class_<blocks::Entropy, Block>(m, "Entropy", kEntropyDoc)
      .def(py::init<std::string, const blocks::EntropyParams&>(), py::arg("name"),
           py::arg("params"));
  py::class_<blocks::Mixer, Block>(m, "Mixer", kMixerDoc)
      .def(py::init<std::string>(), py::arg("name"));
  py::class_<blocks::OmegaSchedule, Block>(m, "OmegaSchedule", kOmegaScheduleDoc)
      .def(py::init<std::string, const blocks::OmegaParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"))
      .def("omega_at", &blocks::OmegaSchedule::omega_at, py::arg("ticks"),
           "omega after `ticks` ticks of learning.")
      .def("ticks", &blocks::OmegaSchedule::ticks, py::arg("context"),
           "Ticks of learning so far in `context`.");
  py::class_<blocks::Tropism, Block>(m, "Tropism", kTropismDoc)
      .def(py::init<std::string, const blocks::TropismParams&>(), py::arg("name"),
           py::arg("params"))
      .def("set_k1", &blocks::Tropism::set_k1, py::arg("context"), py::arg("k1"),
           "Sets k1 in `context` for the next trials.")
      .def("k1", &blocks::Tropism::k1, py::arg("context"));
}

void bind_task(py::module_& m) {
  py::class_<blocks::Reward, Block>(m, "Reward", kRewardDoc)
      .def(py::init<std::string, const blocks::RewardParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"));
  py::class_<blocks::QuadraticReward, Block>(m, "QuadraticReward", kQuadraticRewardDoc)
      .def(py::init<std::string, const blocks::RewardParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"));
  py::class_<blocks::FailureDetector, Block>(m, "FailureDetector", kFailureDetectorDoc)
      .def(py::init<std::string, const blocks::FailureDetectorParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"));
  py::class_<blocks::Sensors, Block>(m, "Sensors", kSensorsDoc)
      .def(py::init<std::string, const blocks::SensorsParams&, double, const plant::SignalIndex&,
                    int>(),
           py::arg("name"), py::arg("params"), py::arg("period"),
           py::arg("signals") = plant::two_wheeler_index(),
           py::arg("state_size") = static_cast<int>(plant::kStateSize));
  py::class_<blocks::TorquePush, Block>(m, "TorquePush", kTorquePushDoc)
      .def(py::init<std::string, const blocks::PushParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"));
  py::class_<blocks::ExternalPush, Block>(m, "ExternalPush", kExternalPushDoc)
      .def(py::init<std::string, const blocks::PushParams&, double>(), py::arg("name"),
           py::arg("params"), py::arg("period"));
}

}  // namespace

void bind_library_blocks(py::module_& m) {
  bind_all_params(m);
  bind_plant_models(m);
  bind_plants(m);
  bind_supervisors(m);
  bind_features(m);
  bind_learners(m);
  bind_exploration(m);
  bind_task(m);
}

}  // namespace cbbg::python
