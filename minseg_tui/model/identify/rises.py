"""The rises of a run log (Task 10's experiment) and the manual's 63 % reading on them.

A rise is usable when at least one row comes before it and five after it at the new
level. Falling edges are not read: at zero command the driver brakes or coasts and dry
friction stops the wheel in finite time, so the 63 % rule does not hold for them (the whole-log
fit of :mod:`.wholelog` models them instead).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.runlog import Edge, RunLog, command, find_edges, segment_end

FloatArray = NDArray[np.float64]

E63: float = 1.0 - math.exp(-1.0)
"""Fraction of the final change reached after one time constant (about 63 %)."""

MIN_AFTER: int = 5
"""Rows a rise needs at its new level (the edge's row included) to be usable."""


@dataclass(frozen=True)
class RiseWindow:
    """The rows around one usable rise.

    edge: the rising edge (``edge.start`` is the first row at the new level, the edge happens at
    its time); low_from: first row of the level before it; pre_from: first row used before
    it (the last third of that level); post_last: last row whose angle belongs to the new
    level (the row of the next edge: its angle is read before the next command acts).
    """

    edge: Edge
    low_from: int
    pre_from: int
    post_last: int

    @property
    def rows(self) -> NDArray[np.int64]:
        """The rows the fit of the rises uses, pre_from..post_last."""
        return np.arange(self.pre_from, self.post_last + 1)


def rise_windows(log: RunLog) -> tuple[list[RiseWindow], list[Edge]]:
    """The usable rises of ``log`` and the rising edges that are not (too short, or
    at the very start). Time and work grow in proportion to the log's length."""
    cmd, _ = command(log)
    edges = find_edges(cmd)
    n = len(log)
    span = float(np.ptp(cmd)) if n else 0.0
    used: list[RiseWindow] = []
    skipped: list[Edge] = []
    prev_end = 0  # first row after the previous edge
    for i, e in enumerate(edges):
        low_from = _level_start(cmd, e, prev_end, span)
        prev_end = e.end
        if not e.rising:
            continue
        nxt = edges[i + 1].end + 1 if i + 1 < len(edges) else n
        last = _level_end(cmd, e, nxt, span)
        post_last = min(last + 1, n - 1)
        pre_from = e.start - max(1, math.ceil((e.start - low_from) / 3))
        if e.start < 1 or post_last - e.end < MIN_AFTER - 1:
            skipped.append(e)
            continue
        used.append(RiseWindow(e, low_from, max(pre_from, 0), post_last))
    return used, skipped


def _level_start(cmd: FloatArray, e: Edge, earliest: int, span: float) -> int:
    """First row of the run of rows just before ``e`` that stay within 10 % of the range of
    e.before (looking back no further than ``earliest``)."""
    before = cmd[earliest : e.start]
    away = np.flatnonzero(np.abs(before - e.before) > 0.1 * span)
    return earliest + int(away[-1]) + 1 if away.size else earliest


def _level_end(cmd: FloatArray, e: Edge, upto: int, span: float) -> int:
    """:func:`~minseg_tui.model.runlog.segment_end` looking only as far as row ``upto``
    (the end of the next edge) first, so that all rises together take time O(rows)."""
    away = np.flatnonzero(np.abs(cmd[e.end : upto] - e.after) > 0.03 * span)
    if away.size:
        return e.end + int(away[0]) - 1
    return segment_end(cmd, e) if upto < cmd.size else cmd.size - 1


def reading_63(
    t: FloatArray,
    omega: FloatArray,
    start: int,
    post_last: int,
    w0: float,
    w_ss: float,
    skip: NDArray[np.bool_] | None = None,
) -> float | None:
    """The manual's reading: the time (s) from the edge at row ``start`` until the speed
    ``omega`` (rad/s) first reaches 63 % of the way from w0 to w_ss (rad/s), interpolated
    linearly between samples; None if it never does by row ``post_last``. Rows marked in
    ``skip`` (a logging stall's spike) are not read."""
    if w_ss <= w0:
        return None
    level = w0 + E63 * (w_ss - w0)
    after = omega[start + 1 : post_last + 1]
    ok = np.ones(after.size, dtype=bool) if skip is None else ~skip[start + 1 : post_last + 1]
    hit = np.flatnonzero((after >= level) & ok)
    if not hit.size:
        return None
    k = start + 1 + int(hit[0])
    before = np.flatnonzero(ok[: int(hit[0])])
    j = start + 1 + int(before[-1]) if before.size else start
    prev_t, prev_w = (t[j], omega[j]) if j > start else (t[start], w0)
    frac = (level - prev_w) / (omega[k] - prev_w) if omega[k] != prev_w else 1.0
    return float(prev_t + frac * (t[k] - prev_t) - t[start])
