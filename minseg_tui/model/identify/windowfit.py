"""The first-order response fitted to each rise on its own, T shared: the fit for logs
the whole-log model does not explain (a coasting wheel, a speed that wanders between steps).

Around each rise at t_e, with s = t - t_e - d (d: a time shift of the steps against
the samples, shared, a nuisance parameter), the angle is

    before the step:  theta = a + w0 s + c s^2 / 2
    after the step:   theta = a + w0 T (1 - e^(-s/T)) + w1 (s - T (1 - e^(-s/T)))

(the integral of a first-order response from speed w0 towards w1; c lets the speed before
the step change steadily, a wheel still slowing down from the step before). a, w0, c and w1
belong to each step, so dry friction (which lowers w1) and whatever happened between the
steps do not bias T. When the wheel stands still before a step, the rows before it repeat
one reading: they count once (the step's row) and w0 = c = 0. For given (T, d) the rest is
linear, and all steps are solved at once as small batched systems (time O(rows)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.identify.lsq import Covariance, cluster_covariance, dot
from minseg_tui.model.identify.rises import RiseWindow
from minseg_tui.model.optimize import least_squares

FloatArray = NDArray[np.float64]

_P = 4  # columns: a, w0, w1, c


@dataclass(frozen=True)
class WindowsFit:
    """T (s) and the time shift d (s) (each maybe on its bound) with their cluster-robust
    covariance (one cluster per step), each step's final speed w1 (rad/s) with its standard error, the residuals (rad) and
    the model's angle (rad) at the rows used (``rows``, in window order); ``start_free``: where
    d was held on its lower bound as a choice, the covariance with d fitted there too."""

    T: float
    d: float
    rss: float
    n_params: int
    T_on_bound: bool
    d_on_bound: bool
    covariance: Covariance
    omega_ss: FloatArray
    omega_ss_se: FloatArray
    rows: NDArray[np.int64]
    residuals: FloatArray
    predicted: FloatArray
    start_free: Covariance | None = None


class _Problem:
    def __init__(
        self,
        t: FloatArray,
        theta: FloatArray,
        windows: list[RiseWindow],
        keep: NDArray[np.bool_] | None = None,
    ) -> None:
        taus, ths, rows_all, seg, still, npre = [], [], [], [], [], []
        for i, w in enumerate(windows):
            k = w.edge.start
            rows = w.rows if keep is None else w.rows[keep[w.rows] | (w.rows == k)]
            at_rest = bool(np.all(theta[w.pre_from : k + 1] == theta[k]))
            if at_rest:
                rows = rows[rows >= k]
            taus.append(t[rows] - t[k])
            ths.append(theta[rows] - theta[k])
            rows_all.append(rows)
            seg.append(np.full(rows.size, i))
            still.append(at_rest)
            npre.append(int(np.count_nonzero(rows <= k)))
        self.tau = np.concatenate(taus)
        self.theta = np.concatenate(ths)
        self.rows = np.concatenate(rows_all)
        self.seg = np.concatenate(seg)
        self.starts = np.flatnonzero(np.concatenate(([True], np.diff(self.seg) != 0)))
        mask = np.ones((len(windows), _P), dtype=bool)
        rest = np.array(still)
        mask[rest, 1] = False
        mask[rest, 3] = False
        mask[np.array(npre) < 4, 3] = False
        self.mask = mask
        self.row_mask = mask[self.seg]

    def basis(self, T: float, d: float) -> FloatArray:
        s = self.tau - d
        after = s >= 0
        sa = np.where(after, s, 0.0)
        g = -T * np.expm1(-sa / T)
        B = np.empty((s.size, _P))
        B[:, 0] = 1.0
        B[:, 1] = np.where(after, g, s)
        B[:, 2] = np.where(after, sa - g, 0.0)
        B[:, 3] = np.where(after, 0.0, 0.5 * s * s)
        return np.where(self.row_mask, B, 0.0)

    def normal(self, B: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Per-step normal matrices, scaled to unit diagonal, and the scales."""
        M = np.add.reduceat(B[:, :, None] * B[:, None, :], self.starts, axis=0)
        diag = np.einsum("gii->gi", M).copy()
        diag[~self.mask | (diag <= 0)] = 1.0
        scale = 1.0 / np.sqrt(diag)
        Ms = M * scale[:, :, None] * scale[:, None, :]
        idx = np.arange(_P)
        Ms[:, idx, idx] = np.where(self.mask, Ms[:, idx, idx], 1.0)
        return Ms, scale

    def project(self, B: FloatArray, y: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Per-step least squares of y on B: the coefficients (steps x 4) and the residual."""
        Ms, scale = self.normal(B)
        b = np.add.reduceat(B * y[:, None], self.starts, axis=0) * scale
        c = np.linalg.solve(Ms, b[:, :, None])[:, :, 0] * scale
        c[~self.mask] = 0.0
        return c, y - np.einsum("nj,nj->n", B, c[self.seg])

    def evaluate(self, x: FloatArray) -> tuple[float, FloatArray, FloatArray]:
        if not (np.all(np.isfinite(x)) and -20.0 < x[0] < 10.0):  # T from 2 ns to 6 hours
            return math.inf, np.zeros(self.mask.size), np.full(self.tau.size, np.inf)
        T, d = math.exp(float(x[0])), float(x[1])
        c, r = self.project(self.basis(T, d), self.theta)
        return dot(r, r), c.ravel(), r

    def derivatives(self, x: FloatArray, coef: FloatArray) -> FloatArray:
        """d(model angle)/d(ln T, d) at fixed per-step coefficients, by central differences."""
        T, d = math.exp(float(x[0])), float(x[1])
        c = coef.reshape(-1, _P)[self.seg]
        hT, hd = 1e-6, 1e-6 * T
        dT = np.einsum(
            "nj,nj->n", self.basis(T * math.exp(hT), d) - self.basis(T / math.exp(hT), d), c
        )
        dd = np.einsum("nj,nj->n", self.basis(T, d + hd) - self.basis(T, d - hd), c)
        return np.column_stack((dT / (2 * hT), dd / (2 * hd)))

    def jacobian(self, x: FloatArray, coef: FloatArray) -> FloatArray:
        """d residual / d(ln T, d) with each step's own terms projected out."""
        B = self.basis(math.exp(float(x[0])), float(x[1]))
        D = self.derivatives(x, coef)
        return -np.column_stack([self.project(B, D[:, k])[1] for k in range(D.shape[1])])


def fit_windows(
    t: FloatArray,
    theta: FloatArray,
    windows: list[RiseWindow],
    ts: float,
    shift: tuple[float, float] = (-math.inf, math.inf),
    T_range: tuple[float, float] = (1e-9, 2e4),
    keep: NDArray[np.bool_] | None = None,
    shift_starts: tuple[float, ...] = (0.0,),
    T_starts: tuple[float, ...] = (),
    quantum: float | None = None,
    start_held: bool = False,
) -> WindowsFit:
    """Fit T and the time shift to the rises' windows: board times ``t`` (s), angle
    ``theta`` (rad) at every row, the usable ``windows``; ``ts``: sample period (s); shift:
    the range (s) of the time shift; T_range: the range of T (s); keep: the rows the fit may
    use (default: all); shift_starts: the shifts (s) the search may start from, each with T
    at ``T_starts`` (s; default: a grid from ts/20 to the longest step); quantum: the
    encoder's count (rad) when the angle is read in whole counts (None otherwise), for the
    rounding's share of the covariance (:func:`.lsq.cluster_covariance`); start_held: the
    shift's lower bound is a start the fit is held to, not a limit of the log (see
    :func:`.wholelog.fit_whole_log`)."""
    prob = _Problem(np.asarray(t, float), np.asarray(theta, float), windows, keep)
    lo = np.array([math.log(T_range[0]), shift[0]])
    hi = np.array([math.log(T_range[1]), shift[1]])
    longest = float(np.max(prob.tau))
    grid = (
        np.array(T_starts)
        if T_starts
        else np.geomspace(max(ts / 20.0, 1e-4, T_range[0]), min(max(longest, ts), T_range[1]), 24)
    )
    tries = [np.clip(np.array([math.log(float(T)), d]), lo, hi) for d in shift_starts for T in grid]
    start = min(tries, key=lambda x: prob.evaluate(x)[0])
    sol = least_squares(prob.evaluate, prob.jacobian, start, lower=lo, upper=hi)
    T, d = math.exp(float(sol.x[0])), float(sol.x[1])
    J = -prob.jacobian(sol.x, sol.coef)  # the derivatives with each step's own terms projected off
    J[:, 0] /= T
    on_bound = (sol.x <= lo + 1e-9) | (sol.x >= hi - 1e-9)
    J_free = J
    J = np.where(on_bound, 0.0, J)  # a parameter held on its bound is not fitted
    lag = math.ceil(2.0 * T / ts)  # two time constants
    predicted = theta[prob.rows] - sol.residuals
    counts = None if quantum is None else (predicted, quantum)
    cov = cluster_covariance(J, sol.residuals, prob.starts, lag, counts)
    start_free = None
    if start_held and on_bound[1] and sol.x[1] <= lo[1] + 1e-9 and not on_bound[0]:
        start_free = cluster_covariance(J_free, sol.residuals, prob.starts, lag, counts)
    coef = sol.coef.reshape(-1, _P)
    B = prob.basis(T, d)
    Ms, scale = prob.normal(B)
    inv = np.linalg.inv(Ms) * scale[:, :, None] * scale[:, None, :]
    n_rows = np.diff(np.concatenate((prob.starts, [prob.tau.size])))
    n_par = prob.mask.sum(axis=1)
    rss_each = np.add.reduceat(sol.residuals**2, prob.starts)
    var = rss_each / np.maximum(n_rows - n_par, 1)
    se = np.sqrt(np.maximum(inv[:, 2, 2] * var, 0.0))
    return WindowsFit(
        T=T,
        d=d,
        rss=sol.rss,
        n_params=int(prob.mask.sum()) + 2,
        T_on_bound=bool(on_bound[0]),
        d_on_bound=bool(on_bound[1]),
        covariance=cov,
        omega_ss=coef[:, 2].copy(),
        omega_ss_se=se,
        rows=prob.rows,
        residuals=sol.residuals,
        predicted=predicted,
        start_free=start_free,
    )
