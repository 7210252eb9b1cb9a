"""Every block of the paper's Fig. 5 a slot from Python: a critic and a reward written in
Python fill their slots; what the learners learnt is read part by part."""

import numpy as np
import pytest

import cbbg


class RewardEchoCritic(cbbg.LeafBlock):
    """A critic whose TD error is the reward it received; it learns nothing."""

    def __init__(self, name, num_features):
        super().__init__(name)
        self.declare_input_port("features", num_features)
        self.reward = self.declare_input_port("reward", 1)
        self.declare_output_port("value", 1, self.calc_value)
        self.declare_output_port("td_error", 1, self.calc_td_error, reads=[self.reward])

    def calc_value(self, context, out):
        out[:] = 0.0

    def calc_td_error(self, context, out):
        out[:] = context.input(self.reward)


class PitchSquareReward(cbbg.LeafBlock):
    """r = -theta_b^2."""

    def __init__(self, name):
        super().__init__(name)
        self.measured = self.declare_input_port("measured", 6)
        self.declare_output_port("reward", 1, self.calc, reads=[self.measured])

    def calc(self, context, out):
        out[0] = -context.input(self.measured)[0] ** 2


def analytic(seeds=1):
    return cbbg.parameters({"plant.kind": "analytic", "seeds": seeds})


def test_a_python_critic_gets_the_features_size_and_whether_it_learns():
    seen = []

    def critic(name, parameters, num_features, learns):
        seen.append((name, num_features, learns))
        return RewardEchoCritic(name, num_features)

    options = cbbg.preset("cbbg").options
    options.slots.critic = critic
    assert options.slots.critic is critic
    arm = cbbg.make_arm("echo", options)
    arm.learner(analytic())
    assert seen == [("critic", 49, True)]
    # Its learnt actor alone, evaluated: the critic is told not to learn.
    cbbg.make_arm("echo_policy", cbbg.learnt_actor(options)).learner(analytic())
    assert seen[-1] == ("critic", 49, False)


def test_the_loop_records_the_python_reward_the_critic_receives():
    options = cbbg.preset("cbbg").options
    options.slots.critic = lambda name, p, n, learns: RewardEchoCritic(name, n)
    task = cbbg.TaskSlots()
    task.reward = lambda name, p: PitchSquareReward(name)
    loop = cbbg.make_arm("echo", options, task=task).learner(analytic())
    context = loop.diagram.create_context(1)
    loop.start_trial(context, 0.1744)
    simulator = cbbg.Simulator(loop.diagram, context, cbbg.SimulatorOptions(accuracy=loop.accuracy))
    log = simulator.add_log(loop.telemetry, 0.01)
    simulator.advance_to(1.0)
    td_error, reward = log.values[12], log.values[14]  # the telemetry's order (telemetry.h)
    np.testing.assert_array_equal(reward, td_error)
    assert len(set(reward.tolist()) - {0.0, -1.0}) > 50  # the pitch cost, not the sliding one


def test_learnt_weights_are_read_part_by_part():
    options = cbbg.preset("cbbg").options
    options.slots.critic = lambda name, p, n, learns: RewardEchoCritic(name, n)
    results = cbbg.run_exp1(analytic(), [cbbg.make_arm("echo", options)])
    weights = results.runs[0].weights
    assert list(weights.actor_parts) == ["weights"]
    np.testing.assert_array_equal(weights.actor_parts["weights"], weights.actor)
    assert weights.critic_parts == {}  # a critic that is no learner keeps nothing
    with pytest.raises(ValueError, match="the critic learnt no part 'weights'"):
        weights.critic
