"""A deep-RL baseline on cbbg's balancing task: PPO (clipped surrogate, GAE) in PyTorch,
collecting from cbbg.VecBalanceEnv's robots in C++ threads.

  /usr/bin/python3 python/examples/ppo_balance.py --plant analytic --seed 1 --out ppo_seed1.json

It trains for --steps environment steps (10 ms each) from the paper's fixed initial pitch,
records the simulated seconds of experience (all robots' together) until an episode first
balanced for the whole trial (20 s, truncated without a fall), then evaluates the final
policy's mean action from each of evaluation.angles under each --condition, the transfer
protocol's keys of evaluation.*, and writes those figures and the CPU time as JSON.

The task is the environment's: its observation (pitch, pitch rate, both wheels' angles and
rates) scaled by running statistics, its torque, its failure and its sliding-surface reward,
plus --alive-bonus per step (1 by default). The bonus is the one change: with the reward
alone (0 or -1 a step) an agent that falls at once loses less than one that balances and
wobbles, and PPO learns to fall.
"""

import argparse
import json
import os
import sys
import tempfile
import time

import numpy as np
import torch
from torch import nn

import cbbg

CONDITIONS = ["evaluation.noise_std=0", "evaluation.body_mass_scale=1.3",
              "evaluation.com_height_scale=1.3", "evaluation.noise_std=0.05",
              "evaluation.push_force=74;evaluation.push_duration=0.5"]


class Normaliser:
    """Running mean and variance of the observations (Chan's parallel update), applied
    clipped to +-10; frozen at evaluation."""

    def __init__(self, size):
        self.mean = np.zeros(size)
        self.var = np.ones(size)
        self.count = 1e-4

    def update(self, batch):
        batch_mean, batch_var, n = batch.mean(0), batch.var(0), batch.shape[0]
        delta, total = batch_mean - self.mean, self.count + n
        self.mean = self.mean + delta * n / total
        self.var = (self.var * self.count + batch_var * n
                    + delta ** 2 * self.count * n / total) / total
        self.count = total

    def __call__(self, observations):
        scaled = (observations - self.mean) / np.sqrt(self.var + 1e-8)
        return torch.as_tensor(np.clip(scaled, -10.0, 10.0), dtype=torch.float32)


class Policy(nn.Module):
    """A Gaussian policy and a value function, two tanh MLPs; actions in units of the
    torque limit (clipped to +-1 before they are scaled)."""

    def __init__(self, observation_size, hidden=64):
        super().__init__()

        def mlp(out, gain):
            layers = [nn.Linear(observation_size, hidden), nn.Tanh(),
                      nn.Linear(hidden, hidden), nn.Tanh(), nn.Linear(hidden, out)]
            for layer in layers[::2]:
                nn.init.orthogonal_(layer.weight, np.sqrt(2))
                nn.init.zeros_(layer.bias)
            nn.init.orthogonal_(layers[-1].weight, gain)
            return nn.Sequential(*layers)

        self.mean = mlp(1, 0.01)
        self.value = mlp(1, 1.0)
        self.log_std = nn.Parameter(torch.full((1,), -0.5))

    def distribution(self, observations):
        return torch.distributions.Normal(self.mean(observations), self.log_std.exp())


def advantages(rewards, values, terminated, ended, valid, last_values, gamma, lam):
    """GAE over a rollout of T steps x N robots, with NEXT_STEP autoreset: the step after an
    episode ended is the reset (valid False, no transition), and the observation fed at it is
    the episode's final one, so values[t + 1] is what a truncated episode bootstraps from.
    `ended` is terminated or truncated; a terminated step bootstraps nothing."""
    steps = rewards.shape[0]
    result = np.zeros_like(rewards)
    running = np.zeros_like(last_values)
    for t in reversed(range(steps)):
        next_values = values[t + 1] if t + 1 < steps else last_values
        delta = rewards[t] + gamma * (1.0 - terminated[t]) * next_values - values[t]
        running = np.where(valid[t], delta + gamma * lam * (1.0 - ended[t]) * running, 0.0)
        result[t] = running
    return result


