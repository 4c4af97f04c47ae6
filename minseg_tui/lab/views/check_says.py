"""The model check's sentences, made from its typed records outside the model: the one place
that words what the check found (the anomalies so far), for ``minseg-tui analyze`` (its
text and its ``--json``), the lab's screen and the report alike.

The model (:mod:`minseg_tui.model.check`) gives records holding the numbers a sentence
needs (which rows, when, how large); each function here turns one kind of record into the
sentence people read. :func:`as_json` is ``analyze --json``'s object, its sentences from
here. Units: s, V, rad/s, ms as each sentence says.
"""

from __future__ import annotations

import numpy as np

from minseg_tui.model.check import CheckResult
from minseg_tui.model.check import anomalies as an


def _miss(a: an.Anomaly, f: an.ModelMiss) -> str:
    times = ", ".join(f"{x:.2f}" for x in f.times[:6]) + (" ..." if len(f.times) > 6 else "")
    edges = f"of the {f.of_edges}" if f.of_edges else f.edges
    what = (
        "the response looks shifted in time (by "
        + ", ".join(f"{x:+.0f}" for x in f.shifts_ms[:6])
        + (" ..." if len(f.shifts_ms) > 6 else "")
        + " ms)"
        if f.shifts_ms
        else "the speed departs from the model's simulation the same way"
    )
    return (
        f"{what} after {len(f.times)} {edges} edges (t = {times} s): a departure that comes back "
        "edge after edge is what the model misses there, not a hand on the wheel; those rows "
        "stay in the fit"
    )


def _hand(a: an.Anomaly, f: an.Hand) -> str:
    size, level = a.size, f.level
    word = "drops" if size * np.sign(level or 1.0) < 0 else "rises"
    share = f" ({100 * abs(size / level):.0f} %)" if level else ""
    if f.left == "restarted":
        out = (
            f"the rows from t = {f.left_t0:.3f} s to {f.left_t1:.3f} s (the departure "
            "until the hand let go) were left out of the fit; from there the model picks up "
            "from the speed the wheel was left at, so its way back stays in the fit"
        )
    elif f.left == "those":
        out = "those rows were left out of the fit"
    else:
        out = (
            f"the rows from t = {f.left_t0:.3f} s to {f.left_t1:.3f} s (the departure, "
            "and the wheel's way back until the model meets the speed again) were left out of "
            "the fit"
        )
    return (
        f"from t = {a.t:.3f} s to {a.t_end:.3f} s the speed {word} by {abs(size):.3g} rad/s{share} "
        f"while the input stays at {f.u:g} V, and comes back: something other than the "
        f"input moved the wheel (a hand on it, a snag); {out}"
    )


def anomaly(a: an.Anomaly) -> str:
    """The sentence of anomaly ``a`` for a student: what the log shows, where, and what the
    check did with those rows."""
    f = a.facts
    if isinstance(f, an.StartsMoving):
        how = (
            "its initial speed was fitted"
            if f.fitted
            else f"taken as the steady speed under its first input ({f.u0:g} V)"
        )
        return f"the log starts with the wheel already turning; {how}"
    if isinstance(f, an.WildSample):
        return (
            f"row {a.row} (t = {a.t:.3f} s): the speed jumps by {a.size:+.2f} rad/s for one sample "
            "and straight back, as a misread encoder count does; it was left out of the fit"
        )
    if isinstance(f, an.Creep):
        word = "creeps up" if a.size > 0 else "sags"
        return (
            f"after each step has settled the speed still {word} by about {abs(a.size):.1f} % "
            "over the rest of the step (warming up, a battery or a load that changes); "
            "no first-order model does that, so it is not counted as a cause"
        )
    if isinstance(f, an.LateStep):
        return (
            f"the step at row {a.row} (t = {a.t:.3f} s) acts about {a.size:+.0f} ms "
            "from its sample time compared with the others: it started between samples"
        )
    if isinstance(f, an.Gaps):
        return (
            f"{f.count} gap(s) in the sample times, the longest {a.size:.0f} ms before row {a.row} "
            f"(nominal {f.nominal_ms:.1f} ms, the clock otherwise regular): about {f.lost} "
            "sample(s) were lost; the simulation uses the real times"
        )
    if isinstance(f, an.Hand):
        return _hand(a, f)
    if isinstance(f, an.ModelMiss):
        return _miss(a, f)
    if isinstance(f, an.LoggingArtefact):
        out = f"row {f.first}" if f.last <= f.first else f"rows {f.first}-{f.last}"
        return (
            f"row {f.at} (t = {f.t_at:.3f} s), right after a gap of {f.gap_ms:.0f} ms in the "
            f"sample times: the speed jumps by {a.size:+.3g} rad/s and straight back, as when the "
            "logger stalls and reads the encoder and its clock at different moments (a logging "
            f"artefact, not the wheel); {out} left out of the fit"
        )
    if isinstance(f, an.StartGlitch):
        return (
            f"the first {f.rows} row(s) (to t = {f.t_last:.3f} s) read up to {a.size:.3g} rad/s "
            "and the next one close to 0 with the input unchanged: a glitch as the logger "
            "starts, not the wheel; left out of the fit"
        )
    return (
        "the speed is averaged over several samples, so a read the logger got wrong across a "
        f"gap in the sample times stays in it for as many rows: the {f.taps + 1} rows after each "
        f"of the {int(a.size)} gap(s) (the first at t = {a.t:.3f} s) were left out of the fit"
    )


class _Says:
    """The sentences here, as the result's JSON asks for them (:class:`~.result.Says`)."""

    anomaly = staticmethod(anomaly)


def as_json(r: CheckResult) -> dict[str, object]:
    """The JSON object of ``minseg-tui analyze --json``, its sentences made here."""
    return r.to_dict(_Says())
