"""The sample times and the speed column as the log took them.

- How a row's speed was computed: the angle change over the row's real interval divided
  by that interval, or by the nominal period (a board that divides by its nominal Ts).
  The log's header may say (``# omega_over: interval`` / ``nominal``); otherwise it is
  detected: counts make the speed (times the divisor) lie on a lattice of one count, and a
  speed divided by the nominal period rises and falls with the interval.
- A coarse clock: stamps in whole ticks (an Arduino's millis(): intervals of 10 or 11 ms)
  and a speed over the nominal period whose rows stamped after a longer interval read no
  faster than their neighbours, so the count was not taken over the stamped interval; such
  rows are simulated as the mean speed over their interval, not as the angle over it divided
  by the nominal period (10 % fast).
- Jitter or lost samples: a regular clock with a few intervals near 2 Ts, 3 Ts, ... lost
  samples; intervals spread widely around Ts are an irregular loop (jitter), nothing lost.
- The speed's resolution, one count per nominal period (2 pi/cpr/ts, rad/s), from ``# cpr:``
  or from the lattice; its noise floor is resolution/sqrt 6 (two uniform roundings), and
  the angle's q/sqrt 12.
- Whether the speed looks like counts at all (rough from sample to sample) or is smooth (a
  tachometer or a filtered signal): then the noise cannot tell an averaging filter from an
  extra pole.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

EVEN = 0.02
"""Intervals within this share of the nominal period count as even."""

REGULAR = 0.05
"""A clock whose intervals spread less than this share (robust sd) is regular."""

COARSE_ROWS = 10
"""Settled rows after an uneven interval needed to tell whether a longer interval lengthens
the count (:func:`_lengthens`); with fewer the timestamps are taken at their word."""

COARSE_SHARE = 0.5
"""A speed over the nominal period whose uneven rows read less than this share of their
interval's excess (0: as their neighbours, 1: 10 % faster after an 11 ms interval of 10 ms)
was counted over about the nominal period: the clock is coarse."""


class CountFrom(Enum):
    """Where the speed's resolution (one count per nominal period) came from: the header's
    ``# cpr:`` line, the lattice that each speed times its own interval lies on (one count in
    rad), the lattice that the speeds themselves lie on, or nowhere (unknown). Worded in
    :func:`minseg_tui.lab.views.check_says.resolution_how`."""

    CPR = "cpr"
    INTERVAL_LATTICE = "interval_lattice"
    SPEED_LATTICE = "speed_lattice"
    UNKNOWN = "unknown"


@dataclass(frozen=True)
class Sampling:
    """How the log was sampled (see the module docstring). Times in s, speeds in rad/s.

    ts: nominal period; over_interval: a row's speed is over its real interval; how: where
    that came from ('header', 'detected', 'even': the intervals are even, both agree);
    interval_min/max: shortest and longest interval; jitter: robust sd of the intervals;
    regular: the clock is regular (so long intervals are lost samples); lost: samples
    lost; gap_row: the row after the longest gap (None without); resolution: one count per
    nominal period (None: unknown); count_from: where it came from (:class:`CountFrom`), with
    the header's ``cpr`` (counts per revolution, None unless it came from there); smooth: the
    speed is smooth from sample to sample (not a difference of counts).
    """

    ts: float
    over_interval: bool
    how: str
    interval_min: float
    interval_max: float
    jitter: float
    regular: bool
    lost: int
    gap_row: int | None
    resolution: float | None
    count_from: CountFrom
    cpr: int | None
    smooth: bool
    uneven: int = 0
    """How many rows follow an interval away from the nominal one (beyond ``EVEN``): what a
    detection of the speed's period has to go on."""
    coarse: float | None = None
    """A coarse clock (None: not one): the speed is over the nominal period, and its rows
    stamped after an uneven interval read only this share of the interval's excess against
    their neighbours (see :func:`_lengthens`), so the count was not taken over the stamped
    interval. The model check then simulates each row as the mean speed over its interval."""

    @property
    def simulated_over_interval(self) -> bool:
        """The simulation reads a row as the angle over its interval divided by that
        interval (a speed over the real interval, or over the nominal period on a coarse
        clock), not by the nominal period."""
        return self.over_interval or self.coarse is not None

    @property
    def floor(self) -> float | None:
        """Noise floor of the Euler speed from counts, rad/s: resolution / sqrt 6."""
        return None if self.resolution is None else self.resolution / math.sqrt(6.0)

    def column_floor(self, taps: int) -> float | None:
        """Noise floor (rad/s) of the speed column when it is an average over ``taps``
        samples: the count floor over taps with the resolution from ``# cpr:``; the floor
        itself with a resolution read off the column's lattice (which an average already
        divides)."""
        if self.floor is None:
            return None
        return self.floor / taps if self.count_from is CountFrom.CPR else self.floor

    @property
    def angle_floor(self) -> float | None:
        """Noise of the angle itself, rad: one count / sqrt 12."""
        return None if self.resolution is None else self.resolution * self.ts / math.sqrt(12.0)

    def to_dict(self, text: str, resolution_how: str) -> dict[str, object]:
        """How the log was sampled as JSON, ``text`` in words and ``resolution_how``: where
        the resolution came from, in words."""
        return {
            "ts": self.ts,
            "omega_over": "interval" if self.over_interval else "nominal",
            "how": self.how,
            "interval_min": self.interval_min,
            "interval_max": self.interval_max,
            "jitter": self.jitter,
            "regular": self.regular,
            "lost_samples": self.lost,
            "resolution": self.resolution,
            "resolution_how": resolution_how,
            "noise_floor": self.floor,
            "smooth": self.smooth,
            "text": text,
        }


