"""The model of Task 14 fitted to the whole log: T omega' = -omega + K (u_A - u_c sgn omega).

The input is the log's applied voltage ``u`` (V), held from each row's instant to the next;
every change of it, rising or falling, is an edge the model follows. The fit works on what is
measured, the wheel angle (rad) at the board's timestamps, with

- K (rad/s per V) and the angle's offset: linear, solved exactly for given nonlinear
  parameters. One offset carries the angle through every edge when the log's timestamps say
  where the edges fall; without them an edge may act up to a loop's lateness away from its
  logged instant, which shifts the angle after it, so each stretch between edges gets its own
  offset and the fit rests on the shape of each response;
- T (s), the time constant, shared by every edge;
- a time shift d (s) of all edges against the samples: a nuisance parameter. A log whose
  samples are read late against the instants the command changes (a busy loop) shows its
  response early; without the shift that lateness comes out of T. Where the edges act is
  given as one or more hypotheses (the sample instants, the board's sample grid): the one that
  fits best is kept;
- u_c (V), the breakaway voltage of dry friction (tau_c R / k_a), when the log calls for it: the
  wheel then slows towards -K u_c after a fall, stops and sticks while |u_A| <= u_c.

The log is taken to start in the steady state of its first level (at rest at 0 V). Between
edges the response is the closed-form exponential, so one evaluation takes time proportional
to the rows: the speed at each edge follows from the one before by a map x -> max(a x + b, c)
(the clamp is the stop), and such maps are composed for all edges at once by doubling.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.identify.lsq import Covariance, cluster_covariance, dot
from minseg_tui.model.optimize import Solution, least_squares

FloatArray = NDArray[np.float64]

FRICTION_F: float = 25.0
"""Dry friction enters the model when it lowers the residual sum of squares by this many times
its per-degree-of-freedom residual variance (an F statistic far beyond chance)."""


@dataclass(frozen=True)
class WholeLogFit:
    """The fitted model and its uncertainty.

    T: time constant (s); d: time shift of the edges (s); K: gain (rad/s per V of the log's u);
    u_c: dry friction's breakaway voltage (V, 0 when not in the model); friction: whether u_c
    was fitted; T_on_bound, d_on_bound: whether T or d ended on its bound; n_used: rows fitted; offsets: whether the angle got a free offset per stretch between edges;
    covariance: cluster-robust covariance of (K, T, d[, u_c]); residuals: angle residuals (rad)
    at every row; predicted: the model's angle (rad) at every row; start_free: where d was
    held on its lower bound as a choice (``start_held``), the covariance with d fitted there
    too (what the start's trade against T adds), else None.
    """

    T: float
    d: float
    K: float
    u_c: float
    friction: bool
    offsets: bool
    rss: float
    n_params: int
    T_on_bound: bool
    d_on_bound: bool
    n_used: int
    covariance: Covariance
    residuals: FloatArray
    predicted: FloatArray
    start_free: Covariance | None = None

    def level(self, u: float) -> float:
        """The steady speed (rad/s) the model gives at a constant applied voltage u (V)."""
        return self.K * (u - math.copysign(self.u_c, u)) if abs(u) > self.u_c else 0.0

    def level_se(self, u: float) -> float:
        """Standard error (rad/s) of :meth:`level` from the covariance of K and u_c."""
        if abs(u) <= self.u_c:
            return 0.0
        grad = np.zeros(self.covariance.cov.shape[0])
        grad[0] = u - math.copysign(self.u_c, u)
        if self.friction:
            grad[3] = -self.K * math.copysign(1.0, u)
        return math.sqrt(max(float(grad @ self.covariance.cov @ grad), 0.0))


def _compose_scan(a: FloatArray, b: FloatArray, c: FloatArray, x0: float) -> FloatArray:
    """x_0 = x0, x_{j+1} = max(a_j x_j + b_j, c_j) (a_j >= 0): all of x_0..x_m.

    The maps x -> max(a x + b, c) are closed under composition, (a2, b2, c2) after
    (a1, b1, c1) = (a2 a1, a2 b1 + b2, max(a2 c1 + b2, c2)), so the prefix compositions
    are built by doubling: log2(m) vector passes.
    """
    A, B, Cc = a.copy(), b.copy(), c.copy()
    k = 1
    while k < A.size:
        A2, B2, C2 = A.copy(), B.copy(), Cc.copy()
        A2[k:] = A[k:] * A[:-k]
        B2[k:] = A[k:] * B[:-k] + B[k:]
        C2[k:] = np.maximum(A[k:] * Cc[:-k] + B[k:], Cc[k:])
        A, B, Cc = A2, B2, C2
        k *= 2
    return np.concatenate(([x0], np.maximum(A * x0 + B, Cc)))


class _Model:
    """Angle of the model at the log's rows, with unit gain: the column K multiplies."""

    def __init__(self, t: FloatArray, u: FloatArray, edge_times: FloatArray) -> None:
        self.t = t - t[0]
        self.sign = 1.0 if np.all(u >= 0) else -1.0 if np.all(u <= 0) else 0.0
        uu = u * self.sign if self.sign else u
        change = np.flatnonzero(np.diff(uu) != 0) + 1
        bounds = np.concatenate(([0], change, [uu.size]))
        csum = np.concatenate(([0.0], np.cumsum(uu)))
        self.v = (csum[bounds[1:]] - csum[bounds[:-1]]) / np.diff(bounds)  # level of each run
        self.edge_t = edge_times[change] - t[0]
        self.first_rows = bounds[:-1]

    @property
    def can_stick(self) -> bool:
        """True when the voltage never changes sign (dry friction's stop is modelled then)."""
        return self.sign != 0.0

    def column(self, T: float, d: float, u_c: float) -> FloatArray:
        """The angle (rad per rad/s/V of K) at every row for time constant T (s), shift d (s)
        and breakaway voltage u_c (V)."""
        return self.response(T, d, u_c)[0]

    def response(self, T: float, d: float, u_c: float) -> tuple[FloatArray, FloatArray]:
        """The angle (as :meth:`column`) and the speed (rad/s per rad/s/V) at every row."""
        t = self.t
        s = np.concatenate(([0.0], np.maximum(self.edge_t + d, 0.0)))
        s = np.maximum.accumulate(s)
        end = max(float(t[-1]), float(s[-1])) + T
        L = np.diff(np.concatenate((s, [end])))
        E = np.exp(-L / T)
        w = self.v - u_c  # the level each run heads for while moving forward
        if self.can_stick:
            x0 = max(float(w[0]), 0.0)
            clamp = np.zeros(w.size - 1)
        else:
            x0 = float(w[0])
            clamp = np.full(w.size - 1, -np.inf)
        speed = _compose_scan(E[:-1], (1.0 - E[:-1]) * w[:-1], clamp, x0)
        stop = np.full(w.size, np.inf)
        if self.can_stick:
            slowing = (w < 0) & (speed > 0)
            ratio = np.where(slowing, (speed - w) / np.where(w < 0, -w, 1.0), 1.0)
            stop = np.where(slowing, T * np.log(ratio), stop)
            stop = np.where((w <= 0) & (speed <= 0), 0.0, stop)
        held = np.minimum(L, stop)
        gained = w * held - (speed - w) * T * np.expm1(-held / T)
        start_angle = np.concatenate(([0.0], np.cumsum(gained[:-1])))
        j = np.searchsorted(s, t, side="right") - 1
        since = t - s[j]
        x = np.minimum(since, stop[j])
        decay = np.exp(-x / T)
        angle: FloatArray = start_angle[j] + w[j] * x + (speed[j] - w[j]) * T * (1.0 - decay)
        now: FloatArray = np.where(since >= stop[j], 0.0, w[j] + (speed[j] - w[j]) * decay)
        return angle, now


class _Problem:
    """Variable projection: for (ln T, d[, u_c]) K and the angle offsets by least squares, one
    offset for the whole log (``starts`` = [0]) or one per stretch of rows (first rows in
    ``starts``)."""

    def __init__(
        self,
        model: _Model,
        theta: FloatArray,
        friction: bool,
        starts: NDArray[np.int64],
        weights: FloatArray,
    ) -> None:
        self.model = model
        self.theta = (theta - theta[0]) * (model.sign if model.sign else 1.0)
        self.friction = friction
        self.starts = starts
        self.w = weights  # 1 for a row the fit uses, 0 for one it leaves out
        self.counts = np.maximum(np.add.reduceat(weights, starts), 1e-300)
        self.group = np.repeat(np.arange(self.starts.size), np.diff(np.append(starts, theta.size)))
        self._last: tuple[bytes, tuple[FloatArray, FloatArray]] | None = None

    def response(self, x: FloatArray) -> tuple[FloatArray, FloatArray]:
        """The model's unit-gain angle and speed at x (the last one is kept: the search asks
        for the same point twice)."""
        key = x.tobytes()
        if self._last is None or self._last[0] != key:
            self._last = (key, self.model.response(*self.unpack(x)))
        return self._last[1]

    def demean(self, v: FloatArray) -> FloatArray:
        """v less its mean over the used rows of each cluster (the per-cluster angle offsets),
        zero at the rows left out."""
        w = self.w
        if v.ndim == 1:
            return w * (v - (np.add.reduceat(w * v, self.starts) / self.counts)[self.group])
        means = np.add.reduceat(w[:, None] * v, self.starts, axis=0) / self.counts[:, None]
        return w[:, None] * (v - means[self.group])

    def every_residual(self, x: FloatArray, K: float) -> FloatArray:
        """The angle residual (rad) at every row, those left out included (the offsets and K
        from the rows used)."""
        col = self.response(x)[0]
        out: FloatArray = self.theta - K * col
        means = np.add.reduceat(self.w * out, self.starts) / self.counts
        res: FloatArray = out - means[self.group]
        return res

    def unpack(self, x: FloatArray) -> tuple[float, float, float]:
        return math.exp(float(x[0])), float(x[1]), float(x[2]) if self.friction else 0.0

    @property
    def n_linear(self) -> int:
        """Linear parameters: K and the offsets."""
        return 1 + int(self.starts.size)

    def evaluate(self, x: FloatArray) -> tuple[float, FloatArray, FloatArray]:
        if not (np.all(np.isfinite(x)) and -20.0 < x[0] < 10.0):  # T from 2 ns to 6 hours
            return math.inf, np.zeros(1), np.full(self.theta.size, np.inf)
        col = self.response(x)[0]
        if not np.all(np.isfinite(col)):
            return math.inf, np.zeros(1), np.full(self.theta.size, np.inf)
        cc = self.demean(col)
        yc = self.demean(self.theta)
        denom = dot(cc, cc)
        K = dot(cc, yc) / denom if denom > 0 else 0.0
        r = yc - K * cc
        return dot(r, r), np.array([K]), r

    def derivatives(self, x: FloatArray, coef: FloatArray, central: bool = True) -> FloatArray:
        """d(model angle)/d x at fixed K, the offsets projected off: for the shift d minus the
        speed (moving every edge later delays the whole response; the log starts steady), for
        the others by central (or forward) differences."""
        K = float(coef[0])
        here, speed = self.response(x)
        out = np.empty((self.theta.size, x.size))
        for k in range(x.size):
            if k == 1:
                out[:, k] = -K * speed
                continue
            up = x.copy()
            up[k] += 1e-6
            if central:
                down = x.copy()
                down[k] -= 1e-6
                diff = self.model.column(*self.unpack(up)) - self.model.column(*self.unpack(down))
                out[:, k] = K * diff / 2e-6
            else:
                out[:, k] = K * (self.model.column(*self.unpack(up)) - here) / 1e-6
        return self.demean(out)

    def jacobian(self, x: FloatArray, coef: FloatArray) -> FloatArray:
        """d residual / d x with K and the offsets projected out (Kaufman's form)."""
        D = self.derivatives(x, coef, central=False)
        cc = self.demean(self.response(x)[0])
        return -(D - np.outer(cc, (cc @ D) / dot(cc, cc)))


T_FACTORS: tuple[float, ...] = (0.5, 0.7, 1.0, 1.4, 2.0)
"""Where the search for T starts, in multiples of the start's T."""


def _starts(
    problem: _Problem,
    start: FloatArray,
    shifts: tuple[float, ...] = (),
    factors: tuple[float, ...] = T_FACTORS,
    lower: FloatArray | None = None,
    upper: FloatArray | None = None,
) -> tuple[float, FloatArray]:
    """The best start of T at ``factors`` times the start's and the shift at the start's or
    at each of ``shifts`` (s), inside the box: (residual sum of squares, x)."""
    tries = []
    for d in shifts or (float(start[1]),):
        for f in factors:
            x = start.copy()
            x[0] += math.log(f)
            x[1] = d
            if lower is not None and upper is not None:
                x = np.clip(x, lower, upper)
            tries.append((problem.evaluate(x)[0], x))
    return min(tries, key=lambda pair: pair[0])


def _better(simple: Solution, rich: Solution, extra: int, n: int, p_rich: int, crit: float) -> bool:
    """True when ``rich`` (``extra`` more parameters) lowers the residual sum of squares by
    more than ``crit`` times ``extra`` residual variances of the richer model."""
    if not (math.isfinite(rich.rss) and rich.rss > 0):
        return False
    var = rich.rss / max(n - p_rich, 1)
    return (simple.rss - rich.rss) / extra > crit * var


def fit_whole_log(
    t: FloatArray,
    u: FloatArray,
    theta: FloatArray,
    T0: float,
    clusters: NDArray[np.int64],
    edge_times: list[FloatArray],
    offsets: bool,
    shift: tuple[float, float] = (-math.inf, math.inf),
    T_range: tuple[float, float] = (1e-9, 2e4),
    weights: FloatArray | None = None,
    shift_starts: tuple[float, ...] = (),
    T_factors: tuple[float, ...] = T_FACTORS,
    quantum: float | None = None,
    start_held: bool = False,
) -> WholeLogFit | None:
    """Fit the first-order model to the whole log.

    t: board times of the samples (s); u: applied voltage per row (V); theta: angle (rad); T0:
    where the search for T starts (s; the step-by-step fit's T); clusters: first rows of the
    stretches from each edge of the command to the next (the first at row 0); edge_times:
    where the voltage of each row may begin to act (s, one array per hypothesis; the one that
    fits best is kept); offsets: give each stretch its own angle offset (the edges' instants
    known only to within a jitter) instead of carrying the angle through every edge; shift:
    the range (s) the time shift of the edges may take; T_range: the range of T (s);
    weights: 1 for each row the fit uses, 0 for one it leaves out (default: all);
    shift_starts: shifts (s) the search may start from (default 0), each with T at
    ``T_factors`` times T0; quantum: the encoder's count (rad) when the angle is read in whole
    counts (None otherwise), for the rounding's share of the covariance
    (:func:`.lsq.cluster_covariance`). None when the voltage never changes.
    """
    th = np.asarray(theta, dtype=float)
    n = th.size
    w = np.ones(n) if weights is None else np.asarray(weights, dtype=float)
    starts = clusters if offsets and clusters.size > 1 else np.zeros(1, dtype=np.int64)
    lo = np.array([math.log(T_range[0]), shift[0]])
    hi = np.array([math.log(T_range[1]), shift[1]])
    start = np.clip(np.array([math.log(T0), 0.0]), lo, hi)
    candidates = []
    for when in edge_times:
        m = _Model(np.asarray(t, float), np.asarray(u, float), when)
        if m.v.size < 2:
            return None
        p = _Problem(m, th, False, starts, w)
        x0 = _starts(p, start, shift_starts, T_factors, lo, hi)[1]
        sol = least_squares(p.evaluate, p.jacobian, x0, lower=lo, upper=hi)
        candidates.append((sol.rss, sol, m, p))
    _, best, model, chosen = min(candidates, key=lambda c: c[0])
    if model.can_stick:
        stick = _Problem(model, th, True, starts, w)
        top = float(np.max(np.abs(u)))
        tries = [np.array([best.x[0], best.x[1], f * top]) for f in (0.0, 0.02, 0.05, 0.1, 0.2)]
        first = min(tries, key=lambda x: stick.evaluate(x)[0])
        lo3, hi3 = np.append(lo, -np.inf), np.append(hi, np.inf)
        with_c = least_squares(stick.evaluate, stick.jacobian, first, lower=lo3, upper=hi3)
        found = stick.unpack(with_c.x)[2] > 0  # a breakaway voltage, not a push
        used = int(np.count_nonzero(w))
        if found and _better(best, with_c, 1, used, chosen.n_linear + 3, FRICTION_F):
            best, chosen = with_c, stick
    T, d, u_c = chosen.unpack(best.x)
    D = chosen.derivatives(best.x, best.coef)
    D[:, 0] /= T  # d/d ln T -> d/d T
    on_bound = (best.x[:2] <= lo + 1e-9) | (best.x[:2] >= hi - 1e-9)
    D_free = D.copy()
    D[:, :2] = np.where(on_bound, 0.0, D[:, :2])  # a parameter held on its bound is not fitted
    col = chosen.demean(model.column(T, d, u_c))
    J = np.column_stack((col, D))  # (K, T, d[, u_c]), the offsets projected off
    lag = math.ceil(2.0 * T / max(float(np.median(np.diff(t))), 1e-9))  # two time constants
    sign = model.sign if model.sign else 1.0
    predicted = th - chosen.every_residual(best.x, float(best.coef[0])) * sign
    counts = None if quantum is None else (np.where(w > 0, predicted, np.nan), quantum)
    cov = cluster_covariance(J, best.residuals, clusters, lag, counts)
    start_free = None
    if start_held and on_bound[1] and best.x[1] <= lo[1] + 1e-9 and not on_bound[0]:
        J_free = np.column_stack((col, D_free))
        start_free = cluster_covariance(J_free, best.residuals, clusters, lag, counts)
    return WholeLogFit(
        T=T,
        d=d,
        K=float(best.coef[0]),
        u_c=u_c,
        friction=chosen.friction,
        offsets=chosen.starts.size > 1,
        rss=best.rss,
        n_params=chosen.n_linear + best.x.size,
        T_on_bound=bool(on_bound[0]),
        d_on_bound=bool(on_bound[1]),
        n_used=int(np.count_nonzero(w)),
        covariance=cov,
        residuals=best.residuals * sign,
        predicted=predicted,
        start_free=start_free,
    )
