"""The model check's result in words, made from its records outside the model: the one
place that names its gain figures (the lab's screens, the report and ``minseg-tui analyze``
read them), says a figure's first-order and extended values, and writes the full text for
lab assistants (:func:`text`, ``minseg-tui analyze``). A model's parameters are written by
:func:`minseg_tui.lab.views.check_params.params` (the check's sentences use it too).

Units: s, V, rad/s, rad; a time (T, the delays) is said in ms, as everywhere people read it
(:func:`~minseg_tui.quantities.format_constant`); the JSON keeps SI.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from minseg_tui.lab.views.check_params import params
from minseg_tui.lab.views.check_says import (
    anomaly,
    caveat,
    evidence,
    lead_why,
    other,
    region_words,
    sampling,
    speed_lag_said,
    where,
)
from minseg_tui.model.check import CheckResult, Gain
from minseg_tui.model.check.deviations import Deviation
from minseg_tui.quantities import MISSING, format_number


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


GAIN_DIGITS = 3
"""Significant digits of a gain figure, wherever one is shown (the CLI's text, the screen's
details, the report's table, the lead's sentence)."""


@dataclass(frozen=True)
class Compared:
    """One gain figure of both models, its values written once for every place that shows
    the before and after (``analyze``'s text, the screen's details, the report's table):
    ``words`` (its name and unit); ``b`` and ``e`` the first-order and the extended model's
    value in that unit (``e`` None when the log does not give it), ``first`` and
    ``extended`` the same written with :data:`GAIN_DIGITS` digits and no unit (``extended``
    None when no cause is named or the log does not give it); ``to_noise``: the extended
    model leaves none of this error above the noise where the first-order model leaves
    some."""

    words: FigureWords
    b: float
    e: float | None
    first: str
    extended: str | None
    to_noise: bool

    def with_unit(self, value: str) -> str:
        """``value`` (:attr:`first` or :attr:`extended`) with the figure's unit, as
        :func:`~minseg_tui.quantities.format_value` writes it (no unit after MISSING)."""
        return value if value == MISSING else f"{value} {self.words.unit}".rstrip()


def compared(gain: Gain | Mapping[str, float | None], key: str, named: bool) -> Compared | None:
    """Gain figure ``key`` (either model's key, or its :func:`stem`) of both models, for a
    check that named a cause (``named``) or not; None when the log does not give it."""
    b, e = figure(gain, key)
    if b is None:
        return None
    words = figure_words(key)
    if not named or e is None:
        return Compared(words, b, e, format_number(b, GAIN_DIGITS), None, False)
    to_noise = e == 0 and b > 0 and stem(key).startswith("above")
    return Compared(
        words, b, e, format_number(b, GAIN_DIGITS), format_number(e, GAIN_DIGITS), to_noise
    )


def _pair(r: CheckResult, key: str) -> str:
    """A figure's name and 'baseline -> extended' with its unit (:func:`compared`)."""
    c = compared(r.gain, key, r.finding.cause != "none")
    if c is None:
        return f"{figure_words(key).name} n/a"
    name, unit = c.words.name, c.words.unit
    if c.extended is None:
        return f"{name} {c.first} {unit}"
    if c.to_noise:
        rms = r.gain.extended_rmse
        return (
            f"{name} {c.first} -> 0 {unit}, the extended model's rms error "
            f"({_n(rms)} {unit}) is no larger than the noise"
        )
    return f"{name} {c.first} -> {c.extended} {unit}"


def _n(x: float | None) -> str:
    """A figure of the gain with three significant digits, trailing zeros kept."""
    return format_number(x, GAIN_DIGITS) if x is not None else "n/a"


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


def deviation_row(d: Deviation) -> str:
    """One row of the full text's table of where the model deviates: the region in the
    words the sentences use ('after the rise' on a log with one, :func:`region_words`),
    its rows, and the rms and mean of the speed's error there (rad/s)."""
    return (
        f"  {region_words(d.region, d.edges):<20} {d.rows:6d} rows  rms {d.rms:.3f} rad/s"
        f"  mean {d.mean:+.3f} rad/s"
    )


def text(r: CheckResult, lag: float | None = None) -> str:
    """The human report: how the log was sampled, the baseline, where it deviates, the
    cause and its evidence, the extended model, the gain (the figure that means most
    first, and why), what the check cannot say, the anomalies. ``lag`` (s): how late the
    log's speed column runs behind its angle column
    (:func:`~minseg_tui.lab.views.check_says.late_speed`), None when it does not."""
    b, e, f, g = r.baseline, r.extended, r.finding, r.gain
    lines = []
    if r.sampling is not None:
        lines.append(f"Log: {sampling(r.sampling, lag)}")
    lines += [
        f"Baseline (first order): {params(b.params, b.intervals)}",
        f"  simulated on the measured input: rmse {b.rmse:.3f} rad/s, fit {b.fit_percent:.1f} %"
        f" ({_over(r)})",
        f"Where it deviates: {where(r.deviations)}",
    ]
    lines += [deviation_row(d) for d in r.deviations]
    lines.append(f"Cause: {f.cause}")
    lines.append(f"  {evidence(f)}")
    for o in f.others:
        lines.append(f"  also: {o.cause} ({params(o.params)}): {other(o)}")
    if f.cause != "none":
        lines.append(f"Extended model ({e.model}): {params(e.params, e.intervals)}")
        lines.append(f"  rmse {e.rmse:.3f} rad/s, fit {e.fit_percent:.1f} % ({_over(r)})")
    else:
        lines.append("Extended model: none needed (it is the baseline)")
    if r.lead is not None:
        lines.append(f"Gain: {_pair(r, r.lead.figure)} (leads because {lead_why(r.lead)})")
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
    cannot = [caveat(c) for c in f.caveats]
    if lag is not None:
        cannot.append(f"{speed_lag_said(lag)}; identify fits the angle")
    if cannot:
        lines.append(CAVEATS)
        lines.extend(f"  - {c}" for c in cannot)
    if r.anomalies:
        lines.append(ANOMALIES)
        lines.extend(f"  - {anomaly(a)}" for a in r.anomalies)
    return "\n".join(lines)
