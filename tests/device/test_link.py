"""The link against the virtual MinSeg, the same tests over a real pty and over the pyserial
URL (the ``make_rig`` fixture runs each on both), and what only one of them can show."""

import os
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.device import protocol as P
from minseg_tui.device.factory import open_device
from minseg_tui.device.link import Link, LinkEvent
from minseg_tui.device.port import lock_path
from minseg_tui.device.samples import SampleBatch, motion
from minseg_tui.errors import DeviceError, InputError
from minseg_tui.lock import holder
from minseg_tui.units import RAD_PER_COUNT

from .conftest import wait_for


def collect(link, n, timeout=10.0):
    """At least ``n`` samples from ``link`` (fails if they do not come within ``timeout`` s)."""
    got = []
    assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= n, timeout), (
        f"got {sum(map(len, got))} of {n} samples in {timeout} s"
    )
    return SampleBatch.concat(got)


def matches_truth(batch, board):
    """Every kept sample is exactly one the board sent (by its raw seq)."""
    with board.lock:
        truth = {s.seq: s for s in board.truth}
    for seq, t_us, count, u in zip(batch.seq, batch.t_us, batch.count, batch.u_req, strict=True):
        s = truth[int(seq) % 2**32]
        assert (s.t_us, s.count, s.u_mV) == (int(t_us) % 2**32, int(count), round(u * 1000))


FAST = 0.005  # s: the sample period the tests stream at (the pty runs in real time)


def test_streams_without_loss(make_rig):
    rig = make_rig(seed=2)
    link = rig.open()
    try:
        assert link.ident.board == "Virtual" and link.ident.proto == P.PROTOCOL_VERSION
        assert link.set_period(FAST) == FAST
        assert link.set_voltage(3.0) == 3.0
        link.samples()
        batch = collect(link, 400)
        assert np.all(np.diff(batch.seq) == 1)
        assert link.stats.dropped == 0 and link.stats.corrupt == 0
        matches_truth(batch, rig.board)
        assert motion(batch).omega[-1] > 1.0  # the wheel turns
        assert link.meter().u_A == pytest.approx(3.0 - 0.45, abs=0.015)
        assert not [e for e in link.events() if e.kind == "watchdog"]  # keep-alive works
        reply = link.command("V,99999")
        assert reply == P.Ok("V", ("5000",))
        assert isinstance(link.command("STEP,0,1000,60000,10"), P.Ok)
        assert link.command("STEP,0,1000,60000,10") == P.Err("BUSY")
        with pytest.raises(InputError):
            link.command("FLY,1")
    finally:
        link.close()


@pytest.mark.parametrize("fault", ["garbage=0.2", "truncate=0.2", "bad_checksum=0.2", "drop=0.1"])
def test_faults_are_counted_and_never_recorded(make_rig, fault):
    rig = make_rig(seed=3)
    link = rig.open()
    try:
        link.set_period(FAST)
        link.set_voltage(2.0)
        name, value = fault.split("=")
        link.samples()
        setattr(rig.board.faults, name, float(value))
        batch = collect(link, 400)
        matches_truth(batch, rig.board)
        assert np.all(np.diff(batch.seq) >= 1)
        if name == "drop":
            gaps = int(np.sum(np.diff(batch.seq) - 1))
            assert gaps > 0 and link.stats.dropped >= gaps
        else:
            assert link.stats.corrupt > 0
    finally:
        link.close()


def test_seq_and_time_unwrap(make_rig):
    rig = make_rig(micros0=4294000000, seq0=4294967200)
    link = rig.open()
    try:
        link.set_period(FAST)
        batch = collect(link, 300)
        assert np.all(np.diff(batch.seq) == 1) and batch.seq[-1] > 2**32
        assert np.all(np.diff(batch.t_us) > 0) and batch.t_us[-1] > 2**32
    finally:
        link.close()


def test_board_that_stops_answering_is_reported(make_rig):
    rig = make_rig()
    link = rig.open(silence_s=0.5)
    try:
        rig.board.faults.silent = True
        assert wait_for(lambda: any(e.kind == "silent" for e in link.events()))
        rig.board.faults.silent = False
        assert wait_for(lambda: any(e.kind == "alive" for e in link.events()))
    finally:
        link.close()


