"""A coarse clock: stamps in whole milliseconds (an Arduino's millis()), so a row is stamped
10 or 11 ms after the last while its count ran about the nominal 10 ms (REAL37: the n20 logs,
whose 11 ms rows the check simulated about 10 % fast).

The log is made here from a first-order motor (T 80 ms, K 5 rad/s/V, steps of 8 V): the loop
counts encoder edges (350 per turn, a random phase) over its real period of 10.1 ms (with a
little jitter), stamps each row with millis() read at its end (10 or 11 ms apart) and divides
the count by the nominal 10 ms, as the n20 sketch does.
"""

import math

import numpy as np

from minseg_tui.lab.views.check_says import sampling as sampling_words
from minseg_tui.model.check import check
from minseg_tui.model.check.sampling import sampling

CPR = 350
TS = 0.010
T = 0.08
K = 5.0


def _angle(t: np.ndarray, steps: list[tuple[float, float]]) -> np.ndarray:
    """The angle (rad) of the first-order motor at times ``t`` under the steps (time, V)."""
    out = np.zeros_like(t)
    prev = 0.0
    for at, v in steps:
        dv = v - prev
        tau = np.maximum(t - at, 0.0)
        out += K * dv * (tau - T * (1.0 - np.exp(-tau / T)))
        prev = v
    return out


def millis_log(seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """t (s, stamped in whole ms), u (V), omega (rad/s: counts over the nominal 10 ms)."""
    rng = np.random.default_rng(seed)
    n = 400
    real = np.cumsum(rng.uniform(0.0100, 0.0102, n))  # the ends of the counts, s
    stamp = np.floor(real * 1e3 + 0.35) / 1e3  # millis() read as the row is printed
    steps = [(0.8, 8.0), (2.4, 0.0), (3.0, 8.0)]
    phase = float(rng.uniform(0.0, 1.0))
    counts = np.floor(_angle(real, steps) * CPR / (2 * math.pi) + phase)
    omega = np.diff(counts, prepend=counts[0]) * 2 * math.pi / CPR / TS
    u = np.zeros(n)
    for at, v in steps:
        u[stamp >= at] = v  # the command of a row is issued as it is stamped
    return stamp, u, omega


def test_a_coarse_clock_is_seen_and_simulated_over_each_interval() -> None:
    t, u, y = millis_log(38)
    dt = np.diff(t)
    assert set(np.round(dt * 1e3).astype(int).tolist()) == {10, 11}  # the premise
    longer = np.concatenate(([False], dt > 0.0105))
    r = check(t, u, y, ts=TS, cpr=CPR)
    # on the plateaus (0.5 s after each rise) the model reads the 11 ms rows as the 10 ms ones,
    # as the data do; simulated as the angle over 11 ms / 10 ms they would read 10 % faster
    flat = ((t > 1.3) & (t < 2.4)) | (t > 3.5)
    pred = r.extended_pred
    ratio = float(np.mean(pred[flat & longer]) / np.mean(pred[flat & ~longer]))
    data = float(np.mean(y[flat & longer]) / np.mean(y[flat & ~longer]))
    assert abs(data - 1.0) < 0.03
    assert abs(ratio - 1.0) < 0.01, ratio
    s = sampling(t, u, y, TS, cpr=CPR)
    assert not s.over_interval and s.coarse is not None and abs(s.coarse) < 0.5
    words = sampling_words(s)
    assert (
        "stamps whole ticks" in words and "simulated as the mean speed over its interval" in words
    )


def test_a_stamped_interval_that_lengthens_the_count_is_not_coarse() -> None:
    """The same clock, but the count runs over the stamped interval (counts read when
    millis() ticks): the 11 ms rows read 10 % faster, and are simulated so."""
    rng = np.random.default_rng(39)
    n = 400
    stamp = np.cumsum(np.where(rng.random(n) < 0.2, 0.011, 0.010))
    steps = [(0.8, 8.0), (2.4, 0.0), (3.0, 8.0)]
    counts = np.floor(_angle(stamp, steps) * CPR / (2 * math.pi) + 0.3)
    y = np.diff(counts, prepend=counts[0]) * 2 * math.pi / CPR / TS
    u = np.zeros(n)
    for at, v in steps:
        u[stamp >= at] = v
    s = sampling(stamp, u, y, TS, cpr=CPR)
    assert not s.over_interval and s.coarse is None
