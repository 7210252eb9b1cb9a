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

// The class comments and port tables of the headers, verbatim.
constexpr const char* kActorDoc =
    R"(Actor: the action network a_A = theta . phi(s) and its learning rule (docs/model.md §2.3,
§2.11).

| port               | dir | size | meaning                                 |
|--------------------|-----|------|-----------------------------------------|
| features           | in  | n    | phi(s_t)                                |
| td_error           | in  | 1    | delta_{t-1}, from the Critic            |
| supervisor_action  | in  | 1    | a_S(t), the supervisor's action         |
| exploration_action | in  | 1    | a_E(t), the sampler's action            |
| omega              | in  | 1    | omega(t), the mixing factor             |
| actor_action       | out | 1    | a_A(t) = theta . phi(s_t)               |

"actor_action" reads only the features, so the mixer's loop through the sampler is not
algebraic. The periodic update at tick t learns from the transition s_{t-1} -> s_t with
delta = delta_{t-1} and the values it stored at t-1 (phi, a_S, a_E, a_A, omega):
  improved: theta <- theta + alpha delta [omega (a_E - a_S) + (a_S - a_A)] phi
            (= alpha delta (a - a_A) phi with a the mixed action);
  weighted: theta <- theta + omega alpha delta (a_E - a_A) phi
                           + (1 - omega) alpha (a_S - a_A) phi
            (the supervised term does not depend on delta);
then stores this tick's values. Nothing is learnt on the first tick of a trial. theta
starts at 0; a new trial (Context::reset_trial_state) forgets the previous tick and keeps
theta. A frozen actor skips the update of theta.
Parameters: alpha = actor.alpha, rule = actor.rule, the period trial.period; n is the
feature count.

Discrete state: weights theta (n, persistent); per trial: previous_features phi(s_{t-1})
(n), previous_actions (a_S, a_E, a_A, omega at t-1), has_previous (1).)";

constexpr const char* kBoltzmannSamplerDoc =
    R"(BoltzmannSampler: the basal ganglia's exploratory action (docs/model.md §2.6).

| port               | dir | size | meaning                        |
|--------------------|-----|------|--------------------------------|
| actor_action       | in  | 1    | a_A(t), from the Actor         |
| temperature        | in  | 1    | T(t) >= 0, from the Tropism    |
| exploration_action | out | 1    | a_E(t) ~ N(a_A, K_B T / 2)     |

Equation: a_E = a_A + sqrt(K_B T / 2) eps, eps a standard normal held in the discrete
state, drawn from the block's own generator by the initialization update (first tick)
and by each periodic update (next tick). The Boltzmann law exp(-(a_E - a_A)^2 / (K_B T))
is this normal. Parameters: K_B = sampler.k_b, the period trial.period.
exploration.kind boltzmann selects it (GaussianExploration and OuExploration are the
alternatives, drawing the same eps).

Discrete state, per trial: noise eps (1).)";

constexpr const char* kCriticDoc =
    R"(Critic: the value function V(s) = w . phi(s), learnt by TD(lambda), the paper's, or by
normalised TD(0) (docs/model.md §2.3, §2.10, §5.4).

| port     | dir | size | meaning                                              |
|----------|-----|------|------------------------------------------------------|
| features | in  | n    | phi(s_t)                                             |
| reward   | in  | 1    | r_{t-1}, the reward of the transition s_{t-1} -> s_t |
| failed   | in  | 1    | 1 when s_t is terminal (the trial fails), else 0     |
| value    | out | 1    | V(s_t) = w . phi(s_t)                                |
| td_error | out | 1    | delta_{t-1}                                          |

Equations, at tick t, with the weights w before this tick's update:
  delta_{t-1} = r_{t-1} + gamma V'(s_t) - w . phi(s_{t-1}),
  V'(s_t) = 0 if failed else w . phi(s_t);  delta = 0 on the first tick of a trial.
