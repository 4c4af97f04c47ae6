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


def moving_rows(y: FloatArray) -> FloatArray:
    """Rows where the measured speed is not exactly 0 (bool array).

    Quantisation noise exists only where the encoder count changes; a wheel at rest reads
    exactly 0, and a noise scale taken over those rows too would be far too small (at a
    5 ms period a wheel at rest for half the log makes the median of |residual| zero).
    """
    out: FloatArray = np.asarray(y, dtype=float) != 0.0
    return out


@dataclass(frozen=True)
class Anomaly:
    """One thing the log shows that is not a model effect: kind, row (0-based, or None),
    time (s, or None), size (in ``unit``), a sentence for a student, and where it ends
    (t_end, s; row_end, exclusive) for one that lasts (a disturbance), else None."""

    kind: str
    row: int | None
    t: float | None
    size: float
    unit: str
    text: str
    t_end: float | None = None
    row_end: int | None = None

    def to_dict(self) -> dict[str, object]:
        return {
            "kind": self.kind,
            "row": self.row,
            "t": self.t,
            "t_end": self.t_end,
            "row_end": self.row_end,
            "size": self.size,
            "unit": self.unit,
            "text": self.text,
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
    """Sentences for the wild rows found."""
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
                f"row {m} (t = {t[m]:.3f} s): the speed jumps by {e[m]:+.2f} rad/s for one sample "
                "and straight back, as a misread encoder count does; it was left out of the fit",
            )
        )
    return out


