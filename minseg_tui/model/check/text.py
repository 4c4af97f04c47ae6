"""The model check's result as the text a student reads (``minseg-tui analyze``)."""

from __future__ import annotations

from minseg_tui.model.check.effects import PARAM_UNITS
from minseg_tui.model.check.fit import T_BOUNDS
from minseg_tui.model.check.result import CheckResult
from minseg_tui.model.identify.identification import DETERMINED, determined
from minseg_tui.quantities import NOT_DETERMINED, format_interval, format_number

_FIGURES: dict[str, tuple[str, str]] = {
    "extended_angle_rms": ("angle error", "rad"),
    "baseline_angle_rms": ("angle error", "rad"),
    "heldout_extended_rmse": ("error on held-out steps", "rad/s"),
    "heldout_baseline_rmse": ("error on held-out steps", "rad/s"),
    "extended_above_noise": ("error above the noise", "rad/s"),
    "baseline_above_noise": ("error above the noise", "rad/s"),
    "extended_above_floor": ("error above the floor", "rad/s"),
    "baseline_above_floor": ("error above the floor", "rad/s"),
    "extended_rmse": ("rms error", "rad/s"),
    "baseline_rmse": ("rms error", "rad/s"),
}


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


def interval_words(
    k: str, lo: float, hi: float, unit: str = "", digits: int = 3, sep: str = "-"
) -> str:
    """The 95 % interval (lo, hi) of parameter ``k`` in ``unit``: the moving average's lengths
    as whole samples (one length only when no other fits within the tolerance), "not
    determined by this log" when it spans more than a factor of ten (or reaches 0), else its
    ends (:func:`~minseg_tui.quantities.format_interval`)."""
    if k == "taps":
        a, b = round(lo), round(hi)
        if a == b:
            return f"{a} only: no other length fits as well"
        return f"{a}{sep}{b} {unit}".rstrip()
    size = (abs(lo), abs(hi)) if hi < 0 else (lo, hi)
    if not determined((min(size), max(size))):
        return f"{NOT_DETERMINED}: it spans more than a factor of {DETERMINED:g}"
    return format_interval(lo, hi, unit, digits=digits, sep=sep)


def value_words(k: str, v: float) -> str:
    """A parameter's value: the moving average's length as a whole number of samples."""
    return f"{round(v)}" if k == "taps" else format_number(v)


def _params(p: dict[str, float], intervals: dict[str, tuple[float, float]] | None = None) -> str:
    """Each parameter with its unit and 95 % interval; a time under a second in ms, as the
    evidence sentences and ``identify`` write it (the JSON keeps seconds)."""
    out = []
    for k, v in p.items():
        unit, scale = PARAM_UNITS.get(k, ""), 1.0
        if unit == "s" and abs(v) < 1.0:
            unit, scale = "ms", 1e3
        s = f"{k} = {value_words(k, v * scale)} {unit}".rstrip()
        bound = bound_words(k, v)
        if bound is not None:
            s += f" ({bound})"
        elif intervals and k in intervals:
            lo, hi = intervals[k]
            s += f" (95 %: {interval_words(k, lo * scale, hi * scale)})"
        out.append(s)
    return ", ".join(out)


def _pair(r: CheckResult, key: str) -> str:
    """'baseline -> extended' of one figure, with its unit."""
    g = r.gain
    b = g.get(key.replace("extended", "baseline"))
    e = g.get(key.replace("baseline", "extended"))
    unit = _FIGURES.get(key, ("", ""))[1]
    if b is None:
        return "n/a"
    if r.finding.cause == "none" or e is None:
        return f"{b:.3g} {unit}"
    if e == 0 and b > 0 and "above" in key:
        rms = g.extended_rmse
        return (
            f"{b:.3g} -> 0 {unit}, the extended model's rms error ({rms:.3g} {unit}) is no "
            "larger than the noise"
        )
    return f"{b:.3g} -> {e:.3g} {unit}"


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
        f"Baseline (first order): {_params(b.params, b.intervals)}",
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
        lines.append(f"  also: {o.cause} ({_params(o.params)}): {o.evidence}")
    if f.cause != "none":
        lines.append(f"Extended model ({e.model}): {_params(e.params, e.intervals)}")
        lines.append(f"  rmse {e.rmse:.3f} rad/s, fit {e.fit_percent:.1f} % ({_over(r)})")
    else:
        lines.append("Extended model: none needed (it is the baseline)")
    if r.lead is not None:
        name = _FIGURES.get(r.lead.figure, (r.lead.figure, ""))[0]
        lines.append(f"Gain: {name} {_pair(r, r.lead.figure)} (leads because {r.lead.why})")
    rest = []
    floor = g.noise_floor
    noise = g.noise
    if floor is not None:
        counts = r.sampling.floor if r.sampling is not None else None
        taps = round(e.params.get("taps", 1.0))
        over = (
            f" (the counts' {counts:.3g} rad/s over the {taps}-sample average)"
            if counts is not None and taps > 1 and floor < counts
            else ""
        )
        rest.append(f"noise floor {floor:.3g} rad/s{over}")
    if noise is not None:
        rest.append(f"scatter {noise:.3g} rad/s")
    rest.append(f"rms error {_pair(r, 'extended_rmse')}")
    above = g.baseline_above_noise
    if above is not None and (above > 0 or g.extended_above_noise):
        rest.append(f"above the noise {_pair(r, 'extended_above_noise')}")
    if g.baseline_above_floor is not None:
        rest.append(f"above the floor {_pair(r, 'extended_above_floor')}")
    rest.append(f"angle error {_pair(r, 'extended_angle_rms')}")
    if g.heldout_baseline_rmse is not None:
        rest.append(f"on held-out steps {_pair(r, 'heldout_extended_rmse')}")
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
        lines.append("What the check cannot say here:")
        lines.extend(f"  - {c.text}" for c in f.caveats)
    if r.anomalies:
        lines.append("Anomalies (reported, not counted as causes):")
        lines.extend(f"  - {a.text}" for a in r.anomalies)
    return "\n".join(lines)
