"""What the numbers of Tasks 6-15 show: observations, each a typed record with a code.

Each record holds what was found and the figures its sentence needs, nothing else; the
sentences a student reads are made from them outside the model, in
:mod:`minseg_tui.lab.content.identify_says` (issue 19 item 4: the model gives records).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.identify.risefit import RISE_SPAN, Rise, TimeConstantFit
from minseg_tui.model.identify.rises import rise_windows
from minseg_tui.model.identify.steady import Reading, Row, omega_ss_at
from minseg_tui.model.runlog import RunLog, zeroed_first_row
from minseg_tui.quantities import RPM

KV_OUTLIER: float = 0.15
"""A row's k_v this far (relative) from the median is called a bad reading."""

RISE_VS_TABLE: float = 0.10
"""Step and table steady-state speeds further apart than this (relative) are reported."""

RPM_GAIN: float = 6.0
"""omega_ss / u_ss above this (rad/s per V; the lab's motor turns about 1.6) but not when read
as rpm: the row's omega_ss was typed in rpm (k_v would come out about ten times small)."""


SHORT_T_SAMPLES: float = 3.0
"""T below this many sample periods: the 63 % reading measures the sampling, not the motor."""


@dataclass(frozen=True)
class Observation:
    """Something the numbers show: a record whose class says what, with the figures its
    sentence needs. ``code``: its short name (the contract of the JSON and the session's
    notices: a class per case, and cases of one finding share a code)."""

    code: ClassVar[str] = ""


@dataclass(frozen=True)
class RowAt:
    """A row of the table as a sentence names it: its number (1-based), its u_req (V) and its
    line in the file (None when typed)."""

    number: int
    u_req: float
    line: int | None


def _row_at(index: int, r: Reading) -> RowAt:
    return RowAt(index + 1, r.u_req, r.line)


@dataclass(frozen=True)
class CurrentInAmperes(Observation):
    """A row's i_ss below 1: typed in A, not mA (``i_ss`` as typed)."""

    code: ClassVar[str] = "i_ss_units"
    row: RowAt
    i_ss: float


@dataclass(frozen=True)
class CurrentHigh(Observation):
    """A row's i_ss (mA) above 100 mA: the meter measured something else."""

    code: ClassVar[str] = "i_ss_high"
    row: RowAt
    i_ss: float


@dataclass(frozen=True)
class SpeedInRpm(Observation):
    """A row's omega_ss (as typed) per u_ss (V) above :data:`RPM_GAIN` but not in rpm: typed
    in rpm."""

    code: ClassVar[str] = "omega_ss_units"
    row: RowAt
    omega_ss: float
    u_ss: float


@dataclass(frozen=True)
class KvNotPositive(Observation):
    """A row whose R i_ss is not below u_ss: R (ohm), i_ss (mA), u_ss (V), its k_v (V s/rad)."""

    code: ClassVar[str] = "k_v_nonpositive"
    row: RowAt
    R: float
    i_ss: float
    u_ss: float
    k_v: float


@dataclass(frozen=True)
class KvOutlier(Observation):
    """A row's k_v (V s/rad) ``dev`` (relative) from the median ``median`` of three or more."""

    code: ClassVar[str] = "k_v_outlier"
    row: RowAt
    k_v: float
    dev: float
    median: float


@dataclass(frozen=True)
class KvDisagree(Observation):
    """The two rows' k_v (V s/rad) ``a`` and ``b``, ``apart`` (relative to the median)."""

    code: ClassVar[str] = "k_v_disagree"
    a: float
    b: float
    apart: float


@dataclass(frozen=True)
class USsAboveUReq(Observation):
    """u_ss above u_req on every row the results use: each row's ``(u_req, u_ss)`` (V)."""

    code: ClassVar[str] = "u_ss_above_u_req"
    rows: tuple[tuple[float, float], ...]


@dataclass(frozen=True)
class DryFriction(Observation):
    """f (N m s/rad) falls with speed (rad/s): from ``f_slow`` at ``w_slow`` to ``f_fast`` at
    ``w_fast``; ``line``: the viscous f (N m s/rad) and dry torque tau_c (N m) of a straight
    line through the rows, when both come out positive (None else)."""

    code: ClassVar[str] = "dry_friction"
    f_slow: float
    w_slow: float
    f_fast: float
    w_fast: float
    line: tuple[float, float] | None


LOG_AGREES: float = 0.3
"""A row's omega_ss / u_ss this close (relative) to the run log's K says the row is in the
log's unit, rad/s: it is not called rpm however fast the motor turns."""


