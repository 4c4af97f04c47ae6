"""The fits' two minimisers, shared by identify and the model check: Levenberg-Marquardt for
least squares in a box, and golden section for one parameter.

Both problems are separable: for given nonlinear parameters (T, a time shift, a cause's
parameter) the model is linear in the rest (K, offsets), which the caller solves exactly
(variable projection). :func:`least_squares` searches the nonlinear ones; the caller says
how the residual and its derivatives are computed.

Written here rather than taken from scipy.optimize.least_squares: that finds the same
minima, but importing scipy.optimize costs more CPU than the fits of a log take
(benchmarks/lsq_engine.py measures both), and the CLI pays it on every run.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

Evaluate = Callable[[FloatArray], tuple[float, FloatArray, FloatArray]]
"""x -> (residual sum of squares, linear coefficients, residuals) for nonlinear parameters x
(an infinite sum marks a point where the model fails)."""

Jacobian = Callable[[FloatArray, FloatArray], FloatArray]
"""(x, coefficients) -> d residual / d x, one column per nonlinear parameter."""


TRIES: int = 8
"""Steps tried from one point, each more damped, before the search stops there."""


@dataclass(frozen=True)
class Solution:
    """Where :func:`least_squares` stopped: the nonlinear parameters ``x``, the residual sum
    of squares ``rss``, the linear coefficients and the residuals there."""

    x: FloatArray
    rss: float
    coef: FloatArray
    residuals: FloatArray
    iterations: int


def least_squares(
    evaluate: Evaluate,
    jacobian: Jacobian,
    x0: FloatArray,
    lower: FloatArray | None = None,
    upper: FloatArray | None = None,
    max_iter: int = 60,
    xtol: float | FloatArray = 1e-9,
    ftol: float = 0.0,
) -> Solution:
    """Minimise the residual sum of squares over the nonlinear parameters from ``x0``.

    Marquardt's damping on the Gauss-Newton step, scaled by the diagonal of J^T J; a step
    is taken only when it does not raise the sum, else the damping grows sixfold, at most
    :data:`TRIES` times (it falls fourfold after a step taken). Stops when a step changes no
    parameter by more than ``xtol`` (in the units of x; an array: one per parameter), when it
    lowers the sum by at most ``ftol`` times the sum, or after ``max_iter`` steps. ``lower``
    and ``upper`` (default: none) box the parameters in: a parameter on its bound whose
    gradient points out of the box is held there while the others move, and every step is
    clipped to the box.
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
        if np.all(held):
            break
        A = np.where(held[:, None] | held[None, :], 0.0, A)
        g = np.where(held, 0.0, g)
        diag = np.where(held, 1.0, np.maximum(np.diag(A), 1e-300))
        A[held, held] = 1.0
        taken = False
        for _ in range(TRIES):
            try:
                step = np.linalg.solve(A + lam * np.diag(diag), -g)
            except np.linalg.LinAlgError:
                lam *= 6.0
                continue
            trial = np.clip(x + step, lo, hi)
            step = trial - x
            rss_t, coef_t, r_t = evaluate(trial)
            if math.isfinite(rss_t) and rss_t <= rss:
                lam = max(lam / 4.0, 1e-12)
                taken = True
                break
            lam *= 6.0
        if not taken:
            break
        done = bool(np.all(np.abs(step) <= xtol)) or (ftol > 0 and rss - rss_t <= ftol * rss)
        x, rss, coef, r = trial, rss_t, coef_t, r_t
        if done:
            break
    return Solution(x=x, rss=rss, coef=coef, residuals=r, iterations=it)


_G = (math.sqrt(5.0) - 1.0) / 2.0


def golden(
    f: Callable[[float], float], a: float, b: float, xatol: float = 2e-3
) -> tuple[float, float]:
    """(x, f(x)) minimising f on [a, b] by golden-section search (f unimodal there)."""
    c, d = b - _G * (b - a), a + _G * (b - a)
    fc, fd = f(c), f(d)
    while b - a > xatol:
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - _G * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + _G * (b - a)
            fd = f(d)
    return (c, fc) if fc < fd else (d, fd)
