"""What a real log has that no cause explains: wild samples, creep, late steps, gaps.

Each is reported for what it is, never forced into a cause:

- a wild sample (a misread count): the whitened residual has one isolated spike (the
  angle is wrong at one sample and right again at the next); it is repaired in the
  measured speed before fitting, so it cannot decide the finding;
- a slow creep after the rise: in the settled part of the driven stretches the residual
  keeps growing, the same way in most of them;
- a step that starts between samples: the response to one edge is shifted in time
  against the others;
- gaps in the sample times (lost samples on a regular clock; an irregular loop's long
  intervals are jitter, not gaps: see :mod:`.sampling`), and a log that starts with the
  wheel turning;
- a disturbance (a hand on the wheel): found by :mod:`.disturbances`, worded here.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.fit import whiten

FloatArray = NDArray[np.float64]

SPIKE_SIGMAS = 8.0
"""A wild sample stands out of the whitened residual by this many robust sigmas..."""

SPIKE_ISOLATION = 3.0
"""...and is this many times larger than its neighbours there."""

LATE_SIGMAS = 5.0
"""A late step is out of line by this many times the timing error the angle quantum allows."""

LATE_SPREAD = 5.0
"""...and by this many times the spread of the other edges' own shifts (robust sigma)."""

LATE_FIT = 3.0
"""Shifted, the rows after a late step miss by at most this many times what the rows after
the other edges miss as they are (the median of their rms)."""

LATE_ABOVE_NOISE = 3.0
"""...the rows after it miss by at least this many times the noise as they are (rms against
the residual's row-to-row noise): a smaller miss is what the noise and the speed's estimator
leave at an edge (a speed from timed edges lags as the wheel slows), not a step's timing."""

LATE_SHARE = 0.4
"""...and the shift takes at least this share of their mean square away: a step that acted
late leaves the model right but for the timing, while a shift that trims a third of a miss
leaves the miss the model's (the weakest true late step found, model.synth seeds 11-18, has
49 %; a pole on the driver named as a delay, held-out 900003, 33 %)."""


def moving_rows(y: FloatArray) -> FloatArray:
    """Rows where the measured speed is not exactly 0 (bool array).

    Quantisation noise exists only where the encoder count changes; a wheel at rest reads
    exactly 0, and a noise scale taken over those rows too would be far too small (at a
    5 ms period a wheel at rest for half the log makes the median of |residual| zero).
    """
    out: FloatArray = np.asarray(y, dtype=float) != 0.0
    return out


@dataclass(frozen=True)
class StartsMoving:
    """The log starts with the wheel turning: ``u0`` the first input (V); ``fitted``: the
    initial speed was fitted (the first input is 0), else taken as the steady speed under
    ``u0``."""

    u0: float
    fitted: bool


@dataclass(frozen=True)
class WildSample:
    """A misread count: the row, its time and the jump (rad/s) are the anomaly's own."""


@dataclass(frozen=True)
class Creep:
    """A creep after the rise: its size (%, signed: + creeps up) is the anomaly's own;
    ``after``: how long after each step (s) the rows it is read over begin (where the model
    has settled: :data:`CREEP_SETTLE` of its time constants with its delay, and at least
    :data:`CREEP_MIN_ROWS` samples), to the step's end."""

    after: float = 0.0


CREEP_SETTLE: float = 5.0
"""A creep is read from this many time constants (with the delay) after each step..."""

CREEP_MIN_ROWS: int = 3
"""... and from at least this many samples after it."""


@dataclass(frozen=True)
class LateStep:
    """A step between samples: its row, time and shift (ms, signed) are the anomaly's own."""


@dataclass(frozen=True)
class Gaps:
    """Gaps in the sample times on a regular clock: how many, the nominal period (ms), and
    about how many samples were lost (the longest gap, ms, and the row after it are the
    anomaly's own)."""

    count: int
    nominal_ms: float
    lost: int


LeftOut = Literal["those", "span", "restarted"]
"""Which rows a disturbance left out of the fit: 'those' (the rows of the departure),
'span' (the departure and the wheel's way back until the model meets the speed again, from
``left_t0`` to ``left_t1``), 'restarted' (the departure until the hand let go, from where
the model picks up from the speed the wheel was left at)."""


