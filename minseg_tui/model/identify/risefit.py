"""T and the steady speeds of a run log by least squares (Tasks 11-12), with 95 % intervals.

Two fits, both on what a log measures, the wheel angle at the board's timestamps (``t_us``
when present), both with a time shift of the steps against the samples as a nuisance
parameter (:mod:`.wholelog`, :mod:`.windowfit`):

- the model of Task 14 over the whole log, every edge rising and falling, dry friction when
  the log shows it: the most the log can tell about T, when the log follows that model;
- each rise on its own, T shared: robust to what happens between the steps (a wheel
  that coasts at zero command, a speed that wanders).

The whole-log fit is used when it explains the rises about as well as the step-by-step
fit does (its residuals on their rows at most :data:`ADEQUATE` times theirs); otherwise the
step-by-step fit. Either way K comes from the fitted steady speeds, not from means over a
step that may not have settled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import partial
from typing import Any

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.identify.counts import count_quantum
from minseg_tui.model.identify.lsq import FEW_CLUSTERS, dot
from minseg_tui.model.identify.rises import RiseWindow, reading_63, rise_windows
from minseg_tui.model.identify.wholelog import WholeLogFit, fit_whole_log
from minseg_tui.model.identify.windowfit import WindowsFit, fit_windows
from minseg_tui.model.runlog import MEAN_SPEED, AngleFrom, RunLog, command, find_edges

FloatArray = NDArray[np.float64]

SHIFT_SAMPLES: float = 1.0
"""The time shift of the steps against the samples (the sampling's lateness, a nuisance) stays
within this many sample periods either way; a response later than that is a dead time, fitted
and named as such, and one earlier than that is said to be on the bound (a misfit)."""

DEAD_TIME_F: float = 25.0
"""A dead time beyond the shift's bound enters the model when it lowers the residual sum of
squares by this many times its residual variance (as dry friction does)."""

DEAD_TIME_SHARE: float = 0.8
"""The longest dead time tried, as a share of the shortest rise (as the check does)."""

T_MIN_SAMPLES: float = 0.05
"""The shortest T the fit tries, in sample periods (T far below a sample cannot be seen)."""

T_MAX_RISES: float = 10.0
"""The longest T the fit tries, in lengths of the longest rise."""

GAP: float = 1.5
"""A sample interval this many times the median is a gap in the logging (a stall)."""

STALL_SIGMAS: float = 6.0
"""The row after a gap whose angle misses the fit by this many robust standard deviations of
the residual (and by more than the encoder's step) is a logging stall: the encoder value was
read before its timestamp. It is left out of the fit."""

RISE_SPAN: float = 4.0
"""The rows of the rises alone: up to this many time constants after each edge acts (the
speed has then come 98 % of the way). T is fitted to them again to see whether the later rows
pull it (a speed that keeps creeping long after the rise, a tail one time constant does not
follow); the 95 % interval then spans both fits."""

ROWS_APART: float = 3.0
"""T of the rises alone differs from T of every row when they are further apart than this many
times the larger of their standard errors (the two share rows, so chance keeps them closer)."""

ADEQUATE: float = 1.3
"""The whole-log fit is used when the rms of its angle residuals on the rises' rows is
at most this many times the step-by-step fit's residual standard deviation."""

WHOLE_LOG = "whole_log"
RISES = "rising_steps"


@dataclass(frozen=True)
class Rise:
    """One rise of the log.

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
class WholeLogWhy:
    """Why T comes from one first-order model over the whole log: on the rises its residual
    is ``ratio`` times that of the rises fitted one by one (``one``: the log has one rise), so
    every edge is used, ``up`` rising and ``down`` falling; ``u_c``: dry friction's breakaway
    voltage (V) this fit found, None without; ``every_row_T``: set when T follows the rise's
    rows instead (the speed creeps on after the rise), the T (s) of every row."""

    ratio: float
    one: bool
    up: int
    down: int
    u_c: float | None
    every_row_T: float | None = None


@dataclass(frozen=True)
class RisesWhy:
    """Why T comes from the rises alone: ``flat``, the applied voltage u never changes in the
    log (nothing else to model); else the whole-log model leaves ``ratio`` times the residual
    of the rises fitted one by one (None: theirs is 0, it leaves more); ``every_row_T``: set
    when T follows the rows of the rises up to :data:`RISE_SPAN` T after each edge instead (the
    speed creeps on after the rise), the T (s) of the rises' every row."""

    ratio: float | None
    flat: bool
    every_row_T: float | None = None


@dataclass(frozen=True)
class TimeConstantFit:
    """The least-squares T (s) with its 95 % interval (s) and standard error (s), the residual
    standard deviation of the angle (rad), the rows and rises used, where the angle and
    the time came from, and:

    method: ``whole_log`` or ``rising_steps`` (see the module docstring) and ``why``, a
    record of why (:class:`WholeLogWhy`, :class:`RisesWhy`); stamped: the time came from the
    board's timestamps (t_us), not the t column; shift: the fitted time shift of the steps (s; > 0: the motor answers later than
    the log says, < 0: the samples are read late) with its 95 % interval; omega_ss and
    omega_ss_se: the fitted steady speed of each rise and its standard error (rad/s);
    gain: the whole-log fit's K per volt of the log's u (rad/s per V, None for the other);
    u_c: dry friction's breakaway voltage (V, 0 when not found); dof: degrees of freedom of
    the t quantile (clusters of rows less one); predicted: the fitted angle (rad) at every
    row (NaN where the fit does not reach); dead_time: the dead time in the model (s, 0 when
    none: the response is then no later than ``shift_bound``, one sample period); shift_on_bound:
    the shift ended on its bound; T_range: the range of T the fit tried (s) and T_on_bound:
    whether T ended on it; left_out: rows (0-based) left out of the fit (logging stalls);
    moved_early: when a dead time fitted better but the wheel already moved before it would
    end, the share of the rise done by then (None otherwise); onset: the time (s) from the
    rises to where the wheel first answers (the median; None if unseen), read off a 3-row
    running median of the speed; first_move: the same read off each row's own speed (a first
    count that the running median drops comes earlier);
    moved_before_rise: the wheel was already moving at the rows of the rises;
    dead_time_sought: whether the wheel started late enough for a dead time to be fitted;
    rise_T, rise_ci: T (s) and its 95 % interval (s) fitted to the rows up to
    :data:`RISE_SPAN` time constants after each edge alone, when that differs from ``T`` by
    more than :data:`ROWS_APART` standard errors (None otherwise): ``ci`` then spans both;
    rise_up_T: with rise_T, T (s) of the rows up to :data:`RISE_SPAN` time constants after
    the rising edges alone, where the fit of every row also uses falling ones (None otherwise);
    angle_mended: the angle, rebuilt from the speed column, was carried wrong across a stall's
    gap and the fit took the step off every later row (:func:`_stall_offsets`);
    rise_fit: with rise_T, the whole fit of those rows alone (its T, steady speeds, shift and
    fitted angle), for a model that follows the rise (None otherwise); every_row_T: set on a
    fit made from ``rise_fit`` (:func:`following_rise`), the T (s) of every row, the other
    reading (None otherwise); counts_hidden: T's interval rests on the residuals of one
    rise (:func:`~minseg_tui.model.identify.lsq.cluster_covariance`) and the angle sits on
    no grid of counts that the log names or shows, so the rounding of counts it may have been
    read from (then interpolated onto other instants) is not in it; start_free_ci: where the
    dead time is held at the earliest start the rise's rows allow (``dead_time_from_rise``),
    T's 95 % interval (s) with that start fitted too, which ``ci`` then holds (None
    otherwise); edge_glitches: rows (0-based) right after a step whose speed reads beyond
    any the rise later reaches and then falls back (:func:`edge_glitches`): a glitch of the
    reading at switch-on, kept in the fit but not taken for the wheel moving before the step.
    """

    T: float
    ci: tuple[float, float]
    se: float
    sigma: float
    n_rows: int
    n_rises: int
    angle_source: AngleFrom
    stamped: bool
    method: str
    why: WholeLogWhy | RisesWhy
    shift: float
    shift_ci: tuple[float, float]
    omega_ss: tuple[float, ...]
    omega_ss_se: tuple[float, ...]
    gain: float | None
    u_c: float
    dof: int
    predicted: FloatArray
    dead_time: float = 0.0
    shift_bound: float = math.inf
    shift_on_bound: bool = False
    T_range: tuple[float, float] = (0.0, math.inf)
    T_on_bound: bool = False
    left_out: tuple[int, ...] = ()
    moved_early: float | None = None
    onset: float | None = None
    first_move: float | None = None
    moved_before_rise: bool = False
    dead_time_sought: bool = False
    rise_T: float | None = None
    rise_ci: tuple[float, float] | None = None
    rise_up_T: float | None = None
    angle_mended: bool = False
    dead_time_from_rise: bool = False
    free_T: float | None = None
    free_ci: tuple[float, float] | None = None
    free_shift: float | None = None
    rise_fit: TimeConstantFit | None = None
    every_row_T: float | None = None
    counts_hidden: bool = False
    edge_glitches: tuple[int, ...] = ()
    start_free_ci: tuple[float, float] | None = None


def following_rise(fit: TimeConstantFit) -> TimeConstantFit | None:
    """``fit`` with T, its standard error, the steady speeds, the time shift (a dead time
    beyond one sample period, whether it ended on its bound), the gain and the fitted angle of
    the fit of the rise's rows alone (``fit.rise_fit``), and without the fit with the shift
    free (made for every row); its interval still spans both fits, and ``every_row_T`` keeps
    the T (s) of every row. None when there is no fit of the rise alone."""
    r = fit.rise_fit
    if r is None:
        return None
    return replace(
        fit,
        T=r.T,
        se=r.se,
        sigma=r.sigma,
        shift=r.shift,
        shift_ci=r.shift_ci,
        omega_ss=r.omega_ss,
        omega_ss_se=r.omega_ss_se,
        gain=r.gain,
        u_c=r.u_c,
        dof=r.dof,
        predicted=r.predicted,
        dead_time=r.dead_time,
        shift_on_bound=r.shift_on_bound,
        free_T=None,
        free_ci=None,
        free_shift=None,
        rise_fit=None,
        every_row_T=fit.T,
        why=replace(fit.why, every_row_T=fit.T),
    )


def fit_time_constant(log: RunLog) -> TimeConstantFit | None:
    """Least-squares T over the usable rises of ``log`` (None if there are none, or
    if the angle never changes: an encoder not read gives nothing to fit).

    Rows right after a gap in the logging whose angle misses the fit far more than the rest
    (a logging stall: the encoder value lags its timestamp) are left out and the fit is done
    again without them."""
    windows, _ = rise_windows(log)
    if not windows:
        return None
    theta, _ = log.angle()
    if not np.ptp(theta) > 0:  # no residual to compare the fits by: it would divide by zero
        return None
    first = _fit(log, windows, None)
    stalls = _stalls(log, first)
    if not stalls:
        return first
    keep = np.ones(len(log), dtype=bool)
    keep[list(stalls)] = False
    offset = _stall_offsets(log, first, stalls)
    again = _fit(log, windows, keep, first, offset)
    return replace(again, left_out=stalls, angle_mended=offset is not None)


def _stall_offsets(log: RunLog, fit: TimeConstantFit, stalls: tuple[int, ...]) -> FloatArray | None:
    """What to add to the angle (rad) where it is rebuilt from the speed column and a stall's
    row carried it wrong for good: the logged speed held across the gap (a speed read at one
    instant, as timed edges give) is not the mean over the gap, so every later angle is off by
    the same amount. It is the step of the residual across the row (the median of the 3 rows
    after it less that of the 3 before), taken off the row and every row after; None when the
    angle is measured (theta, count) or is the counts (an Euler speed over a fixed period:
    its angle cannot stay off), or no step stays (a one-row spike comes back)."""
    theta, source = log.angle()
    if source != MEAN_SPEED:
        return None
    r = theta - fit.predicted
    step = 2.0 * math.pi / log.cpr
    out = np.zeros(theta.size)
    for k in stalls:
        jump = _step_across(r, k)
        if abs(jump) > 2.0 * step:
            out[k:] -= jump
    return out if np.any(out) else None


def _stalls(log: RunLog, fit: TimeConstantFit) -> tuple[int, ...]:
    """Rows after a gap in the logging whose angle misses the fit by :data:`STALL_SIGMAS`
    robust standard deviations of the angle's residual (the encoder value read before its
    timestamp), or whose logged speed misses the fit's mean speed over the row's interval by
    as many of the speed's (a one-row spike: a speed that divides the counts of the whole gap
    by one nominal period, or a count read early in a fast rise, where the angle's miss is a
    count or two but the speed's is many times its scatter)."""
    t = log.board_time()
    dt = np.diff(t)
    after_gap = np.flatnonzero(dt > GAP * float(np.median(dt))) + 1
    if not after_gap.size:
        return ()
    theta, _ = log.angle()
    r = theta - fit.predicted
    used = np.isfinite(r)
    if np.count_nonzero(used) < 8:
        return ()
    step = 2.0 * math.pi / log.cpr
    limit = max(STALL_SIGMAS * _robust_sd(r[used]), 2.0 * step)
    # the speed: the logged one against the fit's mean over each row's interval
    model_speed = np.full(t.size, np.nan)
    model_speed[1:] = np.diff(fit.predicted) / np.where(dt > 0, dt, np.nan)
    miss = np.asarray(log.omega, dtype=float) - model_speed
    both = np.isfinite(miss)
    both[after_gap] = False  # the scatter of the rows without a gap
    w_limit = (
        max(STALL_SIGMAS * _robust_sd(miss[both]), 2.0 * step / log.ts)
        if np.count_nonzero(both) >= 8 and log.ts > 0
        else math.inf
    )
    long_gap = dt > LONG_GAP * float(np.median(dt))
    return tuple(
        int(k)
        for k in after_gap
        if used[k]
        and (
            abs(r[k]) > limit
            or (
                long_gap[k - 1]
                and (
                    (np.isfinite(miss[k]) and abs(miss[k]) > w_limit)
                    or abs(_step_across(r, int(k))) > limit
                )
            )
        )
    )


LONG_GAP: float = 2.5
"""A row's speed or the step it leaves in the angle marks a logging stall only after an
interval this many times the median (two samples or more missed): a log whose loop times
wander (the EV3's 3.4-9 ms, read over the nominal period in the probe
ev3_100_irregular_nominaldt) has speeds off on its long intervals, without a stall."""


def _step_across(r: FloatArray, k: int) -> float:
    """How far the residual ``r`` (rad) steps across row k and stays: the median of the 3
    rows after it less that of the 3 before (0 where those rows are not all fitted)."""
    before, after = r[max(k - 3, 0) : k], r[k + 1 : k + 4]
    if not (before.size and after.size and np.all(np.isfinite(before))):
        return 0.0
    if not np.all(np.isfinite(after)):
        return 0.0
    return float(np.median(after) - np.median(before))


def _robust_sd(x: FloatArray) -> float:
    """The standard deviation of ``x`` from its median absolute deviation."""
    return 1.4826 * float(np.median(np.abs(x - np.median(x))))


def _fit(
    log: RunLog,
    windows: list[RiseWindow],
    keep: NDArray[np.bool_] | None,
    prior: TimeConstantFit | None = None,
    offset: FloatArray | None = None,
) -> TimeConstantFit:
    """The fit of :func:`fit_time_constant` on the rows ``keep`` (default: all); ``prior``: a
    fit of the same log on more rows, whose T and shift the search starts from (and whose
    finding of a dead time or none it keeps, without searching again); ``offset``: added to
    the angle (rad) first (:func:`_stall_offsets`)."""
    t = log.board_time()
    theta, angle_source = log.angle()
    if offset is not None:
        theta = theta + offset
    u = np.asarray(log.u, dtype=float)
    ts = log.ts
    bound = SHIFT_SAMPLES * ts
    longest = max(float(t[w.post_last] - t[w.edge.start]) for w in windows)
    shortest = min(float(t[w.post_last] - t[w.edge.start]) for w in windows)
    T_range = (T_MIN_SAMPLES * ts, T_MAX_RISES * max(longest, ts))
    d_max = DEAD_TIME_SHARE * shortest
    onset = _onset(log, windows)
    first_move = _onset(log, windows, smoothed=False)
    rise_63 = _onset(log, windows, 1.0 - math.exp(-1.0))
    delays: tuple[float, ...] = ()
    quantum = count_quantum(theta, log.cpr)
    # an angle read in counts and then interpolated onto other instants sits on no grid, yet
    # holds their rounding: a `# cpr:` header names the counts, and the interval holds it
    hidden = quantum is None and log.declared_cpr is None
    if quantum is None and log.declared_cpr is not None:
        quantum = 2.0 * math.pi / log.declared_cpr
    windows_fit = partial(fit_windows, quantum=quantum)

    def late_start(T: float) -> bool:
        """Whether the wheel starts later than a first-order rise of T (s) would show, by
        more than 1.5 sample periods: then a dead time is looked for, whatever the shift of
        the fit without one (a rise steep at first can pull that shift early)."""
        nonlocal delays
        if onset is None or d_max <= 1.5 * bound:
            return False
        late = onset - STILL_SHARE * T - 0.5 * ts  # the rise's own time to show, the Euler lag
        if late <= 1.5 * bound:
            return False
        delays = tuple(
            sorted({min(max(onset - f * ts, bound), d_max) for f in (0.0, 0.5, 1.0, 1.5)})
        )
        sought.append(True)
        return True

    sought: list[bool] = []  # whether a dead time was looked for

    moved: list[float] = []  # how far a rejected dead time's rise had come by its end
    if prior is not None:
        if prior.moved_early is not None:
            moved.append(prior.moved_early)
    reach = (-bound, d_max) if prior is not None and prior.dead_time > 0 else (-bound, bound)
    if prior is not None and prior.dead_time_from_rise:
        reach = (prior.dead_time, d_max)
    near = (0.8, 1.0, 1.25)

    def dead(d: float, rss: float, rss_late: float, n: int, p: int) -> bool:
        """A dead time d (s): later than the bound, clearly better, and the wheel stands
        until it ends."""
        if not (d > bound and _significant(rss, rss_late, n, p)):
            return False
        share = _moved_before(log, windows, d - bound)
        if share > STILL_SHARE:
            moved.append(share)
            return False
        return True

    if prior is None:
        rises_fit = windows_fit(t, theta, windows, ts, reach, T_range, keep)
    else:
        T_near = tuple(f * prior.T for f in near)
        rises_fit = windows_fit(t, theta, windows, ts, reach, T_range, keep, (prior.shift,), T_near)
    # the rise's own time from its onset to 63 %: where the search for T with a dead time also
    # starts (the T found without one may have run to its bound chasing a late response, and
    # the factors of it then miss the rise: micromouse-n20-duty255 cut at 1.5 s went to T =
    # 0.25 ms from starts of 0.7-10 s)
    T_read = (
        (rise_63 - onset,) if rise_63 is not None and onset is not None and rise_63 > onset else ()
    )
    rises_reach = reach
    if prior is None and late_start(rises_fit.T):
        T_starts = (*(f * rises_fit.T for f in WIDE_T_FACTORS), *T_read)
        late = windows_fit(
            t, theta, windows, ts, (-bound, d_max), T_range, keep, (0.0, *delays), T_starts
        )
        if dead(late.d, rises_fit.rss, late.rss, late.rows.size, late.n_params):
            rises_fit = late
            rises_reach = (-bound, d_max)
    cmd, _ = command(log)
    clusters = np.unique(np.array([0, *(e.start for e in find_edges(cmd))], dtype=np.int64))
    stamped = "t_us" in log.extra
    # with the board's timestamps the steps act at the sample instants (this project's
    # firmware) or on the board's sample grid (firmware that sets the output on a timer);
    # without them, where a step falls between the logged instants is not known
    timings = [t, board_grid(t)] if stamped else [t]
    weights = None if keep is None else keep.astype(float)

    def whole_fit(
        shift: tuple[float, float], T0: float, rows: FloatArray | None = weights, **kw: Any
    ) -> WholeLogFit | None:
        kw["quantum"] = quantum
        return fit_whole_log(
            t, u, theta, T0, clusters, timings, not stamped, shift, T_range, rows, **kw
        )

    T0 = min(max(rises_fit.T, T_range[0]), T_range[1])
    if prior is None:
        whole = whole_fit(reach, T0)
    else:
        whole = whole_fit(reach, prior.T, shift_starts=(prior.shift,), T_factors=near)
    whole_reach = reach
    if prior is None and whole is not None and late_start(whole.T):
        late_w = whole_fit(
            (-bound, d_max),
            whole.T,
            shift_starts=(0.0, *delays),
            T_factors=(*WIDE_T_FACTORS, *(T / whole.T for T in T_read)),
        )
        if late_w is not None and dead(
            late_w.d, whole.rss, late_w.rss, late_w.n_used, late_w.n_params
        ):
            whole = late_w
            whole_reach = (-bound, d_max)
    late_rise = False  # a dead time the rises' own rows show and the rows after them hide

    def fixed_d(d: float, T0: float) -> float:
        """The residual sum of squares of the fit of the rises' own rows with the dead time
        held at d (s), T free from T0 (s)."""
        f = windows_fit(
            t, theta, windows, ts, (d, d + 1e-9), T_range, mask_r, (d,), (T0, 0.8 * T0, 1.25 * T0)
        )
        return f.rss

    if prior is None and sought and rises_fit.d <= bound and (whole is None or whole.d <= bound):
        # the wheel starts late, yet no dead time fitted every row: the rows long after the
        # rises (a slow creep that one time constant does not follow) outweigh the rises and
        # hold the response early, before the wheel moves. The rises' own rows judge it
        # (micromouse-n20-duty100: the wheel stands 30 ms after the logged step)
        starts_r = np.array([w.edge.start for w in windows], dtype=np.int64)
        # the rows up to RISE_SPAN T after the wheel first answers (a dead time tried up to
        # there keeps rows after it in every window)
        mask_r = _rise_rows(t, starts_r, rises_fit.T, max(rises_fit.d, onset or 0.0), keep)
        if mask_r is not None:
            plain = windows_fit(
                t,
                theta,
                windows,
                ts,
                reach,
                T_range,
                mask_r,
                (rises_fit.d,),
                tuple(f * rises_fit.T for f in (0.5, 0.7, *near)),
            )
            try:
                late_r: WindowsFit | None = windows_fit(
                    t,
                    theta,
                    windows,
                    ts,
                    (-bound, d_max),
                    T_range,
                    mask_r,
                    (0.0, *delays),
                    (*(f * plain.T for f in WIDE_T_FACTORS), *T_read),
                )
            except np.linalg.LinAlgError:  # a dead time that leaves a window no row after it
                late_r = None
            if late_r is not None and dead(
                late_r.d, plain.rss, late_r.rss, late_r.rows.size, late_r.n_params
            ):
                # the response cannot start before the rises show it: the earliest dead time
                # their rows allow (on coarse counts a start between samples trades against T)
                held = (_earliest_start(late_r, bound, fixed_d), d_max)
                rises_fit = windows_fit(
                    t,
                    theta,
                    windows,
                    ts,
                    held,
                    T_range,
                    keep,
                    (late_r.d,),
                    tuple(f * late_r.T for f in (1.0, 1.25, 1.5, 2.0)),
                    start_held=True,
                )
                if whole is not None:
                    whole = whole_fit(
                        held, rises_fit.T, shift_starts=(late_r.d,), T_factors=near, start_held=True
                    )
                rises_reach = whole_reach = (-bound, d_max)
                late_rise = True
    # the latest the response can start: where the wheel is seen to move
    late_end_at = min(d_max, onset) if onset is not None else bound

    def late_end(d: float, d_on_bound: bool, T_on_bound: bool) -> bool:
        """Whether the shift ended on its upper bound, no dead time taken, while the wheel is
        first seen to move later: the log then holds a start anywhere up to there, and T's
        interval with the shift held at the bound leaves that out. Not when a dead time was
        refused because the wheel already moved before it would end (an S-shaped start: the
        samples show the start, the shape is what the model misses)."""
        return (
            d_on_bound and 0.0 < d <= bound and not T_on_bound and late_end_at > bound and not moved
        )

    n_w = rises_fit.rows.size
    sigma_w = math.sqrt(rises_fit.rss / max(n_w - rises_fit.n_params, 1))
    glitched = edge_glitches(log, windows)
    common: dict[str, Any] = dict(
        shift_bound=bound,
        T_range=T_range,
        moved_early=max(moved) if moved else None,
        onset=onset,
        first_move=first_move,
        dead_time_sought=bool(sought) or (prior is not None and prior.dead_time_sought),
        moved_before_rise=_moved_before(log, windows, 0.0, at_edge=True, skip=glitched)
        > STILL_SHARE,
        edge_glitches=glitched,
        counts_hidden=hidden and clusters.size < FEW_CLUSTERS,
    )
    if whole is not None:
        on_rises = whole.residuals[rises_fit.rows]
        rms = math.sqrt(dot(on_rises, on_rises) / max(n_w, 1))
        if rms <= ADEQUATE * sigma_w and sigma_w > 0:  # (0: the steps fit exactly, no scale)
            fit = _from_whole(log, whole, windows, theta, angle_source, stamped, rms, sigma_w)
            rise: tuple[float, float, float] | None = None  # (T, se, half width) of the rises
            alone_fit: TimeConstantFit | None = None

            def fit_rows(starts: NDArray[np.int64]) -> WholeLogFit | None:
                """The fit of the rows up to a few T after the edges at ``starts`` alone."""
                mask = _rise_rows(t, starts, whole.T, whole.d, keep)
                if mask is None:
                    return None
                return whole_fit(
                    whole_reach,
                    whole.T,
                    mask.astype(float),
                    shift_starts=(whole.d,),
                    T_factors=(0.5, 0.7, *near),
                )

            if not whole.T_on_bound:
                alone = fit_rows(clusters[1:])
                if alone is not None and not alone.T_on_bound:
                    c = alone.covariance
                    rise = (alone.T, math.sqrt(max(float(c.cov[1, 1]), 0.0)), c.half_width(1))
                    alone_fit = replace(
                        _from_whole(
                            log, alone, windows, theta, angle_source, stamped, rms, sigma_w
                        ),
                        dead_time=alone.d if alone.d > bound else 0.0,
                        shift_on_bound=alone.d_on_bound and not late_rise,
                    )
            apart = _rows_apart(fit, rise)
            if apart.rise_T is not None:
                apart = replace(apart, rise_fit=alone_fit)
            elif whole.start_free is not None:
                apart = _start_free(apart, whole.start_free.half_width(1))
            up_T = None  # the rows after the rising edges alone, when falling ones are fitted
            ups = np.array([e.start for e in find_edges(cmd) if e.rising], dtype=np.int64)
            if apart.rise_T is not None and 0 < ups.size < clusters.size - 1:
                up = fit_rows(ups)
                if up is not None and not up.T_on_bound:
                    up_T = up.T
            free_w: tuple[float, float, float, float] | None = None
            if late_end(whole.d, whole.d_on_bound, whole.T_on_bound):
                held_w = whole_fit(
                    (-bound, late_end_at), whole.T, shift_starts=(whole.d,), T_factors=near
                )
                if held_w is not None and not held_w.T_on_bound:
                    c = held_w.covariance
                    free_w = (held_w.T, held_w.d, c.half_width(1), 0.0)
            return replace(
                _shift_free(apart, free_w),
                rise_up_T=up_T,
                dead_time=whole.d if whole.d > bound else 0.0,
                shift_on_bound=whole.d_on_bound and not late_rise,
                dead_time_from_rise=late_rise,
                T_on_bound=whole.T_on_bound,
                **common,
            )
        why = RisesWhy(rms / sigma_w if sigma_w > 0 else None, flat=False)
    else:
        why = RisesWhy(None, flat=True)
    fit = _from_rises(log, rises_fit, windows, theta, angle_source, stamped, sigma_w, why)
    rise = None
    alone_rises: TimeConstantFit | None = None
    if not rises_fit.T_on_bound:
        starts = np.array([w.edge.start for w in windows], dtype=np.int64)
        mask = _rise_rows(t, starts, rises_fit.T, rises_fit.d, keep)
        if mask is not None:
            alone_w = windows_fit(
                t,
                theta,
                windows,
                ts,
                rises_reach,
                T_range,
                mask,
                (rises_fit.d,),
                tuple(f * rises_fit.T for f in (0.5, 0.7, *near)),
            )
            if not alone_w.T_on_bound:
                c = alone_w.covariance
                rise = (alone_w.T, math.sqrt(max(float(c.cov[0, 0]), 0.0)), c.half_width(0))
                alone_rises = replace(
                    _from_rises(log, alone_w, windows, theta, angle_source, stamped, sigma_w, why),
                    dead_time=alone_w.d if alone_w.d > bound else 0.0,
                    shift_on_bound=alone_w.d_on_bound and not late_rise,
                )
    free: tuple[float, float, float, float] | None = None
    if late_end(rises_fit.d, rises_fit.d_on_bound, rises_fit.T_on_bound):
        free_f = windows_fit(
            t,
            theta,
            windows,
            ts,
            (-bound, late_end_at),
            T_range,
            keep,
            (rises_fit.d,),
            tuple(f * rises_fit.T for f in near),
        )
        if not free_f.T_on_bound:
            free = (free_f.T, free_f.d, free_f.covariance.half_width(0), 0.0)
    apart_r = _rows_apart(fit, rise)
    if apart_r.rise_T is not None:
        apart_r = replace(apart_r, rise_fit=alone_rises)
    elif rises_fit.start_free is not None:
        apart_r = _start_free(apart_r, rises_fit.start_free.half_width(0))
    return replace(
        _shift_free(apart_r, free),
        dead_time=rises_fit.d if rises_fit.d > bound else 0.0,
        shift_on_bound=rises_fit.d_on_bound and not late_rise,
        dead_time_from_rise=late_rise,
        T_on_bound=rises_fit.T_on_bound,
        **common,
    )


def _rise_rows(
    t: FloatArray,
    edges: NDArray[np.int64],
    T: float,
    d: float,
    keep: NDArray[np.bool_] | None,
) -> NDArray[np.bool_] | None:
    """The rows of the responses alone: the rows before the first edge (first rows
    ``edges``) and those up to :data:`RISE_SPAN` T (s) after each edge acts, d (s) after its
    row's time. Rows outside ``keep`` stay out. None when that leaves out no row more than
    ``keep`` does, or too few rows are left to fit. (Leaving out the rows after the falling
    edges too makes the fit of a short log's single rise fragile: 5 of 30 clean one-rise logs
    of tests/model/identgen.py came out 2-8 % apart with standard errors under 1 %.)"""
    mask = np.ones(t.size, dtype=bool) if keep is None else keep.copy()
    if not edges.size:
        return None
    last = np.searchsorted(edges, np.arange(t.size), side="right") - 1
    after = last >= 0
    since = t[after] - t[edges[last[after]]] - max(d, 0.0)
    late = np.zeros(t.size, dtype=bool)
    late[after] = since > RISE_SPAN * T
    if not np.any(mask & late) or np.count_nonzero(mask & ~late) < 8 * edges.size:
        return None
    out: NDArray[np.bool_] = mask & ~late
    return out


def _rows_apart(fit: TimeConstantFit, rise: tuple[float, float, float] | None) -> TimeConstantFit:
    """``fit`` with its interval widened to hold the rises' own T when that T (``rise``: T,
    its standard error and half its 95 % interval, s) is further from the fit's than
    :data:`ROWS_APART` times the larger standard error."""
    if rise is None:
        return fit
    T_r, se_r, half_r = rise
    if not abs(T_r - fit.T) > ROWS_APART * max(fit.se, se_r):
        return fit
    ci, own = _holding(fit.ci, T_r, half_r)
    return replace(fit, ci=ci, rise_T=T_r, rise_ci=own)


def _holding(
    ci: tuple[float, float], T: float, half: float
) -> tuple[tuple[float, float], tuple[float, float]]:
    """The interval ``ci`` (s) widened to hold the interval ``T`` +- ``half`` (s, not below
    0), and that interval itself."""
    lo, hi = max(T - half, 0.0), T + half
    return (min(ci[0], lo), max(ci[1], hi)), (lo, hi)


PROFILE_CHI2: float = 3.84
"""How far the residual sum of squares of the rises may grow, in residual variances, at the
earliest dead time still held to fit them (the 95 % point of chi-squared with one degree of
freedom)."""


def _earliest_start(late: WindowsFit, bound: float, rss_at: Any) -> float:
    """The earliest dead time (s) the rises' rows allow: stepping from the fitted one ``late.d``
    towards the shift's bound, the last whose residual sum of squares (``rss_at(d, T0)``, T
    fitted again from T0) stays within :data:`PROFILE_CHI2` residual variances of the best."""
    n, p = late.rows.size, late.n_params
    limit = late.rss * (1.0 + PROFILE_CHI2 / max(n - p, 1))
    earliest = late.d
    for d in np.linspace(late.d, bound, 7)[1:]:
        try:
            if rss_at(float(d), late.T) > limit:
                break
        except np.linalg.LinAlgError:
            break
        earliest = float(d)
    return earliest


def _start_free(fit: TimeConstantFit, half: float) -> TimeConstantFit:
    """``fit``, its dead time held at the earliest start the rise's rows allow
    (:func:`_earliest_start`), with T's interval widened to hold T +- ``half`` (s), half the
    95 % interval with that start fitted too: the start is a choice the fit is held to, not
    a measurement, and on coarse counts a start between samples trades against T (the
    interval with the start held left that out: tests/model/identgen.py seed 2 at 5 ms, T
    38.8 ms, got 36.9 ms with 36.4-37.5 ms). Not where the rise's own T is reported beside
    every row's: the rise's fit has its start free already."""
    ci, own = _holding(fit.ci, fit.T, half)
    return replace(fit, ci=ci, start_free_ci=own)


def _shift_free(
    fit: TimeConstantFit, free: tuple[float, float, float, float] | None
) -> TimeConstantFit:
    """``fit`` (its shift held on its upper bound) with T's interval widened to hold the fit
    with the shift free up to where the wheel is first seen to move (``free``: its T, shift
    and half its 95 % interval of T, s): the start of a rise that the counts do not show
    trades against T (a later start, a shorter T), and the bound alone is no measurement."""
    if free is None:
        return fit
    T_f, d_f, half_f, _ = free
    ci, own = _holding(fit.ci, T_f, half_f)
    return replace(fit, ci=ci, free_T=T_f, free_ci=own, free_shift=d_f)


WIDE_T_FACTORS: tuple[float, ...] = (0.1, 0.2, 0.35, 0.5, 0.7, 1.0, 1.4)
"""Where the search for T starts when it looks for a dead time, in multiples of the T found
without one (a T that had to stretch to reach a late response is too long)."""


STILL_SHARE: float = 0.02
"""A dead time is one only while the wheel stands: by one sample period before it ends, the
speed (a 3-row running median) has not come this share of the way from its level before a
rise to the level after it (the median over the steps; plus three times the speed's
scatter before the step over the change). A response that starts at once but slowly (an
S-shaped rise, a ramp) also fits better late; it is not a dead time. (A second pole of T/3
has come 3 % of the way one sample of T/12 before the delay a fit gives it.)"""


def _smooth(w: FloatArray) -> FloatArray:
    """A 3-row running median of ``w`` (one-row spikes out; the ends kept)."""
    out = w.copy()
    if w.size >= 3:
        out[1:-1] = np.median(np.stack((w[:-2], w[1:-1], w[2:])), axis=0)
    return out


def _levels(w: FloatArray, win: RiseWindow) -> tuple[float, float]:
    """The speed (rad/s) before a rise and at the end of it (medians)."""
    k = win.edge.start
    tail = win.post_last - max((win.post_last - k) // 4, 1)
    return float(np.median(w[win.pre_from : k + 1])), float(np.median(w[tail : win.post_last + 1]))


def _onset(
    log: RunLog, windows: list[RiseWindow], share_of: float = STILL_SHARE, smoothed: bool = True
) -> float | None:
    """Where the wheel first answers the rises: the median over the steps of the time
    (s) from the step to the first row whose speed (a 3-row running median; each row's own
    speed when not ``smoothed``) has come ``share_of`` of the way to its new level (default
    :data:`STILL_SHARE`); None when no step shows it."""
    w = np.asarray(log.omega, dtype=float)
    smooth = _smooth(w) if smoothed else w
    t = log.board_time()
    found = []
    for win in windows:
        k = win.edge.start
        w0, w1 = _levels(w, win)
        if w1 <= w0:
            continue
        share = (smooth[k + 1 : win.post_last + 1] - w0) / (w1 - w0)
        hit = np.flatnonzero(share > share_of)
        if hit.size:
            found.append(float(t[k + 1 + int(hit[0])] - t[k]))
    return float(np.median(found)) if found else None


EDGE_GLITCH_ROWS: int = 3
"""At most this many rows from a step's own row on can be a glitch of the reading at
switch-on (:func:`edge_glitches`), as at the start of a log (runlog.MAX_GLITCH_ROWS)."""


def edge_glitches(log: RunLog, windows: list[RiseWindow]) -> tuple[int, ...]:
    """The rows (0-based), from each step's own row on, whose speed reads beyond any speed
    the rise later reaches and after which the speed falls back below the level it settles
    to: a motor answering a step cannot overshoot and fall back within a sample or two, so
    these rows are the reading's (counts picked up at switch-on), not the wheel's.

    A row counts when its speed lies beyond the rise's final level (the median of the last
    quarter of its rows) in the step's direction by more than any later row (a 5-row running
    median, from :data:`EDGE_GLITCH_ROWS` rows after the step) ever does, and by more than
    three times the scatter of that final level; only an unbroken run from the step's own row
    or the next counts, at most :data:`EDGE_GLITCH_ROWS` rows, and the row after the run must
    read below the final level."""
    w = np.asarray(log.omega, dtype=float)
    out: list[int] = []
    for win in windows:
        k = win.edge.start
        w0, w1 = _levels(w, win)
        if w1 == w0:
            continue
        up = 1.0 if w1 > w0 else -1.0
        rest = w[k + EDGE_GLITCH_ROWS : win.post_last + 1]
        tail = win.post_last - max((win.post_last - k) // 4, 1)
        if rest.size < 10 or tail - k < 2 * EDGE_GLITCH_ROWS:
            continue
        smooth = np.median(np.stack([rest[j : rest.size - 4 + j] for j in range(5)]), axis=0)
        later = max(float(np.max(up * (smooth - w1))), 0.0)
        scatter = float(np.std(w[tail : win.post_last + 1]))
        beyond = up * (w[k : k + EDGE_GLITCH_ROWS + 2] - w1) > max(later, 3.0 * scatter, 1e-9)
        first = 0 if beyond[0] else 1
        n = first
        while n < EDGE_GLITCH_ROWS + first and beyond[n]:
            n += 1
        if n > first and up * (w[k + n] - w1) < 0:
            out.extend(range(k + first, k + n))
    return tuple(out)


def _moved_before(
    log: RunLog,
    windows: list[RiseWindow],
    until: float,
    at_edge: bool = False,
    skip: tuple[int, ...] = (),
) -> float:
    """The median over the rises of the largest share of the speed's change reached
    on the rows up to ``until`` (s) after each step (``at_edge``: on the step's own row and
    the one before, whose speeds were measured before the step acts); ``skip``: rows that are
    glitches of the reading (:func:`edge_glitches`), whose speed says nothing of the wheel."""
    w = np.asarray(log.omega, dtype=float)
    if skip:
        # a glitch row stands in for the speed of the row before it
        w = w.copy()
        for r in sorted(skip):
            w[r] = w[r - 1]
    smooth = _smooth(w)
    t = log.board_time()
    shares = []
    for win in windows:
        k = win.edge.start
        rows = np.arange(k + 1, win.post_last + 1)
        before = np.arange(max(k - 1, 1), k + 1) if at_edge else rows[t[rows] <= t[k] + until]
        w0, w1 = _levels(w, win)
        if not before.size or w1 == w0:
            continue
        scatter = 3.0 * float(np.std(w[win.pre_from : k + 1])) / abs(w1 - w0)
        shares.append(float(np.max((smooth[before] - w0) / (w1 - w0))) - scatter)
    return float(np.median(shares)) if shares else 0.0


def _significant(rss: float, rss_late: float, n: int, p: int) -> bool:
    """True when the dead time lowers the residual sum of squares from ``rss`` to ``rss_late``
    by more than :data:`DEAD_TIME_F` residual variances (n rows, p parameters)."""
    if not (math.isfinite(rss_late) and rss_late > 0):
        return rss_late < rss
    return (rss - rss_late) > DEAD_TIME_F * rss_late / max(n - p, 1)


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
    log: RunLog,
    fit: WholeLogFit,
    windows: list[RiseWindow],
    theta: FloatArray,
    angle_source: AngleFrom,
    stamped: bool,
    rms: float,
    sigma_w: float,
) -> TimeConstantFit:
    cov = fit.covariance
    se = math.sqrt(max(float(cov.cov[1, 1]), 0.0))
    u = np.asarray(log.u, dtype=float)
    highs = [float(np.mean(u[w.edge.end : w.post_last])) for w in windows]
    edges = np.flatnonzero(np.diff(u) != 0) + 1
    up = int(sum(abs(u[k]) > abs(u[k - 1]) for k in edges))
    return TimeConstantFit(
        T=fit.T,
        ci=(max(fit.T - cov.half_width(1), 0.0), fit.T + cov.half_width(1)),
        se=se,
        sigma=math.sqrt(fit.rss / max(theta.size - fit.n_params, 1)),
        n_rows=int(theta.size),
        n_rises=len(windows),
        angle_source=angle_source,
        stamped=stamped,
        method=WHOLE_LOG,
        why=WholeLogWhy(
            ratio=rms / sigma_w,
            one=len(windows) == 1,
            up=up,
            down=int(edges.size) - up,
            u_c=fit.u_c if fit.friction else None,
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


def _from_rises(
    log: RunLog,
    fit: WindowsFit,
    windows: list[RiseWindow],
    theta: FloatArray,
    angle_source: AngleFrom,
    stamped: bool,
    sigma_w: float,
    why: WholeLogWhy | RisesWhy,
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
        n_rises=len(windows),
        angle_source=angle_source,
        stamped=stamped,
        method=RISES,
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


def rises(log: RunLog, fit: TimeConstantFit | None = None) -> list[Rise]:
    """Each usable rise with its levels and the manual's 63 % reading (Tasks 11-12).

    The steady speed of each step is the fitted one (``fit``, computed when not given); the
    63 % reading is taken on the log's omega from the mean speed before the step to it.
    """
    windows, _ = rise_windows(log)
    if not windows:
        return []
    fit = fit if fit is not None else fit_time_constant(log)
    if fit is None:  # the angle never changes
        return []
    _, name = command(log)
    omega = np.asarray(log.omega, dtype=float)
    t = np.asarray(log.t, dtype=float)
    skip = np.zeros(t.size, dtype=bool)
    skip[list(fit.left_out)] = True
    out = []
    for w, w_ss in zip(windows, fit.omega_ss, strict=True):
        e = w.edge
        w0 = _speed_before(omega, w)
        out.append(
            Rise(
                row=e.start,
                line=log.line_of(e.start),
                t=float(t[e.start]),
                u_req=float(e.after) if name == "u_req" else None,
                u_high=float(np.mean(log.u[e.end : w.post_last])),
                omega0=w0,
                omega_ss=float(w_ss),
                duration=float(t[w.post_last] - t[e.start]),
                T_63=reading_63(t, omega, e.start, w.post_last, w0, float(w_ss), skip),
            )
        )
    return out


def _speed_before(omega: FloatArray, w: RiseWindow) -> float:
    """Mean speed (rad/s) over the rows before the step (row 0 has no previous sample)."""
    pre = np.arange(w.pre_from, w.edge.start + 1)
    pre = pre[pre >= 1] if pre.size > 1 else pre
    return float(np.mean(omega[pre]))


def model_reading_63(log: RunLog, fit: TimeConstantFit, steps: list[Rise]) -> float | None:
    """The manual's 63 % reading (s, median over the steps) taken on the fitted model instead
    of the measurements: the speed of the model's angle over each sample interval, read with
    the same levels at the log's own sample times. What the sampling alone makes of T."""
    windows, _ = rise_windows(log)
    t = log.board_time()
    th = fit.predicted
    speed = np.zeros(th.size)
    speed[1:] = np.diff(th) / np.diff(t)
    skip = np.zeros(t.size, dtype=bool)
    skip[list(fit.left_out)] = True
    reads = []
    for w, s in zip(windows, steps, strict=True):
        lo, hi = w.edge.start, w.post_last
        if not np.all(np.isfinite(speed[lo + 1 : hi + 1])):
            continue
        r = reading_63(t, speed, lo, hi, s.omega0, s.omega_ss, skip)
        if r is not None:
            reads.append(r)
    return float(np.median(reads)) if reads else None


__all__ = [
    "ADEQUATE",
    "board_grid",
    "RISES",
    "WHOLE_LOG",
    "Rise",
    "TimeConstantFit",
    "fit_time_constant",
    "model_reading_63",
    "rises",
]