def table_observations(
    rows: Sequence[Row], R: float, k_v: float, k_a: float, K_log: float | None = None
) -> list[Observation]:
    """What the table shows: dry friction, a bad reading, currents in the wrong unit, u_ss and
    u_req swapped. ``K_log``: the run log's K (rad/s per V), when there is one: a row that
    agrees with it within :data:`LOG_AGREES` is not said to be in rpm."""
    out: list[Observation] = []
    for i, row in enumerate(rows):
        r = row.reading
        if r.i_ss < 1.0:
            out.append(CurrentInAmperes(_row_at(i, r), r.i_ss))
        elif r.i_ss > 100.0:
            out.append(CurrentHigh(_row_at(i, r), r.i_ss))
        log_agrees = K_log is not None and abs(r.omega_ss / r.u_ss / K_log - 1) <= LOG_AGREES
        if (
            r.omega_ss / r.u_ss > RPM_GAIN
            and r.omega_ss * RPM / r.u_ss <= RPM_GAIN
            and not log_agrees
        ):
            out.append(SpeedInRpm(_row_at(i, r), r.omega_ss, r.u_ss))
        if row.k_v <= 0:
            out.append(KvNotPositive(_row_at(i, r), R, r.i_ss, r.u_ss, row.k_v))
    if len(rows) >= 3:
        for i, row in enumerate(rows):
            dev = (row.k_v - k_v) / k_v if k_v else math.inf
            if abs(dev) > KV_OUTLIER:
                out.append(KvOutlier(_row_at(i, row.reading), row.k_v, dev, k_v))
    elif len(rows) == 2:
        a, b = rows[0].k_v, rows[1].k_v
        if abs(a - b) / abs(k_v) > 2 * KV_OUTLIER:
            out.append(KvDisagree(a, b, abs(a - b) / abs(k_v)))
    above = [row.reading.u_ss > (1.0 + U_SS_ABOVE) * row.reading.u_req for row in rows]
    if rows and all(above) and all(row.reading.u_req > 0 for row in rows):
        out.append(USsAboveUReq(tuple((row.reading.u_req, row.reading.u_ss) for row in rows)))
    out += _dry_friction(rows, k_a)
    return out


U_SS_ABOVE: float = 0.02
"""u_ss this far (relative) above u_req on every row says the columns are swapped (a driver
gives at most what is requested)."""


def _dry_friction(rows: Sequence[Row], k_a: float) -> list[Observation]:
    by_speed = sorted(rows, key=lambda row: row.reading.omega_ss)
    w = np.array([row.reading.omega_ss for row in by_speed])
    f = np.array([row.f for row in by_speed])
    if len(rows) < 2 or np.ptp(w) <= 0.05 * np.max(w):
        return []
    falling = bool(np.all(np.diff(f) < 0)) and f[0] > 1.1 * f[-1]
    if not falling:
        return []
    torque = k_a * np.array([row.reading.i_ss * 1e-3 for row in by_speed])
    slope, intercept = np.polyfit(w, torque, 1)
    line = (float(slope), float(intercept)) if slope > 0 and intercept > 0 else None
    return [DryFriction(float(f[0]), float(w[0]), float(f[-1]), float(w[-1]), line)]


@dataclass(frozen=True)
class USsFromLog(Observation):
    """The log has no u_req column: K divides by the applied voltage it recorded (``u_ss``, V)."""

    code: ClassVar[str] = "u_ss_from_log"
    u_ss: float


@dataclass(frozen=True)
class USsInterpolated(Observation):
    """No table row at the steps' requested ``levels`` (V): u_ss (V) is interpolated between
    the table's rows."""

    code: ClassVar[str] = "u_ss_interpolated"
    levels: tuple[float, ...]
    u_ss: float


@dataclass(frozen=True)
class USsExtrapolated(USsInterpolated):
    """As :class:`USsInterpolated`, extrapolated beyond the table's rows."""

    code: ClassVar[str] = "u_ss_extrapolated"


@dataclass(frozen=True)
class SeveralLevels(Observation):
    """The rising edges go to several requested ``levels`` (V)."""

    code: ClassVar[str] = "several_levels"
    levels: tuple[float, ...]


@dataclass(frozen=True)
class StepVsTable(Observation):
    """The rise at ``t`` (s) settles at ``omega_ss`` (rad/s), the table gives ``omega_table``
    (rad/s) at its ``u_req`` (V)."""

    code: ClassVar[str] = "step_vs_table"
    t: float
    omega_ss: float
    omega_table: float
    u_req: float


@dataclass(frozen=True)
class TShort(Observation):
    """T (s) shorter than ``samples`` sample periods ``ts`` (s)."""

    code: ClassVar[str] = "T_short"
    T: float
    samples: float
    ts: float


