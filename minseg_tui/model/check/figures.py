"""Figures that say how much better the extended model is, past the encoder's noise.

A speed rmse near the noise floor says nothing about a model; the part above it does. The
angle, known to q/sqrt 12, shows what the speed's noise hides. Held-out steps (fit on half
of the steps, predict the other half) are the honest judge where a log has enough steps.
Which figure leads for a log, and why, is data the text and the TUI use.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Literal

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Gain:
    """How much better the extended model does than the first-order baseline, in figures
    that survive the encoder's noise (each field is a key of the JSON's ``gain``, in its
    order; None where the log does not give the figure).

    rmse_reduction_percent: how much lower the extended model's rms speed error is, %;
    fit_percent_gain: its fit (%) less the baseline's, points; whitened_reduction_percent and
    criterion_gain: the share of the whitened residual the causes remove (%) and the
    criterion's gain D; baseline_rmse / extended_rmse: rms speed error, rad/s; noise_floor:
    the speed's noise floor from one count per sample, rad/s; noise: its measured scatter,
    rad/s; *_above_floor / *_above_noise: the rms error above the floor / above the larger of
    floor and noise, rad/s; angle_floor: the angle's quantisation floor, rad;
    *_angle_rms: rms error of the angle, rad; heldout_steps: rises in the held-out
    halves (0: no folds); heldout_*_rmse: rms speed error on held-out steps, rad/s.
    """

    rmse_reduction_percent: float
    fit_percent_gain: float
    whitened_reduction_percent: float
    criterion_gain: float
    baseline_rmse: float
    extended_rmse: float
    noise_floor: float | None
    noise: float
    baseline_above_floor: float | None
    extended_above_floor: float | None
    baseline_above_noise: float | None
    extended_above_noise: float | None
    angle_floor: float | None
    baseline_angle_rms: float
    extended_angle_rms: float
    heldout_steps: float
    heldout_baseline_rmse: float | None
    heldout_extended_rmse: float | None

    def get(self, key: str) -> float | None:
        """The figure named by its JSON key (as :attr:`Lead.figure` names one); None for a key
        that names no figure."""
        return getattr(self, key) if key in GAIN_KEYS else None

    def has(self, key: str) -> bool:
        """``key`` names a figure of the gain."""
        return key in GAIN_KEYS

    def to_dict(self) -> dict[str, float | None]:
        """The JSON's ``gain`` object."""
        return {k: getattr(self, k) for k in GAIN_KEYS}


GAIN_KEYS: tuple[str, ...] = tuple(f.name for f in fields(Gain))
"""The keys of the JSON's ``gain``, in order."""


def above(rmse: float, floor: float | None) -> float | None:
    """The part of an rmse above a noise level, sqrt(max(rmse^2 - floor^2, 0)) (same unit)."""
    if floor is None:
        return None
    return math.sqrt(max(rmse * rmse - floor * floor, 0.0))


def systematic(residual: FloatArray, keep: FloatArray, rows: int = 9) -> float:
    """Rms (rad/s) of the residual averaged over ``rows`` centred rows: the part of a
    model's error that holds over several samples (noise is divided by sqrt(rows) or more)."""
    k = np.asarray(keep, dtype=bool)
    r = np.where(k, residual, 0.0)
    n = np.convolve(k.astype(float), np.ones(rows), mode="same")
    m = np.convolve(r, np.ones(rows), mode="same") / np.maximum(n, 1.0)
    return float(np.sqrt(np.mean(m[k] ** 2))) if np.any(k) else 0.0


def angle_rms(
    t: FloatArray,
    u: FloatArray,
    residual: FloatArray,
    ts: float,
    keep: FloatArray,
    over_interval: bool = True,
) -> float:
    """Rms (rad) of the angle error accumulated since the last change of input, the speed
    residual (rad/s) integrated over the time each row's speed was taken over: the row's
    interval, or the nominal period ts (s) when ``over_interval`` is False (a speed of angle
    steps divided by ts); rows left out add nothing."""
    dt = np.concatenate(([ts], np.diff(t))) if over_interval else np.full(t.size, ts)
    inc = residual * dt * keep
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate(([0], change, [u.size]))
    ang = np.empty_like(inc)
    for a, b in zip(bounds[:-1], bounds[1:], strict=True):
        ang[a:b] = np.cumsum(inc[a:b])
    k = keep > 0
    return float(np.sqrt(np.mean(ang[k] ** 2))) if np.any(k) else 0.0


