"""The two-wheeled robot written in Python with NumPy: a plant of the user's.

`TwoWheeler` is a cbbg.RobotPlant whose equations of motion are the analytic plant's
(M(q) q'' + N(q, q') = E T, docs/model.md), integrated by cbbg's simulator from the
derivatives it declares. It fills the plant slot of any protocol:

    arm = cbbg.make_arm("cbbg_numpy", cbbg.preset("cbbg").options,
                        plant=lambda name, p: TwoWheeler(name, RobotParams.of(p)))

`step` is the same robot stepped by NumPy alone (classical Runge-Kutta), no cbbg at all: the
baseline the environment benchmark compares against.
"""

import math
from dataclasses import dataclass

import numpy as np

import cbbg

SIGNALS = ["pitch", "pitch_rate", "wheel_left", "wheel_right", "wheel_left_rate",
           "wheel_right_rate", "x", "y", "yaw", "yaw_rate"]


@dataclass
class RobotParams:
    body_mass: float = 10.0
    wheel_mass: float = 1.0
    wheel_radius: float = 0.15
    track_width: float = 0.44
    com_height: float = 0.4
    wheel_inertia: float = 0.01125
    body_pitch_inertia: float = 1.5417
    body_yaw_inertia: float = 0.5893
    body_roll_inertia: float = 1.5417
    wheel_diametral_inertia: float = 0.005625
    gravity: float = 9.8
    wheel_ground_friction: float = 0.1
    axle_friction: float = 0.1
    torque_limit: float = 5.0

    @classmethod
    def of(cls, parameters):
        """The plant.* values of a run's parameters."""
        return cls(**{name: parameters[f"plant.{name}"] for name in cls.__dataclass_fields__})


def accelerations(p, q, q_dot, torque):
    """q'' of q = (theta_b, phi_l, phi_r) under the motor torques (tau_l, tau_r)."""
    s, c = math.sin(q[0]), math.cos(q[0])
    rho = p.wheel_radius / p.track_width
    r2 = p.wheel_radius ** 2
    growth = p.body_mass * p.com_height ** 2 + p.body_roll_inertia - p.body_yaw_inertia
    yaw_inertia = growth * s * s + p.body_yaw_inertia + 2.0 * p.wheel_diametral_inertia
    coupling = p.body_mass * p.com_height * p.wheel_radius * c / 2.0
    wheel = p.wheel_mass * r2 + p.wheel_inertia + p.body_mass * r2 / 4.0 + rho * rho * yaw_inertia
    cross = p.body_mass * r2 / 4.0 - rho * rho * yaw_inertia
    mass = np.array([[p.body_mass * p.com_height ** 2 + p.body_pitch_inertia, coupling, coupling],
                     [coupling, wheel, cross],
                     [coupling, cross, wheel]])
    theta_dot, phi_l_dot, phi_r_dot = q_dot
    psi_dot = rho * (phi_r_dot - phi_l_dot)
    mu_w, mu_g = p.axle_friction, p.wheel_ground_friction
    gyro = growth * rho * rho * (phi_l_dot - phi_r_dot) * theta_dot * math.sin(2.0 * q[0])
    centrifugal = p.body_mass * p.com_height * p.wheel_radius / 2.0 * theta_dot ** 2 * s
    sideways = p.body_mass * p.com_height * p.wheel_radius * rho * s * psi_dot
    bias = np.array([
        -p.body_mass * p.gravity * p.com_height * s - growth * psi_dot ** 2 * s * c
        + 2.0 * mu_w * theta_dot - mu_w * (phi_l_dot + phi_r_dot),
        gyro - centrifugal - sideways * phi_r_dot + (mu_g + mu_w) * phi_l_dot - mu_w * theta_dot,
        -gyro - centrifugal + sideways * phi_l_dot + (mu_g + mu_w) * phi_r_dot - mu_w * theta_dot,
    ])
    tau_l, tau_r = np.clip(torque, -p.torque_limit, p.torque_limit)
    force = np.array([-tau_l - tau_r, tau_l, tau_r]) - bias
    return np.linalg.solve(mass, force)


def derivatives(p, x, torque):
    """x = (theta_b, phi_l, phi_r, their rates, x, y, yaw): its time derivative."""
    q, q_dot = x[0:3], x[3:6]
    v = p.wheel_radius * (q_dot[1] + q_dot[2]) / 2.0
    yaw_rate = p.wheel_radius * (q_dot[2] - q_dot[1]) / p.track_width
    return np.concatenate([q_dot, accelerations(p, q, q_dot, torque),
                           [v * math.cos(x[8]), v * math.sin(x[8]), yaw_rate]])


def signals_of(p, x):
    yaw_rate = p.wheel_radius * (x[5] - x[4]) / p.track_width
    return np.array([x[0], x[3], x[1], x[2], x[4], x[5], x[6], x[7], x[8], yaw_rate])


def step(p, x, torque, period=0.01, substeps=10):
    """x after `period` with `torque` held: classical Runge-Kutta, NumPy alone."""
    h = period / substeps
    for _ in range(substeps):
        k1 = derivatives(p, x, torque)
        k2 = derivatives(p, x + h / 2 * k1, torque)
        k3 = derivatives(p, x + h / 2 * k2, torque)
        k4 = derivatives(p, x + h * k3, torque)
        x = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return x


class TwoWheeler(cbbg.RobotPlant):
    """The robot as a cbbg plant: torque (2) in, its ten signals out."""

    def __init__(self, name, params=None):
        super().__init__(name)
        self.params = params or RobotParams()
        self.torque = self.declare_input_port("torque", 2, "tau_l, tau_r, N m (saturated here)")
        self.declare_output_port("state", len(SIGNALS), self.calc_state)
        self.declare_continuous_state(np.zeros(9), self.calc_derivatives)

    def calc_state(self, context, out):
        out[:] = signals_of(self.params, context.continuous_state)

    def calc_derivatives(self, context, out):
        out[:] = derivatives(self.params, context.continuous_state, context.input(self.torque))

    def reset(self, context, initial_pitch):
        x = np.zeros(9)
        x[0] = initial_pitch
        context.set_continuous_state(self, x)

    def signals(self):
        return SIGNALS

    def wheel_radius(self):
        return self.params.wheel_radius