class T63Why(Enum):
    """Why the 63 % reading differs from the least-squares T, the case that applies:
    DEAD_TIME_SHAPE: the dead time, and a shape of the rise beyond the noise; DEAD_TIME: the
    dead time and the half-sample lag; SHAPE: mostly the shape of the rise; NOISE: the
    sampling and the shift on its bound, and the noise of single samples; LAG: the
    half-sample lag of a mean speed (and any filter)."""

    DEAD_TIME_SHAPE = "dead_time_shape"
    DEAD_TIME = "dead_time"
    SHAPE = "shape"
    NOISE = "noise"
    LAG = "lag"


@dataclass(frozen=True)
class T63Differs(Observation):
    """The 63 % reading ``T_63`` (s) and the least-squares ``T`` (s) more than 25 % apart, and
    why (``why``). ``dead_time`` (s); ``shape``: the part of the reading the fitted model read
    the same way does not give (s), or None; ``noise``: the speed's scatter (rad/s) and the
    sway it gives a reading of single samples (s), or None (as
    :func:`response_observations` takes them); ``T_ci``: the least-squares T's 95 % interval
    (s) when it holds the 63 % reading too (the log then does not tell the two apart), else
    None; ``lag``: how late the speed column runs behind the angle column (s,
    :class:`SpeedLags`), or None."""

    code: ClassVar[str] = "T_63_differs"
    T_63: float
    T: float
    why: T63Why
    dead_time: float
    shape: float | None
    noise: tuple[float, float] | None
    T_ci: tuple[float, float] | None = None
    lag: float | None = None


@dataclass(frozen=True)
class NotSettled(Observation):
    """``count`` steps last less than 5 T (T in s)."""

    code: ClassVar[str] = "not_settled"
    count: int
    T: float


@dataclass(frozen=True)
class StepsSkipped(Observation):
    """``count`` rises too short or too close to the start of the log to use."""

    code: ClassVar[str] = "steps_skipped"
    count: int


def _t63_why(
    T: float,
    T_63: float,
    dead_time: float,
    shape: float | None,
    noise: tuple[float, float] | None,
) -> T63Why:
    if (
        dead_time > 0
        and shape is not None
        and noise is not None
        and abs(shape) > max(0.02 * T, 0.1 * abs(T_63 - T - dead_time), noise[1])
    ):
        return T63Why.DEAD_TIME_SHAPE
    if dead_time > 0:
        return T63Why.DEAD_TIME
    if (
        shape is not None
        and abs(shape) > 0.5 * abs(T_63 - T)
        and (noise is None or abs(shape) > noise[1])
    ):
        return T63Why.SHAPE
    if shape is not None and noise is not None and abs(shape) <= noise[1]:
        return T63Why.NOISE
    return T63Why.LAG


def response_observations(
    rows: Sequence[Row],
    steps: Sequence[Rise],
    hows: Sequence[str],
    u_ss: float,
    T: float,
    T_63: float | None,
    ts: float,
    skipped: int,
    dead_time: float = 0.0,
    shape: float | None = None,
    noise: tuple[float, float] | None = None,
    T_ci: tuple[float, float] | None = None,
) -> list[Observation]:
    """What the run log shows (Tasks 11-13): where u_ss came from, steps that disagree with
    the table, a T too short for the sampling, steps too short to settle or to use.

    rows: the table; steps: the rises used; hows: how u_ss was found for each step;
    u_ss: the median u_ss (V); T: least-squares T (s); T_63: the 63 % reading (s); ts: sample
    period (s); skipped: rises not usable; dead_time: the model's dead time (s);
    shape: when the rise may have a shape one time constant does not follow (the steps' time
    shift on its bound, or a dead time in the model and no logging stall read across), the part of the reading the fitted model read the same way does not
    give (s), else None; noise: the speed's scatter (rad/s) and how far it moves a reading of
    single samples (s), from :func:`~.identification.reading_noise`, or None: a shape within
    that sway is said to be the noise, not a shape one time constant does not follow;
    T_ci: the least-squares T's 95 % interval (s), or None.
    """
    observations: list[Observation] = []
    levels = tuple(sorted({s.u_req for s in steps if s.u_req is not None}))
    if "log" in hows:
        observations.append(USsFromLog(u_ss))
    if "extrapolated" in hows:
        observations.append(USsExtrapolated(levels, u_ss))
    elif "interpolated" in hows:
        observations.append(USsInterpolated(levels, u_ss))
    if len(levels) > 1:
        observations.append(SeveralLevels(levels))
    for s in steps:
        if s.u_req is None:
            continue
        w_table = omega_ss_at(rows, s.u_req)
        if w_table is not None and abs(s.omega_ss - w_table) > RISE_VS_TABLE * w_table:
            observations.append(StepVsTable(s.t, s.omega_ss, w_table, s.u_req))
            break
    if T < SHORT_T_SAMPLES * ts:
        observations.append(TShort(T, SHORT_T_SAMPLES, ts))
    if T_63 is not None and abs(T_63 - T) > 0.25 * T:
        why = _t63_why(T, T_63, dead_time, shape, noise)
        holds = T_ci is not None and T_ci[0] <= T_63 <= T_ci[1]
        observations.append(
            T63Differs(T_63, T, why, dead_time, shape, noise, T_ci if holds else None)
        )
    short = [s for s in steps if s.duration < 5 * T]
    if short:
        observations.append(NotSettled(len(short), T))
    if skipped:
        observations.append(StepsSkipped(skipped))
    return observations