@dataclass(frozen=True)
class Hand:
    """A disturbance: the model's speed there (rad/s; its change is the anomaly's size), the
    input it stays at (V), which rows were left out of the fit and from when to when (s)."""

    level: float
    u: float
    left: LeftOut
    left_t0: float = 0.0
    left_t1: float = 0.0


@dataclass(frozen=True)
class ModelMiss:
    """A departure that comes back edge after edge: the times of those edges (s), which
    edges (``edges``: the kinds as :func:`.disturbances.split_repeated` names them, or
    ``of_edges``: of how many edges in all), and what repeats: the speed departs the same
    way (``shifts_ms`` empty) or the response looks shifted in time by ``shifts_ms`` (ms,
    signed)."""

    times: tuple[float, ...]
    edges: str = ""
    of_edges: int = 0
    shifts_ms: tuple[float, ...] = ()


@dataclass(frozen=True)
class LoggingArtefact:
    """A spike right after a gap in the sample times: the row after the gap and its time
    (s), the gap (ms), and the first and last row left out of the fit."""

    at: int
    t_at: float
    gap_ms: float
    first: int
    last: int
    runs_on: bool = False
    """The speed column itself runs on across the gap: no row left out departs from the
    median of the three rows each side of them by more than those rows spread (under half
    the miss: a settled stretch), or a tenth of the miss. The rows across the gap were lost whole, each still over its own period,
    and only the simulation, which reads the gap as one long sample, expects a jump (a
    stall that reads the counts late makes the column itself jump)."""
    level: float = 0.0
    """That median, rad/s (0 when not read)."""


@dataclass(frozen=True)
class StartGlitch:
    """A switch-on glitch: how many rows, the time of the last one (s); its top speed is the
    anomaly's size."""

    rows: int
    t_last: float


@dataclass(frozen=True)
class AveragedGaps:
    """Rows left out after gaps in the sample times of an averaged speed: the average's
    length (samples); how many gaps and the first one's time are the anomaly's own."""

    taps: int


Facts = (
    StartsMoving
    | WildSample
    | Creep
    | LateStep
    | Gaps
    | Hand
    | ModelMiss
    | LoggingArtefact
    | StartGlitch
    | AveragedGaps
)
"""What the sentence of an anomaly needs beyond its kind, row, time and size; the sentence
is written outside the model (:mod:`minseg_tui.lab.views.check_says`)."""


@dataclass(frozen=True)
class Anomaly:
    """One thing the log shows that is not a model effect: kind, row (0-based, or None),
    time (s, or None), size (in ``unit``), what its sentence needs (``facts``), and where it
    ends (t_end, s; row_end, exclusive) for one that lasts (a disturbance), else None."""

    kind: str
    row: int | None
    t: float | None
    size: float
    unit: str
    facts: Facts
    t_end: float | None = None
    row_end: int | None = None

    def to_dict(self, text: str) -> dict[str, object]:
        """The anomaly's JSON, ``text`` its sentence."""
        return {
            "kind": self.kind,
            "row": self.row,
            "t": self.t,
            "t_end": self.t_end,
            "row_end": self.row_end,
            "size": self.size,
            "unit": self.unit,
            "text": text,
        }


def robust_sigma(x: FloatArray) -> float:
    """1.4826 times the median absolute deviation (a standard deviation that ignores outliers)."""
    if x.size == 0:
        return 0.0
    return float(1.4826 * np.median(np.abs(x - np.median(x))))


WILD_COUNTS = 3.0
"""A wild sample is off by more than this many counts of the encoder (when its resolution
is known): a count or two either way is quantisation, not a misread."""