def creep(
    t: FloatArray, u: FloatArray, residual: FloatArray, pred: FloatArray, T: float, ts: float
) -> Anomaly | None:
    """A slow creep of the speed in the settled part of the driven stretches, if clear."""
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate(([0], change, [u.size]))
    settle = max(3, int(np.ceil(5 * T / ts)) + 1)
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
        word = "creeps up" if mean_rel > 0 else "sags"
        return Anomaly(
            "creep",
            None,
            None,
            100 * mean_rel,
            "%",
            f"after each step has settled the speed still {word} by about {abs(100 * mean_rel):.1f} % "
            "over the rest of the step (warming up, a battery or a load that changes); "
            "no first-order model does that, so it is not counted as a cause",
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
    """
    edges = np.flatnonzero(np.diff(u) != 0) + 1
    if edges.size < 3:
        return []
    span = max(6, int(np.ceil(3.0 * T / ts))) if ts > 0 else 6
    est, strength, resolution = [], [], []
    for e in edges.tolist():
        rows = np.arange(e, min(e + span, u.size))
        jump = abs(float(pred[rows[-1]] - pred[e - 1])) if pred is not None else 0.0
        resolution.append(angle_noise / jump if jump > 0 else 0.0)
        den = float(np.dot(d_shift[rows], d_shift[rows]))
        if den <= 0:
            est.append(0.0)
            strength.append(0.0)
            continue
        est.append(shift * float(np.dot(d_shift[rows], residual[rows])) / den)
        strength.append(np.sqrt(den))
    x = np.asarray(est)
    med = float(np.median(x))
    noise = robust_sigma(np.diff(residual)) / np.sqrt(2.0)
    out = []
    for e, dx, st, res_t in zip(edges.tolist(), x.tolist(), strength, resolution, strict=True):
        off = dx - med
        # the shift must be a good part of a sample, well above what the noise allows and
        # well above the timing the angle quantum allows for this edge; and at most a
        # sample: a step between samples acts within one period of its sample time, and a
        # larger figure is the linear estimate outside its range (an edge that is no step,
        # such as noise on u), which says nothing of when the step acted
        if (
            max(0.25 * ts, LATE_SIGMAS * res_t) < abs(off) <= ts
            and abs(off) / shift * st > 6 * noise
        ):
            out.append(
                Anomaly(
                    "late_step",
                    int(e),
                    float(t[e]),
                    1e3 * off,
                    "ms",
                    f"the step at row {e} (t = {t[e]:.3f} s) acts about {1e3 * off:+.0f} ms "
                    "from its sample time compared with the others: it started between samples",
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
        f"{bad.size} gap(s) in the sample times, the longest {1e3 * dt[k]:.0f} ms before row {k + 1} "
        f"(nominal {1e3 * ts:.1f} ms, the clock otherwise regular): about {lost} sample(s) were "
        "lost; the simulation uses the real times",
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
    """The sentence for a disturbance over rows start..end (exclusive): ``size`` the largest
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
    word = "drops" if size * np.sign(level or 1.0) < 0 else "rises"
    share = f" ({100 * abs(size / level):.0f} %)" if level else ""
    if restarted and left is not None:
        a, b = left
        out = (
            f"the rows from t = {t[a]:.3f} s to {t[min(b, t.size) - 1]:.3f} s (the departure "
            "until the hand let go) were left out of the fit; from there the model picks up "
            "from the speed the wheel was left at, so its way back stays in the fit"
        )
    elif left is None or left == (start, end):
        out = "those rows were left out of the fit"
    else:
        a, b = left
        out = (
            f"the rows from t = {t[a]:.3f} s to {t[min(b, t.size) - 1]:.3f} s (the departure, "
            "and the wheel's way back until the model meets the speed again) were left out of "
            "the fit"
        )
    return Anomaly(
        "disturbance",
        int(start),
        float(t[start]),
        float(size),
        "rad/s",
        f"from t = {t[start]:.3f} s to {t1:.3f} s the speed {word} by {abs(size):.3g} rad/s{share} "
        f"while the input stays at {u[start]:g} V, and comes back: something other than the "
        f"input moved the wheel (a hand on it, a snag); {out}",
        t_end=t1,
        row_end=int(end),
    )


def repeated_miss(t: FloatArray, starts: list[int], edges: str, what: str) -> Anomaly:
    """One sentence for departures that come back edge after edge (``starts``: the rows of
    those edges; ``edges``: 'rising', 'falling' or both; ``what``: what repeats, in words):
    the model misses something at those edges; it is not a disturbance."""
    times = ", ".join(f"{t[s]:.2f}" for s in starts[:6]) + (" ..." if len(starts) > 6 else "")
    return Anomaly(
        "model_miss",
        int(starts[0]),
        float(t[starts[0]]),
        float(len(starts)),
        "edges",
        f"{what} after {len(starts)} {edges} edges (t = {times} s): a departure that comes back "
        "edge after edge is what the model misses there, not a hand on the wheel; those rows "
        "stay in the fit",
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
) -> Anomaly:
    """The sentence for a spike right after a gap in the sample times (``at``: the row after
    the gap, default ``row``), with rows row..end (exclusive) left out of the fit (or the
    rows ``left``, first and end exclusive, when given): the logger's clock and its encoder
    read disagree there, the wheel did not move so."""
    at = row if at is None else at
    gap = float(t[at] - t[at - 1]) if at > 0 else 0.0
    a, b = (row, end) if left is None else left
    out = f"row {a}" if b - a <= 1 else f"rows {a}-{b - 1}"
    return Anomaly(
        "logging_artefact",
        int(row),
        float(t[row]),
        float(size),
        "rad/s",
        f"row {at} (t = {t[at]:.3f} s), right after a gap of {1e3 * gap:.0f} ms in the sample "
        f"times: the speed jumps by {size:+.3g} rad/s and straight back, as when the logger stalls "
        "and reads the encoder and its clock at different moments (a logging artefact, not the "
        f"wheel); {out} left out of the fit",
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
    """The sentence for ``rows`` switch-on glitch rows at the start."""
    top = float(np.max(np.abs(y[:rows])))
    return Anomaly(
        "start_glitch",
        0,
        float(t[0]),
        top,
        "rad/s",
        f"the first {rows} row(s) (to t = {t[rows - 1]:.3f} s) read up to {top:.3g} rad/s and the "
        "next one close to 0 with the input unchanged: a glitch as the logger starts, not the "
        "wheel; left out of the fit",
        t_end=float(t[rows]),
        row_end=int(rows),
    )


def averaged_gaps(t: FloatArray, starts: list[int], taps: int) -> Anomaly:
    """The sentence for the rows left out after gaps in the sample times of an averaged
    speed (``starts``: the rows right after each gap; ``taps``: the average's length)."""
    first = starts[0]
    return Anomaly(
        "gap_rows_left_out",
        int(first),
        float(t[first]),
        float(len(starts)),
        "gaps",
        "the speed is averaged over several samples, so a read the logger got wrong across a "
        f"gap in the sample times stays in it for as many rows: the {taps + 1} rows after each "
        f"of the {len(starts)} gap(s) (the first at t = {t[first]:.3f} s) were left out of the fit",
        row_end=int(min(first + taps + 1, t.size)),
    )
