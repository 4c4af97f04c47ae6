"""Fitting the first-order model, alone or with any set of effects, to a run log.

The residual is compared where its noise is white. The measured speed is a difference
of quantised angles, (theta_k - theta_k-N)/(N Ts), so its noise is differenced (lag-N
autocorrelation near -0.5); summing the residual with stride N, leakily,

    e_k = r_k + rho e_k-N        (rho = 0.9)

undoes the difference (whitening the quantisation noise) while a slow model error is
only amplified tenfold instead of piling up as it would in the raw angle. The filter is
monic, so the whitened sums of squares of models with different N compare fairly. A log
whose speed is taken over the real sample interval is first scaled back to angle
differences per nominal period.

For given T and effect parameters the response is proportional to K, which is solved by
linear least squares. The other parameters (T on a log scale, each effect's own) are
started from a coarse grid and polished jointly by Levenberg-Marquardt within their
ranges (:func:`minseg_tui.model.optimize.least_squares`, the derivatives by forward
differences); the moving average's length is an integer, scanned cheaply (the angle does
not depend on it). Where the side of an extra pole shows (with dry friction, a coast or a
cap, it matters whether the pole acts on the drive or on the measurement) both sides are
fitted and the better kept, and a current limit is fitted capped while accelerating only
and capped both ways, with the share of viscous drag that bends its ramp
(:data:`.effects.DRAG`) as a parameter of its own (each cause's ``ways`` and ``second``
in :mod:`.effects`). Rows with weight 0 (wild samples, a hand on the wheel, held-out
steps) do not count: their residual is set to zero before the whitening.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.effects import (
    BY_CAUSE,
    OWNER,
    Range,
    Way,
    counted,
    effects_of,
    field_value,
    reported,
    way_of,
    ways,
)
from minseg_tui.model.check.simulate import (
    Effects,
    Stretches,
    angle_at,
    measured,
    pieces,
    response,
    restart,
)
from minseg_tui.model.optimize import golden, least_squares

FloatArray = NDArray[np.float64]

RHO = 0.9
"""Leak of the whitening sum (1 would be the pure angle domain)."""

T_BOUNDS = (0.002, 3.0)
"""Search range of the time constant T, s."""

MAX_FIT_ROWS = 2400
"""Longer logs are fitted on their first rows only (60 s at 40 Hz) and simulated whole."""


def whiten(x: FloatArray, taps: int = 1) -> FloatArray:
    """e_k = x_k + RHO e_k-taps: the leaky stride-``taps`` sum that whitens differenced noise.

    Up to ``_DIRECT`` strides one scaled cumulative sum; longer inputs in blocks of
    ``_BLOCK`` strides (a scaled cumulative sum inside a block, the carry between blocks as
    a short geometric sum, since RHO^_BLOCK is tiny).
    """
    x = np.asarray(x, dtype=float)
    n = x.size
    rows = -(-n // taps)
    if taps == 1 and rows <= _DIRECT:  # the same sum without the columns
        one: FloatArray = np.cumsum(x * _INV_ALL[:n]) * _POW_ALL[:n]
        return one
    if rows <= _DIRECT:  # e_k = rho^k sum_j rho^-j x_j in one cumulative sum
        buf = np.zeros(rows * taps)
        buf[:n] = x
        cols = buf.reshape(rows, taps)
        direct: FloatArray = (
            np.cumsum(cols * _INV_ALL[:rows, None], axis=0) * _POW_ALL[:rows, None]
        ).reshape(-1)[:n]
        return direct
    nb = -(-rows // _BLOCK)
    buf = np.zeros(nb * _BLOCK * taps)
    buf[:n] = x
    y = buf.reshape(nb, _BLOCK, taps)
    inner = np.cumsum(y * _INV[None, :, None], axis=1) * _POW[None, :, None]
    ends = inner[:, -1, :]
    acc = np.zeros_like(ends)
    q = 1.0
    for i in range(_CARRY_TERMS):
        if i + 1 < nb:
            acc[i + 1 :] += q * ends[: nb - i - 1]
        q *= RHO**_BLOCK
    out: FloatArray = (inner + _POW1[None, :, None] * acc[:, None, :]).reshape(-1)[:n]
    return out


_COARSE_TAPS = (1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 14, 16, 18, 20, 23, 26, 30, 35, 40)
"""Moving-average lengths a scan tries first (then the neighbours of the best)."""

_DIRECT = 3000  # RHO^-3000 = 1e137: the direct sum stays well inside float range
_POW_ALL = RHO ** np.arange(_DIRECT)
_INV_ALL = 1.0 / _POW_ALL
_BLOCK = 32
_POW = RHO ** np.arange(_BLOCK)
_INV = 1.0 / _POW
_POW1 = RHO ** np.arange(1, _BLOCK + 1)
_CARRY_TERMS = 8  # (RHO^32)^8 < 1e-11


@dataclass
class Problem:
    """A run log ready to fit: t (s), u (V, held from each row on), y measured speed (rad/s).

    ts: nominal sample period, s; z0: initial speed in K = 1 units (V), None for steady
    state under the first input; weights: 1 for rows that count, 0 for rows left out;
    over_interval: the speed of a row was taken over its real interval (else over ts).
    """

    t: FloatArray
    u: FloatArray
    y: FloatArray
    ts: float
    z0: float | None = 0.0
    weights: FloatArray = field(default_factory=lambda: np.zeros(0))
    over_interval: bool = False
    smooth: bool = False
    """The speed column is smooth from row to row, not a difference of counts (a filtered
    or analogue speed: :attr:`~.sampling.Sampling.smooth`)."""
    restarts: tuple[int, ...] = ()
    """Rows from which the model picks up again from the speed the wheel was left at (where
    a hand let go of it, :func:`~.simulate.restart`): each adds a departure that dies away
    with the motor's time constant, its size fitted with K."""
    _yw: dict[int, FloatArray] = field(default_factory=dict, repr=False)
    _scale: dict[int, FloatArray | None] = field(default_factory=dict, repr=False)
    _restart: dict[tuple[object, ...], FloatArray] = field(default_factory=dict, repr=False)
    _yw_kept: dict[int, FloatArray] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if self.weights.size != self.y.size:
            self.weights = np.ones(self.y.size)
        self.st = Stretches.from_samples(self.t, self.u)
        self.keep = self.weights > 0
        self._every_row = bool(np.all(self.weights == 1.0))
        """Every row counts with weight 1 (the masks and the weighting change nothing)."""

    def scale(self, taps: int) -> FloatArray | None:
        """Per row, (t_k - t_k-N)/(N ts) for a speed taken over the real interval (None: 1)."""
        if taps not in self._scale:
            if not self.over_interval:
                self._scale[taps] = None
            else:
                tt = np.concatenate((self.t[0] - self.ts * np.arange(taps, 0, -1), self.t))
                self._scale[taps] = (tt[taps:] - tt[:-taps]) / (taps * self.ts)
        return self._scale[taps]

    def white(self, g: FloatArray, taps: int) -> FloatArray:
        """The whitened form of a speed on every row (rows left out count as 0)."""
        s = self.scale(taps)
        if s is None:
            return whiten(g if self._every_row else g * self.weights, taps)
        return whiten(g * s * self.weights, taps)

    def y_white(self, taps: int) -> FloatArray:
        if taps not in self._yw:
            self._yw[taps] = self.white(self.y, taps)
        return self._yw[taps]

    def y_white_kept(self, taps: int) -> FloatArray:
        """:meth:`y_white` on the rows that count only."""
        if taps not in self._yw_kept:
            self._yw_kept[taps] = self.kept(self.y_white(taps))
        return self._yw_kept[taps]

    def kept(self, x: FloatArray) -> FloatArray:
        """``x`` (one value per row) on the rows that count only."""
        return x if self._every_row else x[self.keep]

    def with_weights(self, weights: FloatArray, restarts: tuple[int, ...] | None = None) -> Problem:
        """The same log with other row weights (and other restarts, if given)."""
        return Problem(
            self.t,
            self.u,
            self.y,
            self.ts,
            self.z0,
            np.asarray(weights, float),
            self.over_interval,
            self.smooth,
            self.restarts if restarts is None else restarts,
        )

    def restart_columns(self, T: float, fx: Effects) -> list[tuple[int, FloatArray]]:
        """The departure of each restart (K = 1 units) for the model (T, fx) on every row,
        with the end (exclusive) of the rows its size is read from: those before the next
        step of the input."""
        out = []
        change = np.flatnonzero(np.diff(self.u) != 0) + 1
        for r in self.restarts:
            if r >= self.y.size:
                continue
            # only T and the causes that act on the measurement or the coast shape it
            key = (r, T, fx.delay, fx.taps, fx.T2, fx.pole_measured, fx.pole_filtered, fx.T_coast)
            col = self._restart.get(key)
            if col is None:
                col = restart(self.st, self.t, self.ts, T, fx, r, self.over_interval)
                if len(self._restart) > 64:
                    self._restart.clear()
                self._restart[key] = col
            after = change[change > r]
            out.append((int(after[0]) if after.size else self.y.size, col))
        return out

    def head(self, rows: int) -> Problem:
        """The first ``rows`` rows as a problem of their own (same weights)."""
        if rows >= self.y.size:
            return self
        return Problem(
            self.t[:rows],
            self.u[:rows],
            self.y[:rows],
            self.ts,
            self.z0,
            self.weights[:rows].copy(),
            self.over_interval,
            self.smooth,
            tuple(r for r in self.restarts if r < rows),
        )

    @property
    def rows(self) -> int:
        return int(np.count_nonzero(self.keep))