def find_wild(
    residual: FloatArray,
    taps: int,
    most: int = 10,
    moving: FloatArray | None = None,
    count: float = 0.0,
) -> list[int]:
    """Rows where the measured angle is wild for one sample (isolated whitened spikes).

    With ``moving`` (bool per row, see :func:`moving_rows`) the noise scale is taken
    from the row-to-row changes where the wheel moves (default: e itself, every row).
    ``count``: the speed of one count per sample (rad/s; 0 when unknown): a spike must be
    ``WILD_COUNTS`` counts at least (quantised speeds have a robust sigma near 0). The
    largest spike is taken out first (its leaky tail with it), then the next, so a tail is
    never mistaken for a second wild sample.
    """
    r = np.asarray(residual, dtype=float).copy()
    e = whiten(r, taps)
    s = robust_sigma(e)
    if moving is not None:
        # the noise is local: row-to-row changes of e where the wheel moves (a slow model
        # error, as the baseline has on a log with an effect, cancels in the difference)
        both = np.asarray(moving, dtype=bool)
        both = both[1:] & both[:-1]
        if np.count_nonzero(both) >= 10:
            s = robust_sigma(np.diff(e)[both]) / np.sqrt(2.0)
    rows: list[int] = []
    if s <= 0:
        return rows
    while len(rows) < most:
        e = whiten(r, taps)
        order = np.argsort(-np.abs(e))
        hit = None
        for k in order[:20].tolist():
            if abs(e[k]) <= max(SPIKE_SIGMAS * s, WILD_COUNTS * count / taps):
                break
            nb = [abs(e[j]) for j in (k - 1, k + 1) if 0 <= j < e.size]
            if not nb or abs(e[k]) > SPIKE_ISOLATION * max(nb):
                hit = k
                break
        if hit is None:
            break
        rows.append(hit)
        r[hit] -= e[hit]
        if hit + taps < r.size:
            r[hit + taps] += e[hit]
    return sorted(rows)


def repair(y: FloatArray, residual: FloatArray, rows: list[int], taps: int) -> FloatArray:
    """The measured speed with wild angles taken out: at row m the angle is off by the
    whitened residual e_m, which moved the speed up at m and down at m + taps."""
    e = whiten(residual, taps)
    out = y.copy()
    for m in rows:
        out[m] -= e[m]
        if m + taps < out.size:
            out[m + taps] += e[m]
    return out


def wild_anomalies(
    t: FloatArray, y: FloatArray, residual: FloatArray, rows: list[int], taps: int
) -> list[Anomaly]:
    """The wild rows found, as anomalies."""
    e = whiten(residual, taps)
    out = []
    for m in rows:
        out.append(
            Anomaly(
                "wild_sample",
                m,
                float(t[m]),
                float(e[m]),
                "rad/s",
                WildSample(),
            )
        )
    return out


def creep(
    t: FloatArray, u: FloatArray, residual: FloatArray, pred: FloatArray, T: float, ts: float
) -> Anomaly | None:
    """A slow creep of the speed in the settled part of the driven stretches, if clear."""
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate(([0], change, [u.size]))
    settle = max(CREEP_MIN_ROWS, int(np.ceil(CREEP_SETTLE * T / ts)) + 1)
    slopes, rel, tstat = [], [], []
    noise = robust_sigma(np.diff(residual)) / np.sqrt(2.0)
    for a, b in zip(bounds[:-1], bounds[1:], strict=True):
        if u[a] == 0 or b - a - settle < 12:
            continue
        rows = np.arange(a + settle, b)
        tt = t[rows] - t[rows].mean()
        slope = float(np.dot(tt, residual[rows]) / np.dot(tt, tt))
        level = float(np.mean(np.abs(pred[rows])))
        if level <= 0:
            continue
        slopes.append(slope * np.sign(u[a]))
        rel.append(slope * np.sign(u[a]) * (t[rows[-1]] - t[rows[0]]) / level)
        tstat.append(abs(slope) * np.sqrt(np.dot(tt, tt)) / noise if noise > 0 else np.inf)
    if not slopes:
        return None
    s = np.asarray(slopes)
    r = np.asarray(rel)
    same = max(np.mean(s > 0), np.mean(s < 0))
    mean_rel = float(np.mean(r))
    if r.size >= 3:
        sure = abs(mean_rel) > 3 * float(np.std(r, ddof=1) / np.sqrt(r.size))
    else:
        sure = min(tstat) > 5.0
    if same >= 0.75 and abs(mean_rel) >= 0.02 and sure:
        return Anomaly(
            "creep",
            None,
            None,
            100 * mean_rel,
            "%",
            Creep(settle * ts),
        )
    return None


