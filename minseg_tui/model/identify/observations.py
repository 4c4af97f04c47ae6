"""What the numbers of Tasks 6-15 show: observations a student understands, each with a code."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from minseg_tui.model.identify.risefit import RISE_SPAN, Rise, TimeConstantFit
from minseg_tui.model.identify.rises import rise_windows
from minseg_tui.model.identify.steady import Reading, Row, omega_ss_at
from minseg_tui.model.runlog import RunLog, zeroed_first_row
from minseg_tui.quantities import (
    F_UNIT,
    RPM,
    format_constant,
    format_fixed,
    format_interval,
    format_number,
    format_percent,
    format_quantity,
    format_reading,
    format_signed,
    format_value,
)

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
    """Something the numbers show: a short code and a sentence a student understands."""

    code: str
    message: str


def _row_name(index: int, r: Reading) -> str:
    where = f", line {r.line}" if r.line is not None else ""
    return f"row {index + 1} (u_req {r.u_req:g} V{where})"


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
            out.append(
                Observation(
                    "i_ss_units",
                    f"{_row_name(i, r)}: i_ss = {r.i_ss:g} looks like amperes; the table wants mA ({r.i_ss * 1e3:g} mA?).",
                )
            )
        elif r.i_ss > 100.0:
            out.append(
                Observation(
                    "i_ss_high",
                    f"{_row_name(i, r)}: i_ss = {r.i_ss:g} mA is above 100 mA; the manual says the meter is probably measuring the wrong thing or is in the wrong mode.",
                )
            )
        log_agrees = K_log is not None and abs(r.omega_ss / r.u_ss / K_log - 1) <= LOG_AGREES
        if (
            r.omega_ss / r.u_ss > RPM_GAIN
            and r.omega_ss * RPM / r.u_ss <= RPM_GAIN
            and not log_agrees
        ):
            out.append(
                Observation(
                    "omega_ss_units",
                    f"{_row_name(i, r)}: omega_ss = {r.omega_ss:g} is {format_number(r.omega_ss / r.u_ss, 3)} per volt, more than this motor turns; it looks like rpm, the table wants rad/s ({format_reading(r.omega_ss * RPM, 'rad/s')}?).",
                )
            )
        if row.k_v <= 0:
            out.append(
                Observation(
                    "k_v_nonpositive",
                    f"{_row_name(i, r)}: R i_ss = {format_number(R * r.i_ss * 1e-3, 3)} V is not below u_ss = {r.u_ss:g} V, so k_v comes out {format_number(row.k_v, 3)}; check R and i_ss.",
                )
            )
    if len(rows) >= 3:
        for i, row in enumerate(rows):
            dev = (row.k_v - k_v) / k_v if k_v else math.inf
            if abs(dev) > KV_OUTLIER:
                out.append(
                    Observation(
                        "k_v_outlier",
                        (
                            f"{_row_name(i, row.reading)}: k_v = {format_number(row.k_v)} V s/rad is {format_percent(abs(dev))} "
                            f"{'above' if dev > 0 else 'below'} the median {format_number(k_v)}: probably a bad reading "
                            "(u_ss, omega_ss or i_ss of that row); the median keeps it out of the result."
                        ),
                    )
                )
    elif len(rows) == 2:
        a, b = rows[0].k_v, rows[1].k_v
        if abs(a - b) / abs(k_v) > 2 * KV_OUTLIER:
            out.append(
                Observation(
                    "k_v_disagree",
                    (
                        f"The two rows give k_v = {format_number(a)} and {format_number(b)} V s/rad, {format_percent(abs(a - b) / abs(k_v))} apart: "
                        "one is probably a bad reading, and with two rows the median cannot tell which. Measure a third voltage."
                    ),
                )
            )
    above = [row.reading.u_ss > (1.0 + U_SS_ABOVE) * row.reading.u_req for row in rows]
    if rows and all(above) and all(row.reading.u_req > 0 for row in rows):
        out.append(
            Observation(
                "u_ss_above_u_req",
                (
                    f"u_ss is above u_req on {'the one row' if len(rows) == 1 else 'both rows' if len(rows) == 2 else f'all {len(rows)} rows'} "
                    f"the results use ({_above_range(rows)}): a motor driver gives "
                    "the motor at most the voltage it is asked for, less its drop, so the two columns "
                    "look swapped. k_v, k_a and f divide by these readings: check the table."
                ),
            )
        )
    out += _dry_friction(rows, k_a)
    return out


U_SS_ABOVE: float = 0.02
"""u_ss this far (relative) above u_req on every row says the columns are swapped (a driver
gives at most what is requested)."""


def _above_range(rows: Sequence[Row]) -> str:
    """'by 52 % at 2.5 V and 9 % at 3.5 V': how far u_ss is above u_req on each row (walk 7:
    "by 9 %" alone read as true of every row of the table)."""
    each = [
        f"{format_fixed(100.0 * (row.reading.u_ss / row.reading.u_req - 1.0), 0, '%')} at "
        f"{row.reading.u_req:g} V"
        for row in rows
    ]
    return "by " + (each[0] if len(each) == 1 else ", ".join(each[:-1]) + " and " + each[-1])


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
    line = ""
    if slope > 0 and intercept > 0:
        line = (
            f" A straight line k_a i_ss = f omega + tau_c through the rows gives a viscous f = {format_quantity(slope, F_UNIT)} "
            f"and a dry friction torque tau_c = {format_value(intercept * 1e3, 'mN m')}."
        )
    return [
        Observation(
            "dry_friction",
            (
                f"f falls with speed, from {format_quantity(f[0], F_UNIT)} at {format_reading(w[0], 'rad/s')} to {format_quantity(f[-1], F_UNIT)} at {format_reading(w[-1], 'rad/s')}: "
                "part of the friction is dry (Coulomb) friction, a torque that does not grow with speed. "
                "The lab's model has viscous friction only, so its f depends on the speed it was measured at."
                + line
            ),
        )
    ]


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
    that sway is said to be the noise, not a shape one time constant does not follow.
    """
    observations: list[Observation] = []
    levels = sorted({s.u_req for s in steps if s.u_req is not None})
    if "log" in hows:
        observations.append(
            Observation(
                "u_ss_from_log",
                (
                    f"The log has no u_req column, so K divides by the applied voltage the log recorded "
                    f"({format_number(u_ss, 3)} V) instead of u_ss from the table."
                ),
            )
        )
    if "interpolated" in hows or "extrapolated" in hows:
        which = "extrapolated beyond" if "extrapolated" in hows else "interpolated between"
        observations.append(
            Observation(
                f"u_ss_{'extrapolated' if 'extrapolated' in hows else 'interpolated'}",
                (
                    f"No table row has u_req = {', '.join(f'{v:g}' for v in levels)} V, the step's requested level; "
                    f"u_ss = {format_number(u_ss, 3)} V is {which} the table's rows."
                ),
            )
        )
    if len(levels) > 1:
        observations.append(
            Observation(
                "several_levels",
                (
                    f"The rising edges go to several levels ({', '.join(f'{v:g}' for v in levels)} V); K is the median "
                    "of omega_ss / u_ss over the steps and omega_ss the median of their speeds."
                ),
            )
        )
    for s in steps:
        if s.u_req is None:
            continue
        w_table = omega_ss_at(rows, s.u_req)
        if w_table is not None and abs(s.omega_ss - w_table) > RISE_VS_TABLE * w_table:
            observations.append(
                Observation(
                    "step_vs_table",
                    (
                        f"The step at t = {format_number(s.t, 3)} s settles at {format_number(s.omega_ss, 3)} rad/s, but the table gives "
                        f"{format_number(w_table, 3)} rad/s at u_req = {s.u_req:g} V ({format_percent(abs(s.omega_ss / w_table - 1))} apart): "
                        "the two experiments do not agree (a different wheel load, battery level, or a misread value)."
                    ),
                )
            )
            break
    if T < SHORT_T_SAMPLES * ts:
        observations.append(
            Observation(
                "T_short",
                (
                    f"T = {format_constant(T, 's')} is shorter than {SHORT_T_SAMPLES:g} sample periods (Ts = {format_reading(ts, 'ms', 3)}): "
                    "the speed rises within a few samples. The 63 % reading, the manual's way, reads T off those samples, "
                    "so the sampling and the velocity computation move it as much as the motor does; the least-squares T "
                    "fits whole stretches of the run with the sampling modelled, so the two differ. Both are fair "
                    "readings of T; the program's model and its least-squares J use the least-squares one."
                ),
            )
        )
    if T_63 is not None and abs(T_63 - T) > 0.25 * T:
        observations.append(
            Observation(
                "T_63_differs",
                (
                    f"The 63 % reading ({format_constant(T_63, 's')}) and the least-squares T ({format_constant(T, 's')}) differ by "
                    f"{format_percent(abs(T_63 / T - 1))}. "
                    + (
                        f"The reading counts from the logged step, so it holds the dead time of "
                        f"{format_constant(dead_time, 's')} that T does not. Counted from the end of that dead time "
                        f"it is {format_constant(T_63 - dead_time, 's')} where the fitted model read the "
                        f"same way gives {format_constant(T_63 - shape - dead_time, 's')}: the "
                        f"{format_signed(shape * 1e3, 3)} ms between them is the shape of the rise, which "
                        "one time constant does not follow, not the sampling (the speed's scatter "
                        f"moves the reading by only about {noise[1] * 1e3:.3g} ms). Read T with care."
                        if dead_time > 0
                        and shape is not None
                        and noise is not None
                        and abs(shape) > max(0.02 * T, 0.1 * abs(T_63 - T - dead_time), noise[1])
                        else f"The reading counts from the logged step, so it holds the dead time of "
                        f"{format_constant(dead_time, 's')} that T does not; besides, the measured speed is the "
                        "mean over each sample interval and lags the true speed by half a sample."
                        if dead_time > 0
                        else f"Most of it ({format_signed(shape * 1e3, 3)} ms) is the shape of the rise, which one "
                        "time constant does not follow (see the time shift below): no one time "
                        "constant meets both the 63 % point and the whole rise here."
                        if shape is not None
                        and abs(shape) > 0.5 * abs(T_63 - T)
                        and (noise is None or abs(shape) > noise[1])
                        else f"Of it, {format_signed((T_63 - T - shape) * 1e3, 3)} ms is the sampling "
                        "and the steps' time shift, held at its bound (the measured speed is the mean "
                        "over each sample interval, half a sample late), and "
                        f"{format_signed(shape * 1e3, 3)} ms the noise of reading single samples: the "
                        f"speed scatters {format_number(noise[0], 3)} rad/s from sample to sample, which "
                        f"moves where it first crosses 63 % by about {noise[1] * 1e3:.3g} ms; the "
                        "least-squares T uses every sample, so it is the one to trust."
                        if shape is not None and noise is not None and abs(shape) <= noise[1]
                        else "The measured speed is the mean over each sample interval, so "
                        "it lags the true speed by half a sample; a velocity filter lags it more."
                    )
                ),
            )
        )
    short = [s for s in steps if s.duration < 5 * T]
    if short:
        observations.append(
            Observation(
                "not_settled",
                (
                    f"{len(short)} step(s) last less than 5 T ({format_constant(5 * T, 's')}): the speed has not quite settled "
                    "by their end, so omega_ss is the final speed of the fitted response rather than a reading "
                    "of it (a mean over the end of a step would come out low); longer steps would check it."
                ),
            )
        )
    if skipped:
        observations.append(
            Observation(
                "steps_skipped",
                (f"{skipped} rise(s) were too short or too close to the start of the log to use."),
            )
        )
    return observations