@dataclass(frozen=True)
class Fit:
    """A fitted model: the causes it holds (empty for the first-order baseline), T (s),
    K (rad/s/V), the effects it simulates, and the whitened sum of squares it reached on
    ``rows`` rows."""

    causes: tuple[str, ...]
    T: float
    K: float
    effects: Effects
    sse_white: float
    rows: int
    restart: tuple[tuple[int, float], ...] = ()
    """(row, size in K = 1 units) of each restart of the model (:attr:`Problem.restarts`)."""

    @property
    def name(self) -> str:
        """'none' for the baseline, else the causes joined by '+'."""
        return "+".join(self.causes) if self.causes else "none"

    @property
    def params(self) -> dict[str, float]:
        """Each cause's parameter by its contract name (a_max in rad/s^2)."""
        return {
            BY_CAUSE[c].param: reported(c, field_value(self.effects, c), self.K)
            for c in self.causes
        }

    def value(self, cause: str) -> float:
        """The Effects field behind ``cause`` (K = 1 units)."""
        return field_value(self.effects, cause)

    def predict(self, prob: Problem) -> FloatArray:
        """Simulated measured speed on every row of ``prob``, rad/s (picking up from where
        a hand left the wheel at each restart)."""
        out = self.K * response(
            prob.st, prob.t, prob.ts, self.T, self.effects, prob.z0, prob.over_interval
        )
        for row, c in self.restart:
            if row < prob.y.size and c != 0.0:
                out = out + c * restart(
                    prob.st, prob.t, prob.ts, self.T, self.effects, row, prob.over_interval
                )
        return out


