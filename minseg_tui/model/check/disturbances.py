"""A hand on the wheel: a change of speed that no change of input explains.

It sits inside a stretch of constant input, after the response to the step has settled,
starts and ends abruptly, and leaves the rest of the log fitting well. It is found from
the residual of a model within those stretches (after the step has settled, or, against a
model that follows the steps, from a few rows after it), against the stretch's own level
and the noise: a run of rows whose running mean (over ``SMOOTH`` rows, at least
``SMOOTH_S``) departs by more than ``MIN_SHARE`` of the speed there and ``SIGMAS`` times the
noise of that mean, with quiet rows before it. Its rows are fenced off (left out of the
fit, and never turned into a cause) together with its onset before them and the wheel's
recovery after them: the rows until the model meets the data again, within ``CALM`` times
the residual's own spread in the settled stretches, across a step of the input if the
recovery runs on past one. A wheel a hand let go of comes back
with the motor's own time constant from a speed the model does not know; left in, that
recovery is a slow error that the whitened residual (a leaky sum, much like an angle)
carries on for seconds, into the comparison of the causes.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

MIN_SHARE = 0.08
"""A disturbance changes the speed by at least this share of the level there."""

HAND = 0.15
"""The shortest hold of a hand the check looks for (s). An average over a longer time than
that shows the hand's change of speed spread over the average's length, and smaller:
``MIN_SHARE`` is taken down in proportion, to ``AVERAGED_SHARE`` of it at most."""

AVERAGED_SHARE = 0.5

SIGMAS = 5.0
"""...and by this many times the noise of a mean over ``SMOOTH`` rows."""

SMOOTH = 3
"""Rows of the running mean the residual is looked at through, at least..."""

SMOOTH_S = 0.075
"""...and over at least this long (s; half the shortest hold of a hand, ``HAND``): at fast
sampling three rows hold too little of a hand to lift it above the noise of counts."""

MIN_ROWS = 3
"""...for at least this many rows."""


@dataclass(frozen=True)
class Disturbance:
    """Rows ``start``..``end`` (end exclusive) where something other than the input moved the
    speed; ``size`` the largest change (rad/s, measured - model), ``level`` the model's
    speed there (rad/s)."""

    start: int
    end: int
    size: float
    level: float
    until: int = -1
    """End (exclusive) of the rows left out: ``end`` and the wheel's recovery after it, until
    the model rejoins the data (-1: ``end``)."""

    since: int = -1
    """First row left out: ``start``, or earlier where the departure already shows above
    the model's calm band (-1: ``start``)."""

    free: int = -1
    """With the model restarted where the hand let go (:func:`restarted`): the first row
    whose reading lies wholly after that, from which the rows count again (-1: not
    restarted)."""

    let_go: int = -1
    """The first row read wholly after the last row where the departure was at its deepest
    (where the hand let go of the wheel; -1: ``end``)."""

    @property
    def fence_end(self) -> int:
        if self.free >= 0:
            return self.free
        return max(self.end, self.until)

    @property
    def fence_start(self) -> int:
        return self.start if self.since < 0 else min(self.start, self.since)


def smooth_rows(ts: float) -> int:
    """Rows of the running mean a departure is looked for through at the sample period ``ts``
    (s): ``SMOOTH``, or as many as ``SMOOTH_S`` holds."""
    return max(SMOOTH, int(SMOOTH_S / ts + 1e-6)) if ts > 0 else SMOOTH


def settle_rows(T: float, delay: float, taps: int, ts: float) -> int:
    """Rows after a step until the response has settled: 5 T plus the delay and the filter."""
    return max(3, int(math.ceil((5.0 * T + delay) / ts)) + taps)


def _spans(u: FloatArray, settle: int) -> list[tuple[int, int]]:
    """The settled part (from ``settle`` rows after its step) of every driven stretch long
    enough to hold a disturbance, as (first row, end row exclusive)."""
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate(([0], change, [u.size]))
    spans = [
        (int(a) + settle if a > 0 else int(a) + 1, int(b))
        for a, b in zip(bounds[:-1], bounds[1:], strict=True)
        if u[a] != 0
    ]
    return [(a0, b) for a0, b in spans if b - a0 >= 4 * MIN_ROWS]