def train(settings, seed, steps, num_envs=16, rollout=128, epochs=10, minibatch=512,
          gamma=0.99, lam=0.95, clip=0.2, learning_rate=3e-4, alive_bonus=1.0, threads=0,
          progress=None):
    """PPO for `steps` environment steps; returns (policy, normaliser, report). progress, if
    given, is called after each update with the steps so far and the mean length (s) of the
    episodes that ended in that rollout."""
    torch.manual_seed(seed)
    rng = np.random.default_rng(seed)
    env = cbbg.VecBalanceEnv(num_envs, settings, threads=threads)
    limit = float(env.single_action_space.high[0])
    observations, _ = env.reset(seed=seed)
    normaliser = Normaliser(observations.shape[1])
    policy = Policy(observations.shape[1])
    optimiser = torch.optim.Adam(policy.parameters(), lr=learning_rate, eps=1e-5)
    started = time.process_time()
    report = {"seed": seed, "steps": 0, "experience_to_first_success_s": None,
              "cpu_to_first_success_s": None, "episodes": 0}
    ended_before = np.zeros(num_envs, dtype=bool)
    experience = 0
    lengths = np.zeros(num_envs, dtype=np.int64)
    while report["steps"] < steps:
        normaliser.update(observations)
        ended_lengths = []
        batch = {k: [] for k in ("obs", "act", "logp", "val", "rew", "term", "end", "valid")}
        for _ in range(rollout):
            scaled = normaliser(observations)
            with torch.no_grad():
                dist = policy.distribution(scaled)
                action = dist.sample()
                batch["logp"].append(dist.log_prob(action).sum(-1).numpy())
                batch["val"].append(policy.value(scaled).squeeze(-1).numpy())
            torque = np.clip(action.numpy(), -1.0, 1.0) * limit
            observations, reward, terminated, truncated, _ = env.step(torque)
            valid = ~ended_before
            experience += int(valid.sum())
            if report["experience_to_first_success_s"] is None and (truncated & valid).any():
                report["experience_to_first_success_s"] = round(experience * env.period, 6)
                report["cpu_to_first_success_s"] = time.process_time() - started
            lengths += valid
            ended_before = terminated | truncated
            finished = ended_before & valid
            report["episodes"] += int(finished.sum())
            ended_lengths.extend(lengths[finished] * env.period)
            lengths[finished] = 0
            for key, value in (("obs", scaled), ("act", action.numpy()),
                               ("rew", reward + alive_bonus * (~terminated)),
                               ("term", terminated), ("end", ended_before), ("valid", valid)):
                batch[key].append(value)
        report["steps"] += rollout * num_envs
        with torch.no_grad():
            last_values = policy.value(normaliser(observations)).squeeze(-1).numpy()
        arrays = {k: np.asarray(v, dtype=np.float64) if k != "obs" else torch.stack(v)
                  for k, v in batch.items()}
        gae = advantages(arrays["rew"], arrays["val"], arrays["term"], arrays["end"],
                         arrays["valid"].astype(bool), last_values, gamma, lam)
        update(policy, optimiser, arrays, gae, rng, epochs, minibatch, clip)
        if progress is not None:
            progress(report["steps"], float(np.mean(ended_lengths)) if ended_lengths else None)
    env.close()
    return policy, normaliser, report


def update(policy, optimiser, arrays, gae, rng, epochs, minibatch, clip):
    """Clipped-surrogate epochs over the rollout's valid transitions."""
    valid = arrays["valid"].astype(bool).reshape(-1)
    obs = arrays["obs"].reshape(-1, arrays["obs"].shape[-1])[valid]
    act = torch.as_tensor(arrays["act"].reshape(-1, 1)[valid], dtype=torch.float32)
    old_logp = torch.as_tensor(arrays["logp"].reshape(-1)[valid], dtype=torch.float32)
    adv = torch.as_tensor(gae.reshape(-1)[valid], dtype=torch.float32)
    returns = adv + torch.as_tensor(arrays["val"].reshape(-1)[valid], dtype=torch.float32)
    for _ in range(epochs):
        order = torch.as_tensor(rng.permutation(len(adv)))
        for start in range(0, len(adv), minibatch):
            index = order[start:start + minibatch]
            dist = policy.distribution(obs[index])
            ratio = (dist.log_prob(act[index]).sum(-1) - old_logp[index]).exp()
            a = adv[index]
            a = (a - a.mean()) / (a.std() + 1e-8)
            surrogate = torch.min(ratio * a, ratio.clamp(1 - clip, 1 + clip) * a).mean()
            value_loss = ((policy.value(obs[index]).squeeze(-1) - returns[index]) ** 2).mean()
            loss = -surrogate + 0.5 * value_loss
            optimiser.zero_grad()
            loss.backward()
            nn.utils.clip_grad_norm_(policy.parameters(), 0.5)
            optimiser.step()