def test_the_answer_after_a_silence_says_how_long_it_lasted(make_rig):
    """Walk 8, D5: the status line said "board answers again" with no silence said before
    (both events handled in one pass on a busy PC): the answer now carries the silence's
    length, at least the silence_s after which the silence was said."""
    rig = make_rig()
    link = rig.open(silence_s=0.5)
    try:
        rig.board.faults.silent = True  # the board double pauses
        events: list[LinkEvent] = []

        def seen(kind: str) -> bool:
            events.extend(link.events())
            return any(e.kind == kind for e in events)

        assert wait_for(lambda: seen("silent"))
        rig.board.faults.silent = False
        assert wait_for(lambda: seen("alive"))
        (alive,) = [e for e in events if e.kind == "alive"]
        assert alive.silent_s is not None and alive.silent_s >= 0.5
        assert f"answers again after {alive.silent_s:.1f} s" in alive.message
    finally:
        link.close()


def test_watchdog_event_when_the_host_stops_pinging(make_rig):
    rig = make_rig()
    link = rig.open(keepalive_s=1e9)
    try:
        link.set_voltage(2.0)
        assert wait_for(lambda: any(e.kind == "watchdog" for e in link.events()))
        assert rig.board.u_mV == 0
        assert link.u_req == 0.0  # the link knows the motor is off
    finally:
        link.close()


def test_a_second_link_to_the_same_board_is_refused(make_rig):
    rig = make_rig()
    link = rig.open()
    try:
        with pytest.raises(DeviceError, match="in use by"):
            rig.open()
    finally:
        link.close()
    rig.open().close()  # free again once the first let go


def test_unplug_and_replug_keeps_everything_and_restores_no_motor(make_rig):
    rig = make_rig()
    events = []
    link = rig.open(on_event=events.append, retry_s=0.02)
    try:
        link.set_period(FAST)
        assert link.set_voltage(4.0) == 4.0 and link.u_req == 4.0
        before = collect(link, 100)
        rig.unplug()
        assert wait_for(lambda: any(e.kind == "disconnected" for e in events))
        kept = SampleBatch.concat([before, link.samples()])
        rig.replug()
        assert wait_for(lambda: link.stats.reconnects == 1)
        assert wait_for(lambda: rig.board.period_us == FAST * 1e6)  # the period was restored
        after = collect(link, 50)
        allb = SampleBatch.concat([kept, after])
        assert allb.epoch[0] == 0 and allb.epoch[-1] == 1 and set(allb.epoch) == {0, 1}
        assert np.all(np.diff(allb.seq) >= 1) and np.all(np.diff(allb.t_us) > 0)
        assert link.stats.dropped == 0 and link.stats.corrupt == 0
        # the motor voltage is not restored, and the group is told
        assert np.all(after.u_req == 0.0) and rig.board.u_mV == 0
        assert link.u_req == 0.0
        (motor,) = [e for e in events if e.kind == "motor"]
        assert "off" in motor.message and "4 V" in motor.message
        kinds = [e.kind for e in events]
        assert kinds.index("motor") > kinds.index("connected", kinds.index("disconnected"))
    finally:
        link.close()


def test_wrong_protocol_version_gets_a_clear_message():
    with pytest.raises(DeviceError) as info:
        open_device("minseg://?clock=virtual&proto=2")
    text = str(info.value)
    assert "protocol 2" in text and "protocol 3" in text and "minseg-tui flash" in text


def test_a_second_program_is_told_who_holds_the_port(pty_server):
    link = Link(pty_server.path)
    link.open()
    try:
        with pytest.raises(DeviceError, match=f"in use by minseg-tui \\(pid {os.getpid()}\\)"):
            Link(pty_server.path).open()
        code = (
            "import sys; from minseg_tui.device.link import Link\n"
            "try:\n    Link(sys.argv[1], boot_wait_s=0.1).open()\n"
            "except Exception as exc:\n    print(exc)\n"
        )
        other = subprocess.run(
            [sys.executable, "-c", code, pty_server.slave_name], capture_output=True, text=True
        )
        assert f"is in use by minseg-tui (pid {os.getpid()})" in other.stdout, other
    finally:
        link.close()


