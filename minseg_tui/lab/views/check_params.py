"""A model's parameters in words: the one writer of that line (:func:`params`), which the
check's sentences (:mod:`minseg_tui.lab.views.check_says`), the lab's screens, the report
and ``minseg-tui analyze`` (:mod:`minseg_tui.lab.views.check_text`) use.

Units: s, V, rad/s, rad; a time (T, the delays) is said in ms, as everywhere people read it
(:func:`~minseg_tui.quantities.format_constant`); the JSON keeps SI.
"""

from __future__ import annotations

from collections.abc import Mapping

from minseg_tui.model.check.effects import PARAM_UNITS
from minseg_tui.model.check.fit import T_BOUNDS
from minseg_tui.model.identify.identification import DETERMINED, determined
from minseg_tui.quantities import (
    NOT_DETERMINED,
    format_constant,
    format_constant_interval,
    format_number,
)


def bound_words(k: str, v: float) -> str | None:
    """For T on an end of the range the fit tries (2 ms to 3 s), what to print in place of
    its interval; None for any other parameter or value."""
    if k != "T":
        return None
    end = (
        "lower"
        if v <= T_BOUNDS[0] * (1.0 + 1e-6)
        else "upper"
        if v >= T_BOUNDS[1] * (1.0 - 1e-6)
        else None
    )
    if end is None:
        return None
    return (
        f"on the {end} end of the range the fit tries, {format_number(T_BOUNDS[0])}"
        f"-{format_number(T_BOUNDS[1])} s: {NOT_DETERMINED}"
    )


def interval_words(k: str, lo: float, hi: float, unit: str = "") -> str:
    """The 95 % interval (lo, hi) of parameter ``k`` in SI ``unit``: the moving average's
    lengths as whole samples (one length only when no other fits within the tolerance), "not
    determined by this log" when it spans more than a factor of ten (or reaches 0), else its
    ends in the unit people read it in (:func:`~minseg_tui.quantities.format_constant_interval`:
    T and the delays in ms)."""
    if k == "taps":
        a, b = round(lo), round(hi)
        if a == b:
            return f"{a} only: no other length fits as well"
        return f"{a} – {b} {unit}".rstrip()
    size = (abs(lo), abs(hi)) if hi < 0 else (lo, hi)
    if not determined((min(size), max(size))):
        return f"{NOT_DETERMINED}: it spans more than a factor of {DETERMINED:g}"
    return format_constant_interval(lo, hi, unit)


def value_words(k: str, v: float) -> str:
    """A parameter's value (SI) with its unit: the moving average's length as a whole number
    of samples, a time in ms ('T = 42.61 ms' is '42.61 ms')."""
    unit = PARAM_UNITS.get(k, "")
    if k == "taps":
        return f"{round(v)} {unit}".rstrip()
    return format_constant(v, unit)


def params(
    p: Mapping[str, float], intervals: Mapping[str, tuple[float, float]] | None = None
) -> str:
    """A model's parameters, each with its unit and, when given, its 95 % interval: 'T =
    42.61 ms (95 %: 42.10 – 43.02 ms), K = 1.996 rad/s/V'. The one writer of this line: the
    screens, the report, ``analyze`` and the check's own sentences use it. ``p`` and the
    intervals in SI (:data:`~minseg_tui.model.check.effects.PARAM_UNITS`)."""
    out = []
    for k, v in p.items():
        text = f"{k} = {value_words(k, v)}"
        bound = bound_words(k, v)
        if bound is not None:
            text += f" ({bound})"
        elif intervals and k in intervals:
            lo, hi = intervals[k]
            text += f" (95 %: {interval_words(k, lo, hi, PARAM_UNITS.get(k, ''))})"
        out.append(text)
    return ", ".join(out)