def late_steps(
    t: FloatArray,
    u: FloatArray,
    residual: FloatArray,
    d_shift: FloatArray,
    shift: float,
    ts: float,
    T: float = 0.0,
    pred: FloatArray | None = None,
    angle_noise: float = 0.0,
    keep: NDArray[np.bool_] | None = None,
    delay: float = 0.0,
) -> list[Anomaly]:
    """Edges whose response is shifted in time against the others (a step between samples).

    ``d_shift`` is the change of the prediction when every edge is ``shift`` s later; per
    edge the residual's projection on it estimates that edge's own shift. The projection
    spans the rise, 3 T (T: the model's time constant, s), and at least 6 rows (6 rows
    are only 30 ms at a 5 ms period).

    One edge cannot be timed better than the encoder's angle allows: an angle error of
    ``angle_noise`` (rad, the quantisation noise of the measured angle) over the speed
    change of the edge (from ``pred``, rad/s). At 25 ms a quarter period is far above
    that; at 5 ms (a 4.5 V step: about 1 ms per count against 1.25 ms) it is not, so an
    edge must be out of line by ``LATE_SIGMAS`` such timing errors as well.

    A shift must also explain the rows after the edge better than the model's miss the rows
    before it already had: along a ramp at a current cap's rate, a shift moves the prediction
    by the same amount on every row, as a speed off by a constant does, and a miss that runs
    on through the edge is the model's, not the step's. So the edge's shift is estimated a
    second time with the residual's mean over the rows before it (from the previous edge, at
    most as many as the projection spans; ``keep``: the rows the fit used, bool) taken off
    the rows after it, and both estimates must be out of line.

    And out of line against the other edges' shifts, not only against the noise: where the
    model misses the corners (a pole or a coast it lacks, an estimator's first reading after
    rest), every edge's estimate is off by the miss's projection, which varies from edge to
    edge, and the edges scatter far more widely than the noise allows. That scatter (the
    robust sigma of the other edges' estimates) is this model's timing error on this log, and
    a step that acted late must stand ``LATE_SPREAD`` of them out of it. Once shifted, its
    rows must also fit about as well as the rows after the other edges do as they are (at
    most ``LATE_FIT`` times their median rms): a step that acted late leaves the model right
    but for the timing, while a miss the shift only trims is the model's: the shift must take
    ``LATE_SHARE`` of the mean square of the rows after the edge away, and those rows must miss
    by ``LATE_ABOVE_NOISE`` times the noise at least.

    A step acts late, never early: a board stamps its row, then sends the command, so a step
    acts at its stamp or after (the usual lag, the same at every edge, is what the median
    takes away). An edge that looks early by more than a quarter period is a corner the model
    misses, unless the model itself has a dead time (``delay``, s), against which a step on
    time looks early by up to that delay.
    """
    edges = np.flatnonzero(np.diff(u) != 0) + 1
    if edges.size < 3:
        return []
    span = max(6, int(np.ceil(3.0 * T / ts))) if ts > 0 else 6
    used = np.ones(u.size, dtype=bool) if keep is None else np.asarray(keep, dtype=bool)
    est, carried, strength, resolution = [], [], [], []
    missed, left = [], []  # rms (rad/s) of the residual after each edge, as is and shifted
    for k, e in enumerate(edges.tolist()):
        rows = np.arange(e, min(e + span, u.size))
        jump = abs(float(pred[rows[-1]] - pred[e - 1])) if pred is not None else 0.0
        resolution.append(angle_noise / jump if jump > 0 else 0.0)
        den = float(np.dot(d_shift[rows], d_shift[rows]))
        if den <= 0:
            est.append(0.0)
            carried.append(0.0)
            strength.append(0.0)
            missed.append(0.0)
            left.append(0.0)
            continue
        before = np.arange(max(int(edges[k - 1]) if k else 0, e - span), e)
        before = before[used[before]]
        level = float(np.mean(residual[before])) if before.size else 0.0
        est.append(shift * float(np.dot(d_shift[rows], residual[rows])) / den)
        carried.append(shift * float(np.dot(d_shift[rows], residual[rows] - level)) / den)
        strength.append(np.sqrt(den))
        missed.append(float(np.sqrt(np.mean(residual[rows] ** 2))))
        shifted = residual[rows] - est[-1] / shift * d_shift[rows]
        left.append(float(np.sqrt(np.mean(shifted**2))))
    x = np.asarray(est)
    med = float(np.median(x))
    noise = robust_sigma(np.diff(residual)) / np.sqrt(2.0)
    timed = np.asarray(strength) > 0

    def spread(k: int) -> float:
        """The robust sigma (s) of the timed edges' shifts but edge k's."""
        others = x[timed & (np.arange(x.size) != k)]
        if others.size < 2:
            return 0.0
        return 1.4826 * float(np.median(np.abs(others - np.median(others))))

    def elsewhere(k: int) -> float:
        """The median rms (rad/s) of the residual after the timed edges but edge k."""
        others = np.asarray(missed)[timed & (np.arange(x.size) != k)]
        return float(np.median(others)) if others.size else np.inf

    out = []
    for k, (e, dx, dc, st, res_t) in enumerate(
        zip(edges.tolist(), x.tolist(), carried, strength, resolution, strict=True)
    ):
        off = dx - med
        # the shift must be a good part of a sample, well above what the noise allows and
        # well above the timing the angle quantum allows for this edge; and at most a
        # sample: a step between samples acts within one period of its sample time, and a
        # larger figure is the linear estimate outside its range (an edge that is no step,
        # such as noise on u), which says nothing of when the step acted; and so must the
        # shift left once the miss the rows before the edge had is taken off; and the shift
        # must stand out of the other edges' scatter
        if (
            abs(off) > LATE_SPREAD * spread(k)
            and left[k] <= LATE_FIT * elsewhere(k)
            and off >= -delay
            and missed[k] >= LATE_ABOVE_NOISE * noise
            and left[k] ** 2 <= (1.0 - LATE_SHARE) * missed[k] ** 2
            and all(
                max(0.25 * ts, LATE_SIGMAS * res_t) < abs(o) <= ts
                and abs(o) / shift * st > 6 * noise
                for o in (off, dc - med)
            )
        ):
            out.append(
                Anomaly(
                    "late_step",
                    int(e),
                    float(t[e]),
                    1e3 * off,
                    "ms",
                    LateStep(),
                )
            )
    return out


