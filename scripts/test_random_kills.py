#!/usr/bin/python3
"""cbbg killed at random moments, then resumed, ends with the bytes of an uninterrupted run.

Usage: /usr/bin/python3 scripts/test_random_kills.py BUILD_DIR

The fault points of the unit tests stop cbbg where its authors expected a kill; this test
stops it anywhere. Each command below runs once uninterrupted (the reference, timed), then
again from the start, and is SIGKILLed with its whole process group (cbbg draws figures in
python) after a delay drawn from random.Random(19) in [0, the reference's time]. What a user
does next (resume, or the same command again) runs and is killed in turn at the next delay,
and so on until it ends on its own; then a new start, until KILLS kills have landed. Every
tree that ends so must hold the reference's files, byte for byte, and no temporary file.

Prints one line per command (kills, resumes, identical or not, and each differing run's
first difference) and exits 1 if any run differs.
"""

import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

KILLS = 20
SEED = 19
# Names that only a write or a publish under way may have; none may outlive a resume.
TEMPORARY_MARKS = (".tmp-", "cbbg-tmp", ".new-", ".pending", ".figures.tmp-")
# No command here takes a tenth of this; past it, one hangs.
HANG_SECONDS = 120


class Case:
    """A command killed and resumed.

    start(folder) and again(folder) return the commands to run (at once) first and after a
    kill: again sees the state the kill left, as a user would. finish, if any, runs
    uninterrupted once they end (the merge after the shards). prepare(folder) makes the
    state the commands start from.
    """

    def __init__(self, name, start, again, finish=(), prepare=None, kills_per_start=1):
        self.name, self.start, self.again, self.finish = name, start, again, list(finish)
        self.prepare = prepare or (lambda folder: None)
        self.kills_per_start = kills_per_start


def make_cases(cbbg, study, scratch):
    small = ["--set", "plant.kind=analytic", "--seeds", "2", "--set", "trial.duration=5",
             "--set", "max_trials=20"]
    run = [cbbg, "run"] + small + ["--jobs", "2", "--out", "out"]
    grid = [cbbg, "run"] + small + ["--jobs", "1", "--grid", "actor.alpha=0.05,0.1,0.2"]
    shards = [grid + ["--no-figures", "--shard", f"{k}/2", "--out", "out"] for k in (1, 2)]
    merge = [cbbg, "merge", "out"]
    # The merge starts from two finished shards that draw figures (the merge draws them).
    shards_done = os.path.join(scratch, "shards-done")
    os.makedirs(shards_done)
    for k in (1, 2):
        check_run(grid + ["--shard", f"{k}/2", "--out", "out"], shards_done)
    study_run = [study, "--plant", "analytic", "--seeds", "1", "--jobs", "2", "--out", "out"]

    def run_again(options):
        def again(folder):
            if finished_run(folder):
                return []
            if os.path.lexists(os.path.join(folder, "out.partial")) or \
                    os.path.lexists(os.path.join(folder, "out")):
                return [[cbbg, "run", "--resume", "out"]]
            return [run + options]  # killed before it made anything
        return again

    def merge_again(folder):
        return [] if merged_sweep(folder) else [merge]

    def copy_shards(folder):
        shutil.copytree(os.path.join(shards_done, "out.partial"),
                        os.path.join(folder, "out.partial"), symlinks=True)

    # One kill per start where a start is cheap; where it is not, several, so that the test
    # stays short (a resume costs less than a start).
    return [
        Case("run", lambda folder: [run], run_again([]), kills_per_start=4),
        Case("run --no-figures", lambda folder: [run + ["--no-figures"]],
             run_again(["--no-figures"])),
        Case("sweep shards 1/2 and 2/2", lambda folder: shards, lambda folder: shards,
             finish=[merge]),
        Case("merge", lambda folder: [merge], merge_again, prepare=copy_shards,
             kills_per_start=4),
        Case("robustness study", lambda folder: [study_run], lambda folder: [study_run],
             kills_per_start=10),
    ]


def finished_run(folder):
    out = os.path.join(folder, "out")
    return (os.path.exists(os.path.join(out, ".cbbg-results")) and
            not os.path.lexists(os.path.join(out, ".cbbg-run")) and
            not os.path.lexists(out + ".partial"))


def merged_sweep(folder):
    out = os.path.join(folder, "out")
    return (os.path.exists(os.path.join(out, ".cbbg-results")) and
            not os.path.lexists(os.path.join(out, ".cbbg-sweep-run")) and
            not os.path.lexists(out + ".partial"))


