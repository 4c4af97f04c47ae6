"""Tasks 6-15 put together: the table, the run log, the model of Task 14 and what they show.

K (Task 11) is the steady speed the fit gives for each rise over the u_ss the table
gives at the step's requested voltage (the median over the steps); T (Task 12) the least-
squares time constant, with the manual's 63 % reading beside it and a sentence saying how far
apart the two are and how much of that the sampling explains; J (Task 13) from T; the model
(Task 14) and omega at 5 V (Task 15) from K and T. The K interval holds what the fit knows; the
table's u_ss is taken as exact.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from enum import Enum

import numpy as np

from minseg_tui.model.identify.lsq import t975
from minseg_tui.model.identify.observations import (
    FRICTION_APART,
    Observation,
    SpeedLags,
    T63Differs,
    creep_after_rise,
    fit_observations,
    friction_observations,
    response_observations,
    table_observations,
)
from minseg_tui.model.identify.refusals import IdentifyRefused, NoRisingEdge, RiseNotFitted
from minseg_tui.model.identify.risefit import (
    Rise,
    TimeConstantFit,
    fit_time_constant,
    following_rise,
    model_reading_63,
    rises,
)
from minseg_tui.model.identify.rises import MIN_AFTER, rise_windows
from minseg_tui.model.identify.steady import (
    U_SS_HOW,
    Reading,
    Row,
    UssHow,
    steady_state,
    table_of,
    u_ss_at,
)
from minseg_tui.model.motor import FirstOrder, inertia_from_time_constant
from minseg_tui.model.runlog import (
    LogRefused,
    RunLog,
    StillAngle,
    clock_problem,
    command,
    find_edges,
    problem,
    speed_lag,
    switch_on_glitches,
)

U_TASK15: float = 5.0
"""The applied voltage of Task 15, V."""

DETERMINED: float = 10.0
"""An interval whose ends are further apart than this factor says the log does not tell the
value: it is printed as "not determined by this log", never as numbers."""


def determined(ci: tuple[float, float]) -> bool:
    """True when the interval ``ci`` (lo, hi) of a positive quantity is finite and spans at
    most a factor of :data:`DETERMINED`."""
    lo, hi = ci
    return math.isfinite(lo) and math.isfinite(hi) and lo > 0 and hi <= DETERMINED * lo


@dataclass(frozen=True)
class ResponseResult:
    """Tasks 11-13 from a run log.

    K: static gain (rad/s per V, median over rises of the fitted omega_ss / u_ss);
    T: the least-squares time constant (s), the one the model uses, with the dead time
    ``dead_time`` (s, 0 when the response follows the steps within a sample period); where
    the speed creeps on after the rise, T, the steady speeds (so K and omega_ss) and the
    dead time are the fit of the rise's rows alone, and ``fit.every_row_T`` every row's T;
    glitch_rows: switch-on glitch rows at the start of the log, left out of everything; T_63: the median 63 %
    reading (s, None if no step crossed); T_ci: 95 % interval of T (s); J: inertia (kg m^2);
    omega_ss: median fitted steady speed of the steps (rad/s); u_ss: the applied voltage K
    divides by (V); u_ss_how: how the table gave it (:func:`~.steady.u_ss_at`: 'row',
    'interpolated', 'extrapolated') or 'log' (no u_req column: the log's own u); steps: each
    rise; fit: details of the least-squares fit; K_ci: 95 % interval of K (rad/s per
    V); T_63_model: the 63 % reading taken on the fitted model sampled like the log (s);
    T_63_note: how far the 63 % reading is from T and why, a record (None without a reading).
    """

    K: float
    T: float
    T_63: float | None
    T_ci: tuple[float, float]
    J: float
    omega_ss: float
    u_ss: float
    u_ss_how: UssHow
    rises: tuple[Rise, ...]
    fit: TimeConstantFit
    model_uses: str = "least_squares"
    K_ci: tuple[float, float] = (math.nan, math.nan)
    T_63_model: float | None = None
    T_63_note: T63Note | None = None
    dead_time: float = 0.0
    glitch_rows: int = 0

    @property
    def K_determined(self) -> bool:
        """False when K's 95 % interval spans more than a factor of :data:`DETERMINED`."""
        return determined(self.K_ci)

    @property
    def u_c(self) -> float:
        """Dry friction's breakaway voltage (V) the whole-log fit found, 0 when it found none."""
        return self.fit.u_c if self.fit.gain is not None else 0.0

    @property
    def K_above_u_c(self) -> float | None:
        """With dry friction (:attr:`u_c` > 0), the fit's gain per volt above the breakaway
        (rad/s per V of u_A): the steady speed is K_above_u_c (u_A - u_c); None without."""
        return self.fit.gain if self.u_c > 0 else None

    def omega_with_friction(self, u_A: float) -> float | None:
        """The steady speed (rad/s) at the applied voltage ``u_A`` (V) of the fitted model
        with the dry friction it found: K_above_u_c (u_A - u_c), 0 while |u_A| <= u_c. None
        when the fit found no dry friction (then it is K u_A, the lab's model)."""
        gain = self.K_above_u_c
        if gain is None:
            return None
        if abs(u_A) <= self.u_c:
            return 0.0
        return gain * (u_A - math.copysign(self.u_c, u_A))

    @property
    def task15_with_friction(self) -> float | None:
        """Task 15 by the fitted model with its dry friction (rad/s) when it differs from the
        lab's K u_A by more than :data:`FRICTION_APART` (relative), so that both are said;
        None otherwise (no friction found, or the two agree)."""
        lab = self.K * U_TASK15
        other = self.omega_with_friction(U_TASK15)
        if other is None or not abs(other - lab) > FRICTION_APART * abs(lab):
            return None
        return other

    @property
    def T_determined(self) -> bool:
        """False when T's 95 % interval spans more than a factor of :data:`DETERMINED` (the
        log does not tell T: the interval is then not printed as numbers), or when T ended on
        the bound of the range the fit tries (its interval then says nothing)."""
        return determined(self.T_ci) and not self.fit.T_on_bound


@dataclass(frozen=True)
class Identification:
    """Everything of Tasks 6-15. ``step`` is None without a run log."""

    R: float
    rows: tuple[Row, ...]
    k_v: float
    k_a: float
    f: float
    step: ResponseResult | None
    observations: tuple[Observation, ...]

    @property
    def model(self) -> FirstOrder | None:
        """Task 14: T omega' = -omega + K u_A with the least-squares T and the step's K (the
        dead time, when there is one, is ``step.dead_time``)."""
        return FirstOrder(T=self.step.T, K=self.step.K) if self.step else None

    @property
    def omega_at_5V(self) -> float | None:
        """Task 15 by the lab's model: the final speed for u_A = 5 V, K u_A (rad/s). It has
        no dry friction; see :attr:`omega_at_5V_with_friction`."""
        return self.step.K * U_TASK15 if self.step else None

    @property
    def omega_at_5V_with_friction(self) -> float | None:
        """Task 15 by the fitted model with the dry friction the fit found (rad/s; None when
        it found none): K is omega_ss / u_ss at the step's level, a line through zero, and
        with a breakaway voltage the speed at another voltage is not in proportion to it."""
        return self.step.omega_with_friction(U_TASK15) if self.step else None


@dataclass(frozen=True)
class ZeroVoltRise:
    """A rising edge of the log that ends at 0 V on the motor, so K = omega_ss / u_ss has no
    value there: its time ``t`` (s), the voltage it requested ``u_req`` (V; None when the log
    has no u_req column) and how that 0 V was found (``how``; 'extrapolated' when the level
    is below the nearest table row's driver drop, 'off' when the edge rises to 0 V)."""

    t: float
    u_req: float | None
    how: UssHow


class ZeroVoltRefusal(Exception):
    """:func:`identify`'s refusal of a log with a :class:`ZeroVoltRise`, at ``source``
    (a file name) and ``line`` (the edge's line in it, or None). A record, not words: the
    layer that shows it says it as an InputError (lab/content/u_ss_says.py)."""

    def __init__(self, source: str, line: int | None, rise: ZeroVoltRise) -> None:
        super().__init__(source, line, rise)
        self.source = source
        self.line = line
        self.rise = rise


def _response_result(
    log: RunLog,
    rows: tuple[Row, ...],
    u_ss_table: Sequence[tuple[float, float]],
    R: float,
    k_v: float,
    k_a: float,
    f: float,
) -> tuple[ResponseResult, list[Observation]]:
    cmd, _ = command(log)
    glitches = switch_on_glitches(cmd, log.omega)
    whole_log = log
    log = log.rows_from(glitches) if glitches else log
    windows, skipped = rise_windows(log)
    if not windows:
        cmd, name = command(log)
        edges = find_edges(cmd)
        rising = sum(e.rising for e in edges)
        # a step from rest to a negative voltage: the same run in reverse
        down = [e for e in edges if e.after < 0 and abs(e.before) < 0.1 * abs(e.after)]
        reverse = (down[0].before, down[0].after) if down and not rising else None
        raise IdentifyRefused(
            log.source, log.line_of(0), NoRisingEdge(name, MIN_AFTER, rising, reverse)
        )
    refused = problem(log.board_time(), log.u, log.omega)  # the fit runs on the board's clock
    if refused:
        raise LogRefused(log.source, None, refused)
    if "t_us" in log.extra:  # the fit's clock against the log's
        apart = clock_problem(log.t, log.extra["t_us"])
        if apart:
            raise LogRefused(log.source, log.line_of(0), apart)
    theta, angle_source = log.angle()
    if not np.ptp(theta) > 0:  # nothing to fit: the least squares would divide by zero
        raise LogRefused(log.source, None, StillAngle(angle_source))
    # a speed column that runs behind the angle column is no mean over each interval
    lag = speed_lag(log.t, log.omega, theta) if angle_source.column == "theta" else None
    lagging = lag if lag is not None and lag > LAG_SAMPLES * log.ts else None
    fit = fit_time_constant(log)
    if fit is None:  # cannot happen with usable windows; keeps the types honest
        raise IdentifyRefused(log.source, None, RiseNotFitted())
    # the rise and every row disagree because the speed creeps on after the rise: T, K, J and
    # the model follow the rise, and every row's T is the other reading (issue 17)
    every: TimeConstantFit | None = None
    rise_only = following_rise(fit) if creep_after_rise(log, fit) is not None else None
    if rise_only is not None:
        every, fit = fit, rise_only
    steps = rises(log, fit)
    u_used: list[float] = []
    hows: list[UssHow] = []
    for s in steps:
        if s.u_req is None:
            u_used.append(s.u_high)
            hows.append("log")
        else:
            u, how = u_ss_at(u_ss_table, s.u_req)
            u_used.append(u)
            hows.append(how)
    for s, u, how_u in zip(steps, u_used, hows, strict=True):
        if u == 0:  # K = omega_ss / u_ss has no value
            raise ZeroVoltRefusal(log.source, s.line, ZeroVoltRise(s.t, s.u_req, how_u))
    K_each = [s.omega_ss / u for s, u in zip(steps, u_used, strict=True)]
    K = float(np.median(K_each))
    omega_ss = float(np.median([s.omega_ss for s in steps]))
    u_ss = float(np.median(u_used))
    # how the median u_ss was found: that of the step(s) in the middle by u_ss (not by time),
    # the least direct of the two when the median is the mean of two found differently
    order = sorted(range(len(u_used)), key=lambda k: u_used[k])
    middle = {hows[order[len(order) // 2]], hows[order[(len(order) - 1) // 2]]}
    how = next(h for h in (*U_SS_HOW, *middle) if h in middle)
    T = fit.T
    reads = [s.T_63 for s in steps if s.T_63 is not None]
    T_63 = float(np.median(reads)) if reads else None
    T_63_model = model_reading_63(log, fit, steps) if T_63 is not None else None
    noise = reading_noise(log, steps, T, fit)
    J = inertia_from_time_constant(T, R, f, k_v, k_a)
    result = ResponseResult(
        K=K,
        T=T,
        T_63=T_63,
        T_ci=fit.ci,
        J=J,
        omega_ss=omega_ss,
        u_ss=u_ss,
        u_ss_how=how,
        rises=tuple(steps),
        fit=fit,
        K_ci=_K_interval(K, K_each, u_used, fit),
        T_63_model=T_63_model,
        T_63_note=_T_63_note(
            T,
            T_63,
            T_63_model,
            log.ts,
            fit.dead_time,
            bool(fit.left_out),
            fit.shift_on_bound,
            noise,
            lagging,
        ),
        dead_time=fit.dead_time,
        glitch_rows=glitches,
    )
    shape = (
        T_63 - T_63_model
        if (fit.shift_on_bound or (fit.dead_time > 0 and not fit.left_out))
        and T_63 is not None
        and T_63_model is not None
        else None
    )
    observations = (
        response_observations(
            rows,
            steps,
            hows,
            u_ss,
            T,
            T_63,
            log.ts,
            len(skipped),
            fit.dead_time,
            shape,
            noise,
            fit.ci,
        )
        if rows
        else []
    )
    observations += fit_observations(whole_log, glitches, fit, result.T_determined, every)
    observations += friction_observations(K, u_ss, result.u_c, result.K_above_u_c, U_TASK15)
    if lagging is not None:
        observations = [
            replace(o, lag=lagging) if isinstance(o, T63Differs) else o for o in observations
        ]
        observations.append(SpeedLags(lagging, log.ts))
    return result, observations


def response_alone(log: RunLog, u_ss_table: Sequence[tuple[float, float]]) -> ResponseResult:
    """Tasks 11-12 from the run log and the table's ``(u_req, u_ss)`` pairs (V) alone: K,
    T and the 63 % reading, which need neither R nor i_ss. J (Task 13) needs R, k_v and f:
    it is NaN here. Raises IdentifyRefused, LogRefused and ZeroVoltRefusal as
    :func:`identify` does for the log."""
    return response_observed(log, u_ss_table)[0]


def response_observed(
    log: RunLog, u_ss_table: Sequence[tuple[float, float]]
) -> tuple[ResponseResult, list[Observation]]:
    """:func:`response_alone` and what :func:`identify` observes of the log's fit (its
    dead time, glitch rows, the rise's T beside every row's, ...): the model check's text
    sets identify's T beside its own with them. Raises as :func:`response_alone` does."""
    return _response_result(log, (), u_ss_table, math.nan, math.nan, math.nan, math.nan)


NEAR_63: tuple[float, float] = (0.3, 2.0)
"""The rows whose scatter says how far noise moves a 63 % reading: from 0.3 T to 2 T after
a rise starts (its dead time's end), around where it crosses 63 % (1 T)."""


def reading_noise(
    log: RunLog, steps: Sequence[Rise], T: float, fit: TimeConstantFit | None = None
) -> tuple[float, float] | None:
    """How far the speed's sample-to-sample scatter moves a 63 % reading read off single
    samples: ``(scatter, sway)``, the scatter of the speed (rad/s: the standard deviation of
    successive differences over sqrt 2, counts' steps included, median over the rises) and
    that scatter over the speed's slope where it crosses 63 % (s: the fitted rise's slope,
    (omega_ss - omega0) e^-1 / T). With ``fit``, the scatter is that of the speed less the
    fitted model's over the rows around the crossing (:data:`NEAR_63`; a speed whose noise
    grows with the speed scatters less there than once settled: ev3-large-duty100, 1.55
    against 4.36 rad/s); a rise with fewer than eight such rows uses its settled rows (5 T
    after its step). None when no rise has either."""
    t, w = log.t, log.omega
    model = None
    if fit is not None:
        model = np.full(t.size, np.nan)
        model[1:] = np.diff(fit.predicted) / np.diff(log.board_time())
        start = fit.dead_time
    scatters, sways = [], []
    for s in steps:
        if not T > 0:
            continue
        sd = None
        if model is not None:
            t0 = s.t + start
            near = np.flatnonzero((t >= t0 + NEAR_63[0] * T) & (t <= t0 + NEAR_63[1] * T))
            r = (w - model)[near]
            if near.size >= 8 and np.all(np.isfinite(r)):
                sd = float(np.std(np.diff(r))) / math.sqrt(2.0)
        if sd is None:
            settled = np.flatnonzero((t >= s.t + 5.0 * T) & (t <= s.t + s.duration))
            if settled.size < 10:
                continue
            sd = float(np.std(np.diff(w[settled]))) / math.sqrt(2.0)
        slope = abs(s.omega_ss - s.omega0) * math.exp(-1.0) / T
        if slope > 0:
            scatters.append(sd)
            sways.append(sd / slope)
    if not sways:
        return None
    return float(np.median(scatters)), float(np.median(sways))


def _K_interval(
    K: float, K_each: Sequence[float], u_used: Sequence[float], fit: TimeConstantFit
) -> tuple[float, float]:
    """95 % interval of K (rad/s per V): from the fit's covariance when one model gives every
    step's speed (the whole-log fit), else from the scatter of the steps' K (three or more
    steps) or the fit's standard error of the step's speed (fewer)."""
    i = int(np.argsort(K_each)[len(K_each) // 2])  # the step whose K is the median (upper)
    if fit.gain is not None or len(K_each) < 3:
        se = fit.omega_ss_se[i] / u_used[i]
        half = t975(fit.dof) * se
    else:
        spread = float(np.std(K_each, ddof=1)) * math.sqrt(math.pi / 2) / math.sqrt(len(K_each))
        half = t975(len(K_each) - 1) * spread
    return (K - half, K + half)


LAG_SAMPLES: float = 0.5
"""A speed column that runs behind the angle column by more than this many sample periods
(:func:`~minseg_tui.model.runlog.speed_lag`) is said to: a mean over each interval runs 0
behind (eight of the logs in ../shared: within 1 us; the n20-12v two, a speed over the
nominal period on longer rows, run ahead), ev3dev's speed attribute 1.4-1.9 periods."""


class RestWhy(Enum):
    """What the part of the 63 % reading that sampling the fitted model does not give is:
    WHOLE: nothing worth saying (the sampling is the whole difference); NOISE: the noise of
    reading single samples, within the sway the speed's scatter gives (the shift on its
    bound); SHAPE_MISFIT: the shape of the rise, with that noise (the shift on its bound);
    SHAPE: the shape of the rise, beyond that noise; STALL: reading across a logging stall's
    gap; SINGLE: the noise of reading single samples."""

    WHOLE = "whole"
    NOISE = "noise"
    SHAPE_MISFIT = "shape_misfit"
    SHAPE = "shape"
    STALL = "stall"
    SINGLE = "single"


@dataclass(frozen=True)
class T63Note:
    """How far the manual's 63 % reading ``T_63`` (s) is from the least-squares ``T`` (s),
    and why: ``model``, the reading taken the same way on the fitted model sampled every
    ``ts`` (s) like the log (None when not taken: then only the difference is said), with the
    ``dead_time`` (s) of the model; ``misfit``: the steps' time shift ended on its bound;
    ``rest``: what the part the model does not give is; ``noise``: the speed's scatter
    (rad/s) and the sway it gives a reading of single samples (s), or None; ``lag``: how late
    the log's speed column runs behind its angle column (s, :data:`LAG_SAMPLES`), or None."""

    T_63: float
    T: float
    ts: float
    model: float | None
    dead_time: float
    misfit: bool
    rest: RestWhy
    noise: tuple[float, float] | None
    lag: float | None = None


def _T_63_note(
    T: float,
    T_63: float | None,
    T_63_model: float | None,
    ts: float,
    dead_time: float = 0.0,
    stalled: bool = False,
    misfit: bool = False,
    noise: tuple[float, float] | None = None,
    lag: float | None = None,
) -> T63Note | None:
    """How far the manual's 63 % reading is from the least-squares T, and why (the dead time
    ``dead_time``, s, is part of it when the model has one; ``stalled``: rows of a logging
    stall were left out; ``misfit``: the steps' time shift ended on its bound, so the rise
    may have a shape one time constant does not follow, and the rest is that shape unless
    it is within ``noise``, :func:`reading_noise`'s scatter (rad/s) and the sway (s) it gives
    a reading of single samples). None without a reading."""
    if T_63 is None:
        return None
    rest = RestWhy.WHOLE
    if T_63_model is not None:
        left = T_63 - T_63_model
        # the share that may go unexplained is of the difference the dead time leaves (a
        # delay of 332 ms must not hide a 14 ms miss of the rise: micromouse-n20-duty255)
        if abs(left) > max(0.02 * T, 0.1 * abs(T_63 - T - dead_time)):
            beyond_noise = noise is not None and abs(left) > noise[1]
            if misfit and noise is not None and abs(left) <= noise[1]:
                rest = RestWhy.NOISE
            elif misfit:
                rest = RestWhy.SHAPE_MISFIT
            elif beyond_noise and noise is not None and not stalled:
                rest = RestWhy.SHAPE
            else:
                rest = RestWhy.STALL if stalled else RestWhy.SINGLE
    return T63Note(T_63, T, ts, T_63_model, dead_time, misfit, rest, noise, lag)


def identify(
    readings: Sequence[Reading],
    R: float,
    log: RunLog | None = None,
    source: str = "table",
    u_ss_table: Sequence[tuple[float, float]] | None = None,
) -> Identification:
    """Tasks 6-15 from the table's readings, the resistance R (ohm) and optionally a run log.

    ``u_ss_table``: the ``(u_req, u_ss)`` pairs (V) of every table row that has a u_ss,
    complete or not, which K divides by (:func:`~.steady.u_ss_at`); default: the readings'.
    Raises :class:`~.refusals.IdentifyRefused` for a bad R, a bad row, or a log without a
    usable rise, :class:`~minseg_tui.model.runlog.LogRefused` for a log no analysis takes or
    a wheel that never turns, and :class:`ZeroVoltRefusal` for a rise that ends at 0 V on the
    motor.
    """
    rows, k_v, k_a, f = steady_state(readings, R, source)
    step: ResponseResult | None = None
    more: list[Observation] = []
    if log is not None:
        table = table_of(rows) if u_ss_table is None else list(u_ss_table)
        step, more = _response_result(log, rows, table, R, k_v, k_a, f)
    # the table first; a row in the log's unit is not called rpm (the log says how fast it turns)
    observations = table_observations(rows, R, k_v, k_a, step.K if step is not None else None)
    observations += more
    return Identification(
        R=R, rows=rows, k_v=k_v, k_a=k_a, f=f, step=step, observations=tuple(observations)
    )
