#!/usr/bin/python3
"""cbbg killed at random moments, then resumed, ends with the bytes of an uninterrupted run.

Usage: /usr/bin/python3 scripts/test_random_kills.py BUILD_DIR

The fault points of the unit tests stop cbbg where its authors expected a kill; this test
stops it anywhere. Each command below runs once uninterrupted (the reference, timed), then
again from the start, and is SIGKILLed with its whole process group (cbbg draws figures in
python) after a delay drawn from random.Random(19) in [0, the reference's time], or, for a
few starts, as soon as a file of its work appears (a run's staging folder, a task's rows,
its record, the results' steps.csv; inotify sees it however briefly it is there). What a
user does next (resume, or the same command again) runs and is killed in turn at the next
delay, and so on until it ends on its own; then a new start, until KILLS kills have landed:
a kill counts only when it ended a process that ran (SIGKILL is its exit status), and a
command with fewer fails. Every tree that ends so must hold the reference's files, byte for
byte, and no temporary file (there or in TMPDIR); and no resume may run a finished task
again (inotify: no file of a task whose record was there when the resume began is written).

The commands: a run (with and without figures), a diagram alone (bg_only, 20 seeds), a
transfer run, sweep shards and their merge, the robustness study, the teacher study, and
two robustness studies at once on one folder (one runs, the other is refused as the
folder is in use; either may be the one).

Prints one line per command (kills, resumes, identical or not, and each differing run's
first difference) and exits 1 if any run differs or a command had fewer than KILLS kills.
"""

