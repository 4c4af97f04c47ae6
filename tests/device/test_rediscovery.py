"""Reconnect by USB VID:PID rediscovery: the board comes back on a different path.

A real Mega that is unplugged and plugged back can reappear as /dev/ttyACM1 instead of
/dev/ttyACM0. Here the board is the virtual MinSeg on a real pty, named as udev names a
board: by a symlink in the test's folder (ttyACM0), removed when the cable is pulled, and
a new one (ttyACM1) for the pty the replug makes. The system's port listing is faked
(monkeypatch) to show the board's current path under the Mega's VID:PID among unrelated
ports.

The link never opens a /dev/pts name itself: the kernel hands a pty's number to the next
pty anyone opens, another test's in another process as well, and a link trying the old
number would open and lock that test's port.
"""

import os
from pathlib import Path

import numpy as np

from minseg_tui.device import discovery
from minseg_tui.device.link import Link
from minseg_tui.device.ptyserver import PtyServer
from minseg_tui.device.samples import SampleBatch

from .conftest import wait_for
from .test_discovery import fake

MEGA = (0x2341, 0x0042)


def _named(server: PtyServer, path: Path) -> str:
    """Name the server's pty as udev would (a symlink at ``path``); returns the path."""
    path.symlink_to(server.slave_name)
    return str(path)


def test_reconnects_to_the_board_on_a_new_path(monkeypatch, tmp_path):
    server = PtyServer().start()
    current = {"path": _named(server, tmp_path / "ttyACM0")}

    def listing():
        return [
            fake("/dev/ttyS0"),
            fake("/dev/ttyACM9", 0x1BC7, 0x1201, "Telit"),
            fake(current["path"], *MEGA, "Arduino"),
        ]

    monkeypatch.setattr(discovery, "list_ports", listing)
    events = []
    link = Link(
        current["path"], vid_pid=MEGA, on_event=events.append, retry_s=0.02, boot_wait_s=0.5
    )
    try:
        link.open()
        old = link.port
        assert link.set_period(0.01) == 0.01
        assert wait_for(lambda: len(link.samples()) > 0)
        os.unlink(old)  # the cable is pulled: the board's name goes, then its port
        server.unplug()
        assert wait_for(lambda: any(e.kind == "disconnected" for e in events))
        # the samples the old connection read before the unplug (on a busy machine some came
        # after the wait above had taken the first): only what comes after the replug is judged
        link.samples()
        server.replug()
        current["path"] = new = _named(server, tmp_path / "ttyACM1")
        assert new != old and not os.path.exists(old)
        assert wait_for(lambda: link.stats.reconnects == 1)
        assert link.port == new
        assert any(e.kind == "connected" and new in e.message for e in events)
        assert wait_for(lambda: server.board.period_us == 10000)  # the period was restored
        got = []
        assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= 10)
        after = SampleBatch.concat(got)
        assert np.all(after.epoch == after.epoch[-1]) and after.epoch[-1] >= 1
        assert np.all(np.diff(after.seq) >= 1)
    finally:
        link.close()
        server.stop()


def test_without_vid_pid_it_waits_on_the_old_path(monkeypatch, tmp_path):
    """The control: the same replug without VID:PID is not found (the old path is gone)."""
    server = PtyServer().start()
    current = {"path": _named(server, tmp_path / "ttyACM0")}
    monkeypatch.setattr(discovery, "list_ports", lambda: [fake(current["path"], *MEGA)])
    events = []
    link = Link(current["path"], on_event=events.append, retry_s=0.02, boot_wait_s=0.5)
    try:
        link.open()
        old = link.port
        os.unlink(old)
        server.unplug()
        assert wait_for(lambda: any(e.kind == "disconnected" for e in events))
        server.replug()
        current["path"] = _named(server, tmp_path / "ttyACM1")
        assert not os.path.exists(old)
        # not "nothing within a second" (a busy machine tries less often): ten attempts, on
        # the old path only, and none reconnected
        tried: list[str] = []
        reopen = link._open_port

        def counted(port: str):
            tried.append(port)
            return reopen(port)

        monkeypatch.setattr(link, "_open_port", counted)
        assert wait_for(lambda: len(tried) >= 10)
        assert set(tried) == {old} and link.stats.reconnects == 0
        assert link.port == old and not link.connected
    finally:
        link.close()
        server.stop()
