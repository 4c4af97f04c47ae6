"""Least squares with a few nonlinear parameters, and 95 % intervals that hold.

The step fits are separable: for given nonlinear parameters (T, a time shift, a friction
voltage) the model is linear in the rest, which a linear solve gives exactly (variable
projection). :func:`levenberg_marquardt` searches the nonlinear ones.

The intervals do not trust the residuals to be independent. What a fit leaves out is
correlated in time: the rounding of a slowly turning encoder repeats, a step that the log
places a little late or early shifts a whole transient, and the speed of a real wheel wanders.
So the covariance is the cluster-robust ("sandwich") estimate with the log cut into clusters
of rows that belong together (the stretch after each edge): errors inside a cluster may be
correlated in any way, clusters are taken as independent. Its Student t quantile has as many
degrees of freedom as there are clusters less one. A log with a single step has too few
clusters for that; its rows' correlation over a couple of time constants is estimated then.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

T975: tuple[float, ...] = (
    12.706205,
    4.302653,
    3.182446,
    2.776445,
    2.570582,
    2.446912,
    2.364624,
    2.306004,
    2.262157,
    2.228139,
    2.200985,
    2.178813,
    2.160369,
    2.144787,
    2.13145,
    2.119905,
    2.109816,
    2.100922,
    2.093024,
    2.085963,
    2.079614,
    2.073873,
    2.068658,
    2.063899,
    2.059539,
    2.055529,
    2.051831,
    2.048407,
    2.04523,
    2.042272,
)
"""The 97.5 % quantile of Student's t for 1-30 degrees of freedom (from scipy.stats.t.ppf)."""

_Z975 = 1.959963984540054


def t975(dof: int) -> float:
    """The 97.5 % quantile of Student's t with ``dof`` degrees of freedom (at least 1): from
    :data:`T975` up to 30, beyond that the Cornish-Fisher expansion (error below 1e-7)."""
    if dof < 1:
        raise ValueError("a t quantile needs at least one degree of freedom")
    if dof <= len(T975):
        return T975[dof - 1]
    z, v = _Z975, float(dof)
    return (
        z
        + (z**3 + z) / (4 * v)
        + (5 * z**5 + 16 * z**3 + 3 * z) / (96 * v**2)
        + (3 * z**7 + 19 * z**5 + 17 * z**3 - 15 * z) / (384 * v**3)
        + (79 * z**9 + 776 * z**7 + 1482 * z**5 - 1920 * z**3 - 945 * z) / (92160 * v**4)
    )


def dot(a: FloatArray, b: FloatArray) -> float:
    """The sum of a_i b_i of two long vectors. (Not ``a @ b``: a threaded BLAS dot of a long
    vector can take a hundred times longer on a busy machine.)"""
    return float(np.einsum("i,i->", a, b))


Evaluate = Callable[[FloatArray], tuple[float, FloatArray, FloatArray]]
"""x -> (residual sum of squares, linear coefficients, residuals) for nonlinear parameters x."""

Jacobian = Callable[[FloatArray, FloatArray], FloatArray]
"""(x, coefficients) -> d residual / d x, one column per nonlinear parameter."""


@dataclass(frozen=True)
class Solution:
    """Where :func:`levenberg_marquardt` stopped: the nonlinear parameters ``x``, the residual
    sum of squares ``rss``, the linear coefficients and the residuals there."""

    x: FloatArray
    rss: float
    coef: FloatArray
    residuals: FloatArray
    iterations: int


def levenberg_marquardt(
    evaluate: Evaluate,
    jacobian: Jacobian,
    x0: FloatArray,
    max_iter: int = 60,
    xtol: float = 1e-9,
    lower: FloatArray | None = None,
    upper: FloatArray | None = None,
) -> Solution:
    """Minimise the residual sum of squares over the nonlinear parameters from ``x0``.

    Marquardt's damping on the Gauss-Newton step, scaled by the diagonal of J^T J; a step
    is taken only when it lowers the sum. Stops when a step changes no parameter by more
    than ``xtol`` (in the units of x) or after ``max_iter`` steps. ``lower`` and ``upper``
    (default: none) box the parameters in: a parameter on its bound whose gradient points out
    of the box is held there while the others move, and every step is clipped to the box.
    """
    lo = np.full(len(x0), -np.inf) if lower is None else np.asarray(lower, dtype=float)
    hi = np.full(len(x0), np.inf) if upper is None else np.asarray(upper, dtype=float)
    x = np.clip(np.asarray(x0, dtype=float), lo, hi)
    rss, coef, r = evaluate(x)
    lam = 1e-3
    it = 0
    for it in range(1, max_iter + 1):  # noqa: B007 (the count is returned)
        J = jacobian(x, coef)
        A = J.T @ J
        g = J.T @ r
        held = ((x <= lo) & (g > 0)) | ((x >= hi) & (g < 0))  # pushing out of the box
        A = np.where(held[:, None] | held[None, :], 0.0, A)
        g = np.where(held, 0.0, g)
        diag = np.where(held, 1.0, np.maximum(np.diag(A), 1e-300))
        A[held, held] = 1.0
        taken = False
        while lam < 1e12:
            try:
                step = np.linalg.solve(A + lam * np.diag(diag), -g)
            except np.linalg.LinAlgError:
                lam *= 10.0
                continue
            trial = np.clip(x + step, lo, hi)
            step = trial - x
            rss_t, coef_t, r_t = evaluate(trial)
            if math.isfinite(rss_t) and rss_t <= rss:
                lam = max(lam / 10.0, 1e-12)
                taken = True
                break
            lam *= 10.0
        if not taken:
            break
        done = float(np.max(np.abs(step))) <= xtol
        x, rss, coef, r = trial, rss_t, coef_t, r_t
        if done:
            break
    return Solution(x=x, rss=rss, coef=coef, residuals=r, iterations=it)