def gaps(t: FloatArray, ts: float, regular: bool = True) -> Anomaly | None:
    """Sample intervals longer than 1.5 nominal periods on a regular clock (lost samples),
    if any; an irregular loop (``regular`` False) has jitter, not gaps."""
    dt = np.diff(t)
    bad = np.flatnonzero(dt > 1.5 * ts)
    if bad.size == 0 or not regular:
        return None
    k = int(bad[np.argmax(dt[bad])])
    lost = int(np.sum(np.round(dt[bad] / ts) - 1))
    return Anomaly(
        "gap",
        k + 1,
        float(t[k + 1]),
        float(1e3 * dt[k]),
        "ms",
        Gaps(int(bad.size), 1e3 * ts, lost),
    )


def disturbance(
    t: FloatArray,
    u: FloatArray,
    start: int,
    end: int,
    size: float,
    level: float,
    left: tuple[int, int] | None = None,
    restarted: bool = False,
) -> Anomaly:
    """A disturbance over rows start..end (exclusive): ``size`` the largest
    change of speed (rad/s, measured - model) against the model's ``level`` there; ``left``:
    the rows left out of the fit (first, end exclusive) when more than start..end (the
    departure's onset before it, the wheel's way back to the model after it);
    ``restarted``: the rows left out end where the hand let go, and from there the model
    picks up from the speed the wheel was left at (the way back stays in the fit)."""
    # the sentence says the input stays put: it ends at the next step at the latest (through
    # an average the departure runs on past it, in the rows left out)
    step = np.flatnonzero(u[start + 1 :] != u[start])
    end = min(end, start + 1 + int(step[0])) if step.size else end
    t1 = float(t[min(end, t.size - 1)]) if end < t.size else float(t[-1])
    if restarted and left is not None:
        a, b = left
        facts = Hand(level, float(u[start]), "restarted", float(t[a]), float(t[min(b, t.size) - 1]))
    elif left is None or left == (start, end):
        facts = Hand(level, float(u[start]), "those")
    else:
        a, b = left
        facts = Hand(level, float(u[start]), "span", float(t[a]), float(t[min(b, t.size) - 1]))
    return Anomaly(
        "disturbance",
        int(start),
        float(t[start]),
        float(size),
        "rad/s",
        facts,
        t_end=t1,
        row_end=int(end),
    )


def repeated_miss(
    t: FloatArray,
    starts: list[int],
    edges: str = "",
    of_edges: int = 0,
    shifts_ms: tuple[float, ...] = (),
) -> Anomaly:
    """Departures that come back edge after edge (``starts``: the rows of those edges;
    ``edges``: 'rising', 'falling' or both, or ``of_edges``: of how many edges in all;
    ``shifts_ms``: the response looks shifted by these (ms), else the speed departs the same
    way): the model misses something at those edges; it is not a disturbance."""
    return Anomaly(
        "model_miss",
        int(starts[0]),
        float(t[starts[0]]),
        float(len(starts)),
        "edges",
        ModelMiss(tuple(float(t[s]) for s in starts), edges, of_edges, shifts_ms),
    )