FRICTION_APART: float = 0.005
"""The lab's K u_A and the model with dry friction further apart than this (relative) at
5 V: Task 15's answer is given both ways, with why."""


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
    more = "more" if lab > with_friction else "less"
    return [
        Observation(
            "friction_task15",
            (
                f"The fit found dry friction: its steady speed grows by {format_number(K_above_u_c, 4)} "
                f"rad/s per volt above a breakaway voltage u_c = {format_number(u_c, 3)} V, a line "
                "that does not pass through zero. K = omega_ss / u_ss "
                f"({format_number(K, 4)} rad/s per V) is read at the step's {format_number(u_ss, 3)} V and "
                "makes the speed proportional to u_A, as the lab's model (Task 14) has viscous "
                "friction only, no dry friction. "
                f"So at u_A = {u_A:g} V (Task 15) that model gives {format_number(lab, 4)} rad/s, "
                f"{format_percent(abs(lab / with_friction - 1)) if with_friction > 0 else 'far'} {more} "
                f"than the {format_number(with_friction, 4)} rad/s of the model with dry friction."
            ),
        )
    ]


def _lines(log: RunLog, rows: Sequence[int]) -> str:
    """'line 12' / 'lines 5-6' / 'rows 1-2' for 0-based rows of ``log``."""
    lines = [log.line_of(r) for r in rows]
    if all(x is not None for x in lines):
        nums = [int(x) for x in lines if x is not None]
        word, first, last = "line", nums[0], nums[-1]
    else:
        word, first, last = "row", rows[0] + 1, rows[-1] + 1
    return f"{word} {first}" if first == last else f"{word}s {first}-{last}"


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