# -- one model, its parameters as a vector -----------------------------------------------


@dataclass(frozen=True)
class _Axis:
    cause: str
    lo: float
    hi: float
    step: float
    log_scale: bool
    unit: float  # value = x * unit (linear axes)
    second: str = ""  # the Effects field of a cause's second parameter (key in ``cause``)

    def value(self, x: float) -> float:
        return math.exp(x) if self.log_scale else x * self.unit

    def coord(self, value: float) -> float:
        if self.log_scale:
            return math.log(min(max(value, math.exp(self.lo)), math.exp(self.hi)))
        return min(max(value / self.unit, self.lo), self.hi)


def _axes(prob: Problem, causes: Sequence[str], rng: dict[str, Range]) -> list[_Axis]:
    u_scale = float(np.max(np.abs(prob.u))) or 1.0
    out = [_Axis("T", math.log(T_BOUNDS[0]), math.log(T_BOUNDS[1]), 2e-3, True, 1.0)]
    for c in causes:
        if BY_CAUSE[c].counted:
            continue
        r = rng[c]
        if r.log_scale:
            out.append(_Axis(c, math.log(r.lo), math.log(r.hi), 5e-3, True, 1.0))
        else:
            unit = u_scale if BY_CAUSE[c].scale == "V" else prob.ts
            out.append(_Axis(c, r.lo / unit, r.hi / unit, 5e-3, False, unit))
    for c in causes:
        for sec in BY_CAUSE[c].second:
            out.append(_Axis(sec.key, 0.0, sec.hi, 5e-3, False, 1.0, sec.field))
    return out


