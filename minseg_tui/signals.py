"""From encoder samples to angle and velocity, the lab's way and a better way.

Inputs are arrays of one recording: board time ``t`` in s and encoder ``count``
(720 counts per wheel revolution). Angles are in rad, velocities in rad/s.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from minseg_tui.units import LAB_FIR_TAPS, LAB_TS, RAD_PER_COUNT

FloatArray = NDArray[np.float64]


def angle(count: ArrayLike) -> FloatArray:
    """Wheel angle theta in rad from encoder counts (Preparation 10's scaling)."""
    return np.asarray(count, dtype=float) * RAD_PER_COUNT


def euler_velocity(theta: ArrayLike, ts: float = LAB_TS) -> FloatArray:
    """The manual's Euler backward derivative (theta_k - theta_k-1)/Ts in rad/s.

    Uses the nominal sample period ``ts`` (s), as the Simulink block does; the first
    sample has no predecessor and gets 0.
    """
    th = np.asarray(theta, dtype=float)
    out = np.zeros_like(th)
    if th.size > 1:
        out[1:] = np.diff(th) / ts
    return out


def moving_average(x: ArrayLike, taps: int = LAB_FIR_TAPS) -> FloatArray:
    """The manual's FIR filter: mean of the last ``taps`` values (coefficients 1/taps).

    Before ``taps`` values exist the missing ones count as 0, as in a FIR filter that
    starts from rest.
    """
    v = np.asarray(x, dtype=float)
    c = np.concatenate(([0.0], np.cumsum(v)))
    k = np.arange(1, v.size + 1)
    return (c[k] - c[np.maximum(k - taps, 0)]) / taps


def lab_velocity(count: ArrayLike, ts: float = LAB_TS, taps: int = LAB_FIR_TAPS) -> FloatArray:
    """The velocity the manual builds in Task 3: Euler derivative then the 20-tap average, rad/s."""
    return moving_average(euler_velocity(angle(count), ts), taps)


def timestamp_velocity(t: ArrayLike, count: ArrayLike, window: float = 0.0) -> FloatArray:
    """Velocity in rad/s from the board's own timestamps ``t`` (s), immune to loop jitter.

    With ``window`` 0 it is (theta_k - theta_k-1)/(t_k - t_k-1); with a window in s it is
    (theta_k - theta_j)/(t_k - t_j) for the oldest j with t_k - t_j <= window (at least one
    sample back): the mean speed over the window. The first sample gets 0.
    """
    tt = np.asarray(t, dtype=float)
    th = angle(count)
    out = np.zeros_like(th)
    if tt.size < 2:
        return out
    k = np.arange(1, tt.size)
    if window > 0.0:
        j = np.searchsorted(tt, tt[k] - window, side="left")
        j = np.minimum(j, k - 1)
    else:
        j = k - 1
    dt = tt[k] - tt[j]
    out[1:] = np.where(dt > 0, (th[k] - th[j]) / np.where(dt > 0, dt, 1.0), 0.0)
    return out
