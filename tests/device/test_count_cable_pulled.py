"""A board lost while a revolution is counted by hand (s37 attack: `minseg-tui sim` killed,
or its pty closed, while `board-check --turn` counted): the count said "0 counts: the
encoder counted nothing", a false sentence about the encoder; now the board check says
the board stopped sending and the count is not known. Real ptys: the virtual MinSeg in a
process of its own (killed), and on the PtyServer (unplugged)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest

import minseg_tui.device  # noqa: F401  (registers minseg://)
from minseg_tui.device.boardcheck import count_revolution
from minseg_tui.device.factory import open_device
from minseg_tui.device.ptyserver import PtyServer
from minseg_tui.errors import DeviceError


def _cli() -> list[str]:
    exe = Path(sys.executable).with_name("minseg-tui")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "minseg_tui"]


def _count_while(link, pull) -> str:
    """Count a revolution on ``link``; once samples arrive, ``pull()`` loses the board, and
    the hand is done. The DeviceError's words."""
    read = link.samples
    arrived = threading.Event()
    done = threading.Event()

    def samples():
        batch = read()
        if len(batch):
            arrived.set()
        return batch

    def hand():
        assert arrived.wait(60)
        pull()
        done.set()

    threading.Thread(target=hand, daemon=True).start()
    with pytest.raises(DeviceError) as lost:
        count_revolution(link, done.is_set, samples=samples, timeout=60)
    return str(lost.value)


def test_the_board_s_process_killed_mid_count(tmp_path):
    sim = subprocess.Popen(
        [*_cli(), "sim", "--seed", "1"], stdout=subprocess.PIPE, text=True, start_new_session=True
    )
    try:
        assert sim.stdout is not None
        port = sim.stdout.readline().strip()
        assert port.startswith("/dev/"), port
        link = open_device(port)
        try:
            said = _count_while(link, lambda: os.kill(sim.pid, signal.SIGKILL))
        finally:
            link.close()
    finally:
        sim.kill()
        sim.wait(30)
    assert said.startswith(f"{port}: the board stopped sending "), said
    assert "(cable pulled, or the board reset?)" in said
    assert "counts" not in said


def test_the_pty_closed_mid_count(tmp_path):
    server = PtyServer(link_path=str(tmp_path / "minseg0")).start()
    try:
        link = open_device(server.path)
        try:
            said = _count_while(link, server.unplug)
        finally:
            link.close()
    finally:
        server.stop()
    assert said.startswith(f"{server.path}: the board stopped sending "), said