def cycles(u: FloatArray) -> list[tuple[int, int]]:
    """(first row, end row) of each cycle: from one step that raises |u| to the next."""
    up = [e for e in (np.flatnonzero(np.diff(u) != 0) + 1).tolist() if abs(u[e]) > abs(u[e - 1])]
    if not up:
        return []
    return list(zip(up, [*up[1:], int(u.size)], strict=True))


def folds(u: FloatArray) -> list[FloatArray] | None:
    """Two row masks (1 = held out) splitting the cycles alternately, when the log has at
    least two cycles; None otherwise."""
    cyc = cycles(u)
    if len(cyc) < 2:
        return None
    out = []
    for parity in (0, 1):
        m = np.zeros(u.size)
        for i, (a, b) in enumerate(cyc):
            if i % 2 == parity:
                m[a:b] = 1.0
        out.append(m)
    return out


LeadKind = Literal["turning", "noisy", "heldout", "above", "small_noise", "unknown"]
"""Why a figure leads: the wheel stands still in most rows ('turning': the angle error);
the speed error is mostly noise ('noisy': the angle error); the log has steps to hold out
('heldout'); the noise is a good part of the error ('above': the error above the noise);
the noise is small against the error ('small_noise': the rms error); the noise is not
known ('unknown': the rms error)."""


@dataclass(frozen=True)
class Lead:
    """The figure that means most for this log (a key of ``gain``) and why (``kind``), with
    the figures its sentence needs: ``named`` (two models to tell apart, else one to judge),
    ``noise`` (rad/s), ``error`` (the larger model's rms error, rad/s), for 'turning' the
    error where the wheel turns (``turning``, rad/s rms), the rows where it stands still and
    all ``rows``; for 'heldout' the held-out errors (rad/s) when the extended model predicts
    the held-out steps worse (``worse``)."""

    figure: str
    kind: LeadKind
    named: bool = False
    noise: float = 0.0
    error: float = 0.0
    turning: float = 0.0
    still: int = 0
    rows: int = 0
    worse: tuple[float, float] | None = None

    def to_dict(self, why: str) -> dict[str, str]:
        """The lead's JSON, ``why`` in words."""
        return {"figure": self.figure, "why": why}


SMALL_NOISE = 0.3
"""A noise below this share of both models' rms errors changes "the error above the noise"
by under 5 %: the plain rms error leads then."""


def lead(gain: Gain, named: bool, turning: tuple[float, int, int] | None = None) -> Lead:
    """Which figure leads: the angle error where the speed error is mostly noise (or where
    the wheel stands still in most rows, which makes the rms error over the log small while
    it misses where the wheel turns), the held-out error where the log has
    steps to hold out, the rms error where the noise is small against it, else the error
    above the noise. ``named``: a cause was named (two models to tell apart; else one model
    to judge). ``turning``: the larger model's rms error where the wheel turns (rad/s), the
    rows where it stands still and all rows."""
    noise = max(gain.noise_floor or 0.0, gain.noise or 0.0)
    b, e = gain.baseline_rmse or 0.0, gain.extended_rmse or 0.0
    angle = "extended_angle_rms" if named else "baseline_angle_rms"
    if noise > 0 and turning and 2 * turning[1] > turning[2] and turning[0] >= 1.5 * noise:
        err, still, rows = turning
        return Lead(angle, "turning", named, noise, max(b, e), err, still, rows)
    if noise > 0 and max(b, e) < 1.5 * noise:
        return Lead(angle, "noisy", named, noise, max(b, e))
    if gain.heldout_baseline_rmse is not None:
        hb, he = gain.heldout_baseline_rmse, gain.heldout_extended_rmse
        worse = (hb, he) if named and he is not None and he > hb else None
        return Lead(
            "heldout_extended_rmse" if named else "heldout_baseline_rmse",
            "heldout",
            named,
            worse=worse,
        )
    if noise > 0 and noise >= SMALL_NOISE * min(b, e):
        return Lead(
            "extended_above_noise" if named else "baseline_above_noise", "above", named, noise
        )
    if noise > 0:
        return Lead("extended_rmse" if named else "baseline_rmse", "small_noise", named, noise)
    return Lead("extended_rmse" if named else "baseline_rmse", "unknown", named)


