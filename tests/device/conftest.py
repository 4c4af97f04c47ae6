"""Helpers for the device tests: golden lines, a virtual-clock port, waiting on a link."""

from __future__ import annotations

import itertools
import time
from pathlib import Path

import pytest
import serial

import minseg_tui.device  # noqa: F401  (registers minseg://)
from minseg_tui.device.ptyserver import PtyServer
from minseg_tui.device.virtual import forget_board

GOLDEN = Path(__file__).resolve().parents[2] / "firmware" / "golden" / "lines.txt"
_names = itertools.count()


def golden(kind: str) -> list[str]:
    """The golden lines of one kind (board, host, reject, error), as written."""
    out = []
    for raw in GOLDEN.read_text().splitlines():
        if raw.startswith("#") or not raw.strip():
            continue
        k, _, rest = raw.partition(" ")
        if k == kind:
            out.append(rest)
    return out


@pytest.fixture
def board_name():
    name = f"t{next(_names)}"
    yield name
    forget_board(name)


def vport(query: str = "", name: str = "", timeout: float = 0.05) -> serial.SerialBase:
    """A virtual-clock minseg:// port (board time moves only while reading)."""
    sep = "&" if query else ""
    return serial.serial_for_url(f"minseg://{name}?clock=virtual{sep}{query}", timeout=timeout)


def read_lines(port: serial.SerialBase, seconds: float) -> list[str]:
    """Everything the board sends in the next ``seconds`` of board time, as lines."""
    end = port.board.now + seconds
    data = b""
    while port.board.now < end - 1e-9:
        port.timeout = end - port.board.now
        data += port.read(100000)
    data += port.board.take_output()
    return data.decode("ascii", "replace").splitlines()


def wait_for(cond, timeout: float = 10.0, step: float = 0.005) -> bool:
    """Poll ``cond`` until true or timeout (real seconds); returns the last value.

    The timeout is generous (a loaded 2-core CI machine): a passing test returns as soon
    as ``cond`` holds, so only a failing one waits it out."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if cond():
            return True
        time.sleep(step)
    return bool(cond())


@pytest.fixture
def pty_server(tmp_path):
    server = PtyServer(link_path=str(tmp_path / "minseg0")).start()
    yield server
    server.stop()