FRICTION_APART: float = 0.005
"""The lab's K u_A and the model with dry friction further apart than this (relative) at
5 V: Task 15's answer is given both ways, with why."""


@dataclass(frozen=True)
class FrictionTask15(Observation):
    """The fit found dry friction: ``gain`` (rad/s per V) above a breakaway ``u_c`` (V); K
    (rad/s per V) read at the step's ``u_ss`` (V); at ``u_A`` (V) the lab's model gives
    ``lab`` (rad/s) and the model with dry friction ``with_friction`` (rad/s)."""

    code: ClassVar[str] = "friction_task15"
    gain: float
    u_c: float
    K: float
    u_ss: float
    u_A: float
    lab: float
    with_friction: float


def friction_observations(
    K: float, u_ss: float, u_c: float, K_above_u_c: float | None, u_A: float
) -> list[Observation]:
    """Why Task 15's K u_A is not the speed the log's motor turns at ``u_A`` (V) when the fit
    found dry friction: K (rad/s per V) = omega_ss / u_ss is read at the step's level u_ss (V)
    and makes a line through zero; the fit's model is K_above_u_c (u_A - u_c) (rad/s per V,
    V). Empty without dry friction or when the two agree within :data:`FRICTION_APART`."""
    if K_above_u_c is None or not u_c > 0:
        return []
    lab = K * u_A
    with_friction = K_above_u_c * (u_A - u_c) if u_A > u_c else 0.0
    if not lab > 0 or abs(with_friction / lab - 1) <= FRICTION_APART:
        return []
    return [FrictionTask15(K_above_u_c, u_c, K, u_ss, u_A, lab, with_friction)]


@dataclass(frozen=True)
class Lines:
    """Rows of a log as a sentence names them: ``first`` to ``last`` (equal for one), the
    file's line numbers when ``by_line``, else 1-based row numbers."""

    first: int
    last: int
    by_line: bool


def _lines(log: RunLog, rows: Sequence[int]) -> Lines:
    """The file's lines of the 0-based rows of ``log`` (its rows, 1-based, when a line is
    unknown)."""
    lines = [log.line_of(r) for r in rows]
    if all(x is not None for x in lines):
        nums = [int(x) for x in lines if x is not None]
        return Lines(nums[0], nums[-1], True)
    return Lines(rows[0] + 1, rows[-1] + 1, False)


COARSE_COUNT = 0.1
"""One count per sample above this share of the rise (rad/s over rad/s) is too coarse to show
how a rise starts (n20-12v-pwm25: 1.8 rad/s of a 9.3 rad/s rise)."""


BEHIND_SHARE: float = 0.02
"""The measured speed is behind the fitted response over the first time constant after the
steps when its mean there is lower by more than this share of the rise (the median over the
rises)."""


def _behind_at_first(log: RunLog, fit: TimeConstantFit) -> bool:
    """Whether the measured speed lags the fitted response over the first time constant
    after the rises' steps (median over the rises, by more than :data:`BEHIND_SHARE` of each
    rise): a wheel that starts later or more slowly than the response the fit moved early.
    ``log``: the rows the fit used (its rows count from the first)."""
    t = log.board_time()
    w = np.asarray(log.omega, dtype=float)
    model = np.full(t.size, np.nan)
    model[1:] = np.diff(fit.predicted) / np.diff(t)
    windows, _ = rise_windows(log)
    behind = []
    for win in windows:
        k = win.edge.start
        rows = np.arange(k + 1, win.post_last + 1)
        rows = rows[t[rows] <= t[k] + fit.T]
        rows = rows[np.isfinite(model[rows])]
        tail = model[win.post_last]
        before = float(np.median(w[win.pre_from : k + 1]))
        rise = abs(tail - before) if np.isfinite(tail) else 0.0
        if rows.size and rise > 0:
            behind.append(float(np.mean(model[rows] - w[rows])) / rise)
    return bool(behind) and float(np.median(behind)) > BEHIND_SHARE