@dataclass(frozen=True)
class Covariance:
    """A cluster-robust covariance ``cov`` of the parameters, with the degrees of freedom
    ``dof`` of its t quantile and the number of ``clusters`` it rests on."""

    cov: FloatArray
    dof: int
    clusters: int

    def half_width(self, index: int) -> float:
        """Half the 95 % interval of parameter ``index``."""
        return t975(self.dof) * math.sqrt(max(float(self.cov[index, index]), 0.0))


def _lagged_meat(g: FloatArray, top: int, lag: int) -> FloatArray:
    """sum over k = -top..top of (1 - |k| / (lag + 1)) sum_n g_n+k g_n^T (Newey and West):
    row by row for a few lags, else every lag at once through the FFT of each column pair."""
    n, p = g.shape
    meat: FloatArray = np.einsum("ni,nj->ij", g, g)
    if top < 32:
        for k in range(1, top + 1):
            cross = np.einsum("ni,nj->ij", g[k:], g[:-k])
            meat += (1.0 - k / (lag + 1.0)) * (cross + cross.T)
        return meat
    size = 1 << int(math.ceil(math.log2(2 * n)))
    F = np.fft.rfft(g, n=size, axis=0)
    w = 1.0 - np.arange(1, top + 1) / (lag + 1.0)
    S = np.empty((p, p))
    for i in range(p):
        for j in range(p):
            cross = np.fft.irfft(F[:, i] * np.conj(F[:, j]), n=size)[1 : top + 1]
            S[i, j] = float(w @ cross)  # sum over k of w_k sum_n g_n+k,i g_n,j
    out: FloatArray = meat + S + S.T
    return out


MANY_CLUSTERS: int = 64
"""Above this many clusters the delete-one-cluster shifts use the full fit's J^T J."""

FEW_CLUSTERS: int = 4
"""Below this many clusters (a log with one step) the rows' own correlation is estimated."""


def cluster_covariance(
    J: FloatArray, r: FloatArray, starts: NDArray[np.int64], lag: int
) -> Covariance:
    """The sandwich covariance (J^T J)^-1 (sum_c s_c s_c^T) (J^T J)^-1 of least-squares
    parameters, with s_c = J_c^T r_c summed over the rows of cluster c.

    J: n x p derivatives of the model with respect to the parameters (the linear ones as
    columns of the design; for nuisance parameters that belong to one cluster only, the
    columns of the others projected off them); r: the n residuals; starts: the first row of
    each cluster (rows in order, clusters contiguous). Each cluster's score is taken out of
    the fit first (the delete-one-cluster or jackknife form), which keeps the estimate honest
    with a handful of clusters; dof = clusters - 1. With fewer than :data:`FEW_CLUSTERS`
    clusters (one step: taking it out leaves nothing to fit) the covariance of neighbouring
    rows' scores up to ``lag`` rows apart is estimated instead (Newey and West's weights),
    with n - p degrees of freedom.
    """
    n, p = J.shape
    C = int(starts.size)
    bread = np.einsum("ni,nj->ij", J, J)
    inv = np.linalg.pinv(bread)
    if C < FEW_CLUSTERS:
        g = J * r[:, None]
        meat = _lagged_meat(g, min(max(lag, 0), n - 1), lag)
        cov = inv @ meat @ inv * n / max(n - p, 1)
        return Covariance(cov=cov, dof=max(n - p, 1), clusters=C)
    scores = np.add.reduceat(J * r[:, None], starts, axis=0)  # C x p
    if C <= MANY_CLUSTERS:
        # without cluster c the parameters move by (B - B_c)^-1 s_c
        ends = np.concatenate((starts[1:], [n]))
        shifts = np.empty((C, p))
        for c in range(C):
            Jc = J[starts[c] : ends[c]]
            shifts[c] = np.linalg.pinv(bread - np.einsum("ni,nj->ij", Jc, Jc)) @ scores[c]
    else:  # each cluster holds little of the information: (B - B_c)^-1 ~ B^-1
        shifts = scores @ inv.T
    centred = shifts - shifts.mean(axis=0)
    cov = (C - 1) / C * (centred.T @ centred)
    return Covariance(cov=cov, dof=max(C - 1, 1), clusters=C)