The periodic update then learns from that transition and remembers phi(s_t):
  td_lambda: z <- gamma lambda z + phi(s_{t-1});  w <- w + beta delta_{t-1} z;
  td0:       w <- w + beta delta_{t-1} phi(s_{t-1}) / (epsilon + phi(s_{t-1}) . phi(s_{t-1})).
w starts at 0. A new trial (Context::reset_trial_state) clears z and the previous tick and
keeps w. A frozen critic skips the update of z and w.
Parameters: the rule critic.kind, beta = critic.beta, gamma = critic.gamma, lambda =
critic.lambda (td_lambda), epsilon = critic.epsilon (td0), the period trial.period; n is
the feature count (RbfFeatures::num_features).

Discrete state: weights w (n, persistent); per trial: trace z (n, td_lambda only),
previous_features phi(s_{t-1}) (n), has_previous (1).)";

constexpr const char* kEntropyDoc =
    R"(Entropy: the differential entropy of the exploration law, for logging (docs/model.md §2.12).

| port        | dir | size | meaning                            |
|-------------|-----|------|------------------------------------|
| temperature | in  | 1    | T, from the Tropism                |
| entropy     | out | 1    | E, bits (negative for small K_B T) |

Equation: E = (1/2) log2(pi e K_B T), the entropy of N(a_A, K_B T / 2); -inf at T = 0.
Parameter: K_B = sampler.k_b.)";

constexpr const char* kFailureDetectorDoc =
    R"(FailureDetector: ends the trial when the robot falls (docs/model.md §3).

| port     | dir | size | meaning                                  |
|----------|-----|------|------------------------------------------|
| measured | in  | 6    | the Sensors output (measured_signals.h)   |
| failed   | out | 1    | 1 when the trial fails at this tick, else 0 |

Equation: failed = 1 if |theta_b| > failure_angle (strictly: at the angle it still
stands) or any measured signal is not finite, else 0. The periodic update returns
EventStatus::terminate when failed, so the simulation stops after this tick's updates
(the learning blocks still learn from the failing transition).
Parameters: failure_angle = trial.failure_angle, the period trial.period.)";

constexpr const char* kLqrSupervisorDoc =
    R"(LqrSupervisor: a drop-in replacement of PdSupervisor whose gains come from linear-quadratic
regulation of the linearised robot instead of from config.

| port     | dir | size | meaning                                         |
|----------|-----|------|-------------------------------------------------|
| measured | in  | 6    | the Sensors output (measured_signals.h)          |
| action   | out | 1    | a_S, N m, both wheels (the plant saturates it)  |

Equations: x = (theta_b, phi, theta_b', phi') with phi = (phi_l + phi_r) / 2,
a_S = -K x, K = R^-1 B' X, X the stabilising solution of the continuous-time algebraic
Riccati equation A' X + X A - X B R^-1 B' X + Q = 0 (control::lqr, framework/control/lqr.h)
for the robot linearised upright with both wheels driven alike
(plant::linearize_planar_upright, or the linearisation of another plant, 4 states and 1
input in that order), Q = diag(q), R = r.
K is computed once, at construction.
Parameters: the plant's linearisation, q = supervisor.lqr_q, r = supervisor.lqr_r.)";

constexpr const char* kMixerDoc =
    R"(Mixer: the action sent to the motors, between exploration and supervision (docs/model.md §2.8).

| port               | dir | size | meaning                     |
|--------------------|-----|------|-----------------------------|
| exploration_action | in  | 1    | a_E, from the sampler       |
| supervisor_action  | in  | 1    | a_S, from the supervisor    |
| omega              | in  | 1    | omega, from OmegaSchedule   |
| action             | out | 1    | a, N m                      |

Equation: a = omega a_E + (1 - omega) a_S. The plant saturates the torque, not the mixer.
No parameters.)";

