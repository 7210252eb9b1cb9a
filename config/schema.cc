// The keys of a cbbg config: docs/model.md §4's names, types, defaults and meanings.

#include <limits>
#include <numbers>

#include "config/config.h"

namespace cbbg::config {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

KeySpec number(std::string path, double value, std::string meaning, double min = -kInf,
               bool min_exclusive = false, double max = kInf, bool max_exclusive = false) {
  return {std::move(path), Kind::kNumber, value, std::move(meaning), {}, min, max,
          min_exclusive,   max_exclusive, 0};
}

KeySpec positive(std::string path, double value, std::string meaning) {
  return number(std::move(path), value, std::move(meaning), 0.0, true);
}

KeySpec integer(std::string path, long long value, std::string meaning, double min,
                double max = kInf) {
  return {std::move(path), Kind::kInteger, value, std::move(meaning), {}, min, max,
          false,           false,          0};
}

KeySpec text(std::string path, std::string value, std::string meaning,
             std::vector<std::string> choices) {
  return {std::move(path),
          Kind::kText,
          std::move(value),
          std::move(meaning),
          std::move(choices),
          -kInf,
          kInf,
          false,
          false,
          0};
}

KeySpec numbers(std::string path, std::vector<double> value, std::string meaning, int size,
                double min = -kInf) {
  return {std::move(path),
          Kind::kNumbers,
          std::move(value),
          std::move(meaning),
          {},
          min,
          kInf,
          false,
          false,
          size};
}

std::vector<std::string> experiment_choices() {
  std::vector<std::string> choices{"exp1", "exp2", "exp3"};
  for (const auto& name : diagram_names()) choices.push_back(name);
  return choices;
}

std::vector<KeySpec> make_schema() {
  return {
      text("experiment", "exp1",
           "exp1 | exp2 | exp3 (skill acquisition) | a diagram name (one arm, exp1's protocol)",
           experiment_choices()),
      {"arms", Kind::kNames, std::vector<std::string>{"cbbg", "bg_only"},
       "diagrams compared in one run (exp1, exp3)", diagram_names(), -kInf, kInf, false, false, 0},
      integer("seeds", 20, "independent runs per arm; run k uses root seed + k", 1, kMaxSeeds),
      integer("seed", 1, "root seed", 0, kMaxSeed),
      integer("max_trials", 100, "exp1: give up after this many trials without a success", 1,
              kMaxTrials),
      text("plant.kind", "simbody", "simbody (3-D multibody, reference) | analytic (fast)",
           {"simbody", "analytic"}),
      positive("plant.wheel_mass", 1.0, "m_l = m_r, kg"),
      positive("plant.body_mass", 10.0, "M, kg"),
      positive("plant.wheel_radius", 0.15, "R, m"),
      positive("plant.track_width", 0.44, "d, distance between the wheels, m"),
      positive("plant.com_height", 0.4, "L, axle midpoint to body centre of mass, m"),
      positive("plant.wheel_inertia", 0.01125, "J_w, wheel about its axle, kg m^2"),
      positive("plant.body_pitch_inertia", 1.5417,
               "J_y, body pitch about its centre of mass, kg m^2"),
      positive("plant.body_yaw_inertia", 0.5893, "J_z, body yaw inertia, kg m^2"),
      positive("plant.body_roll_inertia", 1.5417,
               "J_x, body roll inertia, kg m^2 (matters only when turning)"),
      number("plant.wheel_diametral_inertia", 0.005625,
             "wheel inertia about a diameter, kg m^2 (matters only when turning)", 0.0),
      positive("plant.gravity", 9.8, "g, m/s^2"),
      number("plant.wheel_ground_friction", 0.1, "mu_l = mu_r, viscous, N m/(rad/s)", 0.0),
      number("plant.axle_friction", 0.1, "mu_w, wheel-axle viscous, N m/(rad/s)", 0.0),
      positive("plant.torque_limit", 5.0, "motor torques saturate to +-this, N m"),
      positive("plant.accuracy", 1e-6, "integrator error tolerance (relative and absolute)"),
      text("plant.simbody_integrator", "merson",
           "merson (Runge-Kutta-Merson, the reference) | rk3 | verlet: the Simbody plant's",
           {"merson", "rk3", "verlet"}),
      text("plant.simbody_model", "rolling",
           "rolling (no-slip built into the base's mobilizer) | constrained (three no-slip "
           "constraints, the reference): the Simbody plant's formulation",
           {"rolling", "constrained"}),
      number("trial.theta0", 0.1744, "initial pitch of every trial, rad"),
      positive("trial.duration", 20.0, "a trial that lasts this long succeeds, s"),
      number("trial.failure_angle", 0.5236, "|theta_b| beyond this fails the trial, rad", 0.0, true,
             std::numbers::pi / 2.0),
      positive("trial.period", 0.01, "sampling period Ts of the controller, s"),
      number("trial.settle_time", 5.0, "the oscillation figures of trials.csv (exp2) start here, s",
             0.0),
      positive("normaliser.scale_theta", 0.05817764, "n_theta: pitch per grid unit, rad"),
      positive("normaliser.scale_dtheta", 0.05817764, "n_dtheta: pitch rate per grid unit, rad/s"),
      positive("normaliser.saturation", 3.0, "inputs saturate to +-this (the RBF grid)"),
      numbers("rbf.centres", {-3, -2, -1, 0, 1, 2, 3}, "grid coordinates per axis (n x n units)",
              0),
      positive("rbf.width", 0.5, "b: Gaussian width of every unit, grid units"),
      text("supervisor.kind", "pd",
           "pd (docs/model.md §2.4) | lqr (Riccati gains of the linearised robot)", {"pd", "lqr"}),
      number("supervisor.k_theta", 50.0, "PD gain on theta_b, N m/rad"),
      number("supervisor.k_dtheta", 10.0, "PD gain on theta_b', N m s/rad"),
      number("supervisor.k_phi", 1.0, "PD gain on (phi_l + phi_r)/2, N m/rad"),
      number("supervisor.k_dphi", 1.0, "PD gain on (phi_l' + phi_r')/2, N m s/rad"),
      numbers("supervisor.lqr_q", {100, 1, 1, 1},
              "LQR state weights on (theta_b, phi, theta_b', phi')", 4, 0.0),
      positive("supervisor.lqr_r", 1.0, "LQR weight on the torque"),
      positive("critic.beta", 0.1, "critic learning rate"),
      number("critic.gamma", 0.8, "discount, in (0, 1]", 0.0, true, 1.0),
      number("critic.lambda", 0.8, "eligibility trace decay, in [0, 1)", 0.0, false, 1.0, true),
      positive("actor.alpha", 0.1, "actor learning rate"),
      text("actor.rule", "improved", "improved (paper eq. 11) | weighted (eq. 7)",
           {"improved", "weighted"}),
      positive("tropism.k1", 10.0, "annealing factor: T = k1 / (1 + exp(k2 V))"),
      number("tropism.k2", 0.1, "how strongly a high value cools the temperature"),
      positive("sampler.k_b", 1.0, "K_B: a_E ~ N(a_A, K_B T / 2); the paper's 1.38e-23 works too"),
      number("omega.n2", 500.0, "ticks of supervision before omega rises", 0.0),
      positive("omega.n3", 200.0, "time constant of omega's rise, ticks"),
      number("reward.a1", 10.0, "sliding surface weight on theta_b, 1/rad"),
      number("reward.a2", 1.0, "sliding surface weight on theta_b', s/rad"),
      numbers("sensors.noise_std", {0, 0, 0, 0, 0, 0},
              "Gaussian noise std per measured signal (theta_b, theta_b', phi_l, phi_r, phi_l', "
              "phi_r'); 0 = off",
              6, 0.0),
      numbers("sensors.quantisation", {0, 0, 0, 0, 0, 0},
              "quantisation step per measured signal; 0 = off", 6, 0.0),
      number("push.torque", 0.0,
             "a torque pulse added to each wheel in every trial, N m; 0 = none (disturbance)"),
      number("push.start", 5.0, "when the push begins, s from the trial's start", 0.0),
      positive("push.duration", 0.2, "how long the push lasts, s"),
      {"annealing",
       Kind::kAnnealing,
       std::vector<AnnealingStep>{{1, 10}, {11, 5}, {16, 1}, {21, 0.5}, {23, 0.1}},
       "exp2: k1 from a trial on (trial 1 is the CB-coordinated one)",
       {},
       -kInf,
       kInf,
       false,
       false,
       0},
      integer("exp2.trials", 30, "exp2: trials in all, the CB-coordinated one included", 2,
              kMaxTrials),
      integer("log.decimation", 1, "steps.csv keeps every n-th tick; 0 writes no steps.csv", 0),
      numbers("evaluation.angles", {0.05, 0.1, 0.15, 0.2, 0.25},
              "initial pitches the learnt actor is evaluated from, rad", 0),
      positive("evaluation.body_mass_scale", 1.0,
               "evaluation only: body mass and inertias times this (training stays nominal)"),
      positive("evaluation.com_height_scale", 1.0,
               "evaluation only: centre-of-mass height times this (training stays nominal)"),
      number("evaluation.noise_std", 0.0,
             "evaluation only: Gaussian noise std added to the measured pitch (rad) and pitch "
             "rate (rad/s), on top of sensors.noise_std",
             0.0),
      number("evaluation.push_torque", 0.0,
             "evaluation only: a push of this many N m on each wheel; 0 = push.* as set"),
      number("evaluation.push_start", 5.0, "evaluation only: when that push begins, s", 0.0),
      positive("evaluation.push_duration", 0.2, "evaluation only: how long that push lasts, s"),
      numbers("exp3.angles", {0.05, 0.1744, 0.25},
              "exp3: the learnt actor alone must balance from each of these, rad", 0),
  };
}

}  // namespace

const std::vector<std::string>& diagram_names() {
  static const std::vector<std::string> names{"cbbg", "cbbg_weighted", "bg_only", "cb_only",
                                              "pd_only"};
  return names;
}

const std::vector<KeySpec>& schema() {
  static const std::vector<KeySpec> keys = make_schema();
  return keys;
}

}  // namespace cbbg::config
