"""T and the steady speeds of a step log by least squares (Tasks 11-12), with 95 % intervals.

Two fits, both on what a log measures, the wheel angle at the board's timestamps (``t_us``
when present), both with a time shift of the steps against the samples as a nuisance
parameter (:mod:`.wholelog`, :mod:`.windowfit`):

- the model of Task 14 over the whole log, every edge rising and falling, dry friction when
  the log shows it: the most the log can tell about T, when the log follows that model;
- each rising step on its own, T shared: robust to what happens between the steps (a wheel
  that coasts at zero command, a speed that wanders).

The whole-log fit is used when it explains the rising steps about as well as the step-by-step
fit does (its residuals on their rows at most :data:`ADEQUATE` times theirs); otherwise the
step-by-step fit. Either way K comes from the fitted steady speeds, not from means over a
step that may not have settled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.identify.lsq import dot
from minseg_tui.model.identify.steps import StepWindow, reading_63, step_windows
from minseg_tui.model.identify.wholelog import WholeLogFit, fit_whole_log
from minseg_tui.model.identify.windowfit import WindowsFit, fit_windows
from minseg_tui.model.steplog import StepLog, command, find_edges

FloatArray = NDArray[np.float64]

ADEQUATE: float = 1.3
"""The whole-log fit is used when the rms of its angle residuals on the rising steps' rows is
at most this many times the step-by-step fit's residual standard deviation."""

WHOLE_LOG = "whole_log"
RISING_STEPS = "rising_steps"


@dataclass(frozen=True)
class RisingStep:
    """One rising step of the log.

    row: first row (0-based) at the high level; line: its file line; t: step time (s);
    u_req: requested high level (V, None if the log has no u_req); u_high: mean applied u
    over the high level (V); omega0: mean measured speed over the rows before (rad/s);
    omega_ss: the steady speed the fit gives for the high level (rad/s); duration: time at the
    high level (s); T_63: the 63 % reading (s, None if the speed never crosses 63 %).
    """

    row: int
    line: int | None
    t: float
    u_req: float | None
    u_high: float
    omega0: float
    omega_ss: float
    duration: float
    T_63: float | None


@dataclass(frozen=True)
class TimeConstantFit:
    """The least-squares T (s) with its 95 % interval (s) and standard error (s), the residual
    standard deviation of the angle (rad), the rows and rising steps used, where the angle and
    the time came from, and:

    method: ``whole_log`` or ``rising_steps`` (see the module docstring) and ``why``, a
    sentence; shift: the fitted time shift of the steps (s; > 0: the motor answers later than
    the log says, < 0: the samples are read late) with its 95 % interval; omega_ss and
    omega_ss_se: the fitted steady speed of each rising step and its standard error (rad/s);
    gain: the whole-log fit's K per volt of the log's u (rad/s per V, None for the other);
    u_c: dry friction's breakaway voltage (V, 0 when not found); dof: degrees of freedom of
    the t quantile (clusters of rows less one); predicted: the fitted angle (rad) at every
    row (NaN where the fit does not reach).
    """

    T: float
    ci: tuple[float, float]
    se: float
    sigma: float
    n_rows: int
    n_steps: int
    angle_source: str
    time_source: str
    method: str
    why: str
    shift: float
    shift_ci: tuple[float, float]
    omega_ss: tuple[float, ...]
    omega_ss_se: tuple[float, ...]
    gain: float | None
    u_c: float
    dof: int
    predicted: FloatArray


