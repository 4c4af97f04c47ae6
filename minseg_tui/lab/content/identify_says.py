"""identify's words: the sentences of what the numbers of Tasks 6-15 show, made from the
model's records (:mod:`minseg_tui.model.identify.observations`), and its refusals of a table,
R or a log (:mod:`minseg_tui.model.identify.refusals`), for the screens, the report, the
session's notices, the table's reader and ``minseg-tui identify`` alike (issue 19 item 4: the
model gives records, the words are written once, here).

It sits in lab/content/, the lowest of lab/'s folders, because the session's notices
(lab/state) quote it as the views, the report and the CLI do.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from functools import singledispatch
from types import MappingProxyType
from typing import Final

from minseg_tui.errors import InputError
from minseg_tui.model.identify.identification import (
    Identification,
    ResponseResult,
    RestWhy,
    T63Note,
)
from minseg_tui.model.identify.observations import (
    CountsHidden,
    CurrentHigh,
    CurrentInAmperes,
    DeadTime,
    DryFriction,
    EdgeGlitch,
    FrictionTask15,
    GlitchRows,
    KvDisagree,
    KvNotPositive,
    KvOutlier,
    LateStart,
    Lines,
    LoggingStall,
    NotSettled,
    Observation,
    RowAt,
    SeveralLevels,
    ShiftEarly,
    ShiftLate,
    ShiftMisfit,
    SpeedInRpm,
    SpeedLags,
    StepsSkipped,
    StepVsTable,
    T63Differs,
    T63Why,
    TNotDetermined,
    TOnBound,
    TRowsApart,
    TShort,
    USsAboveUReq,
    USsExtrapolated,
    USsFromLog,
    USsInterpolated,
)
from minseg_tui.model.identify.refusals import (
    IdentifyRefusal,
    IdentifyRefused,
    Measured,
    MedianKvNotPositive,
    NoRisingEdge,
    NoRows,
    RiseNotFitted,
    RNotPositive,
    RowImplausible,
    RowNotANumber,
    RowNotPositive,
)
from minseg_tui.model.identify.risefit import RISE_SPAN, RisesWhy, TimeConstantFit, WholeLogWhy
from minseg_tui.quantities import (
    F_UNIT,
    RPM,
    format_constant,
    format_diff,
    format_fixed,
    format_interval,
    format_number,
    format_percent,
    format_quantity,
    format_reading,
    format_signed,
    format_value,
)


@singledispatch
def sentence(o: Observation) -> str:
    """The sentence of an observation, as a student reads it."""
    raise TypeError(f"no words for {type(o).__name__}")


def _row(r: RowAt) -> str:
    where = f", line {r.line}" if r.line is not None else ""
    return f"row {r.number} (u_req {r.u_req:g} V{where})"


def _lines(at: Lines) -> str:
    """'line 12' / 'lines 5-6' / 'rows 1-2'."""
    word = "line" if at.by_line else "row"
    return f"{word} {at.first}" if at.first == at.last else f"{word}s {at.first}-{at.last}"


@sentence.register
def _(o: CurrentInAmperes) -> str:
    return f"{_row(o.row)}: i_ss = {o.i_ss:g} looks like amperes; the table wants mA ({o.i_ss * 1e3:g} mA?)."


@sentence.register
def _(o: CurrentHigh) -> str:
    return f"{_row(o.row)}: i_ss = {o.i_ss:g} mA is above 100 mA; the manual says the meter is probably measuring the wrong thing or is in the wrong mode."


@sentence.register
def _(o: SpeedInRpm) -> str:
    return f"{_row(o.row)}: omega_ss = {o.omega_ss:g} is {format_number(o.omega_ss / o.u_ss, 3)} per volt, more than this motor turns; it looks like rpm, the table wants rad/s ({format_reading(o.omega_ss * RPM, 'rad/s')}?)."


@sentence.register
def _(o: KvNotPositive) -> str:
    return f"{_row(o.row)}: R i_ss = {format_number(o.R * o.i_ss * 1e-3, 3)} V is not below u_ss = {o.u_ss:g} V, so k_v comes out {format_number(o.k_v, 3)}; check R and i_ss."


@sentence.register
def _(o: KvOutlier) -> str:
    return (
        f"{_row(o.row)}: k_v = {format_number(o.k_v)} V s/rad is {format_percent(abs(o.dev))} "
        f"{'above' if o.dev > 0 else 'below'} the median {format_number(o.median)}: probably a bad reading "
        "(u_ss, omega_ss or i_ss of that row); the median keeps it out of the result."
    )


@sentence.register
def _(o: KvDisagree) -> str:
    return (
        f"The two rows give k_v = {format_number(o.a)} and {format_number(o.b)} V s/rad, {format_percent(o.apart)} apart: "
        "one is probably a bad reading, and with two rows the median cannot tell which. Measure a third voltage."
    )


def _above_range(rows: tuple[tuple[float, float], ...]) -> str:
    """'by 52 % at 2.5 V and 9 % at 3.5 V': how far u_ss is above u_req on each row (walk 7:
    "by 9 %" alone read as true of every row of the table)."""
    each = [
        f"{format_fixed(100.0 * (u_ss / u_req - 1.0), 0, '%')} at {u_req:g} V"
        for u_req, u_ss in rows
    ]
    return "by " + (each[0] if len(each) == 1 else ", ".join(each[:-1]) + " and " + each[-1])


@sentence.register
def _(o: USsAboveUReq) -> str:
    n = len(o.rows)
    return (
        f"u_ss is above u_req on {'the one row' if n == 1 else 'both rows' if n == 2 else f'all {n} rows'} "
        f"the results use ({_above_range(o.rows)}): a motor driver gives "
        "the motor at most the voltage it is asked for, less its drop, so the two columns "
        "look swapped. k_v, k_a and f divide by these readings: check the table."
    )


@sentence.register
def _(o: DryFriction) -> str:
    line = ""
    if o.line is not None:
        slope, intercept = o.line
        line = (
            f" A straight line k_a i_ss = f omega + tau_c through the rows gives a viscous f = {format_quantity(slope, F_UNIT)} "
            f"and a dry friction torque tau_c = {format_value(intercept * 1e3, 'mN m')}."
        )
    return (
        f"f falls with speed, from {format_quantity(o.f_slow, F_UNIT)} at {format_reading(o.w_slow, 'rad/s')} to {format_quantity(o.f_fast, F_UNIT)} at {format_reading(o.w_fast, 'rad/s')}: "
        "part of the friction is dry (Coulomb) friction, a torque that does not grow with speed. "
        "The lab's model has viscous friction only, so its f depends on the speed it was measured at."
        + line
    )


@sentence.register
def _(o: USsFromLog) -> str:
    return (
        f"The log has no u_req column, so K divides by the applied voltage the log recorded "
        f"({format_number(o.u_ss, 3)} V) instead of u_ss from the table."
    )


@sentence.register
def _(o: USsInterpolated) -> str:
    which = "extrapolated beyond" if isinstance(o, USsExtrapolated) else "interpolated between"
    return (
        f"No table row has u_req = {', '.join(f'{v:g}' for v in o.levels)} V, the step's requested level; "
        f"u_ss = {format_number(o.u_ss, 3)} V is {which} the table's rows."
    )


@sentence.register
def _(o: SeveralLevels) -> str:
    return (
        f"The rising edges go to several levels ({', '.join(f'{v:g}' for v in o.levels)} V); K is the median "
        "of omega_ss / u_ss over the steps and omega_ss the median of their speeds."
    )


@sentence.register
def _(o: StepVsTable) -> str:
    return (
        f"The step at t = {format_number(o.t, 3)} s settles at {format_number(o.omega_ss, 3)} rad/s, but the table gives "
        f"{format_number(o.omega_table, 3)} rad/s at u_req = {o.u_req:g} V ({format_percent(abs(o.omega_ss / o.omega_table - 1))} apart): "
        "the two experiments do not agree (a different wheel load, battery level, or a misread value)."
    )


@sentence.register
def _(o: TShort) -> str:
    return (
        f"T = {format_constant(o.T, 's')} is shorter than {o.samples:g} sample periods (Ts = {format_reading(o.ts, 'ms', 3)}): "
        "the speed rises within a few samples. The 63 % reading, the manual's way, reads T off those samples, "
        "so the sampling and the velocity computation move it as much as the motor does; the least-squares T "
        "fits whole stretches of the run with the sampling modelled, so the two differ. Both are fair "
        "readings of T; the program's model and its least-squares J use the least-squares one."
    )


def _lagging(lag: float) -> str:
    """The speed column's lag behind the angle column, said for the 63 % reading."""
    return (
        f"this log's speed column runs about {format_constant(lag, 's')} behind its angle "
        "column (see below), more than the half sample of a mean over each interval: the "
        "reading, taken off that speed, carries the lag; T, fitted to the angle, does not"
    )