class Runner:
    """Starts commands in their own process groups, logs their stderr, kills them."""

    def __init__(self, scratch):
        self.logs = os.path.join(scratch, "logs")
        os.makedirs(self.logs)
        self.count = 0
        self.live = []  # the process groups of run(), for stop()

    def run(self, commands, folder, delay=None):
        """Runs `commands` at once in `folder`; after `delay` s, kills what still runs.

        Returns (killed, failure): whether the kill found one running, and the first
        command that ended on its own with an error ("" if none).
        """
        started = [self.start(command, folder) for command in commands]
        self.live = [process for process, _ in started]
        deadline = time.monotonic() + (HANG_SECONDS if delay is None else delay)
        for process, _ in started:
            try:
                process.wait(timeout=max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                pass
        running = [process.poll() is None for process, _ in started]
        for (process, _), kill in zip(started, running):
            if kill:
                os.killpg(process.pid, signal.SIGKILL)
        for process, _ in started:
            process.wait()
            wait_for_group(process.pid)
        self.live = []
        if any(running) and delay is None:
            return True, f"{describe(commands[0])} hung for {HANG_SECONDS} s"
        for (process, log), killed in zip(started, running):
            if not killed and process.returncode != 0:
                return any(running), f"{describe(process.args)} exited " \
                                     f"{process.returncode}: {last_line(log)}"
        return any(running), ""

    def stop(self):
        """Kills what runs (the test itself was stopped): its groups are not the test's."""
        for process in self.live:
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            wait_for_group(process.pid)

    def start(self, command, folder):
        self.count += 1
        log = os.path.join(self.logs, f"{self.count}.txt")
        with open(log, "wb") as stderr:
            process = subprocess.Popen(command, cwd=folder, stdin=subprocess.DEVNULL,
                                       stdout=subprocess.DEVNULL, stderr=stderr,
                                       start_new_session=True)
        return process, log


def wait_for_group(group):
    """A SIGKILL is delivered, not done: waits until no process of the group runs (a dying
    cbbg still holds its lock), at most 5 s."""
    for _ in range(500):
        if not group_alive(group):
            return
        time.sleep(0.01)


def group_alive(group):
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue  # ended while listed
        if int(fields[2]) == group and fields[0] not in "ZX":
            return True
    return False


def check_run(command, folder):
    """Runs `command` to its end in `folder`; fails the test if it does not succeed."""
    result = subprocess.run(command, cwd=folder, stdin=subprocess.DEVNULL,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if result.returncode != 0:
        sys.exit(f"test_random_kills: {describe(command)} exited {result.returncode}: "
                 f"{result.stderr.decode(errors='replace').strip()}")


def describe(command):
    return " ".join(os.path.basename(part) if i == 0 else part for i, part in enumerate(command))


def last_line(log):
    with open(log, errors="replace") as text:
        lines = [line.strip() for line in text if line.strip()]
    return lines[-1] if lines else "(nothing on stderr)"


def listing(root):
    """{path under root: "folder" | "file" | "link TARGET"}, every level."""
    entries = {}
    for folder, folders, files in os.walk(root):
        for name in folders + files:
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, root)
            if os.path.islink(path):
                entries[relative] = "link " + os.readlink(path)
            else:
                entries[relative] = "folder" if os.path.isdir(path) else "file"
    return entries


def temporary(name):
    return any(mark in name for mark in TEMPORARY_MARKS) or name.endswith(".partial")


def same_bytes(first, second):
    with open(first, "rb") as a, open(second, "rb") as b:
        while True:
            chunk = a.read(1 << 20)
            if chunk != b.read(1 << 20):
                return False
            if not chunk:
                return True


def leftovers(tree):
    """The temporary files and folders in `tree` (the first three named), or ""."""
    found = [path for path in sorted(listing(tree)) if temporary(os.path.basename(path))]
    more = f" and {len(found) - 3} more" if len(found) > 3 else ""
    return f"leftover {', '.join(found[:3])}{more}" if found else ""


def first_difference(reference, tree):
    """The leftover temporary files in `tree`, else its first difference from `reference`
    (paths in sorted order), else ""."""
    left = leftovers(tree)
    if left:
        return left
    expected, found = listing(reference), listing(tree)
    for path in sorted(expected.keys() | found.keys()):
        if path not in found:
            return f"{path} is missing"
        if path not in expected:
            return f"{path} is there and not in the reference"
        if found[path] != expected[path]:
            return f"{path} is a {found[path]}, not a {expected[path]}"
        if found[path] == "file" and not same_bytes(os.path.join(reference, path),
                                                    os.path.join(tree, path)):
            return f"{path} differs"
    return ""


class Tally:
    def __init__(self):
        self.kills = self.missed = self.resumes = self.starts = 0
        self.differences = []  # (start, first difference)


def reference_run(case, runner, folder):
    """The uninterrupted run: its tree, and how long its killable part took."""
    os.makedirs(folder)
    case.prepare(folder)
    began = time.monotonic()
    _, failure = runner.run(case.start(folder), folder)
    seconds = time.monotonic() - began
    if not failure and case.finish:
        failure = runner.run(case.finish, folder)[1]
    if failure:
        sys.exit(f"test_random_kills: {case.name}: the reference run failed: {failure}")
    left = leftovers(folder)
    if left:
        sys.exit(f"test_random_kills: {case.name}: the reference run has a {left}")
    return seconds


def killed_run(case, runner, folder, reference, seconds, rng, tally):
    """One start, killed and resumed until it ends; its difference from the reference.

    Its kills fall at moments drawn in [0, seconds], in order, on the time its runs add up
    to: each resume is killed after the gap between its moment and the one before.
    """
    os.makedirs(folder)
    case.prepare(folder)
    tally.starts += 1
    moments = sorted(rng.uniform(0, seconds)
                     for _ in range(min(case.kills_per_start, KILLS - tally.kills)))
    delays = [later - earlier for earlier, later in zip([0.0] + moments, moments)]
    commands = case.start(folder)
    while commands:
        delay = delays.pop(0) if delays else None
        killed, failure = runner.run(commands, folder, delay)
        if failure:
            return failure
        if not killed:
            tally.missed += delay is not None
            break
        tally.kills += 1
        commands = case.again(folder)
        tally.resumes += bool(commands)
    failure = runner.run(case.finish, folder)[1] if case.finish else ""
    return failure or first_difference(reference, folder)


def test_case(case, runner, root, rng):
    reference = os.path.join(root, "reference")
    seconds = reference_run(case, runner, reference)
    tally = Tally()
    while tally.kills < KILLS and tally.starts < 3 * KILLS:  # a start that always fails
        folder = os.path.join(root, f"start{tally.starts + 1}")
        difference = killed_run(case, runner, folder, reference, seconds, rng, tally)
        if difference:
            tally.differences.append((tally.starts, difference))
        shutil.rmtree(folder)  # the study's trees are large
    identical = "yes" if not tally.differences else \
        f"no ({len(tally.differences)} of {tally.starts} starts)"
    print(f"{case.name}: reference {seconds:.2f} s; {tally.kills} kills over {tally.starts} "
          f"starts (up to {case.kills_per_start} each; {tally.missed} runs ended before their "
          f"kill), {tally.resumes} resumes; identical: {identical}", flush=True)
    for start, difference in tally.differences:
        print(f"  start {start}: {difference}", flush=True)
    return not tally.differences


def main(argv):
    if len(argv) != 2:
        print("usage: test_random_kills.py BUILD_DIR", file=sys.stderr)
        return 2
    cbbg = os.path.join(os.path.abspath(argv[1]), "apps", "cbbg")
    study = os.path.join(os.path.dirname(os.path.abspath(__file__)), "robustness_study.sh")
    scratch = tempfile.mkdtemp(prefix="cbbg-random-kills.")
    # ctest's timeout stops the test with SIGTERM: the finally below still runs.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("test_random_kills: stopped"))
    runner = None
    try:
        # The study runs this cbbg; temporary files outside the trees stay in the scratch.
        os.makedirs(os.path.join(scratch, "tmp"))
        os.environ.update(CBBG=cbbg, TMPDIR=os.path.join(scratch, "tmp"))
        runner = Runner(scratch)
        rng = random.Random(SEED)
        began = time.monotonic()
        passed = [test_case(case, runner, os.path.join(scratch, f"case{i}"), rng)
                  for i, case in enumerate(make_cases(cbbg, study, scratch))]
        print(f"test_random_kills: {len(passed)} commands, {KILLS} kills each, "
              f"{time.monotonic() - began:.0f} s: " +
              ("every tree identical" if all(passed) else "DIFFERENCES (above)"))
        return 0 if all(passed) else 1
    finally:
        if runner:
            runner.stop()
        shutil.rmtree(scratch)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