def gap_rows(t: FloatArray, ts: float) -> set[int]:
    """Rows right after a sample interval longer than 1.5 nominal periods, and the row after
    each (where a read that lagged its timestamp is caught up)."""
    return {r for a in gap_starts(t, ts) for r in (a, a + 1) if r < t.size}


def gap_starts(t: FloatArray, ts: float) -> list[int]:
    """Rows right after a sample interval longer than 1.5 nominal periods."""
    return [int(a) for a in (np.flatnonzero(np.diff(t) > 1.5 * ts) + 1).tolist()]


def logging_artefact(
    t: FloatArray,
    row: int,
    end: int,
    size: float,
    at: int | None = None,
    left: tuple[int, int] | None = None,
    y: FloatArray | None = None,
) -> Anomaly:
    """A spike right after a gap in the sample times (``at``: the row after
    the gap, default ``row``), with rows row..end (exclusive) left out of the fit (or the
    rows ``left``, first and end exclusive, when given): the logger's clock and its encoder
    read disagree there, the wheel did not move so."""
    at = row if at is None else at
    gap = float(t[at] - t[at - 1]) if at > 0 else 0.0
    a, b = (row, end) if left is None else left
    runs_on, level = False, 0.0
    if y is not None and b > a:
        near = np.concatenate((y[max(a - 3, 0) : a], y[b : b + 3]))
        if near.size >= 2:
            level = float(np.median(near))
            dev = float(np.max(np.abs(y[a:b] - level)))
            spread = float(np.max(near) - np.min(near))
            # in a settled stretch only: while the speed changes (a gap on a rise) the rows
            # around spread wide and show no level to run on at
            runs_on = spread <= 0.5 * abs(size) and dev <= max(spread, 0.1 * abs(size))
    return Anomaly(
        "logging_artefact",
        int(row),
        float(t[row]),
        float(size),
        "rad/s",
        LoggingArtefact(int(at), float(t[at]), 1e3 * gap, int(a), int(b - 1), runs_on, level),
        t_end=float(t[min(end, t.size - 1)]),
        row_end=int(end),
    )


def start_glitch(u: FloatArray, y: FloatArray) -> int:
    """How many rows at the very start (1-3) are a switch-on glitch: fast against the log's
    top speed, then the speed falls by more than three quarters in one sample with the input
    unchanged (no motor slows so in one sample when it turns that fast by itself); 0 if none."""
    top = float(np.max(np.abs(y))) if y.size else 0.0
    if top <= 0 or y.size < 8:
        return 0
    fast = [k for k in range(min(4, y.size)) if abs(y[k]) > 0.2 * top]
    if not fast:
        return 0
    last = max(fast)
    nxt = last + 1
    if last > 2 or np.any(u[: nxt + 1] != u[0]):
        return 0
    small = min(abs(float(y[k])) for k in fast)
    if (
        abs(float(y[nxt])) <= 0.25 * small
        and float(np.max(np.abs(y[nxt : nxt + 4]))) <= 0.25 * small
    ):
        return nxt
    return 0


def glitch_anomaly(t: FloatArray, y: FloatArray, rows: int) -> Anomaly:
    """``rows`` switch-on glitch rows at the start."""
    top = float(np.max(np.abs(y[:rows])))
    return Anomaly(
        "start_glitch",
        0,
        float(t[0]),
        top,
        "rad/s",
        StartGlitch(int(rows), float(t[rows - 1])),
        t_end=float(t[rows]),
        row_end=int(rows),
    )


def averaged_gaps(t: FloatArray, starts: list[int], taps: int) -> Anomaly:
    """The rows left out after gaps in the sample times of an averaged
    speed (``starts``: the rows right after each gap; ``taps``: the average's length)."""
    first = starts[0]
    return Anomaly(
        "gap_rows_left_out",
        int(first),
        float(t[first]),
        float(len(starts)),
        "gaps",
        AveragedGaps(int(taps)),
        row_end=int(min(first + taps + 1, t.size)),
    )