def condition_parameters(settings, condition):
    """The evaluated robot of `condition` ("key=value;key=value", numbers for the evaluation.*
    keys transfer takes). ValueError, or cbbg.ConfigError naming the key, for a bad one."""
    changed = dict(settings)
    for assignment in filter(None, condition.split(";")):
        key, equals, value = assignment.partition("=")
        try:
            changed[key.strip()] = float(value)
        except ValueError:
            equals = ""
        if not equals:
            raise ValueError(f"condition '{condition}': '{assignment}' is not key=number")
    return cbbg.evaluated_parameters(cbbg.parameters(changed))


def evaluate(policy, normaliser, settings, condition, seed):
    """How many of evaluation.angles the policy's mean action balances for the whole trial
    under `condition` (condition_parameters)."""
    parameters = condition_parameters(settings, condition)
    angles = list(parameters["evaluation.angles"])
    env = cbbg.VecBalanceEnv(len(angles), parameters, threads=1)
    limit = float(env.single_action_space.high[0])
    observations, _ = env.reset(seed=seed, options={"initial_pitch": angles})
    ended = np.zeros(len(angles), dtype=bool)
    balanced = np.zeros(len(angles), dtype=bool)
    while not ended.all():
        with torch.no_grad():
            mean = policy.mean(normaliser(observations)).numpy()
        observations, _, terminated, truncated, _ = env.step(np.clip(mean, -1.0, 1.0) * limit)
        balanced |= truncated & ~terminated & ~ended
        ended |= terminated | truncated
    env.close()
    return int(balanced.sum()), len(angles)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--plant", default="analytic", help="plant.kind (default analytic)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--steps", type=int, default=300_000,
                        help="environment steps to train for, all robots together")
    parser.add_argument("--envs", type=int, default=16, help="robots stepped together")
    parser.add_argument("--alive-bonus", type=float, default=1.0)
    parser.add_argument("--condition", action="append",
                        help="an evaluation condition, repeatable (default: transfer's five)")
    parser.add_argument("--out", required=True, help="the JSON report to write (not replaced)")
    parser.add_argument("--progress", action="store_true",
                        help="print the mean episode length after each update (stderr)")
    args = parser.parse_args(argv)
    if os.path.exists(args.out):
        parser.error(f"'{args.out}' exists; give another --out (it is not replaced)")
    if args.steps <= 0 or args.envs <= 0:
        parser.error("--steps and --envs must be positive integers")
    torch.set_num_threads(1)
    settings = {"plant.kind": args.plant}
    conditions = args.condition or CONDITIONS
    for condition in conditions:  # before the training, which a typo would waste
        try:
            condition_parameters(settings, condition)
        except (ValueError, cbbg.ConfigError) as error:
            parser.error(str(error))
    started = time.process_time()

    def progress(done, mean_length):
        print(f"steps {done}: episodes lasted {mean_length} s on average", file=sys.stderr)

    policy, normaliser, report = train(settings, args.seed, args.steps, num_envs=args.envs,
                                       alive_bonus=args.alive_bonus, threads=1,
                                       progress=progress if args.progress else None)
    report["train_cpu_s"] = time.process_time() - started
    report["plant"] = args.plant
    report["balanced"] = {}
    started = time.process_time()
    for condition in conditions:
        report["balanced"][condition] = evaluate(policy, normaliser, settings, condition,
                                                 args.seed)
    report["evaluate_cpu_s"] = time.process_time() - started
    write_new(args.out, json.dumps(report, indent=1) + "\n")
    print(json.dumps(report))
    return 0


def write_new(path, text):
    """Writes `path` whole or not at all, never over a file that appeared meanwhile."""
    descriptor, temporary = tempfile.mkstemp(prefix=".ppo-", dir=os.path.dirname(path) or ".")
    try:
        with os.fdopen(descriptor, "w") as out:
            out.write(text)
        os.link(temporary, path)
    finally:
        os.unlink(temporary)


if __name__ == "__main__":
    sys.exit(main())