def _t63_why(o: T63Differs) -> str:
    T_63, T, dead_time = o.T_63, o.T, o.dead_time
    if o.lag is not None and o.why in (T63Why.DEAD_TIME, T63Why.LAG):
        held = (
            f"The reading counts from the logged step, so it holds the dead time of "
            f"{format_constant(dead_time, 's')} that T does not; besides, "
            if o.why is T63Why.DEAD_TIME
            else ""
        )
        said = _lagging(o.lag)
        return f"{held}{said if held else said[0].upper() + said[1:]}."
    if o.why is T63Why.DEAD_TIME_SHAPE and o.shape is not None and o.noise is not None:
        return (
            f"The reading counts from the logged step, so it holds the dead time of "
            f"{format_constant(dead_time, 's')} that T does not. Counted from the end of that dead time "
            f"it is {format_constant(T_63 - dead_time, 's')} where the fitted model read the "
            f"same way gives {format_constant(T_63 - o.shape - dead_time, 's')}: the "
            f"{format_signed(o.shape * 1e3, 3)} ms between them is the shape of the rise, which "
            "one time constant does not follow, not the sampling (the speed's scatter "
            f"moves the reading by only about {o.noise[1] * 1e3:.3g} ms). Read T with care."
        )
    if o.why is T63Why.DEAD_TIME:
        return (
            f"The reading counts from the logged step, so it holds the dead time of "
            f"{format_constant(dead_time, 's')} that T does not; besides, the measured speed is the "
            "mean over each sample interval and lags the true speed by half a sample."
        )
    if o.why is T63Why.SHAPE and o.shape is not None:
        return (
            f"Most of it ({format_signed(o.shape * 1e3, 3)} ms) is the shape of the rise, which one "
            "time constant does not follow (see the time shift below): no one time "
            "constant meets both the 63 % point and the whole rise here."
        )
    if o.why is T63Why.NOISE and o.shape is not None and o.noise is not None:
        return (
            f"Of it, {format_signed((T_63 - T - o.shape) * 1e3, 3)} ms is the sampling "
            "and the steps' time shift, held at its bound (the measured speed is the mean "
            "over each sample interval, half a sample late), and "
            f"{format_signed(o.shape * 1e3, 3)} ms the noise of reading single samples: the "
            f"speed scatters {format_number(o.noise[0], 3)} rad/s from sample to sample, which "
            f"moves where it first crosses 63 % by about {o.noise[1] * 1e3:.3g} ms; the "
            + (
                "least-squares T uses every sample, so it is the one to trust."
                if o.T_ci is None
                else "least-squares T uses every sample, but its own 95 % interval "
                f"({format_interval(o.T_ci[0] * 1e3, o.T_ci[1] * 1e3, 'ms')}) holds the "
                "reading too: this log does not tell them apart, and neither pins T (see "
                "T's interval below)."
            )
        )
    return (
        "The measured speed is the mean over each sample interval, so "
        "it lags the true speed by half a sample; a velocity filter lags it more."
    )


