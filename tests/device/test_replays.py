"""Old lines sent again (a USB hub or a serial bridge replaying a block), seq jumps and
counts no motor makes, through the real Link on a real pty, into a recorded run.

The adversarial board is scripted (``ScriptedBoard``): it sends the true stream of a Task
10 step run, and between its lines blocks of lines it sent before, re-encoded with valid
checksums. The run is recorded as the TUI records it (a session's Recorder fed with every
batch the link hands over) and kept as a run log; what is saved must be the true stream,
and the link's counters must say what happened.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from minseg_tui.device import protocol as P
from minseg_tui.device.link import Link
from minseg_tui.device.samples import SampleBatch
from minseg_tui.lab.content.steps import RunPlan
from minseg_tui.lab.state.session import Session

from .conftest import wait_for

PERIOD = 25_000  # us, Task 10's sample period
SEQ0 = 51_000  # the board has been streaming for a while
T0 = 1_300_000_000  # its micros() then, us (21.7 min after reset)


def square_wave_run(n: int, rng: np.random.Generator) -> list[P.SampleLine]:
    """A Task 10 run as the board sends it: square wave 0 / 2.5 V every 1.5 s, the wheel
    a first-order motor (K = 2 rad/s/V, T = 45 ms), 720 counts per revolution, up to
    40 us of loop jitter."""
    lines = []
    omega, theta = 0.0, 0.0
    for k in range(n):
        u = 2.5 if (k * PERIOD // 1_500_000) % 2 == 0 else 0.0
        dt = PERIOD / 1e6
        target = 2.0 * u
        new = target + (omega - target) * math.exp(-dt / 0.045)
        theta += (omega + new) / 2 * dt
        omega = new
        t_us = T0 + k * PERIOD + int(rng.integers(0, 40))
        count = round(theta * 720 / (2 * math.pi))
        lines.append(P.SampleLine(SEQ0 + k, t_us % 2**32, count, round(u * 1000)))
    return lines


def _open(board) -> Link:
    link = Link(board.path, boot_wait_s=0.05, retry_s=0.02, reconnect=False)
    link.open()
    return link


def _record(link: Link, tmp_path, n_true: int):
    """Record the run as the TUI does; the saved log and the batches handed over."""
    session = Session.create(tmp_path / "sessions", ["Ada"], date="2026-11-26")
    plan = RunPlan(low=0.0, high=2.5, half_period=1.5, periods=4, ts=PERIOD / 1e6)
    rec = session.start_run("steps", plan=plan, flush_interval=0.0)
    got: list[SampleBatch] = []

    def take() -> bool:
        batch = link.samples()
        got.append(batch)
        for s, t, c, u in zip(
            batch.seq.tolist(),
            batch.t_us.tolist(),
            batch.count.tolist(),
            np.rint(batch.u_req * 1000).astype(int).tolist(),
            strict=True,
        ):
            rec.append(s, t, c, u)
        return sum(map(len, got)) >= n_true

    assert wait_for(take), f"{sum(map(len, got))} of {n_true} samples"
    info = session.finish_run(rec)
    assert info is not None
    log = session.load_run(info.name)
    session.close()
    return info, log, SampleBatch.concat(got)


def test_replayed_blocks_are_dropped_counted_and_the_saved_run_is_the_true_stream(
    scripted, tmp_path
):
    rng = np.random.default_rng(18)
    true = square_wave_run(487, rng)
    wire: list[P.SampleLine] = []
    replayed = 0
    for k, line in enumerate(true[:-1]):
        wire.append(line)
        if k >= 40 and rng.random() < 0.08:  # a block of 3-30 old lines, 0-200 lines back
            size = int(rng.integers(3, 31))
            back = int(rng.integers(0, 201))
            end = max(k - back, size)
            block = true[end - size : end]
            wire += block
            replayed += len(block)
    wire += true[:12]  # the run's first lines again, just before its last line
    replayed += 12
    wire.append(true[-1])
    assert replayed > 300
    link = _open(scripted)
    try:
        for i in range(0, len(wire), 64):
            scripted.send(*wire[i : i + 64])
        info, log, batch = _record(link, tmp_path, len(true))
        assert wait_for(lambda: link.stats.replayed == replayed)
        assert link.stats.replayed == replayed
        assert link.stats.corrupt == replayed and link.stats.dropped == 0
        assert set(batch.epoch.tolist()) == {0}  # no restart
        assert not [e for e in link.events() if e.kind == "boot"]
        assert len(link.samples()) == 0  # nothing more came
    finally:
        link.close()
    # the saved run is exactly the true stream
    assert info.samples == len(true) and info.dropped == 0
    assert log.extra["seq"].tolist() == [s.seq for s in true]
    assert log.extra["t_us"].tolist() == [s.t_us for s in true]
    assert log.extra["count"].tolist() == [s.count for s in true]
    assert float(np.max(np.abs(log.omega))) < 6.0  # 5 rad/s at 2.5 V, never 166,650


def test_a_seq_jump_is_a_gap_never_a_restart(scripted):
    """The stream's seq jumps by +5 at 36 places (time goes on a period): each is 4 samples
    lost, every line is kept, one epoch."""
    rng = np.random.default_rng(5)
    true = square_wave_run(486, rng)
    jumps = sorted(rng.choice(np.arange(20, 480, 12), 36, replace=False).tolist())
    offset, wire = 0, []
    for k, s in enumerate(true):
        if k in jumps:
            offset += 4
        wire.append(P.SampleLine(s.seq + offset, s.t_us, s.count, s.u_mV))
    link = _open(scripted)
    try:
        scripted.send(*wire)
        scripted.send(P.SampleLine(wire[-1].seq + 1, wire[-1].t_us + PERIOD, true[-1].count, 0))
        got: list[SampleBatch] = []
        assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= len(true))
        batch = SampleBatch.concat(got)
        assert batch.count.tolist()[: len(true)] == [s.count for s in true]
        assert set(batch.epoch.tolist()) == {0}
        assert link.stats.dropped == 4 * 36 and link.stats.corrupt == 0
    finally:
        link.close()


def test_single_lines_with_seq_plus_5_are_refused_not_restarts(scripted):
    """36 lines whose seq alone was altered (+5, a valid checksum): each is refused and is one
    lost sample; no restart, nothing else lost."""
    rng = np.random.default_rng(7)
    true = square_wave_run(486, rng)
    altered = set(rng.choice(np.arange(5, 480), 36, replace=False).tolist())
    wire = [
        P.SampleLine(s.seq + 5, s.t_us, s.count, s.u_mV) if k in altered else s
        for k, s in enumerate(true)
    ]
    link = _open(scripted)
    try:
        scripted.send(*wire)
        n = len(true) - len(altered)
        got: list[SampleBatch] = []
        assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= n)
        batch = SampleBatch.concat(got)
        assert set(batch.epoch.tolist()) == {0}
        kept = set(batch.seq.tolist())
        assert kept <= {s.seq for s in true}  # nothing false kept
        lost = len(true) - len(kept)
        assert link.stats.dropped == lost and link.stats.corrupt == lost
        assert lost <= len(altered) + 6  # a run of three altered lines can take a neighbour
    finally:
        link.close()


@pytest.mark.parametrize("jump", [500, -500, 250])
def test_a_count_no_motor_makes_is_refused(scripted, jump):
    """A count that moved further in one period than the wheel can turn (250 counts in 25 ms
    is 87 rad/s) is refused and counted; the sample is lost, the rest kept."""
    rng = np.random.default_rng(3)
    true = square_wave_run(120, rng)
    wire = list(true)
    wire[60] = P.SampleLine(true[60].seq, true[60].t_us, true[60].count + jump, true[60].u_mV)
    link = _open(scripted)
    try:
        scripted.send(*wire)
        got: list[SampleBatch] = []
        assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= 119)
        batch = SampleBatch.concat(got)
        assert batch.seq.tolist() == [s.seq for k, s in enumerate(true) if k != 60]
        assert link.stats.dropped == 1 and link.stats.corrupt == 1
    finally:
        link.close()


def test_a_zeroed_count_is_kept(scripted):
    """After $OK,Z the count starts again at 0: that jump is the board's, not a false line."""
    rng = np.random.default_rng(4)
    true = square_wave_run(120, rng)
    zero_at = true[70].count
    wire = [
        s if k < 70 else P.SampleLine(s.seq, s.t_us, s.count - zero_at, s.u_mV)
        for k, s in enumerate(true)
    ]
    link = _open(scripted)
    try:
        scripted.send(*wire[:70])
        assert wait_for(lambda: link.stats.samples >= 69)
        assert isinstance(link.command(P.Zero()), P.Ok)
        scripted.send(*wire[70:])
        assert wait_for(lambda: link.stats.samples >= 119)
        assert link.stats.corrupt == 0 and link.stats.dropped == 0
    finally:
        link.close()