def _on(v: FloatArray, q: float) -> float:
    """Share of the nonzero values v within 2 % of a multiple of q."""
    nz = np.abs(v[v != 0])
    if nz.size == 0:
        return 0.0
    k = nz / q
    return float(np.mean(np.abs(k - np.round(k)) < 0.02))


def _lattice(v: FloatArray) -> float | None:
    """The step q of a lattice that the nonzero values v lie on (within 2 %), if any."""
    nz = np.abs(v[v != 0])
    if nz.size < 10:
        return None
    q0 = float(np.min(nz))
    for div in (1, 2, 3, 4):
        q = q0 / div
        if _on(nz, q) >= 0.95 and float(np.max(nz / q)) < 5e4:
            return q
    return None


def _smooth(y: FloatArray, u: FloatArray) -> bool:
    """True when the speed is smooth from row to row where the input is constant: the
    deviation from a running mean of 5 rows correlates strongly with itself one row on."""
    n = y.size
    if n < 20:
        return False
    m = np.convolve(y, np.ones(5) / 5.0, mode="same")
    d = y - m
    same = np.ones(n, dtype=bool)
    change = np.flatnonzero(np.diff(u) != 0) + 1
    for e in change.tolist():
        same[max(e - 3, 0) : e + 6] = False
    same[:3] = same[-3:] = False
    a, b = d[:-1][same[:-1] & same[1:]], d[1:][same[:-1] & same[1:]]
    if a.size < 10 or float(np.dot(a, a)) == 0.0:
        return float(np.ptp(d[same])) == 0.0 if np.any(same) else False
    return float(np.dot(a, b) / math.sqrt(float(np.dot(a, a)) * float(np.dot(b, b)))) > 0.5


def sampling(
    t: FloatArray,
    u: FloatArray,
    y: FloatArray,
    ts: float,
    cpr: int | None = None,
    omega_over: str | None = None,
) -> Sampling:
    """How the log (t s, u V, y rad/s) was sampled; ``ts`` its nominal period (s), ``cpr``
    and ``omega_over`` ('interval' or 'nominal') from its header when it says."""
    dt = np.diff(t)
    rel = dt / ts
    even = bool(np.all(np.abs(rel - 1.0) < EVEN))
    jitter = float(1.4826 * np.median(np.abs(dt - np.median(dt)))) if dt.size else 0.0
    regular = jitter < REGULAR * ts
    long = np.flatnonzero(rel > 1.5)
    lost = int(np.sum(np.round(rel[long]) - 1)) if regular and long.size else 0
    gap_row = int(long[np.argmax(dt[long])]) + 1 if regular and long.size else None
    # over which time the speed of a row was taken
    prev = np.concatenate(([ts], dt))
    lat_nom = _lattice(y * ts)
    lat_int = _lattice(y * prev) if not even else lat_nom
    uneven = np.abs(prev / ts - 1.0) > EVEN
    share_nom = _on((y * ts)[uneven], lat_nom) if lat_nom else 0.0
    share_int = _on((y * prev)[uneven], lat_int) if lat_int else 0.0
    if omega_over in ("interval", "nominal"):
        over, how = omega_over == "interval", "header"
    elif even:
        over, how = False, "even"
    elif max(share_nom, share_int) >= 0.9 and min(share_nom, share_int) < 0.6:
        over, how = share_int > share_nom, "detected"
    else:
        over, how = _divides_by_interval(y, rel, u), "detected"
    q = lat_int if over else lat_nom
    resolution: float | None
    if cpr is not None and cpr > 0:
        resolution, count_from = 2.0 * math.pi / cpr / ts, CountFrom.CPR
    elif q is not None and over and not even:
        resolution, count_from = q / ts, CountFrom.INTERVAL_LATTICE
    elif q is not None:
        resolution, count_from = q / ts, CountFrom.SPEED_LATTICE
    else:
        resolution, count_from = None, CountFrom.UNKNOWN
    smooth = resolution is None and _smooth(y, u)
    coarse = None
    if not over and not even and regular and _ticks(dt[rel < 1.5]):
        share, rows = _lengthens(y, rel, u)
        if rows >= COARSE_ROWS and share < COARSE_SHARE:
            coarse = share
    return Sampling(
        ts=ts,
        over_interval=over,
        how=how,
        interval_min=float(np.min(dt)) if dt.size else ts,
        interval_max=float(np.max(dt)) if dt.size else ts,
        jitter=jitter,
        regular=regular,
        lost=lost,
        gap_row=gap_row,
        resolution=resolution,
        count_from=count_from,
        cpr=cpr if count_from is CountFrom.CPR else None,
        smooth=smooth,
        uneven=int(np.count_nonzero(uneven)),
        coarse=coarse,
    )