_NO_COEF = np.zeros(0)


class Model:
    """One set of causes on one problem: the parameters as a vector in a box, and the
    whitened residual (K solved) of any point in it."""

    def __init__(self, prob: Problem, causes: Sequence[str], rng: dict[str, Range]) -> None:
        self.prob = prob
        self.causes = tuple(causes)
        self.rng = rng
        self.axes = _axes(prob, self.causes, rng)
        self.lo = np.array([a.lo for a in self.axes])
        self.hi = np.array([a.hi for a in self.axes])
        self.step = np.array([a.step for a in self.axes])
        self.counted = counted(self.causes)
        self.taps = 1
        self.way: Way = {}
        self.evaluations = 0
        self._last: tuple[bytes, FloatArray] = (b"", np.zeros(0))

    def effects(self, x: FloatArray) -> tuple[float, Effects]:
        T = math.exp(float(x[0]))
        values: dict[str, float] = {
            a.cause: a.value(float(v)) for a, v in zip(self.axes[1:], x[1:], strict=True)
        }
        flags: dict[str, Any] = {}
        for a in self.axes[1:]:
            if a.second:
                v = values.pop(a.cause)
                if v > 0.0:
                    flags[a.second] = v
        if self.counted is not None:
            values[self.counted] = float(self.taps)
        fx = effects_of(values)
        flags.update({k: True for k, on in self.way.items() if on and OWNER[k] in self.causes})
        fx = replace(fx, **flags) if flags else fx
        for c in self.causes:
            tie = BY_CAUSE[c].tie
            if tie is not None:
                fx = tie(fx, T)
        return T, fx

    def x_of(self, T: float, values: dict[str, float]) -> FloatArray:
        """The vector of T (s) and {cause: Effects field value}."""
        x = [self.axes[0].coord(T)]
        for a in self.axes[1:]:
            x.append(a.coord(values.get(a.cause, 0.0) if a.second else values[a.cause]))
        return np.array(x)

    def residual(self, x: FloatArray) -> FloatArray:
        """Whitened residual on the rows that count, with the best K."""
        return self.residual_of(*self.effects(x))

    def residual_of(self, T: float, fx: Effects) -> FloatArray:
        """:meth:`residual` of the model (T in s, fx) already made from x."""
        g = self.response(T, fx)
        return self.fit_k(g, fx.taps, self.prob.restart_columns(T, fx))[0]

    def response(self, T: float, fx: Effects) -> FloatArray:
        self.evaluations += 1
        p = self.prob
        return response(p.st, p.t, p.ts, T, fx, p.z0, p.over_interval)

    def fit_k(
        self, g: FloatArray, taps: int, cols: Sequence[tuple[int, FloatArray]] = ()
    ) -> tuple[FloatArray, float, tuple[float, ...]]:
        """(whitened residual on the rows that count, K, the size of each restart) for the
        response g and the restarts' departures ``cols`` (K = 1; each with the end of the
        rows its size is read from). The size of a restart is the speed the hand left the
        wheel at, read off the measured speed before the next step of the input (against
        the model's speed with K fitted jointly first); K is then fitted with those sizes
        held. A size fitted freely on the rows after the step would stand in for a miss of
        the model at that step."""
        p = self.prob
        gw = p.kept(p.white(g, taps))
        yw = p.y_white_kept(taps)
        den = float(np.dot(gw, gw))
        if den <= 0.0 or not math.isfinite(den):
            return np.full(yw.size, math.inf), 0.0, tuple(0.0 for _ in cols)
        k = float(np.dot(gw, yw)) / den
        if not cols:
            return yw - k * gw, k, ()
        hw = [p.kept(p.white(c, taps)) for _, c in cols]
        use = [i for i, h in enumerate(hw) if float(np.dot(h, h)) > 1e-12 * den]
        if use:
            a = np.column_stack([gw, *(hw[i] for i in use)])
            coef, *_ = np.linalg.lstsq(a, yw, rcond=None)
            k = float(coef[0])
        sizes = [0.0] * len(cols)
        for i in use:
            end, c = cols[i]
            rows = np.flatnonzero(c[:end] != 0.0)
            rows = rows[p.keep[rows]]
            cc = c[rows]
            cd = float(np.dot(cc, cc))
            if cd > 0.0:
                sizes[i] = float(np.dot(cc, p.y[rows] - k * g[rows])) / cd
        rest = yw - sum((sizes[i] * hw[i] for i in use), np.zeros(yw.size))
        k = float(np.dot(gw, rest)) / den
        return rest - k * gw, k, tuple(sizes)

    def sse(self, x: FloatArray) -> float:
        r = self.residual(x)
        return float(np.dot(r, r)) if np.all(np.isfinite(r)) else math.inf

    def evaluate(self, x: FloatArray) -> tuple[float, FloatArray, FloatArray]:
        """(whitened sum of squares, no coefficients, whitened residual) at x, for
        :func:`least_squares` (K is solved inside the residual)."""
        r = self.residual(x)
        self._last = (x.tobytes(), r)
        sse = float(np.dot(r, r)) if np.all(np.isfinite(r)) else math.inf
        return sse, _NO_COEF, r

    def jacobian(self, x: FloatArray, coef: FloatArray) -> FloatArray:
        """d whitened residual / d x by forward differences of each axis' step (backward at
        the upper bound); a model that fails there counts as flat."""
        key = x.tobytes()
        r = self._last[1] if self._last[0] == key else self.residual(x)
        jac = np.empty((r.size, x.size))
        here = self.effects(x)
        for i in range(x.size):
            h = self.step[i] if x[i] + self.step[i] <= self.hi[i] else -self.step[i]
            xp = x.copy()
            xp[i] += h
            there = self.effects(xp)
            if there == here:
                jac[:, i] = 0.0  # a parameter this way ties or ignores (Candidate.tie)
                continue
            jac[:, i] = (self.residual_of(*there) - r) / h
        out: FloatArray = np.nan_to_num(jac, nan=0.0, posinf=0.0, neginf=0.0)
        return out

    def _solve(self, x0: FloatArray, max_iter: int) -> tuple[FloatArray, float]:
        sol = least_squares(
            self.evaluate, self.jacobian, x0, self.lo, self.hi, max_iter, 1e-3 * self.step, 1e-6
        )
        return sol.x, sol.rss

    def fit(self, x0: FloatArray, max_iter: int = 25) -> Fit:
        """Levenberg-Marquardt from x0 (the taps, if any, scanned around as well)."""
        x, f = self._solve(x0, max_iter)
        if self.counted is not None:
            # the length trades against T (one more sample of averaging, half a sample less
            # of T): each neighbour is judged with the other parameters fitted again
            hi = int(self.rng[self.counted].hi)
            best = (f, x, self.taps)
            tried = {self.taps}
            while True:
                centre = best[2]
                for n in (centre - 1, centre + 1):
                    if n < 1 or n > hi or n in tried:
                        continue
                    tried.add(n)
                    self.taps = n
                    xn, fn = self._solve(best[1], max_iter)
                    if fn < best[0]:
                        best = (fn, xn, n)
                if best[2] == centre:
                    break
            f, x, self.taps = best
        return self.make(x, f)

    def make(self, x: FloatArray, f: float | None = None) -> Fit:
        T, fx = self.effects(x)
        g = self.response(T, fx)
        r, k, sizes = self.fit_k(g, fx.taps, self.prob.restart_columns(T, fx))
        sse = float(np.dot(r, r)) if f is None else f
        rows = [r for r in self.prob.restarts if r < self.prob.y.size]
        return Fit(self.causes, T, k, fx, sse, self.prob.rows, tuple(zip(rows, sizes, strict=True)))

    def scan_taps(self, x: FloatArray, anchors: Sequence[float] = ()) -> FloatArray:
        """x with T and the moving-average length set to the best pair on a grid of T from
        0.15 to 1.5 times x's and each of ``anchors`` (s) (the length scanned in full at
        each)."""
        best = (math.inf, x, self.taps)
        ts = [math.exp(float(x[0])), *anchors]
        lo, hi = math.log(0.15 * min(ts)), math.log(1.5 * max(ts))
        grid = np.linspace(lo, hi, max(7, int(math.ceil((hi - lo) / 0.3)) + 1))
        assert self.counted is not None
        top = int(self.rng[self.counted].hi)
        coarse = [n for n in _COARSE_TAPS if n <= top]
        for g in grid.tolist():
            xt = x.copy()
            xt[0] = min(max(g, self.lo[0]), self.hi[0])
            taps, sse = self._taps_sse(xt, coarse)
            if sse < best[0]:
                best = (sse, xt, taps)
        near = list(range(max(1, best[2] - 3), min(top, best[2] + 3) + 1))
        self.taps = self._taps_sse(best[1], near)[0]
        return best[1]

    def _taps_sse(self, x: FloatArray, tries: Sequence[int]) -> tuple[int, float]:
        """The moving-average length among ``tries`` that fits best with the other
        parameters at x, and its whitened sum of squares (the angle computed once)."""
        T, fx = self.effects(x)
        top = max(tries)
        p = self.prob
        tb = p.t[0] - p.ts * np.arange(top, 0, -1)
        theta = angle_at(pieces(p.st, T, fx, p.z0), np.concatenate((tb, p.t)), fx)
        self.evaluations += 1
        best, best_sse = 1, math.inf
        for n in tries:
            g = measured(theta[top:], p.t, theta[top - n : top], p.ts, n, p.over_interval)
            r, _, _ = self.fit_k(g, n, p.restart_columns(T, replace(fx, taps=n)))
            sse = float(np.dot(r, r))
            if sse < best_sse:
                best, best_sse = n, sse
        return best, best_sse