@dataclass(frozen=True)
class GlitchRows(Observation):
    """The first ``count`` rows left out as switch-on glitches. ``zeroed``: the first of them
    reads 0 rad/s as the first row of a speed from counts does (``first``: where); ``rows``:
    the glitch rows besides it, whose speeds (rad/s) are ``speeds``; ``start``: where the fit
    starts."""

    code: ClassVar[str] = "glitch_rows"
    count: int
    zeroed: bool
    first: Lines
    rows: Lines
    n_rows: int
    speeds: tuple[float, ...]
    start: Lines


@dataclass(frozen=True)
class SpeedLags(Observation):
    """The log's speed column runs ``lag`` (s) behind its angle column
    (:func:`~minseg_tui.model.runlog.speed_lag`), more than half a sample period ``ts`` (s):
    it is no mean over each interval but a filtered or late speed."""

    code: ClassVar[str] = "speed_lags"
    lag: float
    ts: float


@dataclass(frozen=True)
class EdgeGlitch(Observation):
    """Rows right after a step (``rows``) whose speeds (rad/s, ``speeds``) read beyond any
    speed the rise later reaches (``level``, rad/s: the furthest a 5-row running median of
    the rows after them reaches up to the next change of the command), after which the speed
    falls back to ``after`` (rad/s): a glitch of the reading at switch-on
    (:func:`~minseg_tui.model.identify.risefit.edge_glitches`), kept in the fit."""

    code: ClassVar[str] = "edge_glitch"
    rows: Lines
    n_rows: int
    speeds: tuple[float, ...]
    level: float
    after: float


@dataclass(frozen=True)
class LoggingStall(Observation):
    """A row (``at``) after a ``gap`` (s) of ``gap / ts`` sample periods (``ts``, s), left out
    of the fit; ``mended``: the angle rebuilt from the speed column carried it across."""

    code: ClassVar[str] = "logging_stall"
    at: Lines
    gap: float
    ts: float
    mended: bool


@dataclass(frozen=True)
class DeadTime(Observation):
    """A dead time (s) in the model, more than the one sample period ``bound`` (s); with
    ``from_rise``, the rows of the rise alone show it (``onset``: where the speed first
    shows, s after the steps, or None); ``creep``: the speed creeps on after the rise
    (:class:`TRowsApart`'s ``creep``), which holds the fit of every row early; without it,
    the fit of every row takes no dead time only because it does not fit them clearly better
    (a start between coarse counts: tests/model/identgen.py seed 2). ``first_move``: where a
    row's own speed first leaves its level (s after the steps), when it does more than one
    sample period before ``onset``, which a 3-row running median reads (a first count alone,
    as coarse counts give, is dropped by it); None otherwise."""

    code: ClassVar[str] = "dead_time"
    dead_time: float
    bound: float
    from_rise: bool
    onset: float | None
    creep: bool
    first_move: float | None = None


class LateStart(Enum):
    """Why a shift on its upper bound is no dead time: MOVED_EARLY: a dead time fits better
    but the wheel moves before it would end; NO_BETTER: a dead time does not fit clearly
    better; COARSE: no dead time to fit, and one count per sample is too coarse to show the
    start; SLOW_START: no dead time to fit, the rise starts more slowly than one time
    constant gives."""

    MOVED_EARLY = "moved_early"
    NO_BETTER = "no_better"
    COARSE = "coarse"
    SLOW_START = "slow_start"


@dataclass(frozen=True)
class ShiftFree:
    """The fit with the shift free up to the wheel's first move (``onset``, s after the steps,
    read off a 3-row running median of the speed): its shift (s), T (s) and T's 95 % interval
    (s). ``first_move``: where a row's own speed first leaves its level (s after the steps),
    when that is earlier than ``onset`` (a first count the running median drops), else None."""

    onset: float
    shift: float
    T: float
    ci: tuple[float, float]
    first_move: float | None = None


@dataclass(frozen=True)
class ShiftLate(Observation):
    """The steps' time shift ended on its upper bound (``shift``, s): the wheel answers later
    than the sampling explains, and ``why`` it is no dead time. ``moved_early``: the share of
    the rise done when a dead time would end; ``onset``: where the wheel first moves (s after
    the steps, read off a 3-row running median of the speed); ``count``: one count per sample
    (rad/s) and ``rise`` the rise (rad/s), for COARSE; ``free``: the fit with the shift free,
    when made; ``first_move``: where a row's own speed first leaves its level (s after the
    steps), when that is earlier than ``onset`` (a first count the running median drops),
    else None."""

    code: ClassVar[str] = "shift_on_bound"
    shift: float
    why: LateStart
    moved_early: float | None
    onset: float | None
    count: float | None
    rise: float
    free: ShiftFree | None
    first_move: float | None = None


@dataclass(frozen=True)
class ShiftEarly(Observation):
    """The shift ended on its lower bound (``shift``, s) and the wheel moves before the logged
    steps: the steps are logged late."""

    code: ClassVar[str] = "shift_on_bound"
    shift: float


