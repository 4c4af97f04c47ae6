"""95 % intervals that hold for the step fits' least-squares parameters (the search itself
is :func:`minseg_tui.model.optimize.least_squares`).

The intervals do not trust the residuals to be independent. What a fit leaves out is
correlated in time: the rounding of a slowly turning encoder repeats, a step that the log
places a little late or early shifts a whole transient, and the speed of a real wheel wanders.
So the covariance is the cluster-robust ("sandwich") estimate with the log cut into clusters
of rows that belong together (the stretch after each edge): errors inside a cluster may be
correlated in any way, clusters are taken as independent. Its Student t quantile has as many
degrees of freedom as there are clusters less one. A log with a single step has too few
clusters for that; its rows' correlation over a couple of time constants is estimated then,
and where the angle is whole encoder counts the spread the counts' rounding gives the
parameters is added to it (that estimate alone is low on one step: see
:func:`cluster_covariance`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


def _t_cdf(x: float, dof: int) -> float:
    """P(T <= x) for Student's t with a whole number ``dof`` of degrees of freedom, from its
    finite series (Abramowitz and Stegun 26.7.3-4)."""
    theta = math.atan2(x, math.sqrt(dof))
    s, c = math.sin(theta), math.cos(theta)
    if dof % 2:  # odd: 2 theta / pi + 2 / pi sin cos (1 + 2/3 cos^2 + ...)
        term, total = c, c if dof > 1 else 0.0
        for k in range(3, dof - 1, 2):
            term *= c * c * (k - 1) / k
            total += term
        a = (2.0 * theta + 2.0 * s * total) / math.pi
    else:  # even: sin (1 + 1/2 cos^2 + 1.3/2.4 cos^4 + ...)
        term = total = 1.0
        for k in range(2, dof - 1, 2):
            term *= c * c * (k - 1) / k
            total += term
        a = s * total
    return 0.5 + 0.5 * a


_Z975 = 1.959963984540054


def t975(dof: int) -> float:
    """The 97.5 % quantile of Student's t with ``dof`` degrees of freedom (at least 1): up to
    30 the root of the distribution function (Newton's method from the normal quantile),
    beyond that the Cornish-Fisher expansion (error below 1e-7)."""
    if dof < 1:
        raise ValueError("a t quantile needs at least one degree of freedom")
    z, v = _Z975, float(dof)
    if dof <= 30:
        norm = math.gamma((v + 1) / 2) / (math.sqrt(v * math.pi) * math.gamma(v / 2))
        x = z
        for _ in range(30):
            step = (_t_cdf(x, dof) - 0.975) / (norm * (1 + x * x / v) ** (-(v + 1) / 2))
            x -= step
            if abs(step) < 1e-13 * x:
                break
        return x
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


ROUNDING_PHASES: int = 32
"""How many phases of the encoder's grid against the fitted angle :func:`rounding_errors`
lays out (evenly, so the same log gives the same interval)."""


def rounding_errors(predicted: FloatArray, quantum: float) -> FloatArray:
    """The errors (rad) the encoder's rounding would leave on the angle ``predicted`` (rad)
    read as whole counts of ``quantum`` rad, one row per phase of the counts' grid
    (:data:`ROUNDING_PHASES` phases, evenly spaced): ``quantum`` floor(predicted / quantum +
    phase) less ``predicted``. NaN rows (not fitted, left out) give 0."""
    phases = (np.arange(ROUNDING_PHASES) + 0.5) / ROUNDING_PHASES
    x = np.where(np.isfinite(predicted), predicted, 0.0) / quantum
    out: FloatArray = quantum * (np.floor(x[None, :] + phases[:, None]) - x[None, :])
    return out


def cluster_covariance(
    J: FloatArray,
    r: FloatArray,
    starts: NDArray[np.int64],
    lag: int,
    counts: tuple[FloatArray, float] | None = None,
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
    with n - p degrees of freedom. That estimate is low on a single step: the scores of its
    rows sum to zero at the optimum, so the lagged sums that should hold their correlation
    cancel. Where the angle is read in whole counts, ``counts`` (the fitted angle at the n
    rows, rad, NaN at a row left out, and the count, rad) adds the spread the rounding alone
    gives the parameters over the phases of the counts' grid against the fitted angle
    (:func:`rounding_errors`; linearised: (J^T J)^-1 J^T e for each phase's errors e): on a slow wheel's coarse counts the rounding error follows the
    angle's slow sweep across the grid, and the residuals of one rise do not show how much of
    T it can move (tests/model/identgen.py at 5 ms, one rise of 2-5 counts a sample: T's
    spread 0.9 ms where the lagged estimate gave 0.45).
    """
    n, p = J.shape
    C = int(starts.size)
    bread = np.einsum("ni,nj->ij", J, J)
    inv = np.linalg.pinv(bread)
    if C < FEW_CLUSTERS:
        g = J * r[:, None]
        meat = _lagged_meat(g, min(max(lag, 0), n - 1), lag)
        cov = inv @ meat @ inv * n / max(n - p, 1)
        if counts is not None:
            rounding = rounding_errors(*counts)
            moved = rounding @ J  # phases x p: what each phase's rounding moves the scores by
            moved -= moved.mean(axis=0)
            cov = cov + inv @ (moved.T @ moved / rounding.shape[0]) @ inv
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