@sentence.register
def _(o: T63Differs) -> str:
    return (
        f"The 63 % reading ({format_constant(o.T_63, 's')}) and the least-squares T ({format_constant(o.T, 's')}) differ by "
        f"{format_percent(abs(o.T_63 / o.T - 1))}. " + _t63_why(o)
    )


@sentence.register
def _(o: NotSettled) -> str:
    return (
        f"{o.count} step(s) last less than 5 T ({format_constant(5 * o.T, 's')}): the speed has not quite settled "
        "by their end, so omega_ss is the final speed of the fitted response rather than a reading "
        "of it (a mean over the end of a step would come out low); longer steps would check it."
    )


@sentence.register
def _(o: StepsSkipped) -> str:
    return f"{o.count} rise(s) were too short or too close to the start of the log to use."


@sentence.register
def _(o: FrictionTask15) -> str:
    more = "more" if o.lab > o.with_friction else "less"
    return (
        f"The fit found dry friction: its steady speed grows by {format_number(o.gain, 4)} "
        f"rad/s per volt above a breakaway voltage u_c = {format_number(o.u_c, 3)} V, a line "
        "that does not pass through zero. K = omega_ss / u_ss "
        f"({format_number(o.K, 4)} rad/s per V) is read at the step's {format_number(o.u_ss, 3)} V and "
        "makes the speed proportional to u_A, as the lab's model (Task 14) has viscous "
        "friction only, no dry friction. "
        f"So at u_A = {o.u_A:g} V (Task 15) that model gives {format_number(o.lab, 4)} rad/s, "
        f"{format_percent(abs(o.lab / o.with_friction - 1)) if o.with_friction > 0 else 'far'} {more} "
        f"than the {format_number(o.with_friction, 4)} rad/s of the model with dry friction."
    )


@sentence.register
def _(o: GlitchRows) -> str:
    speeds = ", ".join(format_reading(w, "", 3) for w in o.speeds)
    n = o.n_rows
    first = (
        f"{_lines(o.first).capitalize()} reads 0 rad/s, as the first row of a speed taken "
        "from counts does (no sample before it), and the "
        + (f"{n} rows after it" if n > 1 else "row after it")
        + f" ({_lines(o.rows)}) read{'' if n > 1 else 's'} {speeds} rad/s"
        if o.zeroed
        else f"The first {o.count} row(s) ({_lines(o.rows)}) read {speeds} rad/s"
    )
    return (
        f"{first} while the "
        "command holds still, further from the speed of the rows after them than any later "
        "row ever is: switch-on glitches of the logging, not motion. They are left out"
        + (" with the zeroed row before them" if o.zeroed else "")
        + f": the fit starts at {_lines(o.start)}."
    )


@sentence.register
def _(o: SpeedLags) -> str:
    return (
        "The speed column runs behind the angle column: summed over the sample intervals it "
        f"falls behind the angle as a speed {format_constant(o.lag, 's')} late would "
        f"({format_fixed(o.lag / o.ts, 1)} sample periods of {format_reading(o.ts, 'ms', 3)}), "
        "where the mean speed over each interval would not fall behind at all. So it is a "
        "filtered or late speed (as a motor driver's own speed estimate), not the angle's "
        "difference over each interval. T is fitted to the angle and does not carry that lag; "
        "the 63 % reading, and the model check (analyze), which read the speed column, do."
    )


@sentence.register
def _(o: EdgeGlitch) -> str:
    speeds = ", ".join(format_reading(w, "", 3) for w in o.speeds)
    n = o.n_rows
    return (
        f"{_lines(o.rows).capitalize()}, right after the step, read{'' if n > 1 else 's'} "
        f"{speeds} rad/s, beyond any speed the rise reaches later (at most "
        f"{format_reading(o.level, '', 3)} rad/s, a 5-row running median), and the row after {'them' if n > 1 else 'it'} falls back to "
        f"{format_reading(o.after, '', 3)} rad/s: a motor answering a step does not overshoot "
        "and fall back within a sample or two, so "
        + ("these are glitches" if n > 1 else "this is a glitch")
        + " of the reading at switch-on (counts picked up as the motor is switched), not the "
        "wheel moving before the step. The fit keeps "
        + ("them" if n > 1 else "it")
        + ", which pulls T; read it with care."
    )


@sentence.register
def _(o: LoggingStall) -> str:
    return (
        f"{_lines(o.at).capitalize()} comes after a gap of {format_fixed(o.gap * 1e3, 0, 'ms')} in the logging "
        f"({format_fixed(o.gap / o.ts, 1)} sample periods) and departs from the fit by far more than the "
        "other rows do: its encoder value or its speed does not belong to its timestamp (a "
        "logging stall), not the motor. It is left out of the fit"
        + (
            "; the angle rebuilt from the speed column carried that speed across the gap "
            "and stayed off after it, so the fit takes that step off the rows after it."
            if o.mended
            else "."
        )
    )