constexpr const char* kNormaliserDoc =
    R"(Normaliser: pitch and pitch rate in grid units, saturated to the RBF grid (docs/model.md §2.2),
and, with normaliser.inputs, the wheels' mean angle and rate likewise.

| port     | dir | size  | meaning                                               |
|----------|-----|-------|-------------------------------------------------------|
| measured | in  | 6     | the Sensors output (measured_signals.h)               |
| x        | out | 2 - 4 | normalised (theta_b, theta_b'[, phi][, phi'])         |

Equations: x = clamp((theta_b / n_theta, theta_b' / n_dtheta), -S, S), then, as the inputs
ask, clamp(phi / n_phi, -S, S) and clamp(phi' / n_dphi, -S, S), with phi = (phi_l + phi_r) / 2
and phi' = (phi_l' + phi_r') / 2. Without the clamp the pitch rate leaves the grid and every
feature vanishes. Parameters: n_theta = normaliser.scale_theta, n_dtheta =
normaliser.scale_dtheta, S = normaliser.saturation, normaliser.inputs, n_phi =
normaliser.scale_phi, n_dphi = normaliser.scale_dphi.
Its layout (feature_layout.h): the scales of what it sees and S, as normaliser.* (the
paper's inputs: n_theta, n_dtheta and S only, so its weights files keep their layout).)";

constexpr const char* kOmegaScheduleDoc =
    R"(OmegaSchedule: the coordination factor between cerebellum and basal ganglia (docs/model.md
§2.7).

| port  | dir | size | meaning               |
|-------|-----|------|-----------------------|
| omega | out | 1    | omega(t), in [0, 1]   |

Equation (mode schedule): omega(t) = max(0, 1 - exp(-(t - n2) / n3)), t the ticks since
learning began: a counter in the discrete state, advanced by each periodic update and
NOT reset between trials. Modes zero and one output that constant, mode constant its
`constant`.
Parameters: n2 = omega.n2, n3 = omega.n3, mode = omega.mode, the period trial.period.)";

constexpr const char* kPdSupervisorDoc =
    R"(PdSupervisor: the cerebellum's target action, a PD law on pitch and wheel angle (docs/model.md
§2.4).

| port     | dir | size | meaning                                 |
|----------|-----|------|-----------------------------------------|
| measured | in  | 6    | the Sensors output (measured_signals.h)  |
| action   | out | 1    | a_S, N m (the plant saturates it)        |

Equation: a_S = k_theta theta_b + k_dtheta theta_b' + k_phi (phi_l + phi_r) / 2
                + k_dphi (phi_l' + phi_r') / 2.
Parameters: supervisor.k_theta, supervisor.k_dtheta, supervisor.k_phi, supervisor.k_dphi.)";

constexpr const char* kRbfFeaturesDoc =
    R"(RbfFeatures: the Gaussian radial-basis features of the critic and the actor (docs/model.md
§2.3).

