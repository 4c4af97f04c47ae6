"""SIGTERM and SIGHUP to the real TUI in a real pty (issue 18, item 7): what stands in an
entry is stored, the terminal is given back (the app's screen left, the cursor shown) and
the exit status is 128 + the signal's number. Before, the signal killed the program: the
text was lost and the terminal stayed in the app's screen.

The waits read the pty until a text shows (a minute at most: a hang guard, never a
threshold a busy machine could cross)."""

from __future__ import annotations

import fcntl
import json
import os
import select
import signal
import struct
import subprocess
import sys
import termios
from pathlib import Path

import pytest

from minseg_tui.lab.saving.store import list_sessions

GUARD = 60.0
"""Most seconds a wait reads the pty without seeing what it waits for (a hang guard)."""

LEAVE_SCREEN = b"\x1b[?1049l"
"""The alternate screen left: the shell's screen is back."""

SHOW_CURSOR = b"\x1b[?25h"


class Pty:
    """The TUI (``minseg-tui --sim``) on a real 80x24 pty, and what it wrote so far."""

    def __init__(self, root: Path) -> None:
        master, slave = os.openpty()
        fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 80, 0, 0))
        self.master = master
        self.out = b""
        self.proc = subprocess.Popen(
            [sys.executable, "-c", "from minseg_tui.cli import main; raise SystemExit(main())"]
            + ["--sim", "--sessions", str(root)],
            stdin=slave,
            stdout=slave,
            stderr=slave,
            env={**os.environ, "TERM": "xterm-256color"},
            start_new_session=True,
        )
        os.close(slave)

    def _read(self, timeout: float) -> bool:
        ready, _, _ = select.select([self.master], [], [], timeout)
        if not ready:
            return False
        try:
            chunk = os.read(self.master, 1 << 16)
        except OSError:  # EIO: the program closed the terminal
            chunk = b""
        self.out += chunk
        return bool(chunk)

    def until(self, text: bytes) -> None:
        while text not in self.out:
            if not self._read(GUARD):
                raise AssertionError(f"the TUI never showed {text!r}")

    def write(self, data: bytes) -> None:
        os.write(self.master, data)

    def finish(self) -> int:
        """Read what the program writes until it closes the terminal; its exit status."""
        while self._read(GUARD):
            pass
        code = self.proc.wait(GUARD)
        os.close(self.master)
        return code

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGHUP], ids=["SIGTERM", "SIGHUP"])
def test_a_terminating_signal_stores_the_entry_and_gives_the_terminal_back(tmp_path, signum):
    root = tmp_path / "sessions"
    tui = Pty(root)
    try:
        tui.until(b"New session")
        tui.write(b"Ada\r")
        tui.until(b"reading")  # Preparation 1, its notes entry focused
        tui.write(b"\x1b[200~wheel [b]loose\x1b[201~")  # pasted, not yet stored
        tui.until(b"wheel [b]loose")
        mark = len(tui.out)
        os.kill(tui.proc.pid, signum)
        code = tui.finish()
    finally:
        tui.close()
    assert code == 128 + signum  # 143 for SIGTERM, as a shell reports it
    after = tui.out[mark:]
    assert LEAVE_SCREEN in after and SHOW_CURSOR in after
    (info,) = list_sessions(root)
    assert info.locked_by is None and info.damaged is None
    data = json.loads((info.path / "session.json").read_text(encoding="utf-8"))
    assert data["entries"]["prep1.notes"]["text"] == "wheel [b]loose"


def test_a_hangup_after_the_window_closed_still_stores_the_entry(tmp_path):
    """The terminal window closed first (nothing can be written to it any more), then SIGHUP."""
    root = tmp_path / "sessions"
    tui = Pty(root)
    try:
        tui.until(b"New session")
        tui.write(b"Ada\r")
        tui.until(b"reading")
        tui.write(b"\x1b[200~window closed\x1b[201~")
        tui.until(b"window closed")
        os.close(tui.master)
        os.kill(tui.proc.pid, signal.SIGHUP)
        code = tui.proc.wait(GUARD)
    finally:
        tui.close()
    assert code == 128 + signal.SIGHUP
    (info,) = list_sessions(root)
    assert info.locked_by is None
    data = json.loads((info.path / "session.json").read_text(encoding="utf-8"))
    assert data["entries"]["prep1.notes"]["text"] == "window closed"