def fit_baseline(prob: Problem, rng: dict[str, Range]) -> Fit:
    """The first-order model T w' = -w + K u: a log grid in T, then golden section."""
    m = Model(prob, (), rng)
    xs = np.linspace(math.log(T_BOUNDS[0]), math.log(T_BOUNDS[1]), 16)
    vals = [m.sse(np.array([x])) for x in xs]
    i = int(np.argmin(vals))
    a, b = xs[max(i - 1, 0)], xs[min(i + 1, xs.size - 1)]
    x, f = golden(lambda v: m.sse(np.array([v])), float(a), float(b), xatol=1e-4)
    if f > vals[i]:
        x, f = float(xs[i]), float(vals[i])
    return m.make(np.array([x]), f)


def fit_causes(
    prob: Problem,
    causes: Sequence[str],
    rng: dict[str, Range],
    starts: Sequence[tuple[float, dict[str, float]]],
    max_iter: int = 25,
    scan: bool | None = True,
    polish: tuple[str, ...] = (),
    way: Way | None = None,
) -> Fit:
    """The first-order model with ``causes`` fitted jointly, from the best of ``starts``
    ((T in s, {cause: Effects field value})) by Levenberg-Marquardt. With a moving average
    among the causes its length is first scanned in full (``scan`` True), else only around
    the start's (False), or both ways (None). For each cause in ``polish`` the best two
    starts with other values of it are polished too (a cause that does not act at the best
    start has no gradient to grow by), and the best result kept.

    ``way``: the flags of the way each cause acts (an extra pole on the measurement, a cap
    that brakes too: :attr:`.effects.Candidate.ways`); None: every way of every cause is
    fitted, the first from ``starts``, and the better kept."""
    out: Fit | None = None
    for w in ways(tuple(causes), prob.smooth) if way is None else [way]:
        if out is not None and not all(
            worth(w, out) for c in causes if (worth := BY_CAUSE[c].worth) is not None
        ):
            continue
        if out is None:
            f = _fit_side(prob, causes, rng, starts, max_iter, scan, polish, w)
        else:
            # the other way from where the first ended, and from every start (scored
            # again: a start far from the first way's valley, a cap's ramp with little
            # drag, may be the best in this one): the ways differ only where the wheel
            # stops, coasts or is capped; a cause may carry the first way's values over
            again = [(out.T, values_of(out)), *starts]
            for c in causes:
                carry = BY_CAUSE[c].carry
                moved = None if carry is None else carry(w, out.effects, values_of(out), prob.ts)
                if moved is not None:
                    again.insert(0, (out.T, moved))
            f = _fit_side(prob, causes, rng, again, max_iter, False, (), w)
        if out is None or f.sse_white < out.sse_white:
            out = f
    assert out is not None
    return out