def fit_time_constant(log: StepLog) -> TimeConstantFit | None:
    """Least-squares T over the usable rising steps of ``log`` (None if there are none, or
    if the angle never changes: an encoder not read gives nothing to fit)."""
    windows, _ = step_windows(log)
    if not windows:
        return None
    t = log.board_time()
    theta, angle_source = log.angle()
    if not np.ptp(theta) > 0:  # no residual to compare the fits by: it would divide by zero
        return None
    u = np.asarray(log.u, dtype=float)
    ts = log.ts
    steps_fit = fit_windows(t, theta, windows, ts)
    cmd, _ = command(log)
    clusters = np.unique(np.array([0, *(e.start for e in find_edges(cmd))], dtype=np.int64))
    stamped = "t_us" in log.extra
    # with the board's timestamps the steps act at the sample instants (this project's
    # firmware) or on the board's sample grid (firmware that sets the output on a timer);
    # without them, where a step falls between the logged instants is not known
    timings = [t, board_grid(t)] if stamped else [t]
    whole = fit_whole_log(t, u, theta, steps_fit.T, clusters, timings, offsets=not stamped)
    time_source = "the board's timestamps (t_us)" if stamped else "the t column"
    n_w = steps_fit.rows.size
    sigma_w = math.sqrt(steps_fit.rss / max(n_w - steps_fit.n_params, 1))
    if whole is not None:
        on_steps = whole.residuals[steps_fit.rows]
        rms = math.sqrt(dot(on_steps, on_steps) / max(n_w, 1))
        if rms <= ADEQUATE * sigma_w and sigma_w > 0:  # (0: the steps fit exactly, no scale)
            return _from_whole(log, whole, windows, theta, angle_source, time_source, rms, sigma_w)
        times = f"{rms / sigma_w:.1f} times" if sigma_w > 0 else "more than"
        why = (
            f"the first-order model over the whole log leaves {times} the "
            "residual of the steps fitted one by one (the wheel between the steps does not "
            "follow it: coasting at zero command, or a speed that wanders), so T comes from "
            "the rising steps alone"
        )
    else:
        why = "the applied voltage u never changes in the log, so T comes from the rising steps"
    return _from_steps(log, steps_fit, windows, theta, angle_source, time_source, sigma_w, why)


def board_grid(t: FloatArray) -> FloatArray:
    """The board's sample grid under timestamps ``t`` (s) read late by a busy loop: t0 + k P.

    k counts the grid periods sample by sample (each interval is a whole number of periods
    give or take the lateness). The grid is the highest line under every sample (a late-only
    jitter leaves samples above it): for a period P the best t0 is min(t - k P), and the mean
    height min(t - k P) + P mean(k) is concave in P, so P is found by a ternary search."""
    if t.size < 8:
        return t
    P0 = float(np.median(np.diff(t)))
    if not P0 > 0:
        return t
    k = np.concatenate(([0.0], np.cumsum(np.maximum(np.round(np.diff(t) / P0), 1.0))))
    km = float(np.mean(k))

    def height(P: float) -> float:
        return float(np.min(t - k * P)) + P * km

    lo, hi = 0.9 * P0, 1.1 * P0
    for _ in range(80):
        a, b = lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0
        if height(a) < height(b):
            lo = a
        else:
            hi = b
    P = 0.5 * (lo + hi)
    return k * P + float(np.min(t - k * P))


def _interval(value: float, half: float) -> tuple[float, float]:
    return (value - half, value + half)


def _from_whole(
    log: StepLog,
    fit: WholeLogFit,
    windows: list[StepWindow],
    theta: FloatArray,
    angle_source: str,
    time_source: str,
    rms: float,
    sigma_w: float,
) -> TimeConstantFit:
    cov = fit.covariance
    se = math.sqrt(max(float(cov.cov[1, 1]), 0.0))
    u = np.asarray(log.u, dtype=float)
    highs = [float(np.mean(u[w.edge.end : w.post_last])) for w in windows]
    friction = f"; dry friction found: breakaway at u_c = {fit.u_c:.3g} V" if fit.friction else ""
    return TimeConstantFit(
        T=fit.T,
        ci=(max(fit.T - cov.half_width(1), 0.0), fit.T + cov.half_width(1)),
        se=se,
        sigma=math.sqrt(fit.rss / max(theta.size - fit.n_params, 1)),
        n_rows=int(theta.size),
        n_steps=len(windows),
        angle_source=angle_source,
        time_source=time_source,
        method=WHOLE_LOG,
        why=(
            "the first-order model explains the whole log (on the rising steps its residual is "
            f"{rms / sigma_w:.2f} times that of the steps fitted one by one), so every edge, "
            f"rising and falling, is used{friction}"
        ),
        shift=fit.d,
        shift_ci=_interval(fit.d, cov.half_width(2)),
        omega_ss=tuple(fit.level(h) for h in highs),
        omega_ss_se=tuple(fit.level_se(h) for h in highs),
        gain=fit.K,
        u_c=fit.u_c,
        dof=cov.dof,
        predicted=fit.predicted,
    )


