"""The library's PD supervisor written in Python: a_S = k_theta theta + k_dtheta theta' +
k_phi phi + k_dphi phi', phi and phi' the mean of both wheels, in the C++ block's order of
operations, so that it gives the same numbers bit for bit. It fills the supervisor slot:

    options = cbbg.preset("cbbg").options
    options.slots.supervisor = PdSupervisor          # called as PdSupervisor(name, parameters)
"""

import cbbg

GAIN_KEYS = ("supervisor.k_theta", "supervisor.k_dtheta", "supervisor.k_phi", "supervisor.k_dphi")


class PdSupervisor(cbbg.LeafBlock):
    def __init__(self, name, parameters=None):
        super().__init__(name)
        parameters = parameters or cbbg.parameters()
        self.gains = [parameters[key] for key in GAIN_KEYS]
        self.measured = self.declare_input_port("measured", 6, "the sensors' six signals")
        self.declare_output_port("action", 1, self.calc_action, reads=[self.measured],
                                 description="a_S, the supervisor's torque")

    def calc_action(self, context, action):
        y = context.input(self.measured)
        k_theta, k_dtheta, k_phi, k_dphi = self.gains
        action[0] = (k_theta * y[0] + k_dtheta * y[1] + k_phi * (y[2] + y[3]) / 2.0
                     + k_dphi * (y[4] + y[5]) / 2.0)