import ctypes
import ctypes.util
import fnmatch
import os
import random
import select
import shutil
import signal
import struct
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
    state the commands start from. triggers: globs below the folder, a start each whose
    first command is killed as soon as one matches. refusal: the last line with which one of
    several commands run at once may end (exit 2), refused as another holds what it needs.
    """

    def __init__(self, name, start, again, finish=(), prepare=None, kills_per_start=1,
                 triggers=(), refusal=None):
        self.name, self.start, self.again, self.finish = name, start, again, list(finish)
        self.prepare = prepare or (lambda folder: None)
        self.kills_per_start = kills_per_start
        self.triggers = list(triggers)
        self.refusal = refusal


def make_cases(cbbg, scripts, scratch):
    small = ["--set", "plant.kind=analytic", "--seeds", "2", "--set", "trial.duration=5",
             "--set", "max_trials=20"]
    run = [cbbg, "run"] + small + ["--jobs", "2", "--out", "out"]
    grid = [cbbg, "run"] + small + ["--jobs", "1", "--grid", "actor.alpha=0.05,0.1,0.2"]
    shards = [grid + ["--no-figures", "--shard", f"{k}/2", "--out", "out"] for k in (1, 2)]
    merge = [cbbg, "merge", "out"]
    # A diagram alone, its 20 seeds; a transfer run (trained as exp3) of three arms, the
    # supervisor alone among them, under two conditions.
    diagram = [cbbg, "run", "--experiment", "bg_only", "--seeds", "20", "--set",
               "plant.kind=analytic", "--jobs", "2", "--no-figures", "--out", "out"]
    transfer = [cbbg, "run", "--experiment", "transfer", "--set", "plant.kind=analytic",
                "--seeds", "3", "--set", "arms=[cbbg, bg_only, pd_only]",
                "--set", "transfer.conditions=[evaluation.noise_std=0, evaluation.push_force=40]",
                "--jobs", "2", "--no-figures", "--out", "out"]
    # The merge starts from two finished shards that draw figures (the merge draws them).
    shards_done = os.path.join(scratch, "shards-done")
    os.makedirs(shards_done)
    for k in (1, 2):
        check_run(grid + ["--shard", f"{k}/2", "--out", "out"], shards_done)
    robustness = [os.path.join(scripts, "robustness_study.sh"), "--plant", "analytic",
                  "--seeds", "1", "--jobs", "2", "--out", "out"]
    teacher = [os.path.join(scripts, "teacher_study.sh"), "--plant", "analytic", "--seeds", "1",
               "--jobs", "2", "--variants", "paper,wheel_rate_reward", "--out", "out"]
    in_use = ("robustness_study.sh: out is in use by another robustness_study.sh (or the cbbg "
              "it started); wait for it to end")

    def run_again(start):
        def again(folder):
            if finished_run(folder):
                return []
            if os.path.lexists(os.path.join(folder, "out.partial")) or \
                    os.path.lexists(os.path.join(folder, "out")):
                return [[cbbg, "run", "--resume", "out"]]
            return [start]  # killed before it made anything
        return again

    def merge_again(folder):
        return [] if merged_sweep(folder) else [merge]

    def copy_shards(folder):
        shutil.copytree(os.path.join(shards_done, "out.partial"),
                        os.path.join(folder, "out.partial"), symlinks=True)

    # Killed as soon as a task's rows begin, its record is kept, the results are written.
    work = ["out.partial/tasks/*.steps.csv.pending", "out.partial/tasks/*.run",
            "out.partial/steps.csv"]
    # One kill per start where a start is cheap; where it is not, several, so that the test
    # stays short (a resume costs less than a start).
    return [
        Case("run", lambda folder: [run], run_again(run), kills_per_start=4),
        Case("run --no-figures", lambda folder: [run + ["--no-figures"]],
             run_again(run + ["--no-figures"])),
        Case("diagram alone (bg_only, 20 seeds)", lambda folder: [diagram], run_again(diagram),
             kills_per_start=5, triggers=work),
        Case("transfer", lambda folder: [transfer], run_again(transfer), kills_per_start=4,
             triggers=work),
        Case("sweep shards 1/2 and 2/2", lambda folder: shards, lambda folder: shards,
             finish=[merge]),
        Case("merge", lambda folder: [merge], merge_again, prepare=copy_shards,
             kills_per_start=4),
        Case("robustness study", lambda folder: [robustness], lambda folder: [robustness],
             kills_per_start=10, triggers=["out/.transfer.partial.cbbg-tmp-*"]),
        # Killed while cbbg makes a run's work folder under its staging name (issue 35: the
        # study published beside one), and as the paper's exp2 keeps a task.
        Case("teacher study", lambda folder: [teacher], lambda folder: [teacher],
             kills_per_start=10, triggers=["out/paper/.exp2.partial.cbbg-tmp-*",
                                           "out/paper/exp2.partial/tasks/*.run"]),
        Case("two robustness studies at once", lambda folder: [robustness, robustness],
             lambda folder: [robustness, robustness], kills_per_start=10, refusal=in_use),
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
        self.refusals = 0  # the commands that ended with the case's refusal
        self.live = []  # the process groups of run(), for stop()

    def run(self, commands, folder, delay=None, trigger=None, refusal=None):
        """Runs `commands` at once in `folder`; after `delay` s, or as soon as the glob
        `trigger` (below `folder`) matches, kills what still runs.

        Returns (killed, failure): how many processes the kill ended (SIGKILL is their exit
        status: they ran when it landed), and the first command that ended on its own with
        an error other than `refusal` (its last line, exit 2), or that hung ("" if none).
        """
        # Watched from before the start: a staging folder is there for a moment only.
        appearance = Appearance(folder, trigger) if trigger is not None else None
        started = [self.start(command, folder) for command in commands]
        self.live = [process for process, _ in started]
        deadline = time.monotonic() + (HANG_SECONDS if delay is None else delay)
        if appearance is None:
            for process, _ in started:
                try:
                    process.wait(timeout=max(0.0, deadline - time.monotonic()))
                except subprocess.TimeoutExpired:
                    pass
        else:
            while time.monotonic() < deadline and not appearance.seen and \
                    any(process.poll() is None for process, _ in started):
                appearance.wait(0.01)
        hung = delay is None and (appearance is None or not appearance.seen)
        sent = [False] * len(started)
        for i, (process, _) in enumerate(started):
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGKILL)
                sent[i] = True
        for process, _ in started:
            process.wait()
            wait_for_group(process.pid)
        self.live = []
        if appearance is not None:
            appearance.close()
        ended = [was_sent and process.returncode == -signal.SIGKILL
                 for was_sent, (process, _) in zip(sent, started)]
        if hung and any(sent):
            return sum(ended), f"{describe(commands[0])} hung for {HANG_SECONDS} s"
        for (process, log), killed in zip(started, ended):
            if killed or process.returncode == 0:
                continue
            if refusal is not None and process.returncode == 2 and last_line(log) == refusal:
                self.refusals += 1
                continue
            return sum(ended), f"{describe(process.args)} exited {process.returncode}: " \
                               f"{last_line(log)}"
        return sum(ended), ""

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


# inotify(7), for Appearance and TaskWatch.
IN_CLOSE_WRITE, IN_MOVED_TO, IN_CREATE, IN_Q_OVERFLOW = 0x8, 0x80, 0x100, 0x4000
IN_ISDIR = 0x40000000
IN_NONBLOCK, IN_CLOEXEC = os.O_NONBLOCK, os.O_CLOEXEC
LIBC = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)


def inotify_open():
    fd = LIBC.inotify_init1(IN_NONBLOCK | IN_CLOEXEC)
    if fd < 0:
        sys.exit(f"test_random_kills: inotify_init1: {os.strerror(ctypes.get_errno())}")
    return fd


def inotify_events(fd):
    """The events waiting on `fd`: (watch descriptor, mask, name)."""
    data = b""
    while True:
        try:
            chunk = os.read(fd, 1 << 16)
        except BlockingIOError:
            break
        if not chunk:
            break
        data += chunk
    events, at = [], 0
    while at < len(data):
        wd, mask, _, length = struct.unpack_from("iIII", data, at)
        name = data[at + 16:at + 16 + length].rstrip(b"\0").decode(errors="replace")
        events.append((wd, mask, name))
        at += 16 + length
    return events


class Appearance:
    """Whether a path below `folder` matching the glob `pattern` has appeared, even for a
    moment (a staging folder, a results file renamed away by the commit): every folder of
    the tree is watched from its creation on (inotify), and what a new one already holds is
    looked at when its watch begins."""

    def __init__(self, folder, pattern):
        self.fd = inotify_open()
        self.folder, self.pattern = folder, pattern
        self.folders = {}  # watch descriptor: the folder, relative to `folder`
        self.seen = False
        self.watch("")

    def watch(self, relative):
        path = os.path.join(self.folder, relative)
        wd = LIBC.inotify_add_watch(self.fd, os.fsencode(path), IN_CREATE | IN_MOVED_TO)
        if wd < 0:
            return  # gone again (a staging folder renamed)
        self.folders[wd] = relative
        try:
            entries = list(os.scandir(path))
        except OSError:
            return
        for entry in entries:
            self.found(os.path.join(relative, entry.name),
                       entry.is_dir(follow_symlinks=False))

    def found(self, relative, folder):
        self.seen = self.seen or fnmatch.fnmatchcase(relative, self.pattern)
        if folder:
            self.watch(relative)

    def wait(self, timeout):
        """Waits at most `timeout` s for events, and takes them in."""
        if select.select([self.fd], [], [], timeout)[0]:
            for wd, mask, name in inotify_events(self.fd):
                if wd in self.folders and name:
                    self.found(os.path.join(self.folders[wd], name), bool(mask & IN_ISDIR))

    def close(self):
        os.close(self.fd)


def task_of(name):
    """The task a file of a tasks/ folder belongs to (N.run, N.steps.csv, N.weights.txt,
    N.steps.csv.pending, or a temporary .N.run.cbbg-tmp-...), or None."""
    number = name.lstrip(".").split(".", 1)[0]
    return int(number) if number.isdigit() else None


class TaskWatch:
    """Watches, while a resume runs, every tasks/ folder of a tree that holds finished tasks
    (an N.run record): a file of a finished task created, renamed into place or written
    there means the resume ran that task again."""

    def __init__(self, tree):
        self.fd = inotify_open()
        self.tree = tree
        self.watched = {}  # watch descriptor: (folder, the finished tasks there)
        for folder, _, files in os.walk(tree):
            if "tasks" not in os.path.relpath(folder, tree).split(os.sep):
                continue
            finished = {task_of(name) for name in files
                        if name.endswith(".run") and not name.startswith(".")} - {None}
            if not finished:
                continue
            wd = LIBC.inotify_add_watch(self.fd, os.fsencode(folder),
                                        IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE)
            if wd < 0:
                sys.exit(f"test_random_kills: inotify_add_watch {folder}: "
                         f"{os.strerror(ctypes.get_errno())}")
            self.watched[wd] = (folder, finished)

    def tasks(self):
        return sum(len(finished) for _, finished in self.watched.values())

    def rerun(self):
        """The first file of a finished task written since, or ""; closes the watch."""
        try:
            events = inotify_events(self.fd)
        finally:
            os.close(self.fd)
        for wd, mask, name in events:
            if mask & IN_Q_OVERFLOW:
                return "inotify lost events: cannot tell whether a finished task ran again"
            if wd in self.watched and task_of(name) in self.watched[wd][1]:
                folder = os.path.relpath(self.watched[wd][0], self.tree)
                return f"the resume ran finished task {task_of(name)} again " \
                       f"({os.path.join(folder, name)} was written)"
        return ""


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


def left_in_tmpdir():
    """What the commands left in their TMPDIR (then removed), or ""."""
    tmpdir = os.environ["TMPDIR"]
    left = sorted(os.listdir(tmpdir))
    for name in left:
        path = os.path.join(tmpdir, name)
        shutil.rmtree(path) if os.path.isdir(path) and not os.path.islink(path) else os.unlink(path)
    return f"left in TMPDIR: {', '.join(left[:3])}" if left else ""


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
        self.kills = self.missed = self.resumes = self.starts = self.watched = 0
        self.differences = []  # (start, first difference)


def reference_run(case, runner, folder):
    """The uninterrupted run: its tree, and how long its killable part took."""
    os.makedirs(folder)
    case.prepare(folder)
    began = time.monotonic()
    _, failure = runner.run(case.start(folder), folder, refusal=case.refusal)
    seconds = time.monotonic() - began
    if not failure and case.finish:
        failure = runner.run(case.finish, folder)[1]
    if failure:
        sys.exit(f"test_random_kills: {case.name}: the reference run failed: {failure}")
    left = leftovers(folder) or left_in_tmpdir()
    if left:
        sys.exit(f"test_random_kills: {case.name}: the reference run has a {left}")
    return seconds


def killed_run(case, runner, folder, reference, seconds, rng, tally, trigger=None):
    """One start, killed and resumed until it ends; its difference from the reference.

    Its kills fall at moments drawn in [0, seconds], in order, on the time its runs add up
    to: each resume is killed after the gap between its moment and the one before. With a
    trigger, its one kill falls as soon as the glob `trigger` matches, and the resume runs
    to its end.
    """
    os.makedirs(folder)
    case.prepare(folder)
    tally.starts += 1
    moments = [] if trigger else sorted(
        rng.uniform(0, seconds) for _ in range(min(case.kills_per_start, KILLS - tally.kills)))
    delays = [later - earlier for earlier, later in zip([0.0] + moments, moments)]
    commands = case.start(folder)
    watch = None
    first = True
    while commands:
        delay = delays.pop(0) if delays else None
        killed, failure = runner.run(commands, folder, delay, trigger if first else None,
                                     case.refusal)
        rerun = watch.rerun() if watch else ""
        watch = None
        if failure or rerun:
            return failure or rerun
        if not killed:
            if trigger and first:
                return MISSED_TRIGGER
            tally.missed += delay is not None
            break
        first = False
        tally.kills += 1
        commands = case.again(folder)
        tally.resumes += bool(commands)
        if commands:
            watch = TaskWatch(folder)
            tally.watched += watch.tasks()
    failure = runner.run(case.finish, folder)[1] if case.finish else ""
    return failure or first_difference(reference, folder)


# A start whose kill at a file's appearance came too late (the run had ended: a loaded
# machine's poll is slow); it starts again, up to TRIGGER_TRIES times.
MISSED_TRIGGER = "missed"
TRIGGER_TRIES = 3


def test_case(case, runner, root, rng):
    reference = os.path.join(root, "reference")
    runner.refusals = 0
    seconds = reference_run(case, runner, reference)
    tally = Tally()
    triggers = list(case.triggers)
    tries = {}  # missed kills, by trigger
    while tally.kills < KILLS and tally.starts < 3 * KILLS:  # a start that always fails
        folder = os.path.join(root, f"start{tally.starts + 1}")
        trigger = triggers.pop(0) if triggers else None
        difference = killed_run(case, runner, folder, reference, seconds, rng, tally, trigger)
        if difference == MISSED_TRIGGER:
            tries[trigger] = tries.get(trigger, 0) + 1
            difference = "" if tries[trigger] < TRIGGER_TRIES else \
                f"nothing ran when {trigger} appeared, {TRIGGER_TRIES} times: the kill missed"
            if not difference:
                triggers.insert(0, trigger)
        in_tmpdir = left_in_tmpdir()  # emptied for the next start either way
        difference = difference or in_tmpdir
        if difference:
            where = f" (killed as {trigger} appeared)" if trigger else ""
            tally.differences.append((f"{tally.starts}{where}", difference))
        shutil.rmtree(folder)  # the study's trees are large
    if tally.kills < KILLS:
        tally.differences.append(("all", f"only {tally.kills} of {KILLS} kills landed on a "
                                         "running process"))
    if case.refusal is not None and runner.refusals == 0:
        tally.differences.append(("all", "no command was refused: none ran beside another"))
    identical = "yes" if not tally.differences else \
        f"no ({len(tally.differences)} of {tally.starts} starts)"
    refused = f", {runner.refusals} refused as in use" if case.refusal is not None else ""
    print(f"{case.name}: reference {seconds:.2f} s; {tally.kills} kills over {tally.starts} "
          f"starts ({len(case.triggers)} at a file's appearance, up to {case.kills_per_start} "
          f"at random each; {tally.missed} runs ended before their kill), {tally.resumes} "
          f"resumes{refused}, {tally.watched} finished tasks not run again; identical: "
          f"{identical}", flush=True)
    for start, difference in tally.differences:
        print(f"  start {start}: {difference}", flush=True)
    return not tally.differences


def main(argv):
    if len(argv) != 2:
        print("usage: test_random_kills.py BUILD_DIR", file=sys.stderr)
        return 2
    cbbg = os.path.join(os.path.abspath(argv[1]), "apps", "cbbg")
    scripts = os.path.dirname(os.path.abspath(__file__))
    scratch = tempfile.mkdtemp(prefix="cbbg-random-kills.")
    # ctest's timeout stops the test with SIGTERM: the finally below still runs.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("test_random_kills: stopped"))
    runner = None
    try:
        # The studies run this cbbg; temporary files outside the trees stay in the scratch.
        os.makedirs(os.path.join(scratch, "tmp"))
        os.environ.update(CBBG=cbbg, TMPDIR=os.path.join(scratch, "tmp"))
        runner = Runner(scratch)
        rng = random.Random(SEED)
        began = time.monotonic()
        passed = [test_case(case, runner, os.path.join(scratch, f"case{i}"), rng)
                  for i, case in enumerate(make_cases(cbbg, scripts, scratch))]
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