@dataclass(frozen=True)
class ShiftMisfit(Observation):
    """The shift ended on its lower bound (``shift``, s) although the wheel does not move
    before the steps (``onset``: where it first moves, s after them, when well past the one
    sample period; None else): a shape the model misses. ``behind``: the fitted response
    starts before the wheel and rises more slowly (``rows_apart``: the later rows pull T);
    else the rise is steeper at first and slower later."""

    code: ClassVar[str] = "shift_on_bound"
    shift: float
    onset: float | None
    behind: bool
    rows_apart: bool


@dataclass(frozen=True)
class TRowsApart(Observation):
    """The rows up to ``span`` T after each edge alone give ``rise_T`` (s, 95 % ``rise_ci``),
    all the rows ``T`` (s). ``creep``: when every row's T is the longer, the first rise's
    speed after its rows (rad/s: the mean of the first and of the last tenth of the rows
    from ``span`` rise_T after the wheel answers to the next edge) when it moves on by more
    than :data:`CREEP_SHARE` of the rise, else None; ``miss``: how far the model of every
    row falls behind the wheel on that rise's rows (rad/s, the largest 5-row mean), with it.
    ``up_T``: T (s) of the rows up to ``span`` T after the rising edges alone, when the fit
    of every row also uses falling edges (None otherwise). ``follows_rise``: with ``creep``,
    T, K, J and the model follow the rise (``rise_T`` and the rise's steady speed
    ``rise_speed``, rad/s), and ``T`` is the other reading. ``levels``: where the speed
    after the rise holds level (:func:`holds_level`) and the two lie within
    :data:`LEVEL_SHARE` of each other, the steady speed (rad/s, the median
    over the rises) the fit of the rise's rows alone reaches for, and the one the fit of
    every row holds (None otherwise). ``creep_span``: with
    ``creep``, how long after the first rise's step (s) the first and the last row it is
    read over come."""

    code: ClassVar[str] = "T_rows_apart"
    span: float
    rise_T: float
    rise_ci: tuple[float, float]
    T: float
    creep: tuple[float, float] | None = None
    miss: float | None = None
    up_T: float | None = None
    follows_rise: bool = False
    rise_speed: float | None = None
    levels: tuple[float, float] | None = None
    creep_span: tuple[float, float] | None = None


CREEP_SHARE: float = 0.03
"""After a rise the speed creeps on when it moves by more than this share of the rise between
the first and the last tenth of the rows after the rise's own (:class:`TRowsApart`)."""


@dataclass(frozen=True)
class _AfterRise:
    """The first rise of a log, for :func:`creep_after_rise` and :func:`holds_level`: board
    times t (s) and speeds w (rad/s) of the rows the fit used, the step's row k, the rise's own
    rows (up to :data:`RISE_SPAN` rise_T after the wheel answers) and the rows after them up to
    the next edge, with the first and last tenth of those rows' mean speeds and the median
    speed before the step (rad/s)."""

    t: NDArray[np.float64]
    w: NDArray[np.float64]
    k: int
    rise_rows: NDArray[np.int64]
    later: NDArray[np.int64]
    first: float
    last: float
    before: float

    @property
    def creeps(self) -> bool:
        """The speed moves by more than :data:`CREEP_SHARE` of the rise between the first and
        the last tenth of the rows after the rise's own."""
        return abs(self.last - self.first) > CREEP_SHARE * abs(self.first - self.before)

    @property
    def holds(self) -> bool:
        """The speed moves by at most that share: it holds level (neither, on a NaN)."""
        return abs(self.last - self.first) <= CREEP_SHARE * abs(self.first - self.before)


def _after_rise(log: RunLog, fit: TimeConstantFit) -> _AfterRise | None:
    """:class:`_AfterRise` of ``log``'s first rise under ``fit``, or None where the fit has no
    rise_T, the log no rise window, or fewer than 20 rows follow the rise's own."""
    if fit.rise_T is None:
        return None
    t = log.board_time()
    w = np.asarray(log.omega, dtype=float)
    windows, _ = rise_windows(log)
    if not windows:
        return None
    win = windows[0]
    k = win.edge.start
    start = float(t[k]) + max(fit.dead_time, fit.shift, 0.0)
    rows = np.arange(k + 1, int(win.post_last) + 1)
    own = t[rows] <= start + RISE_SPAN * fit.rise_T
    later = rows[~own]
    if later.size < 20:
        return None
    tenth = later.size // 10
    return _AfterRise(
        t,
        w,
        k,
        rows[own],
        later,
        float(np.mean(w[later[:tenth]])),  # means: a count's steps alternate
        float(np.mean(w[later[-tenth:]])),
        float(np.median(w[win.pre_from : k + 1])),
    )