def _fit_side(
    prob: Problem,
    causes: Sequence[str],
    rng: dict[str, Range],
    starts: Sequence[tuple[float, dict[str, float]]],
    max_iter: int,
    scan: bool | None,
    polish: tuple[str, ...],
    way: Way,
) -> Fit:
    m = Model(prob, causes, rng)
    m.way = way
    scored = []
    for T, values in starts:
        if m.counted is not None:
            m.taps = int(round(values.get(m.counted, m.taps)))
        x = m.x_of(T, values)
        scored.append((m.sse(x), m.taps, x, values))
    ok = [r for r in scored if math.isfinite(r[0])]
    if not ok:  # no start moves the wheel (friction above the cap, say)
        T, fx = m.effects(m.x_of(*starts[0]))
        return Fit(m.causes, T, 0.0, fx, math.inf, prob.rows)
    ok.sort(key=lambda r: r[0])
    picks = [ok[0]]
    for c in polish:
        seen = {ok[0][3].get(c)}
        for r in ok:
            if len(picks) >= 3:
                break
            if r[3].get(c) not in seen:
                seen.add(r[3].get(c))
                picks.append(r)
    best: Fit | None = None
    scans = (True, False) if scan is None and m.counted is not None else (bool(scan),)
    for _, taps, x, _ in picks:
        for full in scans:
            m.taps = taps
            xs = x
            if m.counted is not None and full:
                xs = m.scan_taps(x, sorted({T for T, _ in starts}))
            f = m.fit(xs, max_iter)
            if best is None or f.sse_white < best.sse_white:
                best = f
    assert best is not None
    return best