def _from_steps(
    log: StepLog,
    fit: WindowsFit,
    windows: list[StepWindow],
    theta: FloatArray,
    angle_source: str,
    time_source: str,
    sigma_w: float,
    why: str,
) -> TimeConstantFit:
    cov = fit.covariance
    se = math.sqrt(max(float(cov.cov[0, 0]), 0.0))
    predicted = np.full(theta.size, np.nan)
    predicted[fit.rows] = fit.predicted
    return TimeConstantFit(
        T=fit.T,
        ci=(max(fit.T - cov.half_width(0), 0.0), fit.T + cov.half_width(0)),
        se=se,
        sigma=sigma_w,
        n_rows=int(fit.rows.size),
        n_steps=len(windows),
        angle_source=angle_source,
        time_source=time_source,
        method=RISING_STEPS,
        why=why,
        shift=fit.d,
        shift_ci=_interval(fit.d, cov.half_width(1)),
        omega_ss=tuple(float(w) for w in fit.omega_ss),
        omega_ss_se=tuple(float(s) for s in fit.omega_ss_se),
        gain=None,
        u_c=0.0,
        dof=cov.dof,
        predicted=predicted,
    )


def rising_steps(log: StepLog, fit: TimeConstantFit | None = None) -> list[RisingStep]:
    """Each usable rising step with its levels and the manual's 63 % reading (Tasks 11-12).

    The steady speed of each step is the fitted one (``fit``, computed when not given); the
    63 % reading is taken on the log's omega from the mean speed before the step to it.
    """
    windows, _ = step_windows(log)
    if not windows:
        return []
    fit = fit if fit is not None else fit_time_constant(log)
    if fit is None:  # the angle never changes
        return []
    _, name = command(log)
    omega = np.asarray(log.omega, dtype=float)
    t = np.asarray(log.t, dtype=float)
    out = []
    for w, w_ss in zip(windows, fit.omega_ss, strict=True):
        e = w.edge
        w0 = _speed_before(omega, w)
        out.append(
            RisingStep(
                row=e.start,
                line=log.line_of(e.start),
                t=float(t[e.start]),
                u_req=float(e.after) if name == "u_req" else None,
                u_high=float(np.mean(log.u[e.end : w.post_last])),
                omega0=w0,
                omega_ss=float(w_ss),
                duration=float(t[w.post_last] - t[e.start]),
                T_63=reading_63(t, omega, e.start, w.post_last, w0, float(w_ss)),
            )
        )
    return out


def _speed_before(omega: FloatArray, w: StepWindow) -> float:
    """Mean speed (rad/s) over the rows before the step (row 0 has no previous sample)."""
    pre = np.arange(w.pre_from, w.edge.start + 1)
    pre = pre[pre >= 1] if pre.size > 1 else pre
    return float(np.mean(omega[pre]))


def model_reading_63(log: StepLog, fit: TimeConstantFit, steps: list[RisingStep]) -> float | None:
    """The manual's 63 % reading (s, median over the steps) taken on the fitted model instead
    of the measurements: the speed of the model's angle over each sample interval, read with
    the same levels at the log's own sample times. What the sampling alone makes of T."""
    windows, _ = step_windows(log)
    t = log.board_time()
    th = fit.predicted
    speed = np.zeros(th.size)
    speed[1:] = np.diff(th) / np.diff(t)
    reads = []
    for w, s in zip(windows, steps, strict=True):
        lo, hi = w.edge.start, w.post_last
        if not np.all(np.isfinite(speed[lo + 1 : hi + 1])):
            continue
        r = reading_63(t, speed, lo, hi, s.omega0, s.omega_ss)
        if r is not None:
            reads.append(r)
    return float(np.median(reads)) if reads else None


__all__ = [
    "ADEQUATE",
    "board_grid",
    "RISING_STEPS",
    "WHOLE_LOG",
    "RisingStep",
    "TimeConstantFit",
    "fit_time_constant",
    "model_reading_63",
    "rising_steps",
]
