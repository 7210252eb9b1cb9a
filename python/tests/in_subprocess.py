"""Code run by a fresh interpreter (this one's executable, the same PYTHONPATH): a crash ends
it, not the suite, and it can be sent a signal."""

import signal
import subprocess
import sys
import time


def run_python(code, timeout=120):
    """The CompletedProcess of `code`, its output as text."""
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=timeout)


def interrupt_python(code, after=1.0, timeout=30):
    """Runs `code`, which prints "ready" as it starts the work to interrupt; sends it SIGINT
    `after` seconds later and waits for it to end. (CompletedProcess, seconds from the signal
    to its end)."""
    process = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        ready = process.stdout.readline()
        assert ready == "ready\n", ready + process.stderr.read()
        time.sleep(after)
        process.send_signal(signal.SIGINT)
        sent = time.monotonic()
        out, err = process.communicate(timeout=timeout)
        took = time.monotonic() - sent
        return subprocess.CompletedProcess(process.args, process.returncode, ready + out, err), took
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