def test_motion_by_hand():
    rows = [
        (0, 0, 0, 0, 0, 0.0),
        (1, 25000, 10, 0, 0, 0.0),
        (2, 50000, 30, 0, 0, 0.0),
        (3, 7000000, 0, 0, 1, 0.0),
        (4, 7020000, 4, 0, 1, 0.0),
    ]
    b = SampleBatch.from_rows(rows)
    mo = motion(b)
    w = RAD_PER_COUNT
    assert mo.theta == pytest.approx([0, 10 * w, 30 * w, 0, 4 * w])
    assert mo.omega == pytest.approx([0, 10 * w / 0.025, 20 * w / 0.025, 0, 4 * w / 0.02])
    tail = motion(SampleBatch.from_rows(rows[2:3]), before=SampleBatch.from_rows(rows[:2]))
    assert tail.omega == pytest.approx([20 * w / 0.025])


def _as_plain_user() -> None:
    """preexec_fn: a root test run opens the port as nobody (root may bypass TIOCEXCL)."""
    if os.geteuid() == 0:
        os.setgroups([])
        os.setgid(65534)
        os.setuid(65534)


def _plain_open(path: str) -> str:
    """What a plain serial monitor gets opening ``path``: 'opened' or the shell's error."""
    done = subprocess.run(
        ["/bin/sh", "-c", 'exec 3<>"$1" && echo opened', "sh", path],
        capture_output=True,
        text=True,
        timeout=20,
        preexec_fn=_as_plain_user,
    )
    return (done.stdout + done.stderr).strip()


def test_a_plain_serial_monitor_cannot_open_a_port_the_link_holds(pty_server):
    if os.geteuid() == 0:  # let the plain user reach the pty at all
        os.chmod(pty_server.slave_name, 0o666)
    assert _plain_open(pty_server.slave_name) == "opened"  # the control: a free port opens
    link = Link(pty_server.slave_name, retry_s=0.02)
    link.open()
    try:
        got = _plain_open(pty_server.slave_name)
        assert "opened" not in got and "busy" in got.lower(), got
    finally:
        link.close()
    assert wait_for(lambda: _plain_open(pty_server.slave_name) == "opened")  # free again


class _GatedLink(Link):
    """A link whose handshakes after the first wait at a gate the test opens (a reconnect
    that is still under way when the program closes the link, as on a loaded machine)."""

    def __init__(self, *args: object, **kwargs: object) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.handshakes = 0
        self.at_gate = threading.Event()
        self.gate = threading.Event()

    def _handshake(self, ser):  # type: ignore[no-untyped-def]
        self.handshakes += 1
        if self.handshakes > 1:
            self.at_gate.set()
            self.gate.wait()
        return super()._handshake(ser)


def test_a_reconnect_that_ends_after_close_gives_the_port_and_its_lock_back(pty_server):
    """Closed while the reader was reconnecting: the port the reader then opened is closed
    and its lock given back, so the next program (or a test given the same pty name, as
    the kernel hands names out again) can open it. Before, the reader kept the port and
    its lock past the close: the lock outlived the port once the port was collected."""
    link = _GatedLink(pty_server.path, retry_s=0.02, boot_wait_s=0.5)
    link.open()
    pty_server.unplug()
    pty_server.replug()
    assert link.at_gate.wait(30), "the link did not try to reconnect"
    link.close()  # the reader is held in the reconnect's handshake
    link.gate.set()
    assert link._thread is not None
    link._thread.join(30)
    assert not link._thread.is_alive()
    assert not link.connected
    assert holder(Path(lock_path(os.path.realpath(pty_server.path)))) is None
    again = Link(pty_server.path, boot_wait_s=0.5)
    again.open()  # the port opens again
    again.close()


def test_a_pulled_cable_takes_the_board_s_name_with_it(pty_server):
    """The symlink goes with the cable, as udev's /dev/serial/by-id link does, and comes
    back for the new pty: left behind, it named the old pty number, which the kernel hands
    to the next pty anyone opens, and a link retrying it opened and locked that port (a
    test in another process was told "in use by minseg-tui")."""
    old = pty_server.slave_name
    assert os.readlink(pty_server.path) == old
    pty_server.unplug()
    assert not os.path.lexists(pty_server.path)
    pty_server.replug()
    assert os.readlink(pty_server.path) == pty_server.slave_name