@sentence.register
def _(o: DeadTime) -> str:
    return (
        f"The wheel answers {format_fixed(o.dead_time * 1e3, 0, 'ms')} after the logged steps, more than the "
        f"one sample period ({format_reading(o.bound, 'ms', 3)}) that the sampling's lateness can explain: a "
        "dead time. It is fitted as the model check fits it and is part of the model "
        f"(Task 14): T omega'(t) = -omega(t) + K u_A(t - {format_number(o.dead_time, 3)} s). T is counted "
        "from the moment the wheel answers."
        + (
            " The rows of the rise alone show it"
            + (
                f" (the speed first shows {format_constant(o.onset, 's')} after the steps)"
                if o.onset is not None and o.first_move is None
                else (
                    " (the speed, a running median over 3 rows, first shows "
                    f"{format_constant(o.onset, 's')} after the steps; a single row's speed "
                    f"leaves its level {format_constant(o.first_move, 's')} after them, a "
                    "first count the median drops)"
                )
                if o.onset is not None and o.first_move is not None
                else ""
            )
            + (
                ": over every row, the slow part long after the rise, which one time "
                "constant does not follow, would hold a response without it early, "
                "starting before the wheel moves. The model check (analyze) fits the "
                "speed of every row, that slow part included, and can give a shorter "
                "dead time."
                if o.creep
                else ": over every row it does not fit clearly better than none, and the "
                "fit starts it no earlier than the rise's rows allow. The model check "
                "(analyze) fits the speed of every row and can give a shorter dead time."
            )
            if o.from_rise
            else ""
        )
    )


def _moved_within(o: ShiftLate) -> bool:
    """Whether the wheel is seen to move within the shift's bound (one sample period), by a
    row's own speed the 3-row running median of the onset drops."""
    return o.first_move is not None and o.first_move <= o.shift * (1.0 + 1e-9)


def _late(o: ShiftLate) -> str:
    if o.why is LateStart.MOVED_EARLY and o.moved_early is not None:
        return (
            "A dead time fits the log better, but it is not one: the wheel already moves before "
            f"it would end ({format_percent(o.moved_early)} of the way to its new speed), so the rise "
            "starts at once but slowly, a shape the first-order model misses (an S-shaped start: "
            "a second pole or a filtered speed; a ramp: a current limit). Read T with care."
        )
    if o.why is LateStart.NO_BETTER:
        return "A dead time does not fit the log clearly better."
    if _moved_within(o):  # said before: the wheel moves within the sampling's lateness
        if o.why is LateStart.COARSE and o.count is not None:
            return (
                f"One count per sample is {format_number(o.count, 3)} rad/s, "
                f"{format_percent(o.count / o.rise)} of the rise, too coarse to show how the rise "
                "starts: a slow start (a second pole or a filtered speed) and the counts' steps "
                "look alike here. Read T with care."
            )
        return (
            "The rise starts more slowly than one time constant gives (an S-shaped start: a "
            "second pole or a filtered speed), a shape the first-order model misses. Read T "
            "with care."
        )
    first = o.first_move if o.first_move is not None else o.onset
    moves = (
        "The wheel first moves "
        + (f"{format_constant(first, 's')} " if first is not None else "")
        + "after the steps, no later than the rise itself and the sampling explain, "
    )
    if o.why is LateStart.COARSE and o.count is not None:
        return moves + (
            f"so there is no dead time to fit. One count per sample is {format_number(o.count, 3)} "
            f"rad/s, {format_percent(o.count / o.rise)} of the rise, too coarse to show how the "
            "rise starts: a slow start (a second pole or a filtered speed) and the counts' "
            "steps look alike here. Read T with care."
        )
    return moves + (
        "so there is no dead time to fit: the rise starts more slowly than one "
        "time constant gives (an S-shaped start: a second pole or a filtered speed), "
        "a shape the first-order model misses. Read T with care."
    )


@sentence.register
def _(o: ShiftLate) -> str:
    free = o.free
    answers = (
        "the first-order response fits best starting later than that, although the wheel is "
        f"first seen to move {format_constant(o.first_move, 's')} after the steps, within the "
        "sampling's lateness: there is no dead time to fit."
        if o.first_move is not None and _moved_within(o)
        else "the wheel answers later than the sampling's lateness explains."
    )
    where = (
        "where the speed, a running median over 3 rows, first leaves its level"
        if free is not None and free.first_move is not None
        else "where the wheel is first seen to move"
    )
    return (
        f"The time shift of the steps against the samples ended on its bound of one sample "
        f"period ({format_signed(o.shift * 1e3, 3)} ms): {answers} {_late(o)} T is the fit with "
        "the shift held there."
        + (
            f" With the shift free up to {where} "
            f"({format_constant(free.onset, 's')} after the steps), the fit starts the response "
            f"{format_signed(free.shift * 1e3, 3)} ms from the steps with T = "
            f"{format_constant(free.T, 's')} (95 % "
            f"{format_interval(free.ci[0] * 1e3, free.ci[1] * 1e3, 'ms')}): "
            "a later start goes with a shorter T, and the samples do not pin where a "
            "first-order response would start (coarse counts, or a start that bends "
            "in smoothly), so the 95 % interval of T holds both fits."
            if free is not None
            else ""
        )
    )


@sentence.register
def _(o: ShiftEarly) -> str:
    return (
        f"The time shift of the steps against the samples ended on its bound of one sample "
        f"period ({format_signed(o.shift * 1e3, 3)} ms): the wheel moves earlier than the logged steps "
        "by more than the sampling's lateness explains. The steps in the log are placed late "
        "(a command logged after it acted); T is the fit with the shift held at the bound."
    )