| port     | dir | size | meaning                                  |
|----------|-----|------|------------------------------------------|
| x        | in  | d    | normalised (theta_b, theta_b'), d = 2     |
| features | out | m^d  | phi(x), unit k = i m + j at (c_i, c_j)    |
|          |     | (d m)| (rbf.units per_axis: unit k = a m + i)    |

Equations: phi_k(x) = exp(-((x_0 - c_i)^2 + (x_1 - c_j)^2) / (2 b^2)), k = i m + j, for
i, j in [0, m): pitch picks the row i, pitch rate the column j. Since V = w . phi and
a_A = theta . phi, phi is also the gradient of both with respect to their weights.
With d = 3 or 4 inputs (normaliser.inputs) the grid has an axis per input, the first the
slowest: phi_k(x) = exp(-sum_a (x_a - c_{k_a})^2 / (2 b^2)), k = sum_a k_a m^(d-1-a).
With rbf.units per_axis the units sit on each axis alone: phi_k(x) = exp(-(x_a - c_i)^2 /
(2 b^2)), k = a m + i, d m of them; what a learner sums over them is a sum of one function
per input (the PD law's shape), with far fewer weights than the grid's m^d.
Parameters: c = rbf.centres (m of them), b = rbf.width. Its layout (feature_layout.h):
rbf.centres and rbf.width, and rbf.per_axis 1 with rbf.units per_axis.)";

constexpr const char* kRewardDoc =
    R"(Reward: the sliding-surface reward of docs/model.md §2.9.

| port     | dir | size | meaning                                              |
|----------|-----|------|------------------------------------------------------|
| measured | in  | 6    | the Sensors output (measured_signals.h)               |
| failed   | in  | 1    | 1 when the trial fails at this tick, else 0           |
| reward   | out | 1    | r_{t-1}, the reward of the transition s_{t-1} -> s_t  |

Equations: s(t) = a1 theta_b + a2 theta_b' + k_phi phi', phi' = (phi_l' + phi_r') / 2 (with
  k_phi = 0, the paper's surface, computed without the term: the same bits);
  r_{t-1} = -1 if failed, else 0 if s(t)^2 <= s(t-1)^2, else -1;
0 on the first tick of a trial without failure (there is no transition yet). The
periodic update remembers s(t); a new trial forgets it.
Parameters: a1 = reward.a1, a2 = reward.a2, k_phi = reward.k_phi, the period trial.period.
reward.kind sliding selects it (QuadraticReward is quadratic's).

Discrete state, per trial: previous_surface s(t-1), has_previous.)";

constexpr const char* kSensorsDoc =
    R"(Sensors: the plant state to the signals the controller measures (docs/model.md §2.1).

| port        | dir | size | meaning                                                  |
|-------------|-----|------|----------------------------------------------------------|
| plant_state | in  | n    | the plant's signals (plant/plant_signals.h)              |
| measured    | out | 6    | theta_b, theta_b', phi_l, phi_r, phi_l', phi_r' (rad, s) |

Equations, per signal i taken from the plant state x by name (`signals`: where each sits in
the n = `state_size` signals; a plant of one wheel gives it for both sides):
  y_i = Q_i(x_i + sigma_i n_i),   Q_i(v) = q_i round(v / q_i) if q_i > 0, else v,
with n_i a standard normal held in the discrete state: drawn by the initialization update
for the first tick and by each periodic update for the next, from the block's own
generator (only for signals with sigma_i > 0). The initialization update runs at the start
of every trial, so a trial never reuses the previous one's last draw. Parameters: sigma =
sensors.noise_std, q = sensors.quantisation (both off by default), the period trial.period.)";

constexpr const char* kTorquePushDoc =
    R"(TorquePush: a disturbance through the motors, as a torque pulse (push.torque) added to the
held action of both wheels. The motors' limit bounds the sum, so it models a command
fault more than a blow: ExternalPush is the push from outside.

| port   | dir | size | meaning                                    |
|--------|-----|------|--------------------------------------------|
| action | in  | 1    | a, the held (zero-order hold) action, N m  |
| torque | out | 1    | a + p, the torque each wheel gets, N m     |

Equations: at each tick t_k = k Ts the periodic update sets
  p = torque if start <= t_k < start + duration (PushParams::on_at), else 0
(comparisons within the simulator's 1e-9 * max(1, |t|) of simultaneity) and p holds until
t_{k+1}. The push therefore switches only at tick instants, where the action does too: the
torque is piecewise constant between ticks and both plants integrate it exactly. It starts
at the first tick at or after `start` and covers the ticks before start + duration. The
plant saturates the sum a + p (plant.torque_limit).
Parameters: PushParams, the period Ts = trial.period.

Discrete state: [p].)";

constexpr const char* kExternalPushDoc =
    R"(ExternalPush: a disturbance from outside the robot, for a plant's input "disturbance"
