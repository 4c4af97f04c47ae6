"""Opening a serial port for one program only.

Three guards, each for what the others miss:

- the port's lock file (:class:`minseg_tui.lock.FileLock` in XDG_RUNTIME_DIR or the temp
  dir, named after the real path): a second minseg-tui is told who holds the port
  ("in use by minseg-tui (pid 4242)"), whichever name of the port it used;
- pyserial's ``exclusive=True``: a flock on the device itself, for other programs that
  ask for one;
- the tty's exclusive mode (TIOCEXCL): every further ``open(2)`` fails with EBUSY, a
  plain serial monitor's (screen, minicom, cat) included; only CAP_SYS_ADMIN passes.

A pty is a tty like a USB port and gets all three. A pyserial URL (``minseg://``) has no
device: no lock file, no tty; its handler lets one link attach to a board at a time.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import os
import re
import stat
import tempfile
import termios
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import serial
from serial.serialutil import SerialException

from minseg_tui.errors import DeviceError
from minseg_tui.lock import FileLock, LockHeld


def lock_path(port: str) -> str:
    """The lock file of a device path (in XDG_RUNTIME_DIR or the temp dir), named after the
    path with symlinks resolved, so two names of one port share one lock."""
    real = os.path.realpath(port)
    base = os.environ.get("XDG_RUNTIME_DIR") or tempfile.gettempdir()
    return os.path.join(
        base, "minseg-tui-" + re.sub(r"[^A-Za-z0-9]+", "_", real).strip("_") + ".lock"
    )


def _exclusive_tty(ser: Any, on: bool) -> None:
    """Put the tty behind ``ser`` in exclusive mode (TIOCEXCL) or back (TIOCNXCL); nothing
    to do for a pyserial URL or where the OS has no such mode."""
    try:
        fd = ser.fileno()
    except (AttributeError, OSError, ValueError, SerialException):
        return
    request = getattr(termios, "TIOCEXCL" if on else "TIOCNXCL", None)
    if request is None or not isinstance(fd, int) or not os.isatty(fd):
        return
    with contextlib.suppress(OSError):
        fcntl.ioctl(fd, request)


PORTS_HINT = "`minseg-tui ports` lists the serial ports"


def not_a_device(port: str) -> str | None:
    """Why ``port`` cannot be a serial port when it names a file that is not a device (a
    regular file, a folder), one line; None for a device, a URL or a path that does not
    exist (that is the board not plugged in, said when it fails to open)."""
    if "://" in port or os.name != "posix":
        return None
    try:
        mode = os.stat(port).st_mode
    except OSError:
        return None
    if stat.S_ISCHR(mode):
        return None
    kind = (
        "a folder"
        if stat.S_ISDIR(mode)
        else "a regular file"
        if stat.S_ISREG(mode)
        else "no device"
    )
    return (
        f"expected the board's serial port (a device such as /dev/ttyACM0 or /dev/ttyUSB0), "
        f"got {port}, {kind}; {PORTS_HINT}"
    )


def _errno(exc: BaseException) -> int | None:
    """The OS error number behind a pyserial or OS error (pyserial puts some in its text)."""
    n = getattr(exc, "errno", None)
    if isinstance(n, int):
        return n
    m = re.search(r"\[Errno (\d+)\]|\((\d+), '", str(exc))
    return int(m.group(1) or m.group(2)) if m else None


def _why(port: str, exc: BaseException) -> str:
    """One line of our own words for a port that did not open (never pyserial's text)."""
    n = _errno(exc)
    if n == errno.ENOENT:
        return f"{port}: no such port (is the board plugged in? {PORTS_HINT})"
    if n in (errno.EACCES, errno.EPERM):
        return (
            f"{port}: not allowed to open it; on Linux add yourself to the dialout group "
            "(sudo usermod -aG dialout $USER) and log in again"
        )
    if n in (errno.ENOTTY, errno.EISDIR, errno.ENXIO, errno.ENODEV):
        return f"{port} is not a serial port that answers (a device such as /dev/ttyACM0); {PORTS_HINT}"
    reason = os.strerror(n) if n is not None else "the system refused it"
    return f"cannot open {port} ({reason}); {PORTS_HINT}"


@dataclass
class OpenPort:
    """A port opened by :func:`open_exclusive`: the pyserial object and its lock file."""

    ser: Any
    lock: FileLock | None


def open_exclusive(port: str, baud: int, program: str = "minseg-tui") -> OpenPort:
    """Open ``port`` (a device path or a pyserial URL) for this program only; DeviceError
    with one line ("in use by minseg-tui (pid N)", "cannot open ...") otherwise."""
    lock = None
    if "://" not in port:
        lock = FileLock(Path(lock_path(port)), program)
        try:
            lock.acquire()
        except LockHeld as exc:
            raise DeviceError(
                f"{port} is in use by {exc.holder}: close that program first "
                "(one program per board)"
            ) from None
        except OSError:
            lock = None  # no writable runtime folder: the exclusive open still guards
    try:
        ser = serial.serial_for_url(
            port, baudrate=baud, timeout=0.05, write_timeout=1.0, exclusive=True
        )
    except SerialException as exc:
        if lock is not None:
            lock.release()
        text = str(exc)
        if "lock" in text.lower() or "busy" in text.lower():
            raise DeviceError(
                f"{port} is in use by another program: close that program first "
                "(one program per board)"
            ) from None
        raise DeviceError(_why(port, exc)) from None
    except (OSError, ValueError) as exc:
        if lock is not None:
            lock.release()
        raise DeviceError(_why(port, exc)) from None
    _exclusive_tty(ser, True)
    return OpenPort(ser, lock)


def close(opened: OpenPort) -> None:
    """Close the port and give its lock file back (never raises)."""
    _exclusive_tty(opened.ser, False)
    with contextlib.suppress(Exception):
        opened.ser.close()
    if opened.lock is not None:
        opened.lock.release()


__all__ = ["OpenPort", "close", "lock_path", "not_a_device", "open_exclusive"]
