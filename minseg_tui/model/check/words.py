"""The model check's result in words: the one place that names its gain figures and writes a
model's parameters (the lab's screens, the report and ``minseg-tui analyze`` read both), and
the full text for lab assistants (:func:`text`, ``minseg-tui analyze``).

Units: s, V, rad/s, rad; a time (T, the delays) is said in ms, as everywhere people read it
(:func:`~minseg_tui.quantities.format_constant`); the JSON keeps SI.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from minseg_tui.model.check.effects import PARAM_UNITS
from minseg_tui.model.check.figures import Gain
from minseg_tui.model.check.fit import T_BOUNDS
from minseg_tui.model.check.result import CheckResult
from minseg_tui.model.identify.identification import DETERMINED, determined
from minseg_tui.quantities import (
    NOT_DETERMINED,
    format_constant,
    format_constant_interval,
    format_number,
)


@dataclass(frozen=True)
class FigureWords:
    """How people are told one gain figure: ``name`` (in the details, the report's table and
    the CLI), its ``unit``, and ``said``: what it is in the lead sentence ("its error in the
    wheel's angle")."""

    name: str
    unit: str
    said: str


FIGURES: dict[str, FigureWords] = {
    "angle_rms": FigureWords("rms error of the angle", "rad", "its error in the wheel's angle"),
    "heldout_rmse": FigureWords(
        "speed error on held-out steps", "rad/s", "its speed error on steps it was not fitted to"
    ),
    "above_noise": FigureWords(
        "speed error above the measured noise", "rad/s", "its speed error beyond the noise"
    ),
    "above_floor": FigureWords(
        "speed error above the encoder's noise floor",
        "rad/s",
        "its speed error beyond the encoder's noise",
    ),
    "rmse": FigureWords("rms error of the speed", "rad/s", "its rms speed error"),
}
"""The model check's gain figures (``gain`` keys without their baseline_/extended_ prefix,
:func:`stem`), the most telling first: the one table of their names."""


def stem(key: str) -> str:
    """A gain figure's key without its model: 'heldout_extended_rmse' -> 'heldout_rmse',
    'baseline_angle_rms' -> 'angle_rms'."""
    return key.replace("baseline_", "").replace("extended_", "")


def figure_words(key: str) -> FigureWords:
    """The words of gain figure ``key`` (either model's key, or its :func:`stem`)."""
    s = stem(key)
    return FIGURES.get(s, FigureWords(s, "", s))


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


def figure(gain: Gain | Mapping[str, float | None], key: str) -> tuple[float | None, float | None]:
    """The first-order and the extended model's value of gain figure ``key`` (either
    model's key, or its :func:`stem`): the keys are 'baseline_<stem>' and 'extended_<stem>',
    or 'heldout_baseline_rmse' and 'heldout_extended_rmse'. None where the log does not give
    it. ``gain``: the check's record, or its JSON as a session keeps it."""
    g = gain.to_dict() if isinstance(gain, Gain) else gain
    s = stem(key)
    for b, e in (
        (f"baseline_{s}", f"extended_{s}"),
        (
            s.replace("heldout_", "heldout_baseline_", 1),
            s.replace("heldout_", "heldout_extended_", 1),
        ),
    ):
        if b in g or e in g:
            return g.get(b), g.get(e)
    return None, None


def _pair(r: CheckResult, key: str) -> str:
    """A figure's name and 'baseline -> extended' with its unit (three digits)."""
    words = figure_words(key)
    b, e = figure(r.gain, key)
    if b is None:
        return f"{words.name} n/a"
    if r.finding.cause == "none" or e is None:
        return f"{words.name} {_n(b)} {words.unit}"
    if e == 0 and b > 0 and stem(key).startswith("above"):
        rms = r.gain.extended_rmse
        return (
            f"{words.name} {_n(b)} -> 0 {words.unit}, the extended model's rms error "
            f"({_n(rms)} {words.unit}) is no larger than the noise"
        )
    return f"{words.name} {_n(b)} -> {_n(e)} {words.unit}"


def _n(x: float | None) -> str:
    """A figure of the gain with three significant digits, trailing zeros kept."""
    return format_number(x, 3) if x is not None else "n/a"


CAVEATS = "What the check cannot say here:"
"""The heading of the check's caveats (``analyze`` and the report)."""

ANOMALIES = "Anomalies (reported, not counted as causes):"
"""The heading of the anomalies (``analyze`` and the report)."""


def _over(r: CheckResult) -> str:
    """Which rows the rms and fit figures cover: all of them, or those the fit used."""
    n = int(r.t.size)
    used = r.baseline.rows or n
    if used >= n:
        return f"over all {n} rows"
    return f"over the {used} of {n} rows the fit used ({n - used} left out, see the anomalies)"


def text(r: CheckResult) -> str:
    """The human report: how the log was sampled, the baseline, where it deviates, the
    cause and its evidence, the extended model, the gain (the figure that means most
    first, and why), what the check cannot say, the anomalies."""
    b, e, f, g = r.baseline, r.extended, r.finding, r.gain
    lines = []
    if r.sampling is not None:
        lines.append(f"Log: {r.sampling.text()}")
    lines += [
        f"Baseline (first order): {params(b.params, b.intervals)}",
        f"  simulated on the measured input: rmse {b.rmse:.3f} rad/s, fit {b.fit_percent:.1f} %"
        f" ({_over(r)})",
        f"Where it deviates: {r.where}",
    ]
    for d in r.deviations:
        lines.append(
            f"  {d.region.replace('_', ' '):<20} {d.rows:6d} rows  rms {d.rms:.3f} rad/s"
            f"  mean {d.mean:+.3f} rad/s"
        )
    lines.append(f"Cause: {f.cause}")
    lines.append(f"  {f.evidence}")
    for o in f.others:
        lines.append(f"  also: {o.cause} ({params(o.params)}): {o.evidence}")
    if f.cause != "none":
        lines.append(f"Extended model ({e.model}): {params(e.params, e.intervals)}")
        lines.append(f"  rmse {e.rmse:.3f} rad/s, fit {e.fit_percent:.1f} % ({_over(r)})")
    else:
        lines.append("Extended model: none needed (it is the baseline)")
    if r.lead is not None:
        lines.append(f"Gain: {_pair(r, r.lead.figure)} (leads because {r.lead.why})")
    rest = []
    floor = g.noise_floor
    noise = g.noise
    if floor is not None:
        counts = r.sampling.floor if r.sampling is not None else None
        taps = round(e.params.get("taps", 1.0))
        over = (
            f" (the counts' {_n(counts)} rad/s over the {taps}-sample average)"
            if counts is not None and taps > 1 and floor < counts
            else ""
        )
        rest.append(f"noise floor {_n(floor)} rad/s{over}")
    if noise is not None:
        rest.append(f"scatter {_n(noise)} rad/s")
    rest.append(_pair(r, "rmse"))
    above = g.baseline_above_noise
    if above is not None and (above > 0 or g.extended_above_noise):
        rest.append(_pair(r, "above_noise"))
    if g.baseline_above_floor is not None:
        rest.append(_pair(r, "above_floor"))
    rest.append(_pair(r, "angle_rms"))
    if g.heldout_baseline_rmse is not None:
        rest.append(_pair(r, "heldout_rmse"))
    if f.cause != "none":
        rest.append(
            f"rmse {g.rmse_reduction_percent:.1f} % lower, fit {g.fit_percent_gain:+.1f} points"
        )
    held = (
        ", the held-out error over the rows of the steps each fit left out"
        if g.heldout_baseline_rmse is not None
        else ""
    )
    lines.append("  " + "; ".join(rest) + f" (rms, noise and fit figures {_over(r)}{held})")
    if f.caveats:
        lines.append(CAVEATS)
        lines.extend(f"  - {c.text}" for c in f.caveats)
    if r.anomalies:
        lines.append(ANOMALIES)
        lines.extend(f"  - {a.text}" for a in r.anomalies)
    return "\n".join(lines)