(plant/plant_ports.h): a pulse of horizontal force at the body's centre of mass
(push.force) and of torque on the body about the axle (push.pitch_torque). Unlike
TorquePush it does not pass through the motors, so their limit does not bound it.

| port        | dir | size | meaning                                      |
|-------------|-----|------|----------------------------------------------|
| disturbance | out | 2    | F, N; tau_ext, N m (zero outside the pulse)  |

Equations: at each tick t_k = k Ts the periodic update sets
  (F, tau_ext) = (force, pitch_torque) if PushParams::on_at(t_k), else (0, 0)
and holds it until t_{k+1}, exactly as TorquePush does with its torque.
Parameters: PushParams, the period Ts = trial.period.

Discrete state: [F, tau_ext].)";

constexpr const char* kTropismDoc =
    R"(Tropism: the exploration temperature from the critic's value (docs/model.md §2.5).

| port        | dir | size | meaning                       |
|-------------|-----|------|-------------------------------|
| value       | in  | 1    | V(s_t), from the Critic       |
| temperature | out | 1    | T                             |

Equation: T = k1 / (1 + exp(k2 V)): high value, low temperature. With tropism.kind fixed,
T = k1 / 2 (the paper's T at V = 0) whatever V: exploration no longer cools as the critic
learns, yet still follows k1's annealing.
Parameters: k1 is the context parameter "k1" (default tropism.k1), so the annealing
schedule changes it between trials without rebuilding (set_k1); k2 = tropism.k2, kind =
tropism.kind.)";

constexpr const char* kGaussianExplorationDoc =
    R"(GaussianExploration: exploration.kind gaussian, a temperature-free alternative to the
BoltzmannSampler (docs/model.md §5.4).

| port               | dir | size | meaning                          |
|--------------------|-----|------|----------------------------------|
| actor_action       | in  | 1    | a_A(t), from the Actor           |
| exploration_action | out | 1    | a_E(t) = a_A + sigma(t) eps      |

Equations: a_E = a_A + sigma(t) eps, sigma(t) = sigma_0 2^(-elapsed / half_life)
(sigma_0 when half_life = 0), elapsed the learning time the block has run. eps is a
standard normal held in the discrete state, drawn from the block's own generator by the
initialization update (first tick) and by each periodic update (next tick), exactly as
the BoltzmannSampler draws its own: at the same path and seed both see the same eps.
Each periodic update advances elapsed by the period.
Parameters: sigma_0 = exploration.sigma, half_life = exploration.half_life, the period
trial.period.

Discrete state: per trial, noise eps (1); persistent, elapsed (1, s), carried across
trials as learning goes on.)";

constexpr const char* kOuExplorationDoc =
    R"(OuExploration: exploration.kind ou, temporally correlated exploration: the actor's action
plus an Ornstein-Uhlenbeck process (docs/model.md §5.4).

| port               | dir | size | meaning                  |
|--------------------|-----|------|--------------------------|
| actor_action       | in  | 1    | a_A(t), from the Actor   |
| exploration_action | out | 1    | a_E(t) = a_A + x(t)      |

Equations: dx = -theta x dt + sigma sqrt(2 theta) dW, stationary law N(0, sigma^2),
sampled exactly at the ticks: the initialization update draws x from the stationary law,
x = sigma eps_0; each periodic update sets
  x <- x e^(-theta Ts) + sigma sqrt(1 - e^(-2 theta Ts)) eps_k,
so the lag-one autocorrelation is e^(-theta Ts). eps is a standard normal from the
block's own generator, one per update in the BoltzmannSampler's order (common random
numbers); for theta Ts large enough that e^(-theta Ts) is 0, a_E is GaussianExploration's
with a fixed sigma, bit for bit.
Parameters: sigma = exploration.sigma, theta = exploration.ou_theta, the period Ts =
trial.period.

Discrete state, per trial: noise x (1, N m); a new trial draws it afresh.)";

