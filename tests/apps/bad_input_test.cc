// Bad input of every kind, across every subcommand: one line in the project's words naming
// the key, flag or path and what is allowed, exit 2 for what the user typed, and nothing
// written or changed.

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/apps/cbbg_process.h"
#include "tests/support/scratch_directory.h"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

struct BadInput {
  std::string arguments;  // after `cbbg`; {S} stands for the scratch directory
  std::string message;    // a part of the one line printed
};

std::string expand(std::string text, const std::string& scratch) {
  for (std::size_t at = text.find("{S}"); at != std::string::npos; at = text.find("{S}")) {
    text.replace(at, 3, scratch);
  }
  return text;
}

std::vector<BadInput> bad_inputs() {
  const std::string quick = "run --set plant.kind=analytic --seeds 1 --out {S}/out ";
  const std::string any_seeds = "run --set plant.kind=analytic --out {S}/out ";
  const std::string eval = "eval --set plant.kind=analytic --load-weights {S}/w.txt ";
  const std::string graph = "graph --diagram cbbg ";
  const std::string digits309 = "1" + std::string(308, '0');
  std::string many_centres = "0";
  for (int c = 1; c < 32; ++c) {
    many_centres += ',';
    many_centres += std::to_string(c);
  }
  return {
      // Keys and values, from --set.
      {quick + "--set critic.gama=0.5", "unknown key 'critic.gama'; did you mean 'critic.gamma'?"},
      {quick + "--set colour=red", "unknown key 'colour'; `cbbg list` shows every key"},
      {quick + "--set seeds=0", "seeds must be an integer in [1, 10000]; got 0"},
      {quick + "--set max_trials=0", "max_trials must be an integer in [1, 100000]; got 0"},
      {quick + "--set max_trials=100001", "max_trials must be an integer in [1, 100000]"},
      {quick + "--set exp2.trials=1", "exp2.trials must be an integer in [2, 100000]; got 1"},
      {quick + "--set trial.period=0", "trial.period must be > 0; got 0"},
      {quick + "--set trial.duration=0.001",
       "trial.duration (0.001 s) must be at least one trial.period (0.01 s)"},
      {quick + "--set trial.theta0=0.6",
       "trial.theta0 (0.6 rad) must lie inside trial.failure_angle (0.5236 rad)"},
      {quick + "--set trial.theta0=-0.6", "trial.theta0 (-0.6 rad) must lie inside"},
      {quick + "--set trial.failure_angle=0",
       "trial.failure_angle must be in (0, 1.5707963267948966]; got 0"},
      {quick + "--set trial.failure_angle=3.2", "trial.failure_angle must be in (0, 1.57"},
      {quick + "--set evaluation.angles=[0.1,0.6]",
       "evaluation.angles[1] (0.6 rad) must lie inside trial.failure_angle"},
      {quick + "--set evaluation.angles=[]", "evaluation.angles must be a non-empty list"},
      {quick + "--experiment exp3 --set exp3.angles=[0.1,0.6]",
       "exp3.angles[1] (0.6 rad) must lie inside trial.failure_angle"},
      {quick + "--experiment transfer --set exp3.angles=[-0.6]",
       "exp3.angles[0] (-0.6 rad) must lie inside trial.failure_angle"},
      {quick + "--set critic.gamma=nan", "critic.gamma must be a number; got 'nan'"},
      {quick + "--set critic.gamma=1.5", "critic.gamma must be in (0, 1]; got 1.5"},
      {quick + "--set critic.lambda=1", "critic.lambda must be in [0, 1); got 1"},
      {quick + "--set sampler.k_b=.inf", "sampler.k_b must be a finite number"},
      {quick + "--set actor.alpha=-1", "actor.alpha"},
      {quick + "--set actor.rule=best", "actor.rule must be one of improved, weighted; got 'best'"},
      {quick + "--set critic.kind=td1", "critic.kind must be one of td_lambda, td0; got 'td1'"},
      {quick + "--set critic.epsilon=0", "critic.epsilon must be > 0; got 0"},
      {quick + "--set exploration.kind=uniform",
       "exploration.kind must be one of boltzmann, gaussian, ou; got 'uniform'"},
      {quick + "--set exploration.half_life=-1", "exploration.half_life must be >= 0; got -1"},
      {quick + "--set reward.kind=cost",
       "reward.kind must be one of sliding, quadratic; got 'cost'"},
      {quick + "--set reward.q=[1,2]",
       "reward.q must be a list of 3 numbers (on theta_b^2, theta_b'^2, phi'^2); got a list of 2"},
      {quick + "--set tropism.kind=none", "tropism.kind must be one of value, fixed; got 'none'"},
      {quick + "--set plant.kind=ode", "plant.kind must be one of simbody, analytic"},
      {quick + "--set plant.body_mass=-10", "plant.body_mass must be > 0; got -10"},
      {quick + "--set supervisor.kind=mpc", "supervisor.kind must be one of pd, lqr"},
      {quick + "--set arms=[cbbg,cbbg]", "arms lists 'cbbg' twice"},
      {quick + "--set arms=[cbbg,nope]", "arms[1] must be one of"},
      {quick + "--set 'annealing=[{from_trial: 2, k1: 10}]'", "must start at from_trial 1"},
      {quick + "--set trial=3", "trial is a section: give a map of its keys"},
      {quick + "--set =3", "expected key.path=value"},
      {quick + "--set seeds", "expected key.path=value"},
      {quick + "--set seeds=", "seeds has no value after '='"},
      {quick + "--set log.decimation=-1", "log.decimation must be an integer >= 0; got -1"},
      {quick + "--set rbf.width=0", "rbf.width"},
      // The run's own flags.
      {any_seeds + "--seeds 0", "--seeds 0: seeds must be an integer in [1, 10000]; got 0"},
      {any_seeds + "--seeds 10001", "seeds must be an integer in [1, 10000]; got 10001"},
      {any_seeds + "--seeds many", "seeds must be an integer in [1, 10000]; got 'many'"},
      {quick + "--seed -1", "seed must be an integer in [0, 1000000000000]; got -1"},
      {quick + "--seed " + digits309, "seed must be an integer in [0, 1000000000000]; got '1000"},
      {quick + "--jobs 0", "--jobs must be an integer from 1 to 1024; got '0'"},
      {quick + "--jobs many", "--jobs must be an integer from 1 to 1024; got 'many'"},
      {quick + "--experiment ''", "--experiment needs a name"},
      {quick + "--experiment exp9", "experiment must be one of exp1, exp2"},
      {"run --set plant.kind=analytic --out ''", "--out needs a directory path"},
      {"run --out {S}/file", "--out '{S}/file' is a file; give a directory path"},
      {"run --out {S}/mine", "--out '{S}/mine' exists and was not made by cbbg run"},
      {"run --resume ''", "--resume needs the results directory of the interrupted run"},
      {"run --resume {S}/never", "nothing to resume: neither '{S}/never.partial' nor"},
      {"run --resume {S}/mine --seeds 2",
       "--resume continues with the config, weights and options"},
      {any_seeds + "--seeds 2 --save-weights {S}/x.txt",
       "--save-weights keeps the weights of one learning run; this run has 4"},
      {"run --set plant.kind=analytic --experiment bg_only --seeds 1 --out {S}/out "
       "--save-weights {S}/mine",
       "--save-weights '{S}/mine' is a directory; give a file path"},
      {"run --set plant.kind=analytic --experiment bg_only --seeds 1 --out {S}/out "
       "--save-weights {S}/file",
       "--save-weights '{S}/file' exists and cbbg did not write it"},
      {"run --set plant.kind=analytic --experiment bg_only --seeds 1 --out {S}/out "
       "--save-weights {S}/fifo",
       "--save-weights '{S}/fifo' is a FIFO"},
      {quick + "--set evaluation.body_mass_scale=1e308",
       "evaluation.body_mass_scale (1e+308) makes plant.body_mass inf; the scaled value must be "
       "a finite number > 0"},
      {"run --set plant.kind=analytic --experiment bg_only --seeds 1 --out {S}/out "
       "--save-weights {S}/none/x.txt",
       "the directory '{S}/none' does not exist"},
      {quick + "--load-weights {S}/missing.txt", "missing.txt"},
      {quick + "--load-weights {S}/file", "{S}/file"},
      {quick + "--no-such-flag", "--no-such-flag (cbbg --help lists the commands and options)"},
      {"run --set plant.kind=analytic --experiment evaluate --set arms=[bg_only] --seeds 1 "
       "--load-weights {S}/w.txt --save-weights {S}/w2.txt --out {S}/out",
       "--save-weights keeps the weights a run learns; --experiment evaluate learns none (the "
       "weights it uses are those of --load-weights)"},
      {quick + "--set normaliser.inputs=pitch_wheels --set rbf.centres=[" + many_centres + "]",
       "rbf.centres (32 of them) over normaliser.inputs (4 inputs) make 1048576 features per "
       "learner; a learner holds at most 1000000, what a weights file stores: use fewer "
       "rbf.centres or normaliser.inputs"},
      {quick + "--set 'transfer.conditions=[\"evaluation.push_force=1\\nx\"]'",
       "transfer.conditions[0] must be one line; got 'evaluation.push_force=1?x'"},
      // Config files.
      {quick + "--config {S}/missing.yaml",
       "config file '{S}/missing.yaml' cannot be read (missing or unreadable)"},
      {quick + "--config {S}/mine", "config file '{S}/mine' is not a regular file"},
      {quick + "--config /dev/zero", "config file '/dev/zero' is not a regular file"},
      {quick + "--config {S}/huge.yaml", "is larger than 1024 KiB"},
      {quick + "--config {S}/twice.yaml", "key 'seeds' appears twice (again at line 2)"},
      {quick + "--config {S}/malformed.yaml", "malformed YAML at line"},
      {quick + "--config {S}/list.yaml", "a config is a map of keys"},
      // graph.
      {"graph --diagram nope -o {S}/x.dot", "--diagram: unknown diagram 'nope'; the diagrams are"},
      {graph + "-o {S}/x.pdf", "unknown extension '.pdf'"},
      {graph + "-o {S}/mine", "-o '{S}/mine' is a directory; give a file path"},
      {graph + "-o {S}/none/x.dot", "the directory '{S}/none' does not exist"},
      {graph + "-o ''", "-o needs a file path"},
      {graph + "--set trial.theta0=1 -o {S}/x.dot", "trial.theta0 (1 rad) must lie inside"},
      {"graph", "--output is required"},
      {graph + "--depth -5 -o {S}/x.dot", "--depth must be 0 or more (the nesting levels"},
      {graph + "-o {S}/file", "-o '{S}/file' exists and cbbg did not write it"},
      {graph + "-o {S}/fifo", "-o '{S}/fifo' is a FIFO"},
      // plot.
      {"plot {S}/never", "'{S}/never' is not a results directory (it has no config.yaml)"},
      {"plot {S}/mine", "'{S}/mine' is not a results directory (it has no config.yaml)"},
      {"plot {S}/broken", "unknown key 'colour'"},
      // eval.
      {"replay {S}/learnt", "--out is required"},
      {"replay {S}/mine -o {S}/r.html", "'{S}/mine' is not a results directory"},
      {"replay {S}/learnt --arm cbbg -o {S}/r.html", "--arm: no arm 'cbbg' in this run"},
      {"replay {S}/learnt --trial 99 -o {S}/r.html", "--trial: arm 'bg_only', seed 1 has trials"},
      {"replay {S}/learnt --seed x -o {S}/r.html", "--seed"},
      {"replay {S}/learnt -o {S}/file", "-o '{S}/file' exists and cbbg did not write it"},
      {"replay {S}/learnt -o {S}/fifo", "-o '{S}/fifo' is a FIFO; give a regular file's path"},
      {"replay {S}/learnt -o {S}/mine", "-o"},
      {"eval", "--load-weights is required"},
      {"eval --load-weights {S}/missing.txt", "missing.txt"},
      {"eval --load-weights {S}/file", "{S}/file"},
      {eval + "--repeats 0", "--repeats must be from 1 to 10000; got 0"},
      {eval + "--repeats 10001", "--repeats must be from 1 to 10000; got 10001"},
      {eval + "--angles 0.1,inf", "--angles must be finite numbers separated by commas (rad)"},
      {eval + "--angles 0.1,,0.2", "e.g. 0.1,0.2; got '0.1,,0.2'"},
      {eval + "--out {S}/theirs", "--out: '{S}/theirs/evaluation.csv' exists and cbbg did not"},
      {eval + "--set evaluation.body_mass_scale=1e308",
       "evaluation.body_mass_scale (1e+308) makes plant.body_mass inf"},
      {eval + "--angles 0.7", "evaluation.angles[0] (0.7 rad) must lie inside"},
      {eval + "--push-time 1", "a push needs --push-time, --push-duration and at least one of"},
      {eval + "--push-force 3 --push-duration 1", "; missing --push-time\n"},
      {eval + "--push-time 1 --push-pitch-torque nan --push-duration 1",
       "--push-pitch-torque must be a finite number (N m); got nan"},
      {eval + "--push-time 1 --push-torque 2 --push-duration 0",
       "--push-duration must be a finite number > 0 (s); got 0"},
      {eval + "--push-time -1 --push-torque 2 --push-duration 1",
       "--push-time must be a finite number >= 0 (s); got -1"},
      {eval + "--out {S}/file", "--out '{S}/file' is a file, not a directory"},
      {"export --out {S}/gen", "--load-weights is required"},
      {"export --load-weights {S}/w.txt", "--out is required"},
      {"export --load-weights {S}/missing.txt --out {S}/gen", "missing.txt"},
      {"export --load-weights {S}/w.txt --out {S}/gen --scalar half",
       "--scalar must be double or float; got 'half'"},
      {"export --load-weights {S}/w.txt --out {S}/gen --name 9lives",
       "--name must be a C identifier (letters, digits and '_', not first a digit); got '9lives'"},
      {"export --load-weights {S}/w.txt --out {S}/file", "--out '{S}/file' is a file"},
      {"export --load-weights {S}/w.txt --out {S}/gen --omega 1.5",
       "--omega must be a number from 0 to 1; got 1.5"},
      {"export --load-weights {S}/w.txt --out {S}/mine --name policy",
       "--out '{S}/mine/policy.c' exists and cbbg did not write it"},
      {"export --load-weights {S}/w.txt --out {S}/gen --learner --omega 0.5",
       "--learner and --omega exclude each other"},
      {"export --load-weights {S}/w.txt --out {S}/mine --learner --name policy",
       "--out '{S}/mine/policy.c' exists and cbbg did not write it"},
      {eval + "--push-time 0x10 --push-torque 2 --push-duration 1",
       "--push-time: must be a decimal number; got '0x10'"},
      {eval + "--set rbf.centres=[-1,0,1]", "was made for rbf.centres"},
      // drive and robot: refused before any datagram or file.
      {"drive --controller nope --out {S}/d", "--controller: arms[0] must be one of"},
      {"drive --robot 127.0.0.1 --out {S}/d",
       "--robot must be HOST:PORT, HOST an IPv4 address or localhost and PORT 0..65535"},
      {"drive --bind robot:1 --out {S}/d", "--bind must be HOST:PORT"},
      {"drive --duration 0 --out {S}/d", "--duration must be a finite number > 0 (s); got 0"},
      {"drive --trials 0 --out {S}/d", "--trials must be at least 1; got 0"},
      {"drive --key-file {S}/missing.key --out {S}/d",
       "--key-file: cannot read the key file '{S}/missing.key'"},
      {"drive --policy --out {S}/d",
       "realtime.loop policy (cbbg drive --policy) runs learnt weights: give --load-weights"},
      {"drive --policy --controller pd_only --load-weights {S}/w.txt --out {S}/d",
       "realtime.loop policy: arm 'pd_only' has no learnt actor to run alone"},
      {"drive --set remote.host=robot --out {S}/d",
       "remote.host must be an IPv4 address or localhost; got 'robot'"},
      {"drive --set remote.port=70000 --out {S}/d", "remote.port"},
      {"drive --out {S}/mine", "--out '{S}/mine'"},
      {"robot --bind nope", "--bind must be HOST:PORT"},
      {"robot --deadline 2", "--deadline must be a fraction of the period in (0, 1]; got 2"},
      {"robot --timeout-periods 0", "--timeout-periods must be from 1 to 1000; got 0"},
      {"robot --sessions -1", "--sessions must be 0 (until stopped) or more; got -1"},
      {"robot --key-file {S}/missing.key", "--key-file: cannot read the key file"},
      {"robot --set plant.kind=remote",
       "cbbg robot serves a simulated plant; plant.kind remote is cbbg drive's side"},
      // Sweeps: run --grid / --shard, merge, status.
      {quick + "--grid actor.alpha", "--grid actor.alpha: give KEY=V1,V2,..."},
      {quick + "--grid actor.alpha=0.1,fast",
       "--grid actor.alpha=0.1,fast: actor.alpha must be a number; got 'fast'"},
      {quick + "--grid actor.alpa=0.1", "did you mean 'actor.alpha'?"},
      {quick + "--grid actor.alpha=0.1,,0.2", "--grid actor.alpha=0.1,,0.2: an empty value"},
      {quick + "--grid trial.theta0=0.1,0.7", "grid point 002: trial.theta0 (0.7 rad) must lie"},
      {quick + "--shard 0/3", "--shard must be K/N with 1 <= K <= N <= 100000; got '0/3'"},
      {"run --grid seeds=1,2 --resume {S}/out",
       "drop --config, --set, --experiment, --seeds, "
       "--seed, --load-weights, --replace, "
       "--no-figures, --no-replay, --grid, --shard and --check"},
      {"run --set plant.kind=analytic --grid actor.alpha=0.1 --out {S}/mine",
       "--out '{S}/mine' exists; a sweep writes a new directory"},
      {"merge", "DIR is required"},
      {"merge {S}/never", "no sweep at '{S}/never'"},
      {"merge {S}/mine", "no sweep at '{S}/mine'"},
      {"status {S}/never", "no sweep at '{S}/never'"},
      {"merge {S}/learnt", "'{S}/learnt' holds the results of a cbbg run, not of a sweep"},
      {"merge {S}/taken",
       "'{S}/taken' exists and was not made by cbbg merge; the merged results go there: move "
       "it away, then merge"},
      {quick + "--config {S}/sweep_key.yaml",
       "sweep_key.yaml: a sweep's key is a key path such "
       "as actor.alpha; got [a, b]"},
      {quick + "--grid 'critic.beta=[0.1'", "'[0.1' is not a YAML value"},
      // Other commands.
      {"list --bogus", "--bogus"},
      {"frobnicate", "unknown command 'frobnicate' (cbbg --help lists the commands)"},
      {"train --help", "unknown command 'train' (cbbg --help lists the commands)"},
      {"--log-level warn frobnicate --help", "unknown command 'frobnicate'"},
  };
}

