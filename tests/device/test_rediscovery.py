"""Reconnect by USB VID:PID rediscovery: the board comes back on a different path.

A real Mega that is unplugged and plugged back can reappear as /dev/ttyACM1 instead of
/dev/ttyACM0. Here the board is the virtual MinSeg on a real pty; replugging makes a new
pty, and a spare pty holds the old number meanwhile so the new path must differ. The
system's port listing is faked (monkeypatch) to show the board's current path under the
Mega's VID:PID among unrelated ports.
"""

import os

import numpy as np

from minseg_tui.device import discovery
from minseg_tui.device.link import Link
from minseg_tui.device.ptyserver import PtyServer
from minseg_tui.device.samples import SampleBatch

from .conftest import wait_for
from .test_discovery import fake

MEGA = (0x2341, 0x0042)


def test_reconnects_to_the_board_on_a_new_path(monkeypatch):
    server = PtyServer().start()

    def listing():
        return [
            fake("/dev/ttyS0"),
            fake("/dev/ttyACM9", 0x1BC7, 0x1201, "Telit"),
            fake(server.slave_name, *MEGA, "Arduino"),
        ]

    monkeypatch.setattr(discovery, "list_ports", listing)
    events = []
    link = Link(server.path, vid_pid=MEGA, on_event=events.append, retry_s=0.02, boot_wait_s=0.5)
    spare = None
    try:
        link.open()
        old = link.port
        assert link.set_period(0.01) == 0.01
        assert wait_for(lambda: len(link.samples()) > 0)
        server.unplug()
        assert wait_for(lambda: any(e.kind == "disconnected" for e in events))
        # the samples the old connection read before the unplug (on a busy machine some came
        # after the wait above had taken the first): only what comes after the replug is judged
        link.samples()
        spare = os.openpty()  # another device takes the old number
        server.replug()
        os.close(spare[0]), os.close(spare[1])
        spare = None
        new = server.slave_name
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
        if spare is not None:
            os.close(spare[0]), os.close(spare[1])
        link.close()
        server.stop()


def test_without_vid_pid_it_waits_on_the_old_path(monkeypatch):
    """The control: the same replug without VID:PID is not found (the old path is gone)."""
    server = PtyServer().start()
    monkeypatch.setattr(discovery, "list_ports", lambda: [fake(server.slave_name, *MEGA)])
    events = []
    link = Link(server.path, on_event=events.append, retry_s=0.02, boot_wait_s=0.5)
    try:
        link.open()
        old = link.port
        server.unplug()
        assert wait_for(lambda: any(e.kind == "disconnected" for e in events))
        spare = os.openpty()
        server.replug()
        os.close(spare[0]), os.close(spare[1])
        assert server.slave_name != old
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
