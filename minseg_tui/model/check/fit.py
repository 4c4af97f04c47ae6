"""Fitting the first-order model and each candidate to a step log.

The residual is compared where its noise is white. The measured speed is a difference
of quantised angles, (theta_k - theta_k-N)/(N Ts), so its noise is differenced (lag-N
autocorrelation near -0.5); summing the residual with stride N, leakily,

    e_k = r_k + rho e_k-N        (rho = 0.9)

undoes the difference (whitening the quantisation noise) while a slow model error is
only amplified tenfold instead of piling up as it would in the raw angle. The filter is
monic, so the whitened sums of squares of candidates with different N compare fairly.

For given T and effect parameter the response is proportional to K, which is solved by
linear least squares; T (log scale) and the parameter are searched on a grid and polished
with golden-section / Nelder-Mead searches (:mod:`.search`). Rows flagged as wild (weight 0)
do not count.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check.candidates import BY_CAUSE, Candidate, Effects, angle, response
from minseg_tui.model.check.search import golden, nelder_mead
from minseg_tui.model.check.simulate import Stretches

FloatArray = NDArray[np.float64]

RHO = 0.9
"""Leak of the whitening sum (1 would be the pure angle domain)."""

T_BOUNDS = (0.002, 3.0)
"""Search range of the time constant T, s."""

MAX_FIT_ROWS = 2400
"""Longer logs are fitted on their first rows only (60 s at 40 Hz) and simulated whole."""


def whiten(x: FloatArray, taps: int = 1) -> FloatArray:
    """e_k = x_k + RHO e_k-taps: the leaky stride-``taps`` sum that whitens differenced noise.

    Vectorised in blocks of ``_BLOCK`` strides (a scaled cumulative sum inside a block, the
    carry between blocks as a short geometric sum, since RHO^_BLOCK is tiny).
    """
    x = np.asarray(x, dtype=float)
    n = x.size
    rows = -(-n // taps)
    nb = -(-rows // _BLOCK)
    buf = np.zeros(nb * _BLOCK * taps)
    buf[:n] = x
    y = buf.reshape(nb, _BLOCK, taps)
    inner = np.cumsum(y * _INV[None, :, None], axis=1) * _POW[None, :, None]
    ends = inner[:, -1, :]
    carry = np.zeros_like(ends)  # e at the end of the previous block
    acc = np.zeros_like(ends)
    q = 1.0
    for i in range(_CARRY_TERMS):
        if i + 1 < nb:
            acc[i + 1 :] += q * ends[: nb - i - 1]
        q *= RHO**_BLOCK
    carry[:] = acc
    out = inner + _POW1[None, :, None] * carry[:, None, :]
    return out.reshape(-1)[:n]


_BLOCK = 32
_POW = RHO ** np.arange(_BLOCK)
_INV = 1.0 / _POW
_POW1 = RHO ** np.arange(1, _BLOCK + 1)
_CARRY_TERMS = 8  # (RHO^32)^8 < 1e-11


@dataclass
class Problem:
    """A step log ready to fit: t (s), u (V, held from each row on), y measured speed (rad/s).

    ts: nominal sample period, s; z0: initial speed in K = 1 units (V), None for steady
    state under the first input; weights: 1 for rows
    that count, 0 for wild rows.
    """

    t: FloatArray
    u: FloatArray
    y: FloatArray
    ts: float
    z0: float | None = 0.0
    weights: FloatArray = field(default_factory=lambda: np.zeros(0))
    _yw: dict[int, FloatArray] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if self.weights.size != self.y.size:
            self.weights = np.ones(self.y.size)
        self.st = Stretches.from_samples(self.t, self.u)

    def y_white(self, taps: int) -> FloatArray:
        if taps not in self._yw:
            self._yw[taps] = whiten(self.y, taps)
        return self._yw[taps]

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
        )


@dataclass(frozen=True)
class Fit:
    """A fitted model: cause ('none' for the first-order baseline), T (s), K (rad/s/V), the
    cause's parameter, the effects it simulates, and the whitened sum of squares it reached."""

    cause: str
    T: float
    K: float
    params: dict[str, float]
    effects: Effects
    sse_white: float
    rows: int

    def predict(self, prob: Problem) -> FloatArray:
        """Simulated measured speed on every row of ``prob``, rad/s."""
        return self.K * response(prob.st, prob.t, prob.ts, self.T, self.effects, prob.z0)


def _score(prob: Problem, T: float, fx: Effects) -> tuple[float, float]:
    """(whitened SSE, K) of the model (T, fx) with the best K."""
    return _score_response(prob, response(prob.st, prob.t, prob.ts, T, fx, prob.z0), fx.taps)


def _score_response(prob: Problem, g: FloatArray, taps: int) -> tuple[float, float]:
    """(whitened SSE, K) of the response g (K = 1) measured with ``taps``, with the best K."""
    gw = whiten(g, taps)
    yw = prob.y_white(taps)
    w = prob.weights
    den = float(np.dot(w * gw, gw))
    if den <= 0.0 or not math.isfinite(den):
        return math.inf, 0.0
    k = float(np.dot(w * gw, yw)) / den
    r = yw - k * gw
    return float(np.dot(w * r, r)), k