def test_a_block_of_lines_with_seq_plus_5_is_no_restart(scripted):
    """36 lines in a row whose seq was altered (+5, valid checksums), their times and counts
    true: the stream's time goes on through them, so no restart; every line is kept (their
    counts are the board's) and the jump counts at most its 5 samples (seq + 6) as lost."""
    rng = np.random.default_rng(9)
    true = square_wave_run(300, rng)
    wire = [
        P.SampleLine(s.seq + 5, s.t_us, s.count, s.u_mV) if 100 <= k < 136 else s
        for k, s in enumerate(true)
    ]
    link = _open(scripted)
    try:
        scripted.send(*wire)
        got: list[SampleBatch] = []
        assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= len(true))
        batch = SampleBatch.concat(got)
        assert set(batch.epoch.tolist()) == {0}
        assert not [e for e in link.events() if e.kind == "boot"]
        assert batch.count.tolist() == [s.count for s in true]
        assert batch.t_us.tolist() == [s.t_us for s in true]
        assert np.all(np.diff(batch.seq) >= 1)
        assert link.stats.dropped <= 5 and link.stats.corrupt == 0
    finally:
        link.close()


def test_an_old_boot_line_sent_again_is_no_restart(scripted):
    """A $BOOT line replayed mid-stream (the stream goes on as before): no restart, no
    'motor off', the line counted as replayed."""
    rng = np.random.default_rng(12)
    true = square_wave_run(200, rng)
    link = _open(scripted)
    try:
        link.events()
        scripted.send(*true[:100], P.Boot("minseg-fw 2.0.0", P.PROTOCOL_VERSION), *true[100:])
        got: list[SampleBatch] = []
        assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= 200)
        batch = SampleBatch.concat(got)
        assert batch.seq.tolist() == [s.seq for s in true]
        assert set(batch.epoch.tolist()) == {0}
        assert [e.kind for e in link.events()] == []
        assert link.stats.replayed == 1 and link.stats.corrupt == 1
    finally:
        link.close()