def values_of(f: Fit) -> dict[str, float]:
    """{cause: Effects field value} of a fit (and each cause's second parameter under its
    key, :attr:`.effects.Candidate.second`)."""
    out = {c: f.value(c) for c in f.causes}
    for c in f.causes:
        for sec in BY_CAUSE[c].second:
            out[sec.key] = getattr(f.effects, sec.field)
    return out


def refit(prob: Problem, f: Fit, rng: dict[str, Range], max_iter: int = 8) -> Fit:
    """``f``'s causes fitted again on ``prob`` (other weights), started from ``f``."""
    if not f.causes:
        return fit_baseline_near(prob, rng, f.T)
    return fit_causes(
        prob,
        f.causes,
        rng,
        [(f.T, values_of(f))],
        max_iter,
        scan=False,
        way=way_of(f.effects),
    )


def fit_baseline_near(prob: Problem, rng: dict[str, Range], T: float) -> Fit:
    """The baseline polished from T (s) by a short golden-section search in log T."""
    m = Model(prob, (), rng)
    x, f = golden(lambda v: m.sse(np.array([v])), math.log(T) - 0.7, math.log(T) + 0.7, 1e-4)
    return m.make(np.array([x]), f)


# -- 95 % intervals ----------------------------------------------------------------------

Z95 = 1.96


