"""One program at a time: an exclusive OS lock on a file, held while the file stays open.

The one lock of minseg-tui, for a session folder (``<session>/lock``) and for a serial
port (a lock file named after the port, see :func:`minseg_tui.device.port.lock_path`).

Taking it is ``flock(LOCK_EX | LOCK_NB)`` on the opened file: one atomic step in the
kernel, so of any number of programs trying at once exactly one gets it. The kernel lets
go when the holder closes the file or dies (kill -9 and a power cut included), so the
lock of a dead program never blocks anyone: a lock file left behind is only a name. No
pid is ever judged "stale" and no file is unlinked to break a lock.

The file holds ``<program> <pid>`` of its holder, written once the lock is taken, only to
say who has it ("in use by minseg-tui (pid 4242)"); the holder removes the file when it
lets go. Because a file can be removed and made anew while someone waits to lock the
old one, :meth:`FileLock.acquire` checks after locking that the path still names the file
it locked (else it starts again).

POSIX only (``fcntl``), as the serial ports and ptys minseg-tui uses.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import os
import time
from dataclasses import dataclass
from pathlib import Path

_WRITE_WAIT_S = 0.5
"""How long (s) a program that found the lock taken waits for the holder to write its name
(or for :func:`holder`'s brief look to end) before it says the lock is held."""


@dataclass(frozen=True)
class Holder:
    """Who holds a lock: the program's name and pid as it wrote them (None when unknown)."""

    program: str
    pid: int | None

    def __str__(self) -> str:
        return f"{self.program} (pid {self.pid})" if self.pid is not None else self.program


UNKNOWN = Holder("another program", None)
"""The holder of a lock that has not written its name (yet)."""


class LockHeld(Exception):
    """Another program (or another open in this one) holds the lock; ``holder`` says who."""

    def __init__(self, path: Path, holder: Holder) -> None:
        super().__init__(f"{path} is held by {holder}")
        self.path = path
        self.holder = holder


def _read_holder(fd: int) -> Holder | None:
    try:
        raw = os.pread(fd, 200, 0).decode("utf-8", "replace").split()
    except OSError:
        return None
    if len(raw) >= 2 and raw[1].isdigit():
        return Holder(raw[0], int(raw[1]))
    return None


def pid_alive(pid: int | None) -> bool:
    """True when a process with this pid runs on this machine (None or <= 0: no)."""
    if pid is None or pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _locked_elsewhere(fd: int) -> bool:
    """True when another open file holds an exclusive lock on ``fd``'s file (a shared probe)."""
    try:
        fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
    except OSError as exc:
        if exc.errno in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
            return True
        raise
    fcntl.flock(fd, fcntl.LOCK_UN)
    return False


def holder(path: Path) -> Holder | None:
    """Who holds the lock at ``path`` now, or None when nobody does (no file, or a file
    nobody has locked: what a dead program leaves)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_CLOEXEC)
    except OSError:
        return None
    try:
        if not _locked_elsewhere(fd):
            return None
        return _read_holder(fd) or UNKNOWN
    except OSError:
        return None
    finally:
        os.close(fd)


class FileLock:
    """An exclusive lock on the file ``path`` for one program (``program`` names it).

    :meth:`acquire` takes it or raises :class:`LockHeld`; an OSError (a folder that cannot
    be written, a missing folder) comes through unchanged. :meth:`release` gives it back.
    Works as a context manager.
    """

    def __init__(self, path: Path, program: str = "minseg-tui") -> None:
        self.path = Path(path)
        self.program = program
        self._fd: int | None = None

    @property
    def held(self) -> bool:
        """True while this object holds the lock."""
        return self._fd is not None

    def acquire(self) -> None:
        """Take the lock (LockHeld naming the holder if someone has it)."""
        if self._fd is not None:
            return
        deadline = time.monotonic() + _WRITE_WAIT_S
        while True:
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o644)
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError as exc:
                if exc.errno not in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
                    os.close(fd)
                    raise
                who = _read_holder(fd)
                os.close(fd)
                if (who is None or not pid_alive(who.pid)) and time.monotonic() < deadline:
                    # the holder has locked but not written its name yet (the name there is
                    # its predecessor's, or none), or holder() is looking: try again
                    time.sleep(0.005)
                    continue
                raise LockHeld(self.path, who or UNKNOWN) from None
            if not self._same_file(fd):  # removed (and maybe made anew) while we waited
                os.close(fd)
                continue
            try:
                os.ftruncate(fd, 0)
                os.pwrite(fd, f"{self.program} {os.getpid()}\n".encode(), 0)
            except OSError:
                os.close(fd)
                raise
            self._fd = fd
            return

    def _same_file(self, fd: int) -> bool:
        try:
            st = os.stat(self.path)
        except OSError:
            return False
        mine = os.fstat(fd)
        return (st.st_dev, st.st_ino) == (mine.st_dev, mine.st_ino)

    def release(self) -> None:
        """Give the lock back and remove the file (if it can be removed; a file left behind
        is harmless: nobody holds it)."""
        fd, self._fd = self._fd, None
        if fd is None:
            return
        with contextlib.suppress(OSError):
            if self._same_file(fd):
                os.unlink(self.path)
        os.close(fd)

    def __del__(self) -> None:
        # a lock whose object is gone can never be released: let go of it now, so that it
        # does not outlive what it guarded (a port closed when its pyserial object was
        # collected); the file stays, which is harmless (nobody holds it)
        fd, self._fd = getattr(self, "_fd", None), None
        if fd is not None:
            with contextlib.suppress(OSError):
                os.close(fd)

    def __enter__(self) -> FileLock:
        self.acquire()
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()


__all__ = ["UNKNOWN", "FileLock", "Holder", "LockHeld", "holder", "pid_alive"]
