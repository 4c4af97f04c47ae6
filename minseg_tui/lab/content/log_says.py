"""A run log's refusals in words, made from the model's records (:mod:`minseg_tui.model.
runlog`): the one place the reader of a log file (lab/saving/files.py), the CLI and the
session's results take them from; and where an analysis took the wheel's angle from.

It sits in lab/content/, the lowest of lab/'s folders, beside identify_says.py and
u_ss_says.py, because the saving quotes it.
"""

from __future__ import annotations

from minseg_tui.errors import InputError
from minseg_tui.model.runlog import (
    CLOCK_AGREE,
    COLUMN_UNITS,
    MAX_CPR,
    MAX_MAGNITUDE,
    MIN_ROWS,
    TS_RANGE,
    AngleFrom,
    BadHeader,
    ClockApart,
    Column,
    LogRefused,
    NotFinite,
    PeriodOutOfRange,
    Refusal,
    SpeedStill,
    StillAngle,
    TimeNotIncreasing,
    TooFewRows,
    TooLarge,
    UnequalColumns,
)
from minseg_tui.quantities import printed_label


def _named(column: Column) -> str:
    """A run log's column with its unit, as a refusal names it: 'omega (rad/s)'."""
    return printed_label(column, COLUMN_UNITS[column])


def header_words(bad: BadHeader) -> str:
    """Why a header line ``# key: value`` cannot be taken, as the 'expected ...' part of an
    InputError: "expected # omega_over: interval or nominal, got 'sometimes'"."""
    if bad.key == "cpr":
        return (
            f"expected # cpr: a whole number of counts per revolution above 0 and at most "
            f"{MAX_CPR} (the MinSeg's encoder has 720), got '{bad.value}'"
        )
    return f"expected # omega_over: interval or nominal, got '{bad.value}'"


def angle_words(source: AngleFrom) -> str:
    """Where the wheel's angle came from, as identify's report and refusals say it: "the
    encoder count", "the omega column read as the Euler speed (theta_k - theta_k-1) / 25 ms"."""
    if source.column == "theta":
        return "the theta column"
    if source.column == "count":
        return "the encoder count"
    if source.euler_ts is not None:
        return (
            "the omega column read as the Euler speed (theta_k - theta_k-1) / "
            f"{source.euler_ts * 1e3:.6g} ms"
        )
    return "the omega column read as the mean speed over each sample interval"


def refusal_words(why: Refusal) -> str:
    """Why an analysis refuses a run log, as the 'expected ...' part of an InputError:
    "expected at least 8 rows to analyse, got 5"."""
    match why:
        case UnequalColumns(t, u, omega):
            return f"expected t, u and omega of the same length, got {t}, {u} and {omega} rows"
        case TooFewRows(rows):
            return f"expected at least {MIN_ROWS} rows to analyse, got {rows}"
        case NotFinite(column):
            return f"expected finite numbers in {_named(column)}"
        case TooLarge(column, largest):
            return f"expected |{_named(column)}| below {MAX_MAGNITUDE:g}, got {largest:g}"
        case TimeNotIncreasing():
            return "expected t (s) to increase from row to row"
        case PeriodOutOfRange(period):
            lo, hi = TS_RANGE
            return (
                f"expected a sample period between {lo * 1e3:g} ms and {hi:g} s, got "
                f"{period:.3g} s (is t in seconds?)"
            )
        case SpeedStill(omega, glitch) if glitch:
            first = "row" if glitch == 1 else f"{glitch} rows"
            return (
                "expected the speed to change after the voltage changes; omega stays at "
                f"{omega:g} rad/s after the first {first}, a switch-on glitch"
            )
        case SpeedStill(omega):
            return (
                "expected the speed to change after the voltage changes; omega stays at "
                f"{omega:g} rad/s"
            )
        case ClockApart(span_us, span_t):
            return (
                f"expected t_us (us) to keep time with t (s) within {CLOCK_AGREE * 100:g} % "
                "(or two sample periods on a short log): over the log "
                f"t_us advances {span_us:.6g} s and t {span_t:.6g} s ({span_us / span_t:.3g} "
                "times as far); is one of them in other units? Fix it or leave t_us out"
            )
        case StillAngle(source):
            return (
                f"expected the wheel to turn; its angle ({angle_words(source)}) never changes "
                "in the log, so T, K and J cannot be found from it"
            )


def log_refusal(refused: LogRefused) -> InputError:
    """An analysis's refusal of a run log as the one-line InputError the CLI, the session
    and the report show: where, and why."""
    return InputError(refused.source, refused.line, refusal_words(refused.why))


__all__ = ["angle_words", "header_words", "log_refusal", "refusal_words"]
