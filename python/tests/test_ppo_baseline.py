"""The deep-RL baseline (python/examples/ppo_balance.py): its advantage estimate under
autoreset, its normaliser, its determinism, that it learns, its evaluation and its CLI. It needs
PyTorch (Debian's python3-torch, which scripts/setup.sh installs): without it these tests fail,
saying so, rather than pass untried."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

import cbbg

EXAMPLES = os.path.join(os.path.dirname(__file__), os.pardir, "examples")
sys.path.insert(0, EXAMPLES)

try:
    import torch
except ImportError:
    torch = None

ANALYTIC = {"plant.kind": "analytic"}


def ppo():
    if torch is None:
        pytest.fail("python3-torch is not installed, so the PPO baseline cannot be tested; "
                    "scripts/setup.sh installs it", pytrace=False)
    import ppo_balance
    return ppo_balance


def test_advantages_stop_at_a_fall_bootstrap_a_truncation_and_skip_the_reset_step():
    gae = ppo().advantages
    # One robot, four steps: t0 a step, t1 it falls, t2 the reset (no transition), t3 a step.
    rewards = np.array([[1.0], [0.0], [0.0], [1.0]])
    values = np.array([[2.0], [3.0], [9.0], [4.0]])
    terminated = np.array([[0.0], [1.0], [0.0], [0.0]])
    ended = terminated.copy()
    valid = np.array([[True], [True], [False], [True]])
    last = np.array([5.0])
    got = gae(rewards, values, terminated, ended, valid, last, gamma=0.5, lam=0.5)
    a3 = 1.0 + 0.5 * 5.0 - 4.0
    a1 = 0.0 - 3.0  # the fall bootstraps nothing
    a0 = 1.0 + 0.5 * 3.0 - 2.0 + 0.25 * a1
    assert got[:, 0].tolist() == pytest.approx([a0, a1, 0.0, a3])
    # Truncated at t1 instead: the final observation's value (fed at t2) is bootstrapped,
    # and nothing flows back across the episode's end.
    got = gae(rewards, values, np.zeros_like(terminated), ended, valid, last, 0.5, 0.5)
    a1 = 0.0 + 0.5 * 9.0 - 3.0
    assert got[1, 0] == pytest.approx(a1)
    assert got[0, 0] == pytest.approx(1.0 + 0.5 * 3.0 - 2.0 + 0.25 * a1)


def test_the_normaliser_keeps_the_mean_and_variance_of_everything_seen():
    normaliser = ppo().Normaliser(2)
    rng = np.random.default_rng(0)
    batches = [rng.normal(3.0, 2.0, size=(n, 2)) for n in (5, 17, 40)]
    for batch in batches:
        normaliser.update(batch)
    seen = np.concatenate(batches)
    assert normaliser.mean == pytest.approx(seen.mean(0), rel=1e-3)
    assert normaliser.var == pytest.approx(seen.var(0), rel=1e-3)
    assert normaliser(np.array([[1e9, -1e9]])).tolist() == [[10.0, -10.0]]


def test_the_same_seed_trains_the_same_policy_and_another_seed_does_not():
    module = ppo()
    torch.set_num_threads(1)

    def weights(seed):
        policy, _, report = module.train(ANALYTIC, seed, steps=2048, num_envs=8, rollout=128)
        assert report["steps"] == 2048
        return b"".join(p.detach().numpy().tobytes() for p in policy.parameters())

    assert weights(3) == weights(3)
    assert weights(3) != weights(4)


def test_it_learns_to_balance_the_analytic_robot():
    module = ppo()
    torch.set_num_threads(1)
    policy, normaliser, report = module.train(ANALYTIC, 1, steps=160_000)
    # The first 20 s episode came, and from every evaluation angle the final policy balances.
    assert report["experience_to_first_success_s"] is not None
    assert 0 < report["experience_to_first_success_s"] <= 1600
    assert module.evaluate(policy, normaliser, ANALYTIC, "evaluation.noise_std=0", 1) == (5, 5)


class Teacher:
    """The PD supervisor's law, in the baseline's units (the action over the torque limit)."""

    def __init__(self, limit, gains=(50.0, 10.0, 0.5, 0.5, 0.5, 0.5)):
        self.gains = torch.tensor([gains]) / limit

    def mean(self, observations):
        return observations @ self.gains.T


def test_the_evaluation_counts_what_balances_under_each_condition():
    module = ppo()
    identity = module.Normaliser(6)
    identity.var[:] = 1.0 - 1e-8  # scaled observations equal the measured ones
    teacher = Teacher(5.0)
    assert module.evaluate(teacher, identity, ANALYTIC, "evaluation.noise_std=0", 1) == (5, 5)
    push = "evaluation.push_force=300;evaluation.push_duration=0.5"
    assert module.evaluate(teacher, identity, ANALYTIC, push, 1) == (0, 5)
    idle = Teacher(5.0, gains=(0.0,) * 6)
    assert module.evaluate(idle, identity, ANALYTIC, "evaluation.body_mass_scale=1.3", 1) == (0, 5)


def test_the_command_writes_its_report_and_never_replaces_a_file(tmp_path):
    ppo()
    script = os.path.join(EXAMPLES, "ppo_balance.py")
    command = [sys.executable, script, "--plant", "analytic", "--steps", "2048", "--envs", "8",
               "--condition", "evaluation.noise_std=0", "--out", "r.json"]
    done = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    report = json.loads((tmp_path / "r.json").read_text())
    assert report["steps"] == 2048 and report["plant"] == "analytic"
    assert list(report["balanced"]) == ["evaluation.noise_std=0"]
    assert sorted(os.listdir(tmp_path)) == ["r.json"]  # no temporary left
    (tmp_path / "r.json").write_text("mine")
    done = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 2
    assert "'r.json' exists; give another --out (it is not replaced)" in done.stderr
    assert (tmp_path / "r.json").read_text() == "mine"


def test_evaluated_parameters_apply_the_evaluation_keys_to_the_robot():
    nominal = cbbg.parameters(ANALYTIC)
    heavy = cbbg.evaluated_parameters(
        cbbg.parameters({**ANALYTIC, "evaluation.body_mass_scale": 1.3,
                         "evaluation.push_force": 74, "evaluation.noise_std": 0.05}))
    assert heavy["plant.body_mass"] == pytest.approx(1.3 * nominal["plant.body_mass"])
    assert heavy["push.force"] == 74
    assert heavy["sensors.noise_std"][0] == pytest.approx(0.05)
    with pytest.raises(cbbg.ConfigError, match="evaluation.body_mass_scale"):
        cbbg.evaluated_parameters(cbbg.parameters({**ANALYTIC,
                                                   "evaluation.body_mass_scale": 1e308}))


@pytest.mark.parametrize("condition, message", [
    ("evaluation.noise_std", "condition 'evaluation.noise_std': 'evaluation.noise_std' is not "
                             "key=number"),
    ("evaluation.noise_std=big", "'evaluation.noise_std=big' is not key=number"),
    ("evaluation.nois_std=0.1", "unknown key 'evaluation.nois_std'"),
])
def test_the_command_refuses_a_bad_condition_before_it_trains(tmp_path, condition, message):
    ppo()
    script = os.path.join(EXAMPLES, "ppo_balance.py")
    done = subprocess.run([sys.executable, script, "--steps", "2048", "--condition", condition,
                           "--out", "r.json"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 2 and message in done.stderr, done.stderr
    assert os.listdir(tmp_path) == []