@sentence.register
def _(o: ShiftMisfit) -> str:
    shape = (
        ": the fitted response starts before the wheel does and then rises more slowly "
        "than the wheel"
        + (
            " (the rows long after the rise pull the fit: see T's rows below)"
            if o.rows_apart
            else ""
        )
        + ", a shape the first-order model misses"
        if o.behind
        else ": the rise is steeper at first and slower later than one "
        "time constant gives (a second, slower process), a shape the first-order model "
        "misses"
    )
    return (
        f"The time shift of the steps against the samples ended on its bound of one sample "
        f"period ({format_signed(o.shift * 1e3, 3)} ms), earlier than the steps, although the wheel "
        "does not move before them"
        + (
            f" (it first moves {format_constant(o.onset, 's')} after them)"
            if o.onset is not None
            else ""
        )
        + f"{shape}. T is the fit with the shift held at the bound; read it with care."
    )


def _creeping(o: TRowsApart, creep: tuple[float, float]) -> str:
    """The two T (the rise's rows, every row) and the speed's creep after the rise (rad/s),
    up to "by the end of the step"."""
    return (
        f"T depends on which rows are fitted: the rows up to {o.span:g} T after each "
        f"edge alone give {format_constant(o.rise_T, 's')} (95 % "
        f"{format_interval(o.rise_ci[0] * 1e3, o.rise_ci[1] * 1e3, 'ms')}), all the rows the "
        f"fit uses {format_constant(o.T, 's')}. After the rise the speed keeps creeping "
        f"{'up' if creep[1] > creep[0] else 'down'}, from "
        f"{format_number(creep[0], 3)} to {format_number(creep[1], 3)} rad/s by the end "
        "of the step"
        + (
            # analyze's creep reads another window (from its own settling): say this one
            f" (the means of the first and the last tenth of the rows read from "
            f"{format_number(o.creep_span[0], 3)} s after the step, {o.span:g} T after the "
            f"wheel answers, to {format_number(o.creep_span[1], 3)} s after it)"
            if o.creep_span is not None
            else ""
        )
    )


@sentence.register
def _(o: TRowsApart) -> str:
    if o.follows_rise and o.creep is not None and o.miss is not None:
        return (
            _creeping(o, o.creep)
            + ": a second, slower process, outside a first-order model. One time "
            "constant cannot follow both: the fit of every row takes a longer T that partly "
            "follows the creep, and its model rises more slowly than the wheel, by up to "
            f"{format_number(o.miss, 2)} rad/s on the rise. So T, K, J and the model (Task 14) "
            f"follow the rise: T = {format_constant(o.rise_T, 's')}"
            + (
                f", and K from the rise's steady speed ({format_number(o.rise_speed, 3)} rad/s)"
                if o.rise_speed is not None
                else ""
            )
            + "; the model leaves the creep out. "
            f"{format_constant(o.T, 's')}, the T of every row, is the other reading. "
            "The 95 % interval of T spans both fits. Read T with care."
        )
    if o.creep is not None and o.miss is not None:
        return (
            _creeping(o, o.creep)
            + ", and one time constant cannot follow both: the fit of every row takes "
            "a longer T that partly follows the creep, and its model rises more slowly than "
            f"the wheel, by up to {format_number(o.miss, 2)} rad/s on the rise. "
            f"{format_constant(o.rise_T, 's')} is the T the rise itself follows; the model "
            f"(Task 14) uses {format_constant(o.T, 's')}, the T of every row. "
            "The 95 % interval of T spans both fits. Read T with care."
        )
    if o.up_T is not None and o.rise_T > o.up_T and abs(o.up_T - o.T) < abs(o.rise_T - o.up_T):
        return (
            f"T depends on which rows are fitted: the rows up to {o.span:g} T after each "
            f"edge, rising and falling, alone give {format_constant(o.rise_T, 's')} (95 % "
            f"{format_interval(o.rise_ci[0] * 1e3, o.rise_ci[1] * 1e3, 'ms')}), all the rows the "
            f"fit uses {format_constant(o.T, 's')} and the rows after the rising edges alone "
            f"{format_constant(o.up_T, 's')}: the rows after the falling edges make the "
            "difference. There the wheel slows down more slowly than one time constant of its "
            "rise gives (it coasts at zero command, or dry friction slows it), a shape the "
            "first-order model misses. The 95 % interval of T spans both fits. Read T with care."
        )
    if o.levels is not None and (o.levels[0] - o.levels[1]) * (o.rise_T - o.T) > 0:
        # a Pololu Balboa log, flat after its rise (14.6-14.7 rad/s from 0.23 s to 3.6 s):
        # "the rise and the speed after it do not follow one time constant" was said where
        # the rise's 11 rows alone reached for 15.0 rad/s and every row held 14.65
        rise_w, every_w = (format_number(x, 3) for x in o.levels)
        return (
            f"T depends on which rows are fitted: the rows up to {o.span:g} T after each "
            f"edge alone give {format_constant(o.rise_T, 's')} (95 % "
            f"{format_interval(o.rise_ci[0] * 1e3, o.rise_ci[1] * 1e3, 'ms')}) with a steady "
            f"speed of {rise_w} rad/s, all the rows the fit uses {format_constant(o.T, 's')} "
            f"with {every_w} rad/s: the speed after the rise holds level, and the later rows, "
            "long after the rise, hold it "
            f"{'below' if o.levels[1] < o.levels[0] else 'above'} the level the rise's rows "
            "alone reach for; a first-order rise starts at its steady speed over T, so the "
            f"same start with a {'lower' if o.levels[1] < o.levels[0] else 'higher'} steady "
            f"speed takes a {'shorter' if o.T < o.rise_T else 'longer'} T. The 95 % interval "
            "of T spans "
            "both fits. Read T with care."
        )
    return (
        f"T depends on which rows are fitted: the rows up to {o.span:g} T after each "
        f"edge alone give {format_constant(o.rise_T, 's')} (95 % "
        f"{format_interval(o.rise_ci[0] * 1e3, o.rise_ci[1] * 1e3, 'ms')}), all the rows the fit uses "
        f"{format_constant(o.T, 's')}: the later rows, long after the rise, pull T "
        f"{'longer' if o.T > o.rise_T else 'shorter'}: the rise and the speed after it do not "
        "follow one time constant, a shape the first-order model misses. The 95 % "
        "interval of T spans both fits. Read T with care."
    )