Window = Literal["stretch", "fall", "rise", "whole"]
"""What a close-up holds: the stretch where something braked the wheel, a step-down where
the wheel slows and stops, a rise where the response starts, or the whole log."""


@dataclass(frozen=True)
class CloseUp:
    """A window (s, rows start..end exclusive) where the cause acts, for a close-up plot of
    the measured speed and both models there (slice the result's t, omega, baseline_pred
    and extended_pred with [start:end]); ``noise`` the speed's noise level (rad/s, the band
    a plot can draw around the measured speed), ``cause`` the cause it shows ('none' for
    the first rise of a log without one, 'disturbance' for a hand on the wheel), ``shows``:
    what the window holds (:data:`Window`; in words outside the model)."""

    t0: float
    t1: float
    start: int
    end: int
    shows: Window
    noise: float
    cause: str = "none"

    def to_dict(self, what: str) -> dict[str, object]:
        """The close-up's JSON, ``what`` it shows in words."""
        return {
            "t0": self.t0,
            "t1": self.t1,
            "row0": self.start,
            "row1": self.end,
            "what": what,
            "noise": self.noise,
            "cause": self.cause,
        }


def close_up(
    t: FloatArray,
    u: FloatArray,
    cause: str,
    T: float,
    lag: float,
    noise: float,
    fenced: tuple[float, float] | None = None,
    length: float | None = None,
    edge: int | None = None,
    at_fall: bool = False,
) -> CloseUp:
    """The window to look at for ``cause``: one step-down for a cause shown there
    (``at_fall``: dry friction, a coast), one rise for the others (and for none), a disturbance's stretch when ``fenced`` (t, t_end)
    is given. T (s) and lag (s, delay plus filter) size it; ``length`` (s) overrides how long
    the response lasts; ``edge`` (a row) the step-down to show, the one the evidence speaks
    of (the first step-down when it is None or no step-down)."""
    ts = float(np.median(np.diff(t))) if t.size > 1 else 1.0
    change = (np.flatnonzero(np.diff(u) != 0) + 1).tolist()
    falls = [e for e in change if abs(u[e]) < abs(u[e - 1])]
    rises = [e for e in change if abs(u[e]) > abs(u[e - 1])]
    span = length if length is not None else 6.0 * T + lag
    what: Window
    if fenced is not None:
        a, b = fenced
        pad = max(0.5 * (b - a), 4.0 * T, 5 * ts)
        t0, t1, what = a - pad, b + pad, "stretch"
    elif at_fall and falls:
        e = edge if edge in falls else falls[0]
        t0, t1 = float(t[e]) - max(2.0 * T, 5 * ts), float(t[e]) + max(span, 10 * ts)
        what = "fall"
    elif rises:
        e = rises[0]
        t0, t1 = float(t[e]) - max(2.0 * T, 5 * ts), float(t[e]) + max(span, 10 * ts)
        what = "rise"
    else:
        t0, t1, what = float(t[0]), float(t[-1]), "whole"
    t0, t1 = max(t0, float(t[0])), min(t1, float(t[-1]))
    i0 = int(np.searchsorted(t, t0, side="left"))
    i1 = int(np.searchsorted(t, t1, side="right"))
    shown = "disturbance" if fenced is not None else cause
    return CloseUp(float(t[i0]), float(t[max(i1 - 1, i0)]), i0, max(i1, i0 + 1), what, noise, shown)
