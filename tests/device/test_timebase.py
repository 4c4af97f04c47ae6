"""The timeline on a long seeded stream with lines the checksum missed, and by hand."""

from __future__ import annotations

import numpy as np

from minseg_tui.device.protocol import SampleLine
from minseg_tui.device.timebase import Timeline

PERIOD = 5000  # us


def _mutate(value: int, rng: np.random.Generator) -> int:
    """What a checksum can miss: two adjacent digits swapped, or a pair of digits lost."""
    s = str(value)
    if len(s) < 3:
        return value
    i = int(rng.integers(len(s) - 1))
    if rng.random() < 0.5:
        s = s[:i] + s[i + 1] + s[i] + s[i + 2 :]
    else:
        s = s[:i] + s[i + 2 :]
    return int(s) % 2**32 if s else 0


def test_a_long_stream_with_false_lines_keeps_only_the_truth():
    rng = np.random.default_rng(11)
    n = 20000
    seq0, t0 = 2**32 - 3000, 2**32 - 7_000_000  # both wrap during the stream
    jitter = rng.integers(0, 40, n)
    true_seq = [(seq0 + k) % 2**32 for k in range(n)]
    true_t = [(t0 + k * PERIOD + int(jitter[k])) % 2**32 for k in range(n)]
    false_at = set(rng.choice(np.arange(1, n), 200, replace=False).tolist())
    lost_at = set(rng.choice(np.arange(1, n), 50, replace=False).tolist()) - false_at
    tl = Timeline()
    tl.new_epoch()
    kept = []
    for k in range(n):
        if k in lost_at:
            continue
        seq, t_us = true_seq[k], true_t[k]
        if k in false_at:
            if rng.random() < 0.5:
                seq = _mutate(seq, rng)
            else:
                t_us = _mutate(t_us, rng)
        # the host reads in bursts of up to 20 samples, 2-30 ms late
        clock = (k // 20 * 20 + 20) * PERIOD / 1e6 + float(rng.uniform(0.002, 0.03))
        kept += tl.place(SampleLine(seq, t_us, k, 0), clock, clock)
    seqs = np.array([r[0] for r in kept])
    t_out = np.array([r[1] for r in kept])
    k_of = np.array([r[2] for r in kept])  # the count carries the sample's true index
    assert {r[4] for r in kept} == {0}  # no false epoch
    assert np.all(seqs - seqs[0] == k_of - k_of[0])  # every kept seq is the true one
    true_rel = (np.array(true_t)[k_of] - true_t[k_of[0]]) % 2**32
    assert np.max(np.abs((t_out - t_out[0]) - true_rel)) <= 2000  # and its time, to 2 ms
    assert len(kept) + tl.dropped == k_of[-1] - k_of[0] + 1
    assert tl.refused <= len(false_at) and tl.dropped >= len(lost_at)
    missed = len(set(k_of.tolist()) & false_at)  # false lines kept: a harmless change only
    print(f"{n} samples: {len(false_at)} false lines, {tl.refused} refused, {missed} kept")


def test_by_hand_a_period_change_is_learnt_and_a_repeat_is_not_kept():
    tl = Timeline()
    tl.new_epoch()
    out = []
    for k in range(5):
        out += tl.place(SampleLine(k, 1000 + 10000 * k, 0, 0), 1.0, 1.0)
    assert [r[0] for r in out] == [0, 1, 2, 3, 4] and tl.period_us == 10000
    assert tl.place(SampleLine(4, 41000, 0, 0), 1.0, 1.0) == []  # the same line again
    assert tl.repeated == 1
    # the period becomes 25 ms: held until three samples agree, then kept, nothing refused
    got = [tl.place(SampleLine(5 + k, 41000 + 25000 * (k + 1), 0, 0), 1.2, 1.2) for k in range(3)]
    assert got[0] == [] and got[1] == [] and [r[0] for r in got[2]] == [5, 6, 7]
    assert tl.refused == 0 and tl.dropped == 0 and tl.period_us == 25000
    assert [r[0] for r in tl.place(SampleLine(8, 41000 + 25000 * 4, 0, 0), 1.2, 1.2)] == [8]


def test_a_restart_that_repeats_the_last_one_line_for_line_is_kept_once_seen_live():
    """A board whose $BOOT was lost and whose first lines are copies of the last epoch's (same
    seq, same micros): held as a replay, until it has run live for RESTART_S; then a new
    epoch, nothing lost. The same lines sent in a burst stay a replay."""
    start = [SampleLine(k, 1_500_000 + 10000 * k, 0, 0) for k in range(400)]
    tl = Timeline()
    tl.new_epoch()
    kept = []
    for k, s in enumerate(start):
        kept += tl.place(s, 1.5 + 0.01 * k, 1.5 + 0.01 * k)
    assert len(kept) == 400
    # a burst of the first 50 lines again (a replay): nothing kept, nothing started
    for s in start[:50]:
        assert tl.place(s, 5.6, 5.6) == []
    assert tl.epoch == 0
    kept += tl.place(SampleLine(400, 1_500_000 + 10000 * 400, 0, 0), 5.61, 5.61)
    assert len(kept) == 401 and tl.replayed == 50
    # now the board restarts, line for line as before, live
    again = []
    for k, s in enumerate(start):
        again += tl.place(s, 8.0 + 0.01 * k, 8.0 + 0.01 * k)
    assert tl.epoch == 1 and len(again) == 400
    assert [r[2] for r in again] == [0] * len(again) and tl.refused == 0
    assert all(r[4] == 1 for r in again)


def test_old_lines_of_an_earlier_epoch_after_a_restart_are_a_replay():
    tl = Timeline()
    tl.new_epoch()
    first = [SampleLine(k, 1_500_000 + 10000 * k, 3 * k, 0) for k in range(100)]
    for k, s in enumerate(first):
        tl.place(s, 1.5 + 0.01 * k, 1.5 + 0.01 * k)
    tl.new_epoch()  # a $BOOT
    second = [SampleLine(k, 1_700_000 + 10000 * k, 0, 0) for k in range(100)]
    out = []
    for k, s in enumerate(second[:50]):
        out += tl.place(s, 4.0 + 0.01 * k, 4.0 + 0.01 * k)
    for s in first[10:40]:  # the first epoch's lines again: they start again, but are copies
        assert tl.place(s, 4.5, 4.5) == []
    for k, s in enumerate(second[50:]):
        out += tl.place(s, 4.5 + 0.01 * k, 4.5 + 0.01 * k)
    assert [r[0] - out[0][0] for r in out] == list(range(100)) and tl.epoch == 1
    assert tl.replayed + tl.refused == 30 and tl.dropped == 0
