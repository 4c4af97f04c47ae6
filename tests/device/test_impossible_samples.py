"""A sample line that passes the checksum yet cannot be true is refused by the real Link.

The board is scripted on a real pty: 100 samples 10 ms apart, with sample 50 replaced by
a line whose seq or t_us no real gap explains (what a corrupt line the checksum missed
looks like: digits swapped or lost). The link must keep the other 99 exactly as the board
sent them, count sample 50 as lost and the line as corrupt, and stay in the same epoch.
"""

from __future__ import annotations

import numpy as np
import pytest

from minseg_tui.device import protocol as P
from minseg_tui.device.link import Link
from minseg_tui.device.samples import SampleBatch

from .conftest import wait_for

T0 = 1_000_000  # board time of sample 0, us
PERIOD = 10_000  # us


def good(k: int, seq0: int = 0, t0: int = T0) -> P.SampleLine:
    return P.SampleLine((seq0 + k) % 2**32, (t0 + k * PERIOD) % 2**32, 3 * k, 2000)


def _open(board):
    link = Link(board.path, boot_wait_s=0.05, retry_s=0.02, reconnect=False)
    link.open()
    return link


def _collect(link, n):
    got = []
    assert wait_for(lambda: got.append(link.samples()) or sum(map(len, got)) >= n), (
        f"{sum(map(len, got))} of {n} samples"
    )
    return SampleBatch.concat(got)


BAD = {
    # the case: a corrupt seq that counted 245,867,300 dropped samples
    "seq far ahead": lambda s: P.SampleLine(s.seq + 245_867_300, s.t_us, s.count, s.u_mV),
    "seq back": lambda s: P.SampleLine(s.seq - 40, s.t_us, s.count, s.u_mV),  # new epoch today
    "seq a little ahead": lambda s: P.SampleLine(s.seq + 9, s.t_us, s.count, s.u_mV),
    "time far ahead": lambda s: P.SampleLine(s.seq, s.t_us + 245_000_000, s.count, s.u_mV),
    "time back": lambda s: P.SampleLine(s.seq, s.t_us - 900_000, s.count, s.u_mV),
    "time a little ahead": lambda s: P.SampleLine(s.seq, s.t_us + 40_000, s.count, s.u_mV),
}


@pytest.mark.parametrize("kind", list(BAD))
def test_an_impossible_sample_is_refused(scripted, kind):
    link = _open(scripted)
    try:
        lines = [good(k) for k in range(100)]
        lines[50] = BAD[kind](lines[50])
        scripted.send(*lines)
        scripted.send(good(100))  # one more, so the last is not held back for confirmation
        batch = _collect(link, 100)
        kept = [k for k in range(101) if k != 50]
        assert list(batch.seq) == kept
        assert list(batch.t_us) == [T0 + k * PERIOD for k in kept]  # the board's own time
        assert list(batch.count) == [3 * k for k in kept]
        assert set(batch.epoch) == {0}
        assert link.stats.dropped == 1 and link.stats.corrupt == 1
    finally:
        link.close()


def test_a_real_gap_is_kept_and_counted(scripted):
    link = _open(scripted)
    try:
        kept = [k for k in range(60) if not 20 <= k < 25]  # 5 samples lost on the way
        scripted.send(*(good(k) for k in kept))
        batch = _collect(link, len(kept))
        assert list(batch.seq) == kept and list(batch.t_us) == [T0 + k * PERIOD for k in kept]
        assert set(batch.epoch) == {0}
        assert link.stats.dropped == 5 and link.stats.corrupt == 0
    finally:
        link.close()


def test_a_period_change_and_a_wrap_are_no_gap(scripted):
    link = _open(scripted)
    try:
        near = 2**32 - 30 * PERIOD  # board time wraps during the stream
        first = [good(k, seq0=2**32 - 10, t0=near) for k in range(20)]
        t_last = first[-1].t_us
        # the period changes to 25 ms, and a sample is lost just then
        after = [
            P.SampleLine((first[-1].seq + 1 + k) % 2**32, (t_last + (k + 1) * 25_000) % 2**32, 0, 0)
            for k in range(20)
            if k != 0
        ]
        scripted.send(*first, *after)
        batch = _collect(link, 39)
        assert np.all(np.diff(batch.seq) >= 1) and np.all(np.diff(batch.t_us) > 0)
        assert set(batch.epoch) == {0} and batch.seq[-1] - batch.seq[0] == 39
        assert link.stats.dropped == 1 and link.stats.corrupt == 0
    finally:
        link.close()


def test_a_reset_whose_boot_line_was_lost_starts_a_new_epoch_and_loses_nothing(scripted):
    link = _open(scripted)
    try:
        before = [good(k, seq0=5000) for k in range(30)]
        # the board restarted (its $BOOT line lost): seq and time start again near zero
        again = [good(k, seq0=0, t0=3000) for k in range(30)]
        scripted.send(*before, *again)
        batch = _collect(link, 60)
        assert list(batch.epoch) == [0] * 30 + [1] * 30
        assert list(batch.count) == [3 * k for k in range(30)] * 2
        assert np.all(np.diff(batch.seq) == 1) and np.all(np.diff(batch.t_us) > 0)
        assert link.stats.dropped == 0 and link.stats.corrupt == 0
    finally:
        link.close()


def test_a_corrupt_first_sample_does_not_become_the_reference(scripted):
    link = _open(scripted)
    try:
        lines = [good(k) for k in range(40)]
        lines[0] = P.SampleLine(lines[0].seq + 7_000_000, lines[0].t_us, 0, 2000)
        scripted.send(*lines)
        batch = _collect(link, 39)
        assert list(batch.seq) == list(range(1, 40)) and set(batch.epoch) == {0}
        assert link.stats.corrupt == 1
    finally:
        link.close()