COARSE_TICKS = 3
"""A coarse clock's intervals (gaps aside) take at most this many values, to a microsecond:
a clock that counts whole ticks (10 or 11 ms), not a loop whose lateness spreads freely."""


def _ticks(dt: FloatArray) -> bool:
    """The intervals ``dt`` (s) take a few values only (:data:`COARSE_TICKS`)."""
    return 1 < np.unique(np.round(dt, 6)).size <= COARSE_TICKS


def _lengthens(y: FloatArray, rel: FloatArray, u: FloatArray) -> tuple[float, int]:
    """How much a longer interval lengthens a row's speed, and on how many rows that was
    read: over the rows after an uneven interval (beyond ``EVEN``) where the input has not
    changed for 3 rows either side and the wheel turns (the mean of those six neighbours over
    a fifth of the top speed), the least-squares b in y_k = level_k (1 + b x_k), x_k the
    interval's excess over the nominal period (share) and level_k the neighbours' mean. A
    speed of counts over the stamped interval divided by the nominal period gives b = 1; a
    count over about the nominal period, whatever the stamp, b = 0. (Means, not medians: the
    median of a few quantised counts is biased by a count.)"""
    n = y.size
    if n < 8:
        return 0.0, 0
    x = np.concatenate(([0.0], rel - 1.0))
    k = np.arange(3, n - 3)
    level = np.mean(np.stack([y[k + j] for j in (-3, -2, -1, 1, 2, 3)]), axis=0)
    same = np.array([bool(np.all(u[i - 3 : i + 4] == u[i])) for i in k.tolist()], dtype=bool)
    top = float(np.max(np.abs(y))) or 1.0
    ok = same & (np.abs(level) > 0.2 * top) & (np.abs(x[k]) > EVEN)
    xx, yy, ll = x[k][ok], y[k][ok], level[ok]
    den = float(np.dot(xx * xx, ll * ll))
    if den <= 0.0:
        return 0.0, 0
    return float(np.dot(xx * ll, yy - ll)) / den, int(np.count_nonzero(ok))


def _divides_by_interval(y: FloatArray, rel: FloatArray, u: FloatArray) -> bool:
    """True when a row's speed does not follow its interval: the speed relative to its
    neighbours' median is regressed on the interval relative to the nominal (slope near 1:
    the angle change was divided by the nominal period)."""
    n = y.size
    x = np.concatenate(([0.0], rel - 1.0))
    k = np.arange(3, n - 3)
    win = np.stack([y[k + j] for j in (-3, -2, -1, 1, 2, 3)])
    level = np.median(win, axis=0)
    same = np.array([u[i - 3] == u[i + 3] for i in k.tolist()], dtype=bool)
    top = float(np.max(np.abs(y))) or 1.0
    ok = same & (np.abs(level) > 0.2 * top)
    if np.count_nonzero(ok) < 10:
        return True
    r = y[k][ok] / level[ok] - 1.0
    xx = x[k][ok]
    den = float(np.dot(xx, xx))
    if den == 0.0:
        return True
    return float(np.dot(xx, r) / den) < 0.5


def scatter(
    y: FloatArray, u: FloatArray, settle: int, moving: NDArray[np.bool_], keep: float = 0.98
) -> float:
    """The noise (rad/s) of a speed or a residual ``y``: the rms of its departure from a
    centred mean over ``SMOOTH`` rows (times sqrt(m/(m-1)), exact for white noise), in the
    settled part of the constant-input stretches (``settle`` rows after a step) where the
    wheel moves (``moving``: a wheel at rest reads exactly 0, without noise); only the
    smallest share ``keep`` counts. A slow model error drops out with the mean; an average over N samples of
    counts shows the floor over N."""
    n = y.size
    m = SMOOTH
    ok = np.ones(n, dtype=bool)
    for e in (np.flatnonzero(np.diff(u) != 0) + 1).tolist():
        ok[max(e - m // 2, 0) : e + settle] = False
    ok[: m // 2] = ok[n - m // 2 :] = False
    turning = np.asarray(moving, dtype=bool)
    mv = ok & turning
    if np.count_nonzero(mv) >= 10:
        ok = mv
    elif np.count_nonzero(turning) >= 10:
        # the wheel stands still wherever the steps have settled (short stretches, a long
        # average, a stop): the rows where it turns, unsettled or not, hold the noise
        ok = turning.copy()
        ok[: m // 2] = ok[n - m // 2 :] = False
    if np.count_nonzero(ok) < 10:
        ok = np.ones(n, dtype=bool)
    d = (y - np.convolve(y, np.ones(m) / m, mode="same"))[ok]
    d2 = np.sort(d * d)[: max(1, int(math.ceil(keep * d.size)))]
    return float(math.sqrt(float(np.mean(d2)) * m / (m - 1)))


SMOOTH = 9
"""Rows of the centred mean that :func:`scatter` takes the noise against."""