def find(
    t: FloatArray,
    u: FloatArray,
    residual: FloatArray,
    pred: FloatArray,
    settle: int,
    noise: float,
    own_level: bool = True,
    carry: int = 0,
    recover: int = 0,
    transient: int = 0,
) -> list[Disturbance]:
    """Disturbances in the settled part of every driven stretch (see the module docstring).

    ``residual`` = measured - model and ``pred`` the model's speed (rad/s) on every row;
    ``settle``: rows after a step before the stretch counts as settled; ``noise``: the
    speed's noise, rad/s; ``own_level``: the residual is taken against each stretch's own
    median (a model that misses the levels), else against the median of all the settled
    rows (a model that fits: a long disturbance cannot shift its own reference); ``carry``:
    rows the measured speed carries a disturbance on after it ends (an average over that
    many samples); ``recover``: rows at most the wheel takes to rejoin the model after a
    disturbance lets go (see :func:`rejoin`); ``transient``: rows after a step while the
    model's response to it has not settled. A departure there is judged against the size
    of the step (the change of the model's speed across it, rad/s) where that is larger
    than the stretch's level: what a model misses inside a transient grows with the step,
    and a reversal's transient passes through a level near zero.
    """
    spans = _spans(u, settle)
    ts = float(np.median(np.diff(t))) if t.size > 1 else 0.0
    share = (
        MIN_SHARE * min(1.0, max(AVERAGED_SHARE, HAND / ((carry + 1) * ts)))
        if ts > 0
        else MIN_SHARE
    )
    smooth = smooth_rows(ts)
    common = float(np.median(np.concatenate([residual[a0:b] for a0, b in spans]))) if spans else 0.0
    levels = [float(np.median(residual[a0:b])) if own_level else common for a0, b in spans]
    band = _calm_band(residual, spans, levels, noise)
    out: list[Disturbance] = []
    for (a0, b), level in zip(spans, levels, strict=True):
        seg = residual[a0:b]
        dev = seg - level
        speed = float(np.median(np.abs(pred[a0:b])))
        thr = max(SIGMAS * noise / math.sqrt(smooth), share * speed)
        if thr <= 0:
            continue
        sm = np.convolve(dev, np.ones(smooth) / smooth, mode="same")
        limit = np.full(seg.size, thr)
        edges = np.flatnonzero(np.diff(u[: a0 + 1]) != 0)
        step = int(edges[-1]) + 1 if edges.size else 0
        if step > 0 and transient > 0:
            jump = abs(float(pred[b - 1]) - float(pred[step - 1]))
            inside = max(0, min(seg.size, step + transient - a0))
            limit[:inside] = np.maximum(limit[:inside], share * jump)
        out_rows = np.abs(sm) > limit
        k = 0
        while k < out_rows.size:
            if not out_rows[k]:
                k += 1
                continue
            j = k
            while j + 1 < out_rows.size and out_rows[j + 1]:
                j += 1
            if j - k + 1 >= MIN_ROWS and k >= MIN_ROWS:
                quiet = 2.0 * noise + 0.25 * thr
                s = k
                # a mean longer than SMOOTH rows crosses that many rows more ahead of the
                # departure: from the first of them the departure itself reaches quiet in
                ahead = min(k + (smooth - SMOOTH) // 2, j)
                while s < ahead and abs(dev[s]) <= quiet:
                    s += 1
                while s > 0 and abs(dev[s - 1]) > quiet:
                    s -= 1
                e = j
                while e + 1 < dev.size and abs(dev[e + 1]) > quiet:
                    e += 1
                if s >= 2:  # quiet rows before it: it starts inside the stretch
                    big = int(np.argmax(np.abs(dev[s : e + 1]))) + s
                    end = min(a0 + e + 2 + carry, u.size)
                    whole = residual - level
                    # the hand lets go where the departure is deepest (a braked wheel slows
                    # while it is held); a wheel held at rest stays there: the last such row
                    way = np.sign(dev[big]) * sm[s : e + 1]
                    deep = np.flatnonzero(way >= LET_GO * float(np.max(way)))
                    last = s + int(deep[-1]) if deep.size else big
                    out.append(
                        Disturbance(
                            a0 + s,
                            end,
                            float(dev[big]),
                            float(pred[a0 + big]),
                            rejoin(whole, end, band, recover),
                            onset(whole, a0 + s, band, min(recover, s + settle)),
                            let_go=min(a0 + last + carry // 2 + 2, end),
                        )
                    )
            k = j + 1
    return out


CALM = 3.0
"""The model has rejoined the data when the running mean of the residual is back within
this many times its own spread in the settled stretches (a robust sigma: most rows there
hold no disturbance)."""


def _calm_band(
    residual: FloatArray,
    spans: list[tuple[int, int]],
    levels: list[float],
    noise: float,
    keep: NDArray[np.bool_] | None = None,
) -> float:
    """How far (rad/s) the running mean of the residual strays from its level in the
    settled stretches (on the rows ``keep``, default all): ``CALM`` robust sigmas, at most
    twice the noise of that mean."""
    parts = []
    for (a0, b), lv in zip(spans, levels, strict=True):
        sm = np.convolve(residual[a0:b] - lv, np.ones(SMOOTH) / SMOOTH, mode="same")
        parts.append(sm if keep is None else sm[keep[a0:b]])
    sm_all = np.concatenate(parts) if parts else np.zeros(0)
    cap = 2.0 * noise / math.sqrt(SMOOTH)
    if sm_all.size < 4 * MIN_ROWS:
        return cap
    return min(CALM * 1.4826 * float(np.median(np.abs(sm_all))), cap)


def recovered(
    found: list[Disturbance],
    u: FloatArray,
    residual: FloatArray,
    keep: NDArray[np.bool_],
    settle: int,
    noise: float,
    recover: int,
    way_back: Callable[[Disturbance, float], int] | None = None,
) -> list[Disturbance]:
    """``found`` with the onset and the end of the recovery of each found again against
    ``residual`` (measured - model, rad/s) of a model fitted without their rows (``keep``
    False there, and on other rows left out): one fitted with them bends towards the hand
    and misjudges where the wheel rejoins it. ``settle``: rows after a step before the
    stretch counts as settled; ``recover``: rows at most the recovery (and the onset)
    takes; ``way_back``: where the model's own way back can take longer (a current cap
    holds a departure, see :func:`restarted`), the rows from where the hand let go that
    the departure it left lasts above a band (rad/s) through the model, which the
    recovery may take instead."""
    if not found:
        return found
    spans = _spans(u, settle)
    rows = [np.flatnonzero(keep[a0:b]) + a0 for a0, b in spans]
    kept = np.concatenate(rows) if rows else np.zeros(0, dtype=int)
    level = float(np.median(residual[kept])) if kept.size else 0.0
    band = _calm_band(residual, spans, [level] * len(spans), noise, keep)
    dev = residual - level
    change = np.flatnonzero(np.diff(u) != 0) + 1

    def lead(d: Disturbance) -> int:
        # never back past the step of its own stretch: the input stays the same throughout
        before = change[change <= d.start]
        return max(min(recover, d.start - (int(before[-1]) if before.size else 0) - 1), 0)

    def longest(d: Disturbance) -> int:
        if way_back is None:
            return recover
        free = d.end if d.let_go < 0 else d.let_go
        return max(recover, free + way_back(d, band) - d.end)

    return [
        replace(
            d,
            until=rejoin(dev, d.end, band, longest(d)),
            since=onset(dev, d.start, band, lead(d)),
        )
        for d in found
    ]


def rejoin(dev: FloatArray, end: int, band: float, recover: int) -> int:
    """The row (exclusive) from which the model rejoins the data after a disturbance that
    ends at row ``end``: the first of ``MIN_ROWS`` rows whose running mean of ``dev`` (the
    residual against its settled level, rad/s) lies within ``band``, at most ``recover``
    rows on. The wheel a hand let go of recovers with the motor's own time constant, from
    a speed the model does not know, and the recovery runs on across a step of the input;
    left in, it is a slow error the whitened residual piles up."""
    last = min(end + recover, dev.size)
    if last <= end:
        return end
    sm = np.abs(np.convolve(dev, np.ones(SMOOTH) / SMOOTH, mode="same"))
    calm = 0
    for k in range(end, last):
        calm = calm + 1 if sm[k] <= band else 0
        if calm >= MIN_ROWS:
            return k - MIN_ROWS + 1
    return last


def onset(dev: FloatArray, start: int, band: float, lead: int) -> int:
    """The first row of the departure that a disturbance found from row ``start`` begins
    with, looking back at most ``lead`` rows: the corner of the line that fits ``dev`` (the
    residual against its settled level, rad/s) on those rows best as a constant that then
    departs steadily the same way as at ``start`` (a hand's departure grows from the touch
    on, with the wheel's own time constant, through any average of the reading), provided
    the departure up to ``start`` exceeds ``band``. Rows found by a threshold far above the
    noise start late; a corner fitted through the rows' noise, unlike a walk back from row
    to row, is not stopped by one noisy row."""
    first = max(start - lead, 0)
    if start - first < ONSET_FLAT + 1 or start >= dev.size:
        return start
    sm = np.convolve(dev, np.ones(SMOOTH) / SMOOTH, mode="same")
    sign = 1.0 if sm[start] >= 0 else -1.0
    # never back past a row that departs the other way (a spike of the logger, another
    # miss): a hand's departure does not hold that; single rows' outliers are clipped
    other = np.flatnonzero(sign * sm[first:start] < -band)
    if other.size:
        first += int(other[-1]) + 1
    if start - first < ONSET_FLAT + 1:
        return start
    top = abs(float(sm[start])) + band
    x = np.clip(sign * dev[first : start + 1], -top, top)
    n = x.size
    j = np.arange(n, dtype=float)
    best, best_sse = start, math.inf
    for i0 in range(ONSET_FLAT, n - 1):
        r = np.maximum(j - i0 + 1.0, 0.0)
        a = np.vstack((np.ones(n), r)).T
        coef, *_ = np.linalg.lstsq(a, x, rcond=None)
        if coef[1] <= 0 or coef[1] * r[-1] <= band:
            continue
        sse = float(np.sum((x - a @ coef) ** 2))
        if sse < best_sse:
            best, best_sse = first + i0, sse
    return min(best, start)


ONSET_FLAT = 3
"""Rows of the settled level at least, before a departure's corner."""


LET_GO = 0.9
"""The hand is taken to hold the wheel while the running mean of the departure stays within
this share of its deepest value."""


def restarted(
    found: list[Disturbance],
    u: FloatArray,
    early: bool = True,
    held: Callable[[Disturbance], bool] | None = None,
) -> tuple[list[Disturbance], tuple[int, ...]]:
    """(the disturbances, the rows where the model picks up again). Where the wheel's way
    back after a hand would be left out across a step of the input (it has not rejoined
    the model by then), that step's response would be taken out of the comparison of the
    causes with it; there the rows from where the hand let go stay in the fit instead, the
    model restarting from the speed the hand left the wheel at (:func:`.simulate.restart`).
    The rows from the first read wholly after the hand let go (``early``; else from the
    departure's end) count again. Where fewer than ``RESTART_ROWS`` rows lie between there
    and the next step (the speed the hand left cannot be read before the step's response),
    or where the wheel is back on the model before the next step, the rows stay left out
    until it is, as before. Nor where ``held`` says the model holds the departure: under
    a current cap it does not die away with the motor's time constant (the current held at
    the cap, the wheel a hand slowed ramps at the same rate as the model and stays as far
    behind it until the cap lets go: only the wheel's viscous drag closes the gap), so a
    restart's way back (:func:`.simulate.restart`) would be wrong: the rows stay left out
    until the wheel is back on the model (held-out touched seed 901002, a cap of 37
    rad/s^2: the hand's 12 rad/s lasted 5.5 s, through the next step)."""
    out: list[Disturbance] = []
    rows: set[int] = set()
    change = np.flatnonzero(np.diff(u) != 0) + 1
    for d in found:
        free = d.end if d.let_go < 0 or not early else d.let_go
        after = change[change > free]
        nxt = int(after[0]) if after.size else u.size
        if nxt - free < RESTART_ROWS or free >= u.size or d.fence_end <= nxt:
            out.append(d)
            continue
        if held is not None and held(d):
            out.append(d)
            continue
        out.append(replace(d, free=free))
        rows.add(free)
    return out, tuple(sorted(rows))


RESTART_ROWS = 6
"""Rows the speed the hand left the wheel at is read from, before the next step."""


def fence(n: int, found: list[Disturbance]) -> FloatArray:
    """Row weights: 0 on the disturbances' rows, 1 elsewhere."""
    w = np.ones(n)
    for d in found:
        w[d.fence_start : d.fence_end] = 0.0
    return w


REPEAT_MIN = 3
"""A departure found after this many edges of one kind..."""

REPEAT_SHARE = 0.5
"""...and after at least this share of them is the model's miss, not a disturbance."""


def edge_kinds(u: FloatArray) -> tuple[list[tuple[int, int, str]], dict[str, int]]:
    """Every stretch of constant input as (first row, end row exclusive, kind): 'rising'
    when its level is larger in size than the one before (a step up, or a start from rest),
    'falling' otherwise, 'start' for the first; and how many driven stretches of each kind
    are long enough to hold a disturbance."""
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate(([0], change, [u.size]))
    out: list[tuple[int, int, str]] = []
    count: dict[str, int] = {}
    for a, b in zip(bounds[:-1], bounds[1:], strict=True):
        kind = "start" if a == 0 else ("rising" if abs(u[a]) > abs(u[a - 1]) else "falling")
        out.append((int(a), int(b), kind))
        if u[a] != 0 and b - a >= 4 * MIN_ROWS:
            count[kind] = count.get(kind, 0) + 1
    return out, count


def split_repeated(
    found: list[Disturbance], u: FloatArray, settle: int = 0
) -> tuple[list[Disturbance], list[Disturbance], str]:
    """(local, repeated, kind): a departure that comes back after most edges of one kind
    (at least ``REPEAT_MIN`` of them and ``REPEAT_SHARE`` of that kind's driven stretches),
    or after two edges or more while the response to them has not settled (within
    ``settle`` rows of the edge), is what the model misses at those edges, not something
    that touched the wheel; the others stay disturbances. ``kind`` names the edges of the
    repeated ones ('' if none)."""
    stretches, count = edge_kinds(u)
    early = [
        d for d in found if d.start - next(a for a, b, _ in stretches if a <= d.start < b) < settle
    ]
    if len({next(a for a, b, _ in stretches if a <= d.start < b) for d in early}) < 2:
        early = []
    if len(found) < REPEAT_MIN and not early:
        return found, [], ""
    by_kind: dict[str, list[Disturbance]] = {}
    for d in found:
        for a, b, kind in stretches:
            if a <= d.start < b:
                by_kind.setdefault(kind, []).append(d)
                break

    def first_row(d: Disturbance) -> int:
        return next(a for a, b, _ in stretches if a <= d.start < b)

    repeated: list[Disturbance] = []
    kinds: list[str] = []
    for kind, ds in by_kind.items():
        spans = {first_row(d) for d in ds}
        if len(spans) >= REPEAT_MIN and len(spans) >= REPEAT_SHARE * count.get(kind, 0):
            repeated += ds
            kinds.append(kind)
    if early:
        repeated += [d for d in early if d not in repeated]
        for d in early:
            k = next(kind for a, b, kind in stretches if a <= d.start < b)
            if k not in kinds:
                kinds.append(k)
    if repeated:
        # the same miss after an edge of another kind, no later after its edge than the
        # repeated ones come after theirs, is that miss too
        reach = max(d.start - first_row(d) for d in repeated)
        more = [d for d in found if d not in repeated and d.start - first_row(d) <= 1.5 * reach + 2]
        if more:
            repeated += more
            kinds.append("other")
    local = [d for d in found if d not in repeated]
    return local, repeated, " and ".join(kinds)


LOCAL = 4.0
"""A disturbance departs from the model by at least this many times the model's error held
over ``LOCAL_ROWS`` rows elsewhere in the log (rms): a departure no larger than the model
misses by elsewhere is the model's miss, not something that touched the wheel."""

LOCAL_ROWS = 9
"""Rows the model's error elsewhere is averaged over (noise drops out, a miss stays)."""


def split_local(
    found: list[Disturbance], residual: FloatArray, keep: NDArray[np.bool_]
) -> tuple[list[Disturbance], list[Disturbance]]:
    """(local, not local): the disturbances that depart by more than ``LOCAL`` times the
    rms of the residual (measured - model, rad/s), averaged over ``LOCAL_ROWS`` rows, on
    the rows ``keep`` outside every disturbance; the others, where the model misses the
    rest of the log about as much."""
    if not found:
        return found, []
    k = np.asarray(keep, dtype=bool).copy()
    for d in found:
        k[d.fence_start : d.fence_end] = False
    if not np.any(k):
        return found, []
    r = np.where(k, residual, 0.0)
    n = np.convolve(k.astype(float), np.ones(LOCAL_ROWS), mode="same")
    m = np.convolve(r, np.ones(LOCAL_ROWS), mode="same") / np.maximum(n, 1.0)
    rest = float(np.sqrt(np.mean(m[k] ** 2)))
    local = [d for d in found if abs(d.size) > LOCAL * rest]
    return local, [d for d in found if d not in local]


def edges_of(found: list[Disturbance], u: FloatArray) -> list[int]:
    """The first rows of the stretches (after their edges) that hold the disturbances."""
    stretches, _ = edge_kinds(u)
    return sorted({next(a for a, b, _ in stretches if a <= d.start < b) for d in found})