constexpr const char* kQuadraticRewardDoc =
    R"(QuadraticReward: reward.kind quadratic, a graded reward in place of the paper's sliding
surface's 0 or -1 (docs/model.md §5.4).

| port     | dir | size | meaning                                              |
|----------|-----|------|------------------------------------------------------|
| measured | in  | 6    | the Sensors output (measured_signals.h)               |
| failed   | in  | 1    | 1 when the trial fails at this tick, else 0           |
| reward   | out | 1    | r_{t-1}, the reward of the transition s_{t-1} -> s_t  |

Equation: r_{t-1} = -1 if failed, else -(q0 theta_b^2 + q1 theta_b'^2 + q2 phi'^2) of
s_t, phi' = (phi_l' + phi_r') / 2 the wheels' mean rate. It remembers nothing, so it
rewards the first tick of a trial too.
Parameters: q = reward.q (3 numbers, each >= 0); the period trial.period is checked only.)";

constexpr const char* kAnalyticPlantDoc =
    R"(AnalyticPlant: the robot of docs/model.md §1 as its equations of motion (robot_dynamics.h),
integrated by the Simulator's error-controlled Dormand–Prince 5(4) stepper (Boost.Odeint)
at SimulatorOptions::accuracy (the experiments set it from plant.accuracy).

| port   | dir | size | meaning                                                          |
|--------|-----|------|------------------------------------------------------------------|
| torque | in  | 2    | tau_l, tau_r: motor torques body -> wheel, N m (any value; the   |
|        |     |      | plant saturates each to [-torque_limit, torque_limit])           |
| disturbance | in | 2 | with DisturbanceInput::kDeclared only: F, a horizontal force at   |
|        |     |      | the body's centre of mass along the heading, N; tau_ext, a torque |
|        |     |      | on the body about the axle, N m (neither saturated)              |
| state  | out | 10   | theta_b (rad, > 0 leans forward), theta_b' (rad/s), phi_l, phi_r |
|        |     |      | (absolute wheel angles, rad), phi_l', phi_r' (rad/s), x, y (axle |
|        |     |      | midpoint, m), yaw (rad), yaw rate (rad/s); see plant_ports.h     |

Equations: M(q) q'' + N(q, q') = E sat(T) + Q_ext with Q_ext = disturbance_forces(F, tau_ext)
(zero without the input),  q = (theta_b, phi_l, phi_r) (see
robot_dynamics.h); x' = v cos(yaw), y' = v sin(yaw), yaw' = R (phi_r' - phi_l') / d,
v = R (phi_l' + phi_r') / 2 (rolling without slip).
Continuous state (9): theta_b, phi_l, phi_r, theta_b', phi_l', phi_r', x, y, yaw. The
state output reads only this state, never the torque directly.
Parameters: RobotParams (plant.*); the initial pitch (trial.theta0), the rest zero.
Errors: a non-finite torque, disturbance or state throws SimulationError naming the block.)";

constexpr const char* kSimbodyPlantDoc =
    R"(SimbodyPlant: the reference model of the robot, a 3-D Simbody multibody system
(multibody_robot.h): body and two wheels on revolute joints about the axle, rolling
without slip, yaw free. It advances itself between the simulator's instants with the
torque held (zero-order hold), by the Simbody integrator plant.simbody_integrator
(Runge–Kutta–Merson by default; Runge–Kutta 3 or Verlet) at plant.accuracy.

| port   | dir | size | meaning                                                          |
|--------|-----|------|------------------------------------------------------------------|
| torque | in  | 2    | tau_l, tau_r: motor torques body -> wheel, N m (any value; the   |
|        |     |      | plant saturates each to [-torque_limit, torque_limit])           |
| disturbance | in | 2 | with DisturbanceInput::kDeclared only: F, a horizontal force at   |
|        |     |      | the body's centre of mass along the heading, N; tau_ext, a torque |
|        |     |      | on the body about the axle, N m (held like the torque)            |
| state  | out | 10   | theta_b (rad, > 0 leans forward), theta_b' (rad/s), phi_l, phi_r |
|        |     |      | (absolute wheel angles, rad), phi_l', phi_r' (rad/s), x, y (axle |
|        |     |      | midpoint, m), yaw (rad), yaw rate (rad/s); see plant_ports.h     |