def _best_T(prob: Problem, fx: Effects, grid: FloatArray | None = None) -> tuple[float, float]:
    """(T, SSE) minimising over T for fixed effects: log grid, then Brent in the best bracket."""
    lo, hi = math.log(T_BOUNDS[0]), math.log(T_BOUNDS[1])
    xs = np.linspace(lo, hi, 16) if grid is None else np.log(grid)
    vals = [_score(prob, math.exp(x), fx)[0] for x in xs]
    i = int(np.argmin(vals))
    a, b = xs[max(i - 1, 0)], xs[min(i + 1, xs.size - 1)]
    x, fx_val = golden(lambda x: _score(prob, math.exp(x), fx)[0], a, b, xatol=1e-4)
    if fx_val < vals[i]:
        return math.exp(x), fx_val
    return math.exp(float(xs[i])), float(vals[i])


def fit_baseline(prob: Problem) -> Fit:
    """The first-order model T w' = -w + K u, fitted on the whitened residual."""
    T, sse = _best_T(prob, Effects())
    _, K = _score(prob, T, Effects())
    return Fit("none", T, K, {}, Effects(), sse, int(prob.weights.sum()))


def _param_grid(c: Candidate, prob: Problem) -> FloatArray:
    if c.cause == "coulomb_friction":
        top = min(
            c.hi, 0.9 * float(np.min(np.abs(prob.st.value[prob.st.value != 0]), initial=c.hi))
        )
        return np.linspace(0.0, top, 13)[1:]
    if c.log_scale:
        return np.geomspace(c.lo, c.hi, 14)
    return np.linspace(c.lo, c.hi, 13)[1:]


def _within(grid: FloatArray) -> FloatArray:
    """A grid of T (s) taken into T_BOUNDS: values outside move to the nearest bound, once."""
    return np.unique(np.clip(grid, *T_BOUNDS))


def fit_candidate(prob: Problem, c: Candidate, base: Fit, extra: Effects | None = None) -> Fit:
    """Fit the baseline plus the candidate's effect (on top of ``extra`` effects, if any)."""
    extra = extra or Effects()
    tgrid = _within(base.T * np.geomspace(0.25, 4.0, 9))

    def fx_of(p: float) -> Effects:
        d = {**_asdict(extra), c.param: p}
        return Effects.of(d)

    if c.integer:  # taps: the angle does not depend on it, so simulate once per T
        best = (math.inf, base.T, 1)
        for T in _within(base.T * np.geomspace(0.2, 2.0, 13)):
            top = int(c.hi)
            before = prob.t[0] - prob.ts * np.arange(top, 0, -1)
            theta = angle(prob.st, np.concatenate((before, prob.t)), T, extra, prob.z0)
            for taps in range(int(c.lo), top + 1):
                g = (theta[top:] - theta[top - taps : theta.size - taps]) / (taps * prob.ts)
                sse = _score_response(prob, g, taps)[0]
                if sse < best[0]:
                    best = (sse, T, taps)
        tries = []
        for p in range(max(int(c.lo), best[2] - 1), min(int(c.hi), best[2] + 1) + 1):
            tries.append(
                (*_best_T(prob, fx_of(p), _within(best[1] * np.geomspace(0.7, 1.4, 5))), p)
            )
        T, sse, p = min(tries, key=lambda r: r[1])
        _, K = _score(prob, T, fx_of(p))
        return Fit(c.cause, T, K, {c.param: float(p)}, fx_of(p), sse, base.rows)

    grid = _param_grid(c, prob)
    results = [(*_best_T(prob, fx_of(p), tgrid), p) for p in grid]
    T0, sse0, p0 = min(results, key=lambda r: r[1])
    scale = float(grid[-1] - grid[0]) / max(len(grid) - 1, 1)

    def obj(x: FloatArray) -> float:
        p = math.exp(x[1]) if c.log_scale else x[1]
        hi = grid[-1] if c.cause == "coulomb_friction" else c.hi
        T = math.exp(x[0])
        if not (c.lo <= p <= hi and T_BOUNDS[0] <= T <= T_BOUNDS[1]):
            return math.inf
        return _score(prob, T, fx_of(p))[0]

    x0 = np.array([math.log(T0), math.log(p0) if c.log_scale else p0])
    step = np.array([0.15, 0.3 if c.log_scale else scale * 0.5])
    x, val = nelder_mead(obj, x0, step)
    if val < sse0:
        T0, sse0 = math.exp(float(x[0])), val
        p0 = math.exp(float(x[1])) if c.log_scale else float(x[1])
    if c.cause == "second_pole" and p0 > T0:  # two poles in series are symmetric: T2 is the faster
        T0, p0 = p0, T0
    _, K = _score(prob, T0, fx_of(p0))
    return Fit(c.cause, T0, K, {c.param: float(p0)}, fx_of(p0), sse0, base.rows)


def _asdict(fx: Effects) -> dict[str, float]:
    out: dict[str, float] = {}
    if fx.u_c:
        out["u_c"] = fx.u_c
    if fx.delay:
        out["delay"] = fx.delay
    if fx.taps != 1:
        out["taps"] = fx.taps
    if fx.T_coast is not None:
        out["T_coast"] = fx.T_coast
    if fx.T2:
        out["T2"] = fx.T2
    return out


def fit_all(prob: Problem, base: Fit) -> dict[str, Fit]:
    """Every candidate fitted alone on top of the baseline."""
    return {name: fit_candidate(prob, c, base) for name, c in BY_CAUSE.items()}