def test_a_real_boot_is_a_restart_said_once_its_samples_start_again(scripted):
    rng = np.random.default_rng(13)
    true = square_wave_run(100, rng)
    again = [P.SampleLine(k, 1_500_000 + PERIOD * (k + 1), 0, 0) for k in range(50)]
    link = _open(scripted)
    try:
        link.events()
        scripted.send(*true, P.Boot("minseg-fw 2.0.0", P.PROTOCOL_VERSION), *again)
        got: list[SampleBatch] = []
        assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= 150)
        batch = SampleBatch.concat(got)
        assert batch.epoch.tolist() == [0] * 100 + [1] * 50
        assert batch.count.tolist()[100:] == [0] * 50
        kinds = [e.kind for e in link.events()]
        assert kinds.count("boot") == 1
        assert link.stats.corrupt == 0 and link.stats.dropped == 0
    finally:
        link.close()


def test_a_restart_whose_boot_line_was_lost_is_said(scripted):
    rng = np.random.default_rng(14)
    true = square_wave_run(100, rng)
    again = [P.SampleLine(k, 1_500_000 + PERIOD * (k + 1), 0, 0) for k in range(50)]
    link = _open(scripted)
    try:
        link.events()
        scripted.send(*true, *again)
        assert wait_for(lambda: link.stats.samples >= 150)
        (boot,) = [e for e in link.events() if e.kind == "boot"]
        assert "its $BOOT line was lost" in boot.message
    finally:
        link.close()