def creep_after_rise(
    log: RunLog, fit: TimeConstantFit
) -> tuple[tuple[float, float], float, tuple[float, float]] | None:
    """The first rise's creep after its own rows, the every-row model's miss on those rows
    and how long after the rise's step (s) the first and the last row the creep is read over
    come (see :class:`TRowsApart`), or None. ``log``: the rows the fit used."""
    if fit.rise_T is None or not fit.T > fit.rise_T:
        return None
    r = _after_rise(log, fit)
    if r is None or r.rise_rows.size < 5 or not r.creeps:
        return None
    model = np.full(r.t.size, np.nan)
    model[1:] = np.diff(fit.predicted) / np.diff(r.t)
    gap = r.w[r.rise_rows] - model[r.rise_rows]
    gap = gap[np.isfinite(gap)]
    if gap.size < 5:
        return None
    means = np.convolve(gap, np.ones(5) / 5.0, mode="valid")
    after = (float(r.t[r.later[0]] - r.t[r.k]), float(r.t[r.later[-1]] - r.t[r.k]))
    return (r.first, r.last), float(np.max(np.abs(means))), after


def holds_level(log: RunLog, fit: TimeConstantFit) -> bool:
    """Whether the first rise's speed after its own rows (from :data:`RISE_SPAN` rise_T after
    the wheel answers to the next edge) holds level: the means of their first and last tenth
    differ by at most :data:`CREEP_SHARE` of the rise (at least 20 such rows). ``log``: the
    rows the fit used."""
    r = _after_rise(log, fit)
    return r is not None and r.holds


def _levels(
    log: RunLog, fit: TimeConstantFit, every: TimeConstantFit | None
) -> tuple[float, float] | None:
    """The steady speed (rad/s, the median over the rises) of the fit of the rise's rows
    alone and of the fit of every row (``every`` where the model follows the rise, else
    ``fit``), for :attr:`TRowsApart.levels`, where the speed after the rise holds level
    (:func:`holds_level`) and the two are within :data:`LEVEL_SHARE` of each other; None
    otherwise or where either fit has none."""
    whole = fit if every is None else every
    rise = fit.rise_fit if every is None else fit
    if rise is None or not rise.omega_ss or not whole.omega_ss or not holds_level(log, fit):
        return None
    reach, held = float(np.median(rise.omega_ss)), float(np.median(whole.omega_ss))
    if not abs(reach - held) <= LEVEL_SHARE * abs(held):
        return None
    return reach, held


LEVEL_SHARE: float = 0.05
"""The steady speed the fit of a rise's rows alone reaches for, within this share of the one
every row holds, is a level those few rows hardly pin (:attr:`TRowsApart.levels`): a Pololu
Balboa log flat after its rise, 15.0 against 14.65 rad/s (2.1 %); the ubc and rtl logs in
../shared (10-19 %) reach for levels their wheels never hold, and keep the sentence of a
shape the first-order model misses."""


@dataclass(frozen=True)
class CountsHidden(Observation):
    """T's 95 % interval rests on the scatter the fit leaves on the log's one rise, and the
    angle sits on no grid of encoder counts, nor does the log name one (``# cpr:``): the
    rounding of counts it may have been read from, hidden by an interpolation onto other
    instants, is not in the interval (:attr:`TimeConstantFit.counts_hidden`)."""

    code: ClassVar[str] = "counts_hidden"


@dataclass(frozen=True)
class TOnBound(Observation):
    """T (s) ended on the bound of the range ``lo`` to ``hi`` (s) the fit tries."""

    code: ClassVar[str] = "T_on_bound"
    T: float
    lo: float
    hi: float


@dataclass(frozen=True)
class TNotDetermined(Observation):
    """T's 95 % interval spans more than a factor of ten; ``T`` (s) is only the best fit."""

    code: ClassVar[str] = "T_not_determined"
    T: float


