"""Exact simulation of the candidate models on a piecewise-constant input.

The input of a step log is held between samples: ``u[k]`` is in force from ``t[k]`` to
``t[k+1]``. Within each stretch of constant input every candidate has a closed-form
response, so the simulation walks the stretches once (scalar arithmetic, one per input
change) and writes down a table of *pieces*; each piece gives the wheel angle in closed
form from its start:

    theta(tau) = theta0 + c tau + A1 T1 (1 - exp(-tau/T1)) + A2 T2 (1 - exp(-tau/T2))

Evaluating the angle at the sample instants is then one vectorised expression, at any
instants: a dead time is the same table read ``delay`` seconds earlier (exact, not rounded
to samples). Dry friction splits a stretch at its stop time and sticks while the drive
cannot break away; a second pole carries its own state across stretches.

Everything is computed with K = 1 (angles in V s, speeds in V): every candidate's response
is proportional to K, which the fit then solves for by linear least squares.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

_FAR = 1.0e6  # s: start of the piece that stands for "before the log"


@dataclass(frozen=True)
class Stretches:
    """The input as constant stretches: start time (s) and value (V) of each."""

    start: FloatArray
    value: FloatArray

    @classmethod
    def from_samples(cls, t: FloatArray, u: FloatArray) -> Stretches:
        """Stretches of a log whose input ``u[k]`` (V) holds from ``t[k]`` (s) on."""
        change = np.flatnonzero(np.diff(u) != 0) + 1
        idx = np.concatenate(([0], change))
        return cls(start=np.asarray(t, float)[idx], value=np.asarray(u, float)[idx])


class _Pieces:
    """Growing table of closed-form pieces (see the module docstring)."""

    def __init__(self) -> None:
        self.rows: list[tuple[float, float, float, float, float, float, float]] = []

    def add(
        self,
        t0: float,
        th0: float,
        c: float,
        a1: float = 0.0,
        t1: float = 1.0,
        a2: float = 0.0,
        t2: float = 1.0,
    ) -> None:
        self.rows.append((t0, th0, c, a1, t1, a2, t2))

    def angle(self, tau: FloatArray) -> FloatArray:
        """Angle (V s at K = 1) at the instants ``tau`` (s, ascending)."""
        p = np.asarray(self.rows, dtype=float)
        i = np.clip(np.searchsorted(p[:, 0], tau, side="right") - 1, 0, None)
        q = p[i]
        dt = tau - q[:, 0]
        return (
            q[:, 1]
            + q[:, 2] * dt
            - q[:, 3] * q[:, 4] * np.expm1(-dt / q[:, 4])
            - q[:, 5] * q[:, 6] * np.expm1(-dt / q[:, 6])
        )


def _first_order_stretch(
    out: _Pieces, t0: float, w0: float, th0: float, a: float, b: float, d: float, length: float
) -> tuple[float, float]:
    """w' = -a w + b - d sgn(w) over ``length`` s from (w0, th0); sticks at 0 when |b| <= d.

    Adds the pieces to ``out`` and returns (w, theta) at the end.
    """
    if w0 == 0.0:
        if abs(b) <= d:
            out.add(t0, th0, 0.0)
            return 0.0, th0
        s = math.copysign(1.0, b)
    else:
        s = math.copysign(1.0, w0)
    w_inf = (b - s * d) / a
    if w0 != 0.0 and s * w_inf < 0.0:
        t_stop = math.log((w0 - w_inf) / -w_inf) / a
        if t_stop < length:
            out.add(t0, th0, w_inf, w0 - w_inf, 1.0 / a)
            th_stop = th0 + w_inf * t_stop - (w0 - w_inf) * math.expm1(-a * t_stop) / a
            return _first_order_stretch(out, t0 + t_stop, 0.0, th_stop, a, b, d, length - t_stop)
    out.add(t0, th0, w_inf, w0 - w_inf, 1.0 / a)
    e = math.exp(-a * length)
    return w_inf + (w0 - w_inf) * e, th0 + w_inf * length + (w0 - w_inf) * (1.0 - e) / a


def first_order_pieces(
    st: Stretches, T: float, z0: float = 0.0, u_c: float = 0.0, T_coast: float | None = None
) -> _Pieces:
    """T w' = -w + u - u_c sgn(w) (K = 1), with sticking; at u = 0 the time constant is
    ``T_coast`` when given (the bridge open: no drive, friction only). Starts at speed z0 (V)."""
    out = _Pieces()
    out.add(st.start[0] - _FAR, -z0 * _FAR, z0)
    w, th = z0, 0.0
    d = u_c / T
    ends = np.append(st.start[1:], math.inf)
    for t0, t1, u in zip(st.start.tolist(), ends.tolist(), st.value.tolist(), strict=True):
        length = t1 - t0 if math.isfinite(t1) else _FAR
        if T_coast is not None and u == 0.0:
            w, th = _first_order_stretch(out, t0, w, th, 1.0 / T_coast, 0.0, d, length)
        else:
            w, th = _first_order_stretch(out, t0, w, th, 1.0 / T, u / T, d, length)
    return out


def second_pole_pieces(st: Stretches, T: float, T2: float, z0: float = 0.0) -> _Pieces:
    """T2 v' = -v + u, T w' = -w + v (K = 1), from rest at v = w = z0 (V)."""
    if abs(T2 - T) < 1e-6 * T:
        T2 = T * (1.0 + 1e-6)
    out = _Pieces()
    out.add(st.start[0] - _FAR, -z0 * _FAR, z0)
    w, v, th = z0, z0, 0.0
    ends = np.append(st.start[1:], math.inf)
    for t0, t1, u in zip(st.start.tolist(), ends.tolist(), st.value.tolist(), strict=True):
        length = t1 - t0 if math.isfinite(t1) else _FAR
        b = (v - u) * T2 / (T2 - T)
        a = w - u - b
        out.add(t0, th, u, a, T, b, T2)
        e1, e2 = math.exp(-length / T), math.exp(-length / T2)
        th = th + u * length + a * T * (1.0 - e1) + b * T2 * (1.0 - e2)
        w = u + a * e1 + b * e2
        v = u + (v - u) * e2
    return out


def measured(theta: FloatArray, ts: float, taps: int = 1) -> FloatArray:
    """The measured speed from angles at the samples: (theta_k - theta_k-N)/(N ts).

    As the board computes it: the Euler velocity with the nominal ``ts`` (s), averaged over
    ``taps`` samples, missing values before the first sample counting as 0 (row 0 is 0).
    """
    n = theta.size
    back = np.maximum(np.arange(n) - taps, 0)
    return (theta - theta[back]) / (taps * ts)
