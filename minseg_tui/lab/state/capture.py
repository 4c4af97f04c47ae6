"""Task 4's steady-state capture: is the speed settled, and its mean and spread over a window.

Inputs are the recent samples of one estimate of the speed: times ``t`` (s, increasing) and
``omega`` (rad/s). The UI shows :func:`steadiness` as the steady-state indicator and calls
``Session.capture_omega`` (which uses :func:`capture`) when the group captures.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

DEFAULT_WINDOW: float = 2.0
"""Length of the capture window, s (four times the manual's 0.5 s velocity average)."""

DRIFT_TOL: float = 0.03
"""Settled when the speed drifts less than this fraction over the window (fit line)."""


@dataclass(frozen=True)
class Capture:
    """omega_ss (rad/s, mean over the window), spread (rad/s, sample standard deviation),
    the window t0..t1 (s, on the recording's clock), n samples, and which estimate of the
    speed it was taken from (``velocity``)."""

    omega_ss: float
    spread: float
    t0: float
    t1: float
    n: int
    velocity: str = "timestamps"

    def to_json(self) -> dict[str, object]:
        """A JSON-ready dict (the session file's form)."""
        return asdict(self)

    @classmethod
    def from_json(cls, d: Mapping[str, Any]) -> Capture:
        """Inverse of :meth:`to_json` (``d`` checked by :data:`minseg_tui.lab.saving.schema.CAPTURE`)."""
        return cls(
            omega_ss=float(d["omega_ss"]),
            spread=float(d["spread"]),
            t0=float(d["t0"]),
            t1=float(d["t1"]),
            n=int(d["n"]),
            velocity=str(d.get("velocity", "timestamps")),
        )


@dataclass(frozen=True)
class Steadiness:
    """The indicator: ``settled``, the window's mean (rad/s), spread (rad/s), drift (rad/s over
    the window, from a fitted line), and ``ready`` (False while the window is not yet full)."""

    settled: bool
    mean: float
    spread: float
    drift: float
    ready: bool


def _window(t: ArrayLike, omega: ArrayLike, window: float) -> tuple[np.ndarray, np.ndarray, bool]:
    tt = np.asarray(t, dtype=float)
    ww = np.asarray(omega, dtype=float)
    if tt.size != ww.size:
        raise ValueError("t and omega differ in length")
    if tt.size == 0:
        return tt, ww, False
    keep = tt >= tt[-1] - window
    return tt[keep], ww[keep], bool(tt[-1] - tt[0] >= window)


def steadiness(
    t: ArrayLike, omega: ArrayLike, window: float = DEFAULT_WINDOW, tol: float = DRIFT_TOL
) -> Steadiness:
    """Whether the last ``window`` s of the speed are steady: the fitted line's change over the
    window is below ``tol`` of the mean speed (and below 0.1 rad/s near standstill)."""
    tt, ww, full = _window(t, omega, window)
    if tt.size < 3:
        return Steadiness(False, math.nan, math.nan, math.nan, False)
    mean = float(np.mean(ww))
    spread = float(np.std(ww, ddof=1))
    slope = float(np.polyfit(tt - tt[0], ww, 1)[0]) if np.ptp(tt) > 0 else 0.0
    drift = slope * float(tt[-1] - tt[0])
    settled = full and abs(drift) <= max(tol * abs(mean), 0.1)
    return Steadiness(settled, mean, spread, drift, full)


def capture(
    t: ArrayLike, omega: ArrayLike, window: float = DEFAULT_WINDOW, velocity: str = "timestamps"
) -> Capture:
    """omega_ss as the mean over the last ``window`` s, with its spread; ValueError if fewer
    than 3 samples."""
    tt, ww, _ = _window(t, omega, window)
    if tt.size < 3:
        raise ValueError("fewer than 3 samples to capture from")
    return Capture(
        omega_ss=float(np.mean(ww)),
        spread=float(np.std(ww, ddof=1)),
        t0=float(tt[0]),
        t1=float(tt[-1]),
        n=int(tt.size),
        velocity=velocity,
    )