def intervals(prob: Problem, f: Fit, rng: dict[str, Range]) -> dict[str, tuple[float, float]]:
    """A 95 % interval for T, K and each cause's parameter (contract names and units).

    From the Jacobian of the whitened residual at the fit (K as a parameter too); the
    residual variance is the fit's own, inflated by (1 + rho1)/(1 - rho1) for the lag-1
    autocorrelation rho1 left in it (a real log's misfit is not white). The moving
    average's length gets the lengths whose sum of squares stays within the same
    tolerance.
    """
    m = Model(prob, f.causes, rng)
    m.taps = f.effects.taps
    m.way = way_of(f.effects)
    x = m.x_of(f.T, values_of(f))
    T, fx = m.effects(x)
    g = m.response(T, fx)
    starts = prob.restart_columns(T, fx)
    r0, k, _ = m.fit_k(g, fx.taps, starts)
    gw = prob.white(g, fx.taps)[prob.keep]
    cols = [-gw]  # d r / d K
    for i, a in enumerate(m.axes):
        h = a.step if x[i] + a.step <= m.hi[i] else -a.step
        xp = x.copy()
        xp[i] += h
        Tp, fxp = m.effects(xp)
        gp = prob.white(m.response(Tp, fxp), fx.taps)[prob.keep]
        cols.append(-(k * (gp - gw)) / h)
    # the size of each restart is fitted with K (its own dependence on T left out)
    extra = [-prob.white(c, fx.taps)[prob.keep] for _, c in starts]
    jac = np.column_stack([*cols, *extra])
    n, p = jac.shape
    # a residual too large to square (a fit that ran away) pins nothing down: its sums are
    # taken as infinite, without numpy's overflow warnings, and every interval is unbounded
    with np.errstate(over="ignore", invalid="ignore"):
        ss = float(np.dot(r0, r0))
        lag1 = float(np.dot(r0[1:], r0[:-1]))
    if not math.isfinite(ss) or not math.isfinite(lag1):
        ss, lag1 = math.inf, 0.0
    s2 = ss / max(n - p, 1)
    rho = lag1 / ss if n > 2 and 0.0 < ss < math.inf else 0.0
    rho = min(max(rho, 0.0), 0.95)
    s2 *= (1.0 + rho) / (1.0 - rho)
    try:
        cov = np.linalg.pinv(jac.T @ jac) * s2 if s2 < math.inf else np.full((p, p), np.inf)
    except np.linalg.LinAlgError:
        cov = np.full((p, p), np.inf)
    sd = np.sqrt(np.maximum(np.diag(cov), 0.0))[: len(cols)]
    sd = np.where(np.isfinite(sd), sd, np.inf)  # a parameter the log does not pin down
    out: dict[str, tuple[float, float]] = {"K": (k - Z95 * sd[0], k + Z95 * sd[0])}
    tied = [a.cause for i, a in enumerate(m.axes) if not a.second and not np.any(cols[i + 1])]
    for i, a in enumerate(m.axes):
        lo_x, hi_x = x[i] - Z95 * sd[i + 1], x[i] + Z95 * sd[i + 1]
        if a.log_scale:
            lo_x, hi_x = max(lo_x, -700.0), min(hi_x, 700.0)
        if a.cause == "T":
            out["T"] = (math.exp(lo_x), math.exp(hi_x))
            continue
        if a.second:
            continue
        name = BY_CAUSE[a.cause].param
        lo_v, hi_v = (
            (math.exp(lo_x), math.exp(hi_x)) if a.log_scale else (lo_x * a.unit, hi_x * a.unit)
        )
        if not a.log_scale:
            lo_v = max(lo_v, 0.0)
        if a.cause in tied and BY_CAUSE[a.cause].tie is not None:
            lo_v, hi_v = out["T"]  # its way sets it to T (the ringing pair's T2)
        out[name] = (reported(a.cause, lo_v, k), reported(a.cause, hi_v, k))
    if m.counted is not None:
        out[BY_CAUSE[m.counted].param] = _taps_interval(
            m, x, f, 1.0 + Z95**2 * (1.0 + rho) / (1.0 - rho) / max(n - p, 1)
        )
    return out


def _taps_interval(m: Model, x: FloatArray, f: Fit, tol: float) -> tuple[float, float]:
    T, fx = m.effects(x)
    p = m.prob
    assert m.counted is not None
    hi = int(m.rng[m.counted].hi)
    top = hi
    tb = p.t[0] - p.ts * np.arange(top, 0, -1)
    theta = angle_at(pieces(p.st, T, fx, p.z0), np.concatenate((tb, p.t)), fx)
    ok = []
    for n in range(1, hi + 1):
        g = measured(theta[top:], p.t, theta[top - n : top], p.ts, n, p.over_interval)
        r, _, _ = m.fit_k(g, n, p.restart_columns(T, replace(fx, taps=n)))
        if float(np.dot(r, r)) <= tol * f.sse_white:
            ok.append(n)
    taps = f.effects.taps
    if not ok:
        return float(taps), float(taps)
    return float(min(min(ok), taps)), float(max(max(ok), taps))
