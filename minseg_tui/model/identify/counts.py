"""The encoder's count (rad) read off the angle values of a log, when they are whole counts.

T's interval on a single step adds the spread the counts' rounding alone gives T
(:func:`.lsq.rounding_errors`), which needs the count. A log's angle is whole counts when it
comes from a count column or an Euler speed of counts; a theta column written to a few
significant digits sits on the count's grid only to within what those digits keep, and an
encoder whose counts per revolution are not a whole number (12 counts read X4 behind a
29.861:1 gear: 358.33) cannot say so in the ``# cpr:`` header, which takes whole numbers.

So the grid is looked for in the values themselves, each allowed the error its written digits
leave (:func:`written_error`), first the header's count (or the default), then the step the
values themselves show. A grid is only said to be there when chance cannot explain the values
sitting on it (:data:`CHANCE`): values on no grid (an angle interpolated between counts onto
other instants, a speed integrated) or too few of them to tell give None.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

CHANCE: float = 1e-6
"""A grid is taken only when values spread at random would sit on it, each within its
allowance, with at most this probability (the product over the distinct values that can tell)."""

TELLS: float = 0.1
"""A value tells whether it sits on a grid of step q only when its allowance is at most this
share of q (a value written to too few digits fits any fine grid)."""

SURE_GAP: float = 0.01
"""The gap between two values the step is counted from is taken, where the log has one, among
those whose values' allowances make it uncertain by at most this share."""

SUBSTEPS: int = 6
"""The smallest step between the values is tried as 1 to this many counts."""

_MAX_DIGITS: int = 17
"""float64 keeps 15-17 significant digits: a value needing more was written in full."""

_FORMAT_SAMPLE: int = 4096
"""How many of the values (evenly spread) the format of a column is judged from."""


def written_error(x: FloatArray) -> FloatArray:
    """The most by which each value of ``x`` can differ from the number it was written from,
    judged from the digits the column was written with: half a unit in the last place of the
    format, %g-like (as many significant digits as the most any value shows) or %f-like (as
    many decimals as the most any value shows), whichever allows more; values written in full
    (as many digits as float64 keeps) get a few units of float64's last place."""
    x = np.asarray(x, dtype=float)
    a = np.abs(x)
    nonzero = a > 0
    tiny = 4.0 * np.finfo(float).eps * a
    mag = np.floor(np.log10(np.where(nonzero, a, 1.0)))
    # the format, from up to _FORMAT_SAMPLE of the values, evenly spread: the fewest decimals
    # (negative: zeros before the point) that give each back
    some = np.flatnonzero(nonzero)
    some = some[:: max(1, some.size // _FORMAT_SAMPLE)]
    xs = x[some]
    decimals = np.full(xs.shape, _MAX_DIGITS + 8)
    for k in range(_MAX_DIGITS + 8, -_MAX_DIGITS, -1):
        scaled = xs * 10.0**k
        fits = np.abs(scaled - np.rint(scaled)) <= 8.0 * np.finfo(float).eps * np.abs(scaled)
        decimals = np.where(fits | (np.abs(scaled) >= 1e15), k, decimals)
    digits = mag[some] + 1 + decimals
    written = digits < _MAX_DIGITS - 1  # fewer digits than float64 keeps
    if not np.any(written):
        return tiny
    sig = float(np.max(digits[written]))
    dec = float(np.max(decimals[written]))
    out: FloatArray = np.where(
        nonzero, np.maximum(0.5 * 10.0 ** (mag + 1 - sig), 0.5 * 10.0**-dec), 0.5 * 10.0**-dec
    )
    return np.maximum(out, tiny)


def count_quantum(theta: FloatArray, cpr: int) -> float | None:
    """The encoder's count (rad) when the angle ``theta`` (rad) is whole counts of it, to
    within the digits it was written with, else None: 2 pi / ``cpr`` (the header's or the
    default count) when the values sit on that grid, else the step the values themselves sit
    on, when chance cannot explain it (:data:`CHANCE`)."""
    th = np.asarray(theta, dtype=float)
    th = th[np.isfinite(th)]
    if th.size < 2:
        return None
    q = 2.0 * math.pi / cpr
    x = (th - th[0]) / q
    if bool(np.all(np.abs(x - np.round(x)) <= 1e-6)):
        return q
    err = written_error(th)
    ref = int(np.argmin(err))
    dx = th - th[ref]
    allow = err + err[ref]
    if _on_grid(dx, allow, q):
        return q
    return _grid_of(dx, allow)


def _on_grid(dx: FloatArray, allow: FloatArray, q: float) -> bool:
    """Whether the differences ``dx`` (rad) from a reference value all sit on whole multiples
    of ``q`` (rad) within twice their ``allow``-ance, and enough of them tell (:data:`TELLS`)
    that chance would put them there with at most :data:`CHANCE`."""
    tells = allow <= TELLS * q
    n = np.round(dx / q)
    miss = np.abs(dx - n * q)
    if not bool(np.all(miss[tells] <= 2.0 * allow[tells] + 1e-6 * q)):
        return False
    # each distinct value that tells lands within +-2 allow of the grid by chance with
    # probability 4 allow / q; the same value repeated (a wheel at rest) tells once
    counts, first = np.unique(n[tells & (n != 0)], return_index=True)
    if not counts.size:
        return False
    p = np.maximum(4.0 * allow[tells & (n != 0)][first] / q, 1e-300)
    return float(np.sum(np.log10(np.minimum(p, 1.0)))) <= math.log10(CHANCE)


def _grid_of(dx: FloatArray, allow: FloatArray) -> float | None:
    """The largest step (rad) whose whole multiples the differences ``dx`` (rad) sit on
    (:func:`_on_grid`), from the smallest clear gap between distinct values taken as 1 to
    :data:`SUBSTEPS` steps; None when none does. Each try is refined by least squares on the
    values near the reference first, then on ones further out as the step grows surer (a step
    0.2 % off already miscounts values 250 steps away)."""
    order = np.argsort(dx)
    v, a = dx[order], allow[order]
    gaps = np.diff(v)
    apart = gaps > 4.0 * np.maximum(a[1:], a[:-1])
    if not np.any(apart):
        return None
    # a gap known to 1 % or better, where there is one (a large value written to 6 digits
    # leaves a gap between two of them 3 % uncertain, too loose to count values from)
    sure = apart & (2.0 * (a[1:] + a[:-1]) <= SURE_GAP * gaps)
    k = int(np.argmin(np.where(sure if np.any(sure) else apart, gaps, np.inf)))
    smallest, unsure = float(gaps[k]), 2.0 * float(a[k] + a[k + 1])
    far = float(np.max(np.abs(dx)))
    for m in range(1, SUBSTEPS + 1):
        q, rel = smallest / m, unsure / smallest
        while True:
            reach = 0.2 * q / rel  # values within it of the reference are counted right
            use = (allow <= TELLS * q) & (np.abs(dx) <= reach)
            n = np.round(dx[use] / q)
            w = 1.0 / np.maximum(allow[use], 1e-300) ** 2
            den = float(np.sum(w * n**2))
            if den <= 0:
                break
            q = float(np.sum(w * n * dx[use])) / den
            now = 2.0 * float(np.max(allow[use])) / max(float(np.max(np.abs(dx[use]))), q)
            if reach >= far or now >= rel:  # all counted, or reaching no further
                break
            rel = now
        if q > 0 and _on_grid(dx, allow, q):
            return q
    return None