@sentence.register
def _(o: CountsHidden) -> str:
    return (
        "T's 95 % interval rests on the scatter the fit leaves on this log's one rise. The "
        "angle's values sit on no grid of encoder counts and the log names none (a '# cpr:' "
        "line): if the angle was read in whole counts whose grid the log does not show "
        "(interpolated onto other instants, or rebuilt from a rounded speed), their rounding "
        "is hidden from the fit and not in the interval, and T may lie outside it. A "
        "'# cpr:' line giving the encoder's counts per revolution lets the interval hold "
        "that rounding."
    )


@sentence.register
def _(o: TOnBound) -> str:
    return (
        f"T = {format_constant(o.T, 's')} ended on the bound of the range the fit tries "
        f"({format_reading(o.lo, 'ms', 3)} to {format_reading(o.hi, 's', 3)}): this log cannot tell T beyond it, and the "
        "first-order model does not describe it well."
    )


@sentence.register
def _(o: TNotDetermined) -> str:
    return (
        f"T's 95 % interval spans more than a factor of ten: T is not determined by this "
        f"log; {format_constant(o.T, 's')} is only the best fit. Longer steps, more of them, or a "
        "faster sampling would tell it."
    )


def t63_note(n: T63Note) -> str:
    """How far the 63 % reading is from the least-squares T, and why, in sentences (the CLI's
    text and the ``T_63_note`` of its JSON)."""
    T_63, T, dead_time = n.T_63, n.T, n.dead_time
    apart = T_63 - T
    side = "longer" if apart > 0 else "shorter"
    out = (
        f"The 63 % reading ({format_constant(T_63, 's')}) is {format_constant(abs(apart), 's')} "
        f"({abs(apart) / T * 100:.1f} %) {side} than the least-squares T ({format_constant(T, 's')})."
    )
    if n.model is None:
        return out
    sampled = n.model - T - dead_time
    delay = (
        f"the dead time moves the reading by {dead_time * 1e3:+.1f} ms and the sampling by "
        if dead_time > 0
        else "the sampling and the steps' time shift, held at its bound, move the reading by "
        if n.misfit
        else "the sampling alone moves the reading by "
    )
    whose = "the model's speed" if n.lag is not None else "the logged speed"
    out += (
        f" Read the same way on the fitted model sampled every {n.ts * 1e3:.3g} ms like this log, it gives "
        f"{format_constant(n.model, 's')}: {delay}{sampled * 1e3:+.1f} ms "
        f"({whose} is the mean over each sample interval, half a sample late, and the reading "
        "joins the samples by straight lines)"
    )
    rest = T_63 - n.model
    if n.lag is not None:
        return (
            out + f", and {rest * 1e3:+.1f} ms is the rest, with the noise of reading single "
            f"samples: {_lagging(n.lag)}. The least-squares fit models the sampling, so its T "
            "is the one the model uses."
        )
    noise = n.noise
    if n.rest is RestWhy.NOISE and noise is not None:
        out += (
            f", and {rest * 1e3:+.1f} ms is the noise of reading single samples: the speed "
            f"scatters {format_number(noise[0], 3)} rad/s from sample to sample, which moves "
            f"where it first crosses 63 % by about {noise[1] * 1e3:.3g} ms."
        )
    elif n.rest is RestWhy.SHAPE_MISFIT:
        out += (
            f", and {rest * 1e3:+.1f} ms is the shape of the rise, which one time constant does "
            "not follow (see the time shift below), with the noise of reading single samples."
        )
    elif n.rest is RestWhy.SHAPE and noise is not None:
        out += (
            f", and {rest * 1e3:+.1f} ms is the shape of the rise, which one time constant does "
            f"not follow: the speed scatters {format_number(noise[0], 3)} rad/s from sample to "
            f"sample, which moves where it first crosses 63 % by only about "
            f"{noise[1] * 1e3:.3g} ms."
        )
    elif n.rest in (RestWhy.STALL, RestWhy.SINGLE):
        why = (
            "reading across a logging stall's gap and"
            if n.rest is RestWhy.STALL
            else "the noise of"
        )
        out += f", and {rest * 1e3:+.1f} ms is {why} reading single samples."
    else:
        out += ", which is the whole difference."
    return out + " The least-squares fit models the sampling, so its T is the one the model uses."


