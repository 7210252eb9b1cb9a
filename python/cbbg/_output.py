"""What the C++ command line prints, forwarded to Python's sys.stdout and sys.stderr where they
are not the process's own file descriptors 1 and 2 (a notebook, pytest's capture): the C++
writes to the descriptors, which Python's streams there never see."""

import contextlib
import ctypes
import os
import sys
import threading

_libc = ctypes.CDLL(None)


def _is_descriptor(stream, fd):
    try:
        return stream.fileno() == fd
    except (AttributeError, OSError, ValueError):  # io.UnsupportedOperation is an OSError
        return False


class _Forward:
    """Descriptor `fd` pointed into a pipe whose reader thread writes to `stream`."""

    def __init__(self, fd, stream):
        self.fd, self.stream, self.text = fd, stream, []
        stream.flush()
        self.saved = os.dup(fd)
        read, write = os.pipe()
        os.dup2(write, fd)
        os.close(write)
        self.reader = threading.Thread(target=self._copy, args=(read,), daemon=True)
        self.reader.start()

    def _copy(self, read):
        with os.fdopen(read, "r", errors="replace") as pipe:
            for line in iter(pipe.readline, ""):
                self.text.append(line)
                self.stream.write(line)
                self.stream.flush()

    def close(self):
        os.dup2(self.saved, self.fd)  # the pipe's last writer closed: its reader sees the end
        os.close(self.saved)
        self.reader.join()


@contextlib.contextmanager
def forwarded():
    """Within: descriptors 1 and 2 forwarded to sys.stdout and sys.stderr where needed. Yields
    a function giving what reached stderr (None where it went to descriptor 2 directly)."""
    forwards = {}
    for fd, stream in ((1, sys.stdout), (2, sys.stderr)):
        if stream is not None and not _is_descriptor(stream, fd):
            forwards[fd] = _Forward(fd, stream)
    try:
        yield lambda: "".join(forwards[2].text) if 2 in forwards else None
    finally:
        _libc.fflush(None)  # the C stdio buffers, before the descriptors go back
        for forward in forwards.values():
            forward.close()