def fit_observations(
    log: RunLog,
    glitches: int,
    fit: TimeConstantFit,
    T_determined: bool,
    every: TimeConstantFit | None = None,
) -> list[Observation]:
    """What the fit of T had to do with this log: switch-on glitch rows and logging stalls left
    out, a dead time in the model, a time shift or a T on its bound, a T the log does not
    determine.

    log: the whole log as read; glitches: its first rows left out as switch-on glitches; fit:
    the fit of T (its rows count from the first row after the glitches); T_determined: whether
    T's interval spans at most a factor of ten; every: the fit of every row, when ``fit``
    follows the rise instead (:func:`~minseg_tui.model.identify.risefit.following_rise`).
    """
    out: list[Observation] = []
    ts = log.ts
    cpr = log.declared_cpr
    count = 2.0 * math.pi / (cpr * ts) if cpr and ts > 0 else None  # rad/s per count per sample
    rise = float(np.median(np.abs(fit.omega_ss))) if fit.omega_ss else 0.0
    if glitches:
        zeroed = zeroed_first_row(log.omega, glitches)
        rows = list(range(1 if zeroed else 0, glitches))
        out.append(
            GlitchRows(
                count=glitches,
                zeroed=zeroed,
                first=_lines(log, [0]),
                rows=_lines(log, rows),
                n_rows=len(rows),
                speeds=tuple(float(log.omega[r]) for r in rows),
                start=_lines(log, [glitches]),
            )
        )
    if fit.edge_glitches:
        # runs of consecutive rows, each after its own step
        runs: list[list[int]] = []
        for r in fit.edge_glitches:
            if runs and r == runs[-1][-1] + 1:
                runs[-1].append(r)
            else:
                runs.append([r])
        w = np.asarray(log.omega, dtype=float)
        u = np.asarray(log.u, dtype=float)
        for run in runs:
            rows = [r + glitches for r in run]
            after = rows[-1] + 1
            changes = np.flatnonzero(u[after:] != u[rows[0]])
            rest = w[after : after + int(changes[0]) if changes.size else w.size]
            up = 1.0 if w[rows[0]] > w[rows[0] - 1] else -1.0
            # the furthest the rise later reaches, a 5-row running median (its noise out)
            top = (
                float(
                    up
                    * np.max(
                        up
                        * np.median(
                            np.stack([rest[j : rest.size - 4 + j] for j in range(5)]), axis=0
                        )
                    )
                )
                if rest.size >= 5
                else rise
            )
            out.append(
                EdgeGlitch(
                    _lines(log, rows),
                    len(rows),
                    tuple(float(w[r]) for r in rows),
                    top,
                    float(w[after]),
                )
            )
    t = log.board_time()
    for r in fit.left_out:
        k = r + glitches
        gap = float(t[k] - t[k - 1])
        out.append(LoggingStall(_lines(log, [k]), gap, ts, fit.angle_mended))
    bound = fit.shift_bound
    creep = None
    if fit.rise_T is not None and fit.rise_ci is not None:
        creep = creep_after_rise(
            log.rows_from(glitches) if glitches else log, fit if every is None else every
        )
    if fit.dead_time > 0:
        out.append(
            DeadTime(
                fit.dead_time,
                bound,
                fit.dead_time_from_rise,
                fit.onset,
                creep=creep is not None,
                first_move=fit.first_move
                if fit.first_move is not None
                and fit.onset is not None
                and fit.first_move < fit.onset - bound
                else None,
            )
        )
    elif fit.shift_on_bound and fit.shift > 0:
        why = (
            LateStart.MOVED_EARLY
            if fit.moved_early is not None
            else LateStart.NO_BETTER
            if fit.dead_time_sought
            else LateStart.COARSE
            if count is not None and count > COARSE_COUNT * rise
            else LateStart.SLOW_START
        )
        first = (
            fit.first_move
            if fit.first_move is not None and fit.onset is not None and fit.first_move < fit.onset
            else None
        )
        free = (
            ShiftFree(fit.onset, fit.free_shift, fit.free_T, fit.free_ci, first)
            if fit.free_T is not None
            and fit.free_ci is not None
            and fit.free_shift is not None
            and fit.onset is not None
            else None
        )
        out.append(ShiftLate(fit.shift, why, fit.moved_early, fit.onset, count, rise, free, first))
    elif fit.shift_on_bound and fit.moved_before_rise:
        out.append(ShiftEarly(fit.shift))
    elif fit.shift_on_bound:
        out.append(
            ShiftMisfit(
                fit.shift,
                fit.onset if fit.onset is not None and fit.onset > 1.5 * bound else None,
                _behind_at_first(log.rows_from(glitches) if glitches else log, fit),
                fit.rise_T is not None,
            )
        )
    if fit.rise_T is not None and fit.rise_ci is not None:
        out.append(
            TRowsApart(
                RISE_SPAN,
                fit.rise_T,
                fit.rise_ci,
                fit.T if every is None else every.T,
                None if creep is None else creep[0],
                None if creep is None else creep[1],
                fit.rise_up_T,
                every is not None and creep is not None,
                float(np.median(fit.omega_ss)) if every is not None and fit.omega_ss else None,
                _levels(log.rows_from(glitches) if glitches else log, fit, every),
                None if creep is None else creep[2],
            )
        )
    if fit.counts_hidden and T_determined:
        out.append(CountsHidden())
    if fit.T_on_bound:
        lo, hi = fit.T_range
        out.append(TOnBound(fit.T, lo, hi))
    if not T_determined:
        out.append(TNotDetermined(fit.T))
    return out