TEST(BadInput, EveryCaseExitsTwoWithOneLineAndLeavesEverythingAsItWas) {
  cbbg::testing::ScratchDirectory scratch_directory;
  const fs::path scratch = scratch_directory.path();
  fs::create_directories(scratch / "mine");
  std::ofstream(scratch / "mine" / "notes.txt") << "my notes\n";
  std::ofstream(scratch / "mine" / "policy.c") << "int main(void) { return 0; }\n";
  std::ofstream(scratch / "file") << "a file\n";
  std::ofstream(scratch / "huge.yaml") << std::string(2 * 1024 * 1024, '#');
  std::ofstream(scratch / "twice.yaml") << "seeds: 2\nseeds: 3\n";
  std::ofstream(scratch / "malformed.yaml") << "critic:\n  gamma: [0.5\n";
  std::ofstream(scratch / "list.yaml") << "- 1\n- 2\n";
  std::ofstream(scratch / "sweep_key.yaml") << "sweep: {[a, b]: [1]}\n";
  fs::create_directories(scratch / "theirs");
  std::ofstream(scratch / "theirs" / "evaluation.csv") << "theta0\n0.1\n";
  ASSERT_EQ(::mkfifo((scratch / "fifo").c_str(), 0644), 0);
  fs::create_directories(scratch / "broken");
  std::ofstream(scratch / "broken" / "config.yaml") << "colour: red\n";
  const cbbg::testing::Outcome learnt = cbbg::testing::cbbg(
      "--log-level warn run --set plant.kind=analytic --experiment bg_only --seeds 1 "
      "--no-figures --out " +
      (scratch / "learnt").string() + " --save-weights " + (scratch / "w.txt").string());
  ASSERT_EQ(learnt.exit_code, 0) << learnt.output;
  // A sweep whose first shard ran, and a folder of the user's where its merge would publish.
  const cbbg::testing::Outcome shard = cbbg::testing::cbbg(
      "--log-level warn run --set plant.kind=analytic --seeds 1 --grid seed=1,2 --shard 1/2 "
      "--no-figures --out " +
      (scratch / "taken").string());
  ASSERT_EQ(shard.exit_code, 0) << shard.output;
  fs::create_directories(scratch / "taken");
  std::ofstream(scratch / "taken" / "notes.txt") << "my notes\n";
  const auto before = cbbg::testing::tree_of(scratch);

  const std::vector<BadInput> cases = bad_inputs();
  ASSERT_EQ(cases.size(), 161u);  // docs/reliability.md counts them: a case dropped shows here
  for (const BadInput& input : cases) {
    const std::string arguments = expand(input.arguments, scratch.string());
    SCOPED_TRACE(arguments);
    const cbbg::testing::Outcome outcome = cbbg::testing::cbbg(arguments);
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_THAT(outcome.output, ::testing::StartsWith("cbbg: error: "));
    EXPECT_THAT(outcome.output, HasSubstr(expand(input.message, scratch.string())));
    EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1);
    EXPECT_EQ(cbbg::testing::tree_of(scratch), before) << "something was written or changed";
  }
}

}  // namespace
