"""Two small derivative-free minimisers (golden section, Nelder-Mead), so that the model
check loads in a fraction of the time scipy.optimize takes to import."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

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


def nelder_mead(
    f: Callable[[NDArray[np.float64]], float],
    x0: NDArray[np.float64],
    step: NDArray[np.float64],
    xatol: float = 1e-3,
    maxfev: int = 80,
) -> tuple[NDArray[np.float64], float]:
    """(x, f(x)) from the Nelder-Mead simplex started at x0 with edges ``step`` per axis."""
    n = x0.size
    pts = [np.asarray(x0, float)] + [
        np.asarray(x0, float) + np.eye(n)[i] * step[i] for i in range(n)
    ]
    vals = [f(p) for p in pts]
    fev = n + 1
    while fev < maxfev:
        order = np.argsort(vals)
        pts = [pts[i] for i in order]
        vals = [vals[i] for i in order]
        if max(float(np.max(np.abs(p - pts[0]))) for p in pts[1:]) < xatol:
            break
        centre = np.mean(pts[:-1], axis=0)
        xr = centre + (centre - pts[-1])
        fr = f(xr)
        fev += 1
        if fr < vals[0]:
            xe = centre + 2.0 * (centre - pts[-1])
            fe = f(xe)
            fev += 1
            pts[-1], vals[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < vals[-2]:
            pts[-1], vals[-1] = xr, fr
        else:
            xc = centre + 0.5 * (pts[-1] - centre)
            fc = f(xc)
            fev += 1
            if fc < vals[-1]:
                pts[-1], vals[-1] = xc, fc
            else:
                for i in range(1, n + 1):
                    pts[i] = pts[0] + 0.5 * (pts[i] - pts[0])
                    vals[i] = f(pts[i])
                    fev += 1
    i = int(np.argmin(vals))
    return pts[i], float(vals[i])


def least_squares(
    resid: Callable[[NDArray[np.float64]], NDArray[np.float64]],
    x0: NDArray[np.float64],
    lo: NDArray[np.float64],
    hi: NDArray[np.float64],
    step: NDArray[np.float64],
    max_iter: int = 25,
    rtol: float = 1e-6,
) -> tuple[NDArray[np.float64], float, NDArray[np.float64]]:
    """Levenberg-Marquardt within the box [lo, hi]: (x, sum of squares, Jacobian at x).

    ``resid`` gives the residual vector (non-finite entries mark a failed model); the
    Jacobian is taken by forward differences of size ``step`` per axis (backward at the
    upper bound). A coordinate that sits on a bound and is pushed out of the box is held
    there for the step.
    """
    x = np.clip(np.asarray(x0, float), lo, hi)
    r = resid(x)
    f = float(np.dot(r, r)) if np.all(np.isfinite(r)) else math.inf
    lam = 1e-3
    jac = np.zeros((r.size, x.size))
    for _ in range(max_iter):
        for i in range(x.size):
            h = step[i] if x[i] + step[i] <= hi[i] else -step[i]
            xp = x.copy()
            xp[i] += h
            jac[:, i] = (resid(xp) - r) / h
        if not np.all(np.isfinite(jac)):
            jac = np.nan_to_num(jac, nan=0.0, posinf=0.0, neginf=0.0)
        g = jac.T @ r
        a = jac.T @ jac
        free = ~(((x <= lo) & (g > 0)) | ((x >= hi) & (g < 0)))
        if not np.any(free):
            break
        improved = False
        for _ in range(8):
            af = a[np.ix_(free, free)]
            d = np.zeros_like(x)
            try:
                d[free] = np.linalg.solve(af + lam * np.diag(np.diag(af) + 1e-12), -g[free])
            except np.linalg.LinAlgError:
                lam *= 10.0
                continue
            xn = np.clip(x + d, lo, hi)
            rn = resid(xn)
            fn = float(np.dot(rn, rn)) if np.all(np.isfinite(rn)) else math.inf
            if fn < f:
                done = f - fn <= rtol * f or float(np.max(np.abs(xn - x) / step)) < 1e-3
                x, r, f = xn, rn, fn
                lam = max(lam / 4.0, 1e-9)
                improved = True
                break
            lam *= 6.0
        if not improved or done:
            break
    return x, f, jac
