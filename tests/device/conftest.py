"""Helpers for the device tests: golden lines, a virtual-clock port, waiting on a link, a
board the test scripts line by line on a pty."""

from __future__ import annotations

import itertools
import os
import select
import threading
import time
import tty
from pathlib import Path

import pytest
import serial

import minseg_tui.device  # noqa: F401  (registers minseg://)
from minseg_tui.device import protocol as P
from minseg_tui.device.factory import open_device
from minseg_tui.device.link import Link
from minseg_tui.device.ptyserver import PtyServer
from minseg_tui.device.virtual import VirtualBoard, forget_board, named_board, settings_from

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


class ScriptedBoard:
    """A board played by the test on a real pty: it answers ID with $ID and every other
    command with $OK, and sends exactly the lines the test hands to :meth:`send` (made
    with the protocol's own formatter, so they pass whatever checksum it uses)."""

    def __init__(self, period_us: int = 10000) -> None:
        master, slave = os.openpty()
        tty.setraw(slave)
        self.path = os.ttyname(slave)
        os.close(slave)
        self.master = master
        self.period_us = period_us
        self.commands: list[str] = []
        self._write_lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def send(self, *msgs: P.Message) -> None:
        """Put these lines on the wire, in order, as one write."""
        data = b"".join(P.encode(m) for m in msgs)
        with self._write_lock:
            view = memoryview(data)
            while view:
                view = view[os.write(self.master, view) :]

    def _serve(self) -> None:
        buf = b""
        while not self._stop.is_set():
            ready, _, _ = select.select([self.master], [], [], 0.02)
            if not ready:
                continue
            try:
                data = os.read(self.master, 4096)
            except OSError:  # nobody has the slave open yet
                time.sleep(0.01)
                continue
            buf += data
            *lines, buf = buf.split(b"\n")
            for raw in lines:
                try:
                    cmd = P.parse_command(raw)
                except P.ProtocolError:
                    continue
                name = raw.strip().lstrip(b"$").split(b"*")[0].split(b",")[0].decode()
                self.commands.append(name)
                if isinstance(cmd, P.Identify):
                    reply: P.Message = P.Ident(
                        "scripted",
                        P.PROTOCOL_VERSION,
                        "Scripted",
                        720,
                        self.period_us,
                        12000,
                        "BRAKE",
                    )
                else:
                    reply = P.Ok(name)
                self.send(reply)

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2.0)
        os.close(self.master)


@pytest.fixture
def scripted():
    board = ScriptedBoard()
    yield board
    board.close()


class Rig:
    """One virtual MinSeg behind a real serial path: a pty served in real time
    (:class:`PtyServer`, ``kind="pty"``) or the ``minseg://`` URL with the virtual clock
    (``kind="url"``). The same device tests run on both (as TCLab's run on TCLab and
    TCLabModel): ``open()`` gives a Link through the factory, ``board`` is the board,
    ``unplug()``/``replug()`` pull and plug the cable."""

    def __init__(self, kind: str, name: str, folder: Path, options: dict[str, object]) -> None:
        self.kind = kind
        settings = settings_from(options)
        self.server: PtyServer | None = None
        if kind == "pty":
            self.board = VirtualBoard(settings)
            self.server = PtyServer(self.board, link_path=str(folder / f"{name}.tty")).start()
            self.port = self.server.path
        else:
            self.board = named_board(name, settings)
            self.port = f"minseg://{name}?clock=virtual"

    def open(self, **link_options: object) -> Link:
        """A Link to the board, opened and handshaken (options as for :class:`Link`)."""
        return open_device(self.port, **link_options)

    def unplug(self) -> None:
        """Pull the cable."""
        if self.server is not None:
            self.server.unplug()
        else:
            self.board.unplug()

    def replug(self) -> None:
        """Plug it back in."""
        if self.server is not None:
            self.server.replug()
        else:
            self.board.replug()

    def stop(self) -> None:
        if self.server is not None:
            self.server.stop()


@pytest.fixture(params=["pty", "url"])
def make_rig(request, tmp_path):
    """``make_rig(**board_options)``: a :class:`Rig` of the parametrised kind."""
    made: list[tuple[Rig, str]] = []

    def make(**options: object) -> Rig:
        name = f"rig{next(_names)}"
        rig = Rig(request.param, name, tmp_path, options)
        made.append((rig, name))
        return rig

    yield make
    for rig, name in made:
        rig.stop()
        forget_board(name)
