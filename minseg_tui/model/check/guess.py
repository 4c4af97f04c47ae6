"""Where the search for each cause's parameter starts: a few values read off the log.

The starts of each cause are in its entry of :mod:`.effects`. The fit polishes jointly from the best start (:mod:`.fit`); good starts keep it short and
out of the wrong valley (a delay of a third of a second is found from where the wheel
first moves, not by walking there from zero).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


def rises(u: FloatArray) -> list[tuple[int, int]]:
    """(first row, end row) of every stretch after a step that increases |u| (V)."""
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate((change, [u.size]))
    return [
        (int(a), int(b))
        for a, b in zip(bounds[:-1], bounds[1:], strict=True)
        if abs(u[a]) > abs(u[a - 1])
    ]


def first_motion(
    t: FloatArray, u: FloatArray, y: FloatArray, noise: float, settled: bool = False
) -> list[float]:
    """Per rise, the time (s) from the step until the measured speed first leaves its level
    before the step: by more than four times that level's own scatter from sample to sample
    and a twentieth of the change (rad/s). A wheel at rest has no scatter, so its first count
    is its first motion. ``noise`` (rad/s, the log's scatter) stands in when fewer than five
    rows come before the step. ``settled``: leave out rises whose speed still moved before the
    step (its last five rows drift by more than that bound), where the time the speed leaves
    its level says nothing of when the step acts (a speed still falling reads 0 s)."""
    edges = np.flatnonzero(np.diff(u) != 0) + 1
    out = []
    for a, b in rises(u):
        prev = edges[edges < a]
        before = y[max(int(prev[-1]) if prev.size else 0, a - 50) : a]
        if before.size >= 5:
            level = float(np.median(before[-5:]))
            d = np.diff(before)
            scatter = 1.4826 * float(np.median(np.abs(d - np.median(d)))) / math.sqrt(2.0)
        else:
            level, scatter = float(y[a - 1]), noise
        seg = y[a:b] - level
        change = float(np.max(np.abs(seg))) if seg.size else 0.0
        if change <= 0:
            continue
        bound = max(4.0 * scatter, 0.05 * change)
        if settled and before.size >= 5 and abs(float(before[-1] - before[-5])) > bound:
            continue
        k = np.flatnonzero(np.abs(seg) > bound)
        if k.size:
            out.append(float(t[a + int(k[0])] - t[a]))
    return out


def steepest_rate(t: FloatArray, u: FloatArray, y: FloatArray, K: float) -> float | None:
    """The mean slope of the measured speed between 20 % and 70 % of each rise, divided by
    |K|: the acceleration a current limit would allow (V/s at K = 1); None without rises."""
    slopes = []
    for a, b in rises(u):
        seg = y[a:b]
        if seg.size < 4:
            continue
        lo, hi = float(y[a - 1]), float(np.median(seg[-max(3, seg.size // 5) :]))
        if hi == lo:
            continue
        f = (seg - lo) / (hi - lo)
        i20 = np.flatnonzero(f >= 0.2)
        i70 = np.flatnonzero(f >= 0.7)
        if not i20.size or not i70.size or i70[0] <= i20[0]:
            continue
        i, j = a + int(i20[0]), a + int(i70[0])
        slopes.append(abs(float(y[j] - y[i]) / float(t[j] - t[i])))
    if not slopes or K == 0:
        return None
    return float(np.median(slopes)) / abs(K)


def levels_offset(u: FloatArray, y: FloatArray, T: float, ts: float) -> float | None:
    """The voltage at which the line through the settled speeds of the driven stretches
    meets zero speed (V), when the log drives at two levels or more; else None."""
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate(([0], change, [u.size]))
    settle = max(3, int(math.ceil(5.0 * T / ts)))
    us, ws = [], []
    for a, b in zip(bounds[:-1], bounds[1:], strict=True):
        if u[a] == 0 or b - a - settle < 3:
            continue
        us.append(abs(float(u[a])))
        ws.append(abs(float(np.mean(y[a + settle : b]))))
    if len(set(np.round(us, 6))) < 2:
        return None
    slope, icpt = np.polyfit(us, ws, 1)
    if slope <= 0:
        return None
    return float(-icpt / slope)