def as_json(result: Identification) -> dict[str, object]:
    """``minseg-tui identify --json``'s object (SI units, i_ss in mA as entered), its
    ``T_63_note`` in words (:func:`t63_note`)."""
    out: dict[str, object] = {
        "R": result.R,
        "rows": [
            {
                "u_req": r.reading.u_req,
                "u_ss": r.reading.u_ss,
                "omega_ss": r.reading.omega_ss,
                "i_ss": r.reading.i_ss,
                "k_v": r.k_v,
                "f": r.f,
            }
            for r in result.rows
        ],
        "k_v": result.k_v,
        "k_a": result.k_a,
        "f": result.f,
    }
    if result.step is not None:
        s = result.step
        out["step"] = {
            "K": s.K,
            "T": s.T,
            "T_63": s.T_63,
            "T_ci": [s.T_ci[0], s.T_ci[1]],
            "J": s.J,
            "omega_ss": s.omega_ss,
            "K_ci": [s.K_ci[0], s.K_ci[1]],
            "T_63_model": s.T_63_model,
            "T_63_note": t63_note(s.T_63_note) if s.T_63_note is not None else None,
            "method": s.fit.method,
            "shift": s.fit.shift,
            "u_c": s.fit.u_c,
            "dead_time": s.dead_time,
            "T_determined": s.T_determined,
            "T_on_bound": s.fit.T_on_bound,
            "shift_on_bound": s.fit.shift_on_bound,
            "glitch_rows": s.glitch_rows,
            "left_out_rows": [r + s.glitch_rows for r in s.fit.left_out],
            "T_rise_rows": None
            if s.fit.rise_T is None or s.fit.rise_ci is None
            else {"T": s.fit.rise_T, "T_ci": [s.fit.rise_ci[0], s.fit.rise_ci[1]]},
            **(
                {"T_every_row": s.fit.every_row_T} if s.fit.every_row_T is not None else {}
            ),  # the model follows the rise: every row's T is the other reading
            "T_shift_free": None
            if s.fit.free_T is None or s.fit.free_ci is None
            else {
                "T": s.fit.free_T,
                "T_ci": [s.fit.free_ci[0], s.fit.free_ci[1]],
                "shift": s.fit.free_shift,
            },
        }
        out["model"] = {
            "T": s.T,
            "K": s.K,
            "dead_time": s.dead_time,
            "u_c": s.u_c,
            "K_above_u_c": s.K_above_u_c,
        }
        out["omega_at_5V"] = result.omega_at_5V
        out["omega_at_5V_with_friction"] = result.omega_at_5V_with_friction
    return out


def fit_why(why: WholeLogWhy | RisesWhy) -> str:
    """Why T came from the fit it came from, in words (the CLI's note under T, the report's
    "How T was fitted")."""
    if isinstance(why, RisesWhy):
        if why.flat:
            return (
                "the applied voltage u never changes in the log, so T comes from the rises"
                + _follows_rise(why.every_row_T)
            )
        times = f"{why.ratio:.1f} times" if why.ratio is not None else "more than"
        return (
            f"the first-order model over the whole log leaves {times} the "
            "residual of the steps fitted one by one (the wheel between the steps does not "
            "follow it: coasting at zero command, or a speed that wanders), so T comes from "
            "the rises alone" + _follows_rise(why.every_row_T)
        )
    friction = (
        f"; dry friction found: breakaway at u_c = {format_number(why.u_c)} V in this fit "
        "(the model check's fit of the speed finds its own u_c)"
        if why.u_c is not None
        else ""
    )
    alone = "the rise fitted alone does" if why.one else "the rises fitted one by one do"
    theirs = "that fit's" if why.one else "theirs"
    if why.down == 0:
        edges = f"every edge is used (the log has {why.up} rising {'edge' if why.up == 1 else 'edges'} and no falling one)"
    else:
        edges = f"every edge, rising and falling, is used ({why.up} rising, {why.down} falling)"
    return (
        f"one first-order model fits the whole log as well as {alone} "
        f"(on the {'rise' if why.one else 'rises'} its residual is "
        f"{why.ratio:.2f} times {theirs}), so "
        f"{edges}{friction}{_follows_rise(why.every_row_T)}"
    )


def _follows_rise(every_row_T: float | None) -> str:
    """The clause that says T follows the rise's rows, not every row (T of every row, s)."""
    if every_row_T is None:
        return ""
    return (
        "; but the speed creeps on after the rise, which one time constant does not follow "
        f"together with it, so T is the fit of the rows up to {RISE_SPAN:g} T after each edge "
        f"alone, the rise's (every row gives {format_constant(every_row_T, 's')})"
    )


def time_from(fit: TimeConstantFit) -> str:
    """Where the fit's time came from, in words."""
    return "the board's timestamps (t_us)" if fit.stamped else "the t column"


def model_equation(st: ResponseResult, w: str = "omega") -> str:
    """Task 14's model as text, the speed named ``w``: "T w' = -w + K u_A", with "(t)" and
    "u_A(t - D s)" when it has a dead time."""
    num = format_number
    if st.dead_time > 0:
        return f"{num(st.T)} {w}'(t) = -{w}(t) + {num(st.K)} u_A(t - {num(st.dead_time)} s)"
    return f"{num(st.T)} {w}' = -{w} + {num(st.K)} u_A"


def friction_equation(st: ResponseResult, w: str = "omega") -> str | None:
    """The fitted model with its dry friction as text ("T w' = -w + K' (u_A - u_c sgn w)",
    with the dead time as in :func:`model_equation`), None without dry friction."""
    num = format_number
    gain = st.K_above_u_c
    if gain is None:
        return None
    u = f"u_A(t - {num(st.dead_time)} s)" if st.dead_time > 0 else "u_A"
    t = "(t)" if st.dead_time > 0 else ""
    return f"{num(st.T)} {w}'{t} = -{w}{t} + {num(gain)} ({u} - {num(st.u_c)} V sgn {w}{t})"


def u_ss_not_entered(level: float, extrapolated: bool, u_ss: float | None) -> str:
    """identify's sentence on a u_ss the table has no row for, when the row at the step's
    ``level`` (V) is there but its u_ss is not entered: the step's K divides by a u_ss
    (``u_ss``, V, None when not computed) ``extrapolated`` from the table's other rows, or
    interpolated between them."""
    which = "extrapolated from" if extrapolated else "interpolated between"
    got = f" (u_ss = {format_number(u_ss, 3)} V)" if u_ss is not None else ""
    return (
        f"u_ss at {level:g} V is not entered (Task 4): the step's K divides by a u_ss "
        f"{which} the table's other rows{got}, and a K typed on Task 11 is not judged until "
        "it is entered."
    )