Equations: Simbody's, of the same mechanics as robot_dynamics.h (a test holds the two to
1e-6 rad); motor torque +tau on a wheel, -tau on the body; viscous friction mu_l phi'
(wheel-ground) and mu_w (phi' - theta_b') (axle); the disturbance as a force applied at the
body's mass centre and a torque on the body, never through the motors.
Continuous state (10): the state output itself. Each Context's scratch holds its own
multibody system, built once when the context is created, with a Simbody state and
integrator. (One system shared by all contexts would be cheaper, but Simbody's System is
not safe to realise from two threads at once, and contexts may run in parallel.) When
the context's state or time differs from where the scratch left it (reset, set_state,
Context::reset_all_state, a restored or cloned context), the scratch restarts its
integrator from the context's state; a reset rebuilds nothing.
Parameters: RobotParams (plant.*, validated with validate_rigid_bodies); the initial
pitch (trial.theta0), the rest zero.
Errors: a non-finite torque, disturbance or state, or a Simbody failure, throws SimulationError
naming the block.)";

void bind_all_params(py::module_& m) {
  bind_params<plant::RobotParams>(
      m, "RobotParams", "The two-wheeled robot's physical parameters, config keys plant.*.");
  bind_params<blocks::PdSupervisorParams>(
      m, "PdSupervisorParams",
      "Config keys supervisor.* of the PD supervisor (supervisor.kind: pd).");
  bind_params<blocks::LqrSupervisorParams>(
      m, "LqrSupervisorParams",
      "Config keys supervisor.lqr_* of the LQR supervisor (supervisor.kind: lqr).");
  bind_params<blocks::NormaliserParams>(m, "NormaliserParams", "Config keys normaliser.*.");
  bind_params<blocks::RbfParams>(m, "RbfParams", "Config keys rbf.*.");
  bind_params<blocks::CriticParams>(m, "CriticParams", "Config keys critic.*, and frozen.");
  bind_params<blocks::ActorParams>(m, "ActorParams", "Config keys actor.*, and frozen.");
  bind_params<blocks::SamplerParams>(m, "SamplerParams", "Config key sampler.k_b.");
  bind_params<blocks::ExplorationParams>(
      m, "ExplorationParams",
      "Config keys exploration.*: the exploration block's kind and the alternatives' noise.");
  bind_params<blocks::EntropyParams>(m, "EntropyParams",
                                     "The entropy's constant, config key sampler.k_b.");
  bind_params<blocks::OmegaParams>(m, "OmegaParams", "Config keys omega.*, and mode and constant.");
  bind_params<blocks::RewardParams>(m, "RewardParams", "Config keys reward.*.");
  bind_params<blocks::FailureDetectorParams>(m, "FailureDetectorParams",
                                             "Config key trial.failure_angle.");
  bind_params<blocks::SensorsParams>(
      m, "SensorsParams",
      "Config keys sensors.*: per-signal noise and quantisation, in the order of the "
      "\"measured\" port (theta_b, theta_b', phi_l, phi_r, phi_l', phi_r'). Zero turns either "
      "off (default).");
  bind_params<blocks::PushParams>(m, "PushParams", "A push on the robot: config keys push.*.");
  bind_params<blocks::TropismParams>(m, "TropismParams", "Config keys tropism.*.");
}

// What the supervisors and the sensors are designed for: the robot's linearisation and the
// names of a plant's signals.
void bind_plant_models(py::module_& m) {
  py::class_<plant::LinearModel>(m, "LinearModel", "x' = A x + B u.")
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