def fit_observations(
    log: RunLog, glitches: int, fit: TimeConstantFit, T_determined: bool
) -> list[Observation]:
    """What the fit of T had to do with this log: switch-on glitch rows and logging stalls left
    out, a dead time in the model, a time shift or a T on its bound, a T the log does not
    determine.

    log: the whole log as read; glitches: its first rows left out as switch-on glitches; fit:
    the fit of T (its rows count from the first row after the glitches); T_determined: whether
    T's interval spans at most a factor of ten.
    """
    out: list[Observation] = []
    ts = log.ts
    cpr = log.declared_cpr
    count = 2.0 * math.pi / (cpr * ts) if cpr and ts > 0 else None  # rad/s per count per sample
    rise = float(np.median(np.abs(fit.omega_ss))) if fit.omega_ss else 0.0
    if glitches:
        zeroed = zeroed_first_row(log.omega, glitches)
        rows = list(range(1 if zeroed else 0, glitches))
        speeds = ", ".join(format_reading(float(log.omega[r]), "", 3) for r in rows)
        first = (
            f"{_lines(log, [0]).capitalize()} reads 0 rad/s, as the first row of a speed taken "
            "from counts does (no sample before it), and the "
            + (f"{len(rows)} rows after it" if len(rows) > 1 else "row after it")
            + f" ({_lines(log, rows)}) read{'' if len(rows) > 1 else 's'} {speeds} rad/s"
            if zeroed
            else f"The first {glitches} row(s) ({_lines(log, rows)}) read {speeds} rad/s"
        )
        out.append(
            Observation(
                "glitch_rows",
                (
                    f"{first} while the "
                    "command holds still, further from the speed of the rows after them than any later "
                    "row ever is: switch-on glitches of the logging, not motion. They are left out"
                    + (" with the zeroed row before them" if zeroed else "")
                    + f": the fit starts at {_lines(log, [glitches])}."
                ),
            )
        )
    t = log.board_time()
    for r in fit.left_out:
        k = r + glitches
        gap = float(t[k] - t[k - 1])
        out.append(
            Observation(
                "logging_stall",
                (
                    f"{_lines(log, [k]).capitalize()} comes after a gap of {format_fixed(gap * 1e3, 0, 'ms')} in the logging "
                    f"({format_fixed(gap / ts, 1)} sample periods) and departs from the fit by far more than the "
                    "other rows do: its encoder value or its speed does not belong to its timestamp (a "
                    "logging stall), not the motor. It is left out of the fit"
                    + (
                        "; the angle rebuilt from the speed column carried that speed across the gap "
                        "and stayed off after it, so the fit takes that step off the rows after it."
                        if fit.angle_mended
                        else "."
                    )
                ),
            )
        )
    bound = fit.shift_bound
    if fit.dead_time > 0:
        out.append(
            Observation(
                "dead_time",
                (
                    f"The wheel answers {format_fixed(fit.dead_time * 1e3, 0, 'ms')} after the logged steps, more than the "
                    f"one sample period ({format_reading(bound, 'ms', 3)}) that the sampling's lateness can explain: a "
                    "dead time. It is fitted as the model check fits it and is part of the model "
                    f"(Task 14): T omega'(t) = -omega(t) + K u_A(t - {format_number(fit.dead_time, 3)} s). T is counted "
                    "from the moment the wheel answers."
                    + (
                        " The rows of the rise alone show it"
                        + (
                            f" (the speed first shows {format_constant(fit.onset, 's')} after the steps)"
                            if fit.onset is not None
                            else ""
                        )
                        + ": over every row, the slow part long after the rise, which one time "
                        "constant does not follow, would hold a response without it early, "
                        "starting before the wheel moves. The model check (analyze) fits the "
                        "speed of every row, that slow part included, and can give a shorter "
                        "dead time."
                        if fit.dead_time_from_rise
                        else ""
                    )
                ),
            )
        )
    elif fit.shift_on_bound and fit.shift > 0:
        late = (
            "A dead time fits the log better, but it is not one: the wheel already moves before "
            f"it would end ({format_percent(fit.moved_early)} of the way to its new speed), so the rise "
            "starts at once but slowly, a shape the first-order model misses (an S-shaped start: "
            "a second pole or a filtered speed; a ramp: a current limit). Read T with care."
            if fit.moved_early is not None
            else (
                "A dead time does not fit the log clearly better."
                if fit.dead_time_sought
                else (
                    "The wheel first moves "
                    + (f"{format_constant(fit.onset, 's')} " if fit.onset is not None else "")
                    + "after the steps, no later than the rise itself and the sampling explain, "
                    + (
                        f"so there is no dead time to fit. One count per sample is {format_number(count, 3)} "
                        f"rad/s, {format_percent(count / rise)} of the rise, too coarse to show how the "
                        "rise starts: a slow start (a second pole or a filtered speed) and the counts' "
                        "steps look alike here. Read T with care."
                        if count is not None and count > COARSE_COUNT * rise
                        else "so there is no dead time to fit: the rise starts more slowly than one "
                        "time constant gives (an S-shaped start: a second pole or a filtered speed), "
                        "a shape the first-order model misses. Read T with care."
                    )
                )
            )
        )
        out.append(
            Observation(
                "shift_on_bound",
                (
                    f"The time shift of the steps against the samples ended on its bound of one sample "
                    f"period ({format_signed(fit.shift * 1e3, 3)} ms): the wheel answers later than the sampling's "
                    f"lateness explains. {late} T is the fit with the shift held there."
                    + (
                        f" With the shift free up to where the wheel is first seen to move "
                        f"({format_constant(fit.onset, 's')} after the steps), the fit starts the response "
                        f"{format_signed(fit.free_shift * 1e3, 3)} ms from the steps with T = "
                        f"{format_constant(fit.free_T, 's')} (95 % "
                        f"{format_interval(fit.free_ci[0] * 1e3, fit.free_ci[1] * 1e3, 'ms')}): "
                        "a later start goes with a shorter T, and the samples do not pin where a "
                        "first-order response would start (coarse counts, or a start that bends "
                        "in smoothly), so the 95 % interval of T holds both fits."
                        if fit.free_T is not None
                        and fit.free_ci is not None
                        and fit.free_shift is not None
                        and fit.onset is not None
                        else ""
                    )
                ),
            )
        )
    elif fit.shift_on_bound and fit.moved_before_rise:
        out.append(
            Observation(
                "shift_on_bound",
                (
                    f"The time shift of the steps against the samples ended on its bound of one sample "
                    f"period ({format_signed(fit.shift * 1e3, 3)} ms): the wheel moves earlier than the logged steps "
                    "by more than the sampling's lateness explains. The steps in the log are placed late "
                    "(a command logged after it acted); T is the fit with the shift held at the bound."
                ),
            )
        )
    elif fit.shift_on_bound:
        shape = (
            ": the fitted response starts before the wheel does and then rises more slowly "
            "than the wheel"
            + (
                " (the rows long after the rise pull the fit: see T's rows below)"
                if fit.rise_T is not None
                else ""
            )
            + ", a shape the first-order model misses"
            if _behind_at_first(log.rows_from(glitches) if glitches else log, fit)
            else ": the rise is steeper at first and slower later than one "
            "time constant gives (a second, slower process), a shape the first-order model "
            "misses"
        )
        out.append(
            Observation(
                "shift_on_bound",
                (
                    f"The time shift of the steps against the samples ended on its bound of one sample "
                    f"period ({format_signed(fit.shift * 1e3, 3)} ms), earlier than the steps, although the wheel "
                    "does not move before them"
                    + (
                        f" (it first moves {format_constant(fit.onset, 's')} after them)"
                        if fit.onset is not None and fit.onset > 1.5 * bound
                        else ""
                    )
                    + f"{shape}. T is the fit with the shift held at the bound; read it with care."
                ),
            )
        )
    if fit.rise_T is not None and fit.rise_ci is not None:
        longer = fit.T > fit.rise_T
        out.append(
            Observation(
                "T_rows_apart",
                (
                    f"T depends on which rows are fitted: the rows up to {RISE_SPAN:g} T after each "
                    f"edge alone give {format_constant(fit.rise_T, 's')} (95 % "
                    f"{format_interval(fit.rise_ci[0] * 1e3, fit.rise_ci[1] * 1e3, 'ms')}), all the rows the fit uses "
                    f"{format_constant(fit.T, 's')}: the later rows, long after the rise, pull T "
                    f"{'longer' if longer else 'shorter'}: the rise and the speed after it do not "
                    "follow one time constant, a shape the first-order model misses. The 95 % "
                    "interval of T spans both fits. Read T with care."
                ),
            )
        )
    if fit.T_on_bound:
        lo, hi = fit.T_range
        out.append(
            Observation(
                "T_on_bound",
                (
                    f"T = {format_constant(fit.T, 's')} ended on the bound of the range the fit tries "
                    f"({format_reading(lo, 'ms', 3)} to {format_reading(hi, 's', 3)}): this log cannot tell T beyond it, and the "
                    "first-order model does not describe it well."
                ),
            )
        )
    if not T_determined:
        out.append(
            Observation(
                "T_not_determined",
                (
                    f"T's 95 % interval spans more than a factor of ten: T is not determined by this "
                    f"log; {format_constant(fit.T, 's')} is only the best fit. Longer steps, more of them, or a "
                    "faster sampling would tell it."
                ),
            )
        )
    return out