def check_T_beside(
    T_check: float,
    st: ResponseResult | None,
    observations: Sequence[Observation],
    extended: tuple[str, float] | None = None,
) -> str:
    """Which T the model check's first-order model (``minseg-tui analyze``'s baseline) has,
    and identify's T of the same log beside it, so that a lab assistant is not left with two
    T and no word. ``T_check`` (s): the first-order model simulated on the measured input and
    fitted to the speed; ``st``: identify's result for the log, fitted to the angle (None
    when identify cannot fit it), ``observations`` its observations of that fit;
    ``extended``: the check's extended model in words and its T (s), when it has one.

    Where the speed creeps on after the rise and identify's T follows the rise
    (:class:`TRowsApart`), why the check's T, a fit of every row, is longer, with the log's
    figures; elsewhere the extended model's T when it is nearer identify's."""
    own = (
        "This T is the model check's own: the first-order model simulated on the measured "
        "input and fitted to the speed of those rows."
    )
    if st is None or not math.isfinite(st.T) or not (math.isfinite(T_check) and T_check > 0):
        return own
    dead = (
        f", with a dead time of {format_constant(st.dead_time, 's')}," if st.dead_time > 0 else ""
    )
    apart = next(
        (o for o in observations if isinstance(o, TRowsApart) and o.follows_rise and o.creep),
        None,
    )
    if apart is not None and apart.creep is not None and T_check > apart.rise_T:
        return (
            f"{own} identify fits the angle at the log's sample times{dead} and gives "
            f"T = {format_constant(st.T, 's')}, the rise's. For identify, "
            + _creeping(apart, apart.creep)
            + ": a second, slower process, outside a first-order model, which identify's T, "
            "K, J and model (Task 14) leave out; a fit of every row takes a longer T that "
            "partly follows the creep. This T fits every row too"
            + (", and without identify's dead time" if st.dead_time > 0 else "")
            + ", so it comes out longer than the rise's as well."
        )
    rows = (
        f"the rows up to {RISE_SPAN:g} T after each edge"
        if st.fit.every_row_T is not None
        else "the rises"
        if st.fit.method == "rising_steps"
        else "all the rows it uses"
    )
    nearer = (
        f" The extended model below ({extended[0]}) gives T = "
        f"{format_constant(extended[1], 's')}, nearer identify's."
        if extended is not None and abs(extended[1] - st.T) < abs(T_check - st.T)
        else ""
    )
    return (
        f"{own} identify fits the angle of {rows} at the log's sample times{dead} and gives "
        f"T = {format_constant(st.T, 's')} ({format_diff(st.T / T_check - 1.0)} against "
        f"this T).{nearer}"
    )


_ABOVE_0: Final[Mapping[Measured, str]] = MappingProxyType(
    {
        "omega_ss": "rad/s (a zero speed gives no k_v or f)",
        "u_ss": "V (the voltage measured on the motor)",
        "i_ss": "mA (the current measured in Task 5)",
    }
)
"""Each reading a row needs above 0: its unit, and why."""


def identify_refusal_words(why: IdentifyRefusal) -> str:
    """Why identify refuses a table, R or a run log (:mod:`minseg_tui.model.identify.
    refusals`), as the 'expected ...' part of an InputError: "expected omega_ss > 0 rad/s
    (a zero speed gives no k_v or f), got 0"."""
    match why:
        case RowNotANumber(column, value):
            return f"expected a number for {column}, got {value}"
        case RowNotPositive(column, value):
            return f"expected {column} > 0 {_ABOVE_0[column]}, got {value:g}"
        case RNotPositive(R):
            return f"expected a positive resistance in ohm, got {R:g}"
        case NoRows():
            return "expected at least one row u_req,u_ss,omega_ss,i_ss"
        case RowImplausible(R_i_ss, omega_ss, k_v, f):
            return (
                f"expected readings of a plausible size (R i_ss = {R_i_ss:g} V, "
                f"omega_ss = {omega_ss:g} rad/s), they give k_v = {k_v:g} and f = {f:g}"
            )
        case MedianKvNotPositive(k_v):
            return (
                f"expected the rows to give a positive k_v (V s/rad), their median is "
                f"{k_v:.3g}: u_ss - R i_ss is not above 0 on enough rows; check R and i_ss (mA)"
            )
        case NoRisingEdge(column, after, rising, reverse):
            flip = (
                f"; its step goes from {reverse[0] + 0.0:g} to {reverse[1]:g} V, a run in reverse: "
                "identify reads steps up, so flip the signs of its voltage, speed and angle "
                "columns"
                if reverse is not None
                else ""
            )
            return (
                f"expected a rising edge in {column} (V) with at least one sample before it "
                f"and {after} after it; found {rising} rising edge(s), none usable{flip}"
            )
        case RiseNotFitted():
            return "expected a usable rising edge"


R_IN_SESSION = "R (Task 2)"
"""Where a session's R comes from, named in its refusal (identify names its flag, --R)."""


def identify_refusal(refused: IdentifyRefused, r_from: str = "--R") -> InputError:
    """identify's refusal as the one-line InputError the CLI, the session and the report
    show: where, and why. ``r_from``: what a refusal of R names (the session's Task 2,
    :data:`R_IN_SESSION`: a report or class view said "--R", a flag nobody gave; s38
    attack, a session.json edited by hand to hold a negative R)."""
    source = r_from if refused.source == "--R" else refused.source
    return InputError(source, refused.line, identify_refusal_words(refused.why))
