"""The model check's sentences, made from its typed records outside the model: the one place
that words what the check found (the evidence of the causes, the caveats, the anomalies), for ``minseg-tui analyze`` (its
text and its ``--json``), the lab's screen and the report alike.

The model (:mod:`minseg_tui.model.check`) gives records holding the numbers a sentence
needs (which rows, when, how large); each function here turns one kind of record into the
sentence people read. :func:`as_json` is ``analyze --json``'s object, its sentences from
here. A table that words one record for both audiences (the lab assistant: ``analyze``; the
student: the lab's screen and the report) holds the two wordings side by side, one row a
record (:class:`Said`); where the two differ in more than their words (another order, other
clauses), a function each says it (``reason``/``reason_plain``, ``caveat``/``caveat_plain``,
``lost``/``lost_plain``). Units: s, V, rad/s, ms as each sentence says.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Generic, TypeVar

import numpy as np

from minseg_tui.lab.views.check_params import params
from minseg_tui.model.check import CheckResult
from minseg_tui.model.check import anomalies as an
from minseg_tui.model.check import effects as fx
from minseg_tui.model.check import result as rs
from minseg_tui.model.check.decide import MIN_REDUCTION, Reason, ReasonKind
from minseg_tui.model.check.deviations import Deviation
from minseg_tui.model.check.evidence import Lack, Lacks
from minseg_tui.model.check.figures import CloseUp, Lead, Window
from minseg_tui.model.check.sampling import CountFrom, Sampling
from minseg_tui.model.identify.identification import LAG_SAMPLES
from minseg_tui.model.runlog import RunLog, speed_lag
from minseg_tui.quantities import format_constant, format_number

W = TypeVar("W")


@dataclass(frozen=True)
class Said(Generic[W]):
    """One record's words for each of the check's two audiences, side by side: ``assistant``,
    what ``minseg-tui analyze`` says to the lab assistant, in the check's own terms (the
    whitened residual, a pole); ``student``, what the lab's screen and the report say to a
    student (the error, a second time constant); None: the assistant's words serve both."""

    assistant: W
    student: W | None = None

    def to(self, plain: bool) -> W:
        """The words for a student (``plain``) or for the lab assistant."""
        return self.student if plain and self.student is not None else self.assistant


@dataclass(frozen=True)
class CauseWords:
    """A cause of the model check in words: ``label``, a few words for people ('dry
    friction'); ``everyday``, what a student who has not met it is told; ``short``, two or
    three words ('with ... added', 'or ...'); ``within_sample``, what it is when its time is
    under a quarter of the sample period ('a delay'; '' for a cause without that test,
    :attr:`~minseg_tui.model.check.effects.Candidate.within_sample`)."""

    label: str
    everyday: str
    short: str
    within_sample: str = ""


WINDING_LAG_MAX = 0.020
"""The longest second pole (s) the words put down to the armature's inductance. A small DC
motor's L/R is well under it: the UBC motor of ../shared/data/real-motors (its PROVENANCE:
L = 1.2 mH, R = 2.77 ohm) has 0.43 ms. A longer pole is called a second lag, its source
unnamed."""


CAUSE_WORDS: dict[str, CauseWords] = {
    "coulomb_friction": CauseWords(
        "dry friction",
        "dry friction: a constant braking torque (for example from a gearbox or the motor's "
        "brushes), so the wheel stops sooner than the model says (the model only knows a "
        "friction that shrinks with the speed)",
        "dry friction",
    ),
    "dead_time": CauseWords(
        "dead time",
        "a delay: the motor answers a little after the command, as if the voltage arrived late",
        "a delay",
        within_sample="a delay",
    ),
    "velocity_filter": CauseWords(
        "averaged speed (velocity filter)",
        "the logged speed is an average over several samples, which turns every jump into a ramp",
        "an averaged speed",
    ),
    "coast_on_zero": CauseWords(
        "coasting at zero command",
        "at 0 V the driver lets the wheel spin freely instead of braking it, so it runs down "
        "at its own pace, not at the pace of a braked motor",
        "coasting at 0 V",
    ),
    "second_pole": CauseWords(
        "second pole",
        "the current needs time to build up in the motor's winding, so the speed starts "
        "rising gently instead of at once",
        "a slow current build-up",
        within_sample="a pole",
    ),
    "current_limit": CauseWords(
        "current limit",
        "the driver limits the current, so the wheel can only speed up so fast at first",
        "a current limit",
    ),
}
"""Every cause of :data:`~minseg_tui.model.check.effects.CANDIDATES` in words, by its contract
name (the model holds its numbers, this its words)."""


def in_words(model: str, plain: bool = False) -> str:
    """A model or cause name in words: "first_order+coulomb_friction" -> "first order + dry
    friction"; ``none`` stays "none". ``plain``: told to a student, a second pole as
    :data:`PLAIN_LABELS` says (a second-year student has met time constants, not poles)."""
    return " + ".join(
        "first order"
        if p == "first_order"
        else PLAIN_LABELS[p]
        if plain and p in PLAIN_LABELS
        else (CAUSE_WORDS[p].label if p in CAUSE_WORDS else p)
        for p in model.split("+")
    )


PLAIN_LABELS: dict[str, str] = {
    "second_pole": "second time constant",
    "velocity_filter": "averaged speed reading",
    "coast_on_zero": "coasting at 0 V",
}
"""The labels of :data:`CAUSE_WORDS` a student is told otherwise (the lab's details and the
report; the CLI keeps the labels): a second-year student has met time constants, not poles,
and a voltage of 0 V, not a "velocity filter" or a "zero command"."""


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
        # identify reads a creep over another window (from 4 of its rise's T): say this one
        return (
            f"after each step has settled the speed still {word} by about {abs(a.size):.1f} % "
            f"over the rest of the step, read from {format_number(f.after, 2)} s after the "
            "step, where the check's chosen model has settled (past "
            f"{an.CREEP_SETTLE:g} of its time constants, with any delay, and "
            f"{an.CREEP_MIN_ROWS} samples), to its end (warming up, a battery or a load that "
            "changes); "
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
        if f.runs_on:
            # the speed column runs on across the gap (a copy of an n20 log with three rows
            # dropped: 8.98 rad/s on both sides) where the model, reading the gap as one long
            # sample, is off by -27.8 rad/s: told as "the speed jumps", which it does not
            return (
                f"row {f.at} (t = {f.t_at:.3f} s), right after a gap of {f.gap_ms:.0f} ms in the "
                f"sample times: the speed reads on as around it ({f.level:.3g} rad/s), where the "
                f"simulation, taking the gap as one long sample, is off by {a.size:+.3g} rad/s: "
                "rows were lost whole, each read over its own period (a logging artefact, not "
                f"the wheel); {out} left out of the fit"
            )
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


SMOOTH: dict[rs.Alike, Said[str]] = {
    "filters": Said(
        "this speed is smooth, not a difference of encoder counts: an averaging filter on the "
        "speed and an extra pole in the motor look alike here, so the log cannot tell them apart; "
        "the fit prefers the one named",
        student="This speed is smooth, not counted in encoder steps: an averaged speed and a "
        "second time constant in the motor smooth it alike, so this run cannot tell them apart; "
        "the check prefers the one named.",
    ),
    "pole_measured": Said(
        "this speed is smooth, not a difference of encoder counts: an average of the speed and a "
        "first-order filter of it (a pole on the measurement) are both filters of the reading, and "
        "the pole named acts there; the fit prefers it",
        student="This speed is smooth, not counted in encoder steps: an averaged speed and a lag "
        "in the speed reading both smooth it, and the lag named acts there; the check prefers it.",
    ),
}
"""Why a smooth speed column cannot tell the causes that act on the reading apart (the
student's words a whole sentence)."""

TELL_APART: dict[frozenset[str], Said[str]] = {
    frozenset({"dead_time", "second_pole"}): Said(
        "more steps, or finer speed readings in the first samples after each step (more counts per "
        "sample, a faster sampling where the counts allow it), would (a delay leaves those samples "
        "flat and then turns a corner, a pole bends smoothly from the start)",
        student="more steps, or finer speed readings in the first samples after each step, would "
        "(a delay leaves those samples flat and then turns a corner, a second time constant bends "
        "smoothly from the start)",
    ),
    frozenset({"dead_time", "velocity_filter"}): Said(
        "the raw encoder counts or more steps would (a delay shifts the rise, an average turns it "
        "into a ramp)"
    ),
    frozenset({"velocity_filter", "second_pole"}): Said(
        "the raw encoder counts would (an average of the speed acts on the measurement only, a "
        "pole on the motor)",
        student="the raw encoder counts would (an average acts on the speed reading only, a second "
        "time constant on the motor)",
    ),
    frozenset({"coulomb_friction", "coast_on_zero"}): Said(
        "a step down to a small voltage other than 0 would (dry friction slows the wheel there "
        "too, a coast only at 0)"
    ),
    frozenset({"coulomb_friction", "current_limit"}): Said(
        "steps of several sizes would (a cap limits the big steps only, friction takes the same "
        "volts off every level)"
    ),
    frozenset({"coast_on_zero", "second_pole"}): Said(
        "steps down to a small voltage other than 0 would (a coast acts only at 0)"
    ),
}
"""What kind of log would tell two causes apart, in words, for the pairs a log often
cannot tell (the first pair that sets a cause only one model holds against a cause only
the other holds speaks; a pair not here gets the check's general words). A student is told
of a second time constant where the assistant is told of a pole."""


def what_would_tell(a: tuple[str, ...], b: tuple[str, ...], plain: bool = False) -> str:
    """What kind of log would tell causes ``a`` from ``b`` apart, in words (``plain``: told
    to a student)."""
    only_a, only_b = set(a) - set(b), set(b) - set(a)
    for pair, words in TELL_APART.items():
        # a pair that sets a cause of one against a cause of the other
        if pair & only_a and pair & only_b:
            return words.to(plain)
    return (
        "steps of other sizes, a step down to a small voltage and a faster sampling would "
        "show more of each"
    )


LACKS: dict[Lack, str] = {
    "rise": "the log has no step up to show it",
    "drop_to_zero": "the command never drops to zero while the wheel turns",
    "two_levels": "the log has one driven level and no step-down",
}
"""What a log lacks to show a cause, in words (one size both ways: :func:`lacks`)."""


def lacks(w: Lacks) -> str:
    """What a log lacks to show a cause, in words."""
    if w.lack == "one_size":
        return (
            f"the log drives at one size of voltage only ({w.size:.3g} V, forward and reversed) "
            "and never lowers it to a smaller one"
        )
    return LACKS[w.lack]


REFUSAL: dict[fx.RefusalKind, str] = {
    "ramp_under_sample": "the ramp that cap makes would last less than one sample period after "
    "every step: no two samples lie on it, so this log cannot show a cap",
    "no_slower": "it would be a coast no slower than braking",
}
"""A cause's own reason not to be named, in words (an average's scatter: :func:`refusal`)."""


def refusal(r: fx.Refusal) -> str:
    """A cause's own reason not to be named, in words."""
    if r.kind == "scatters":
        return (
            f"the speed scatters {r.scatter:.3g} rad/s around that model's simulation, far more "
            f"than an average of counts over {r.taps} samples leaves ({r.floor:.3g} rad/s)"
        )
    return REFUSAL[r.kind]


REASON: dict[ReasonKind, Said[str]] = {
    "T_bound": Said("the time constant T it needs sits on the bound of its range"),
    "worse_raw": Said("it matches the measured speed itself worse than the first-order model"),
    "others_explain": Said("the other causes explain the log as well without it"),
    "whitened_only": Said(
        "it cuts the whitened residual but not the error of the speed itself",
        student="it improves the check's weighed error but not the error of the speed itself",
    ),
}
"""Why a clear cause was left out, in words, where the sentence has no figure
(:func:`reason` for the others)."""


def _within(r: Reason, what: str) -> str:
    """A cause that acts within the first sample after a step (``what`` it is, in words)."""
    return (
        f"{what} of {1e3 * r.value:.3g} ms, under a quarter of the "
        f"{1e3 * r.ts:.3g} ms sample period, acts within the first sample after a step: "
        "the samples show only a shift in time that the sampling's own lateness gives too"
    )


def reason(r: Reason) -> str:
    """Why a clear cause was left out, in words (every figure from the selection)."""
    if r.kind == "bound":
        return f"its parameter sits on the {r.side} bound of its range"
    if r.kind == "refused" and r.refusal is not None:
        return refusal(r.refusal)
    if r.kind == "within_sample":
        return _within(r, CAUSE_WORDS[r.cause].within_sample)
    if r.kind == "below_noise":
        return (
            f"nowhere does it move the simulated speed, held over {r.rows} samples, by more "
            f"than {r.shown:.3g} rad/s, within what the speed's noise leaves over as many samples "
            f"({r.level:.3g} rad/s): the log cannot show it"
        )
    if r.kind == "too_small":
        return (
            f"nowhere does it move the simulated speed, held over {r.rows} samples, by more "
            f"than {r.shown:.3g} rad/s, {100 * r.shown / r.top:.2g} % of the {r.top:.3g} rad/s "
            "the speed reaches: any model of a real motor misses by that much (a load that "
            "ripples, drag that is not quite viscous, the encoder's timing), and a gain so "
            "small is not a cause of its own"
        )
    if r.kind == "swapped":
        return f"{r.causes[0]} explains the log better together with the others"
    if r.kind == "together":
        return f"{' and '.join(r.causes)} together explain the log better"
    if r.kind == "third_small":
        return (
            f"beside {' and '.join(r.causes)} it moves the simulated speed, held over "
            f"{r.rows} samples, by {r.shown:.3g} rad/s at most, under "
            f"{100 * r.share:.0f} % of what each of them moves it: a third cause so "
            "small is what any pair of causes leaves of a real motor, not a cause of its own"
        )
    if r.kind == "taken_over":
        return (
            f"{' and '.join(r.causes)}, fitted again without it, "
            f"{'takes' if len(r.causes) == 1 else 'take'} over nearly all it does: "
            f"the two models' simulated speeds, held over {r.rows} samples, differ by "
            f"{r.shown:.3g} rad/s at most, {100 * r.shown / r.top:.2g} % of the {r.top:.3g} "
            "rad/s the speed reaches; any model of a real motor misses by that much (a load "
            "that ripples, drag that is not quite viscous, the encoder's timing), and a gain "
            "so small is not a cause of its own"
        )
    if r.kind == "rival_better":
        if r.rows:
            return (
                f"{r.causes[0]} matches the speed itself far better on the {r.rows} samples "
                "where the two models differ"
            )
        return f"{r.causes[0]} matches the speed itself far better"
    return REASON[r.kind].assistant


def _untold(f: rs.Untold) -> str:
    how = {
        "whitened": f"the second leaves {f.ratio:.2f} times the whitened residual of the first",
        "squared": f"the second leaves {f.ratio:.2f} times the squared speed error (their "
        "averages differ, so their whitened residuals cannot be compared) of the first",
        "squared_less": f"the second misses the speed itself slightly less ({f.ratio:.2f} times "
        "the squared speed error of the first; their averages differ, so their "
        "whitened residuals, where the first is ahead, cannot be compared)",
        "split": f"the second leaves {f.ratio:.2f} times the whitened residual of the first, yet "
        f"misses the speed itself less ({f.squared:.2f} times the squared speed error of the "
        "first), so the two measures disagree on which fits better",
    }[f.compared]
    extra = [c for c in f.other if c not in f.named]
    if f.moves > 0.0 and len(extra) == 1:
        return (
            f"this log cannot tell whether {in_words(extra[0])} acts beside "
            f"{in_words('+'.join(f.named))}: with it the model leaves {f.ratio:.2f} times the "
            "whitened residual, but it moves the simulated speed, held over 9 samples, by "
            f"{100 * f.moves:.2g} % of the largest speed at most, about what any model of a real "
            "motor misses by (a load that ripples, drag that is not quite viscous, the "
            f"encoder's timing); {what_would_tell(f.named, f.other)}"
        )
    return (
        f"this log cannot tell {in_words('+'.join(f.named))} from "
        f"{in_words('+'.join(f.other))}: {how}; {what_would_tell(f.named, f.other)}"
    )


REGION_WORDS: dict[str, tuple[str, str, str]] = {
    "after_rising_edges": ("after the rise", "after the {n} rises", "after rising edges"),
    "after_falling_edges": ("after the fall", "after the {n} falls", "after falling edges"),
}
"""A region of :data:`~minseg_tui.model.check.deviations.REGIONS` in words by how many edges
of its kind the log has: one ('after the rise': 'rising edges' was said of logs with a
single rise), several, or not known (0)."""


def region_words(region: str, edges: int) -> str:
    """Where region ``region`` is, in words: 'after the rise' with one edge of its kind,
    'after the 3 rises' with several, 'after rising edges' when not counted (``edges`` 0);
    'in steady state'."""
    if region not in REGION_WORDS:
        return "in " + region.replace("_", " ")
    one, some, any_ = REGION_WORDS[region]
    return one if edges == 1 else some.format(n=edges) if edges > 1 else any_


def caveat(c: rs.Caveat) -> str:
    """The sentence of caveat ``c``: what the check cannot say about this log, and why."""
    f = c.facts
    if isinstance(f, rs.OnBound):
        return (
            f"{c.cause} came out clear ({params(f.params)}), but {reason(f.why)}: "
            "the effect in this log is outside what that cause can express (or its range is "
            "too small), so it is not named"
        )
    if isinstance(f, rs.Misses):
        against = (
            f"{f.size / f.level:.0f} times what the noise leaves ({f.level:.3g} rad/s)"
            if f.level > 0
            else "where the speed's noise measures 0 rad/s"
        )
        return (
            f"the best model found still misses {region_words(f.region, f.edges)}: its error held "
            f"over 9 samples is {f.size:.3g} rad/s rms there, {against}; something outside the "
            "list of causes acts in this log, so the named cause(s) explain only part of it"
        )
    if isinstance(f, rs.Smooth):
        return SMOOTH[f.alike].assistant
    if isinstance(f, rs.Scatter):
        scatter = (
            f"the speed scatters {f.noise:.3g} rad/s from sample to sample, "
            f"{f.noise / f.counts:.1f} times what the encoder's counts explain "
            f"({f.counts:.3g} rad/s)"
        )
        if f.follows:
            return (
                f"{scatter}, yet the model, simulated at the log's own sample times, follows "
                f"it to {f.left:.3g} rad/s rms: the scatter is the sampling's timing, which the "
                "simulation reproduces"
            )
        return (
            f"{scatter}: timing jitter, ripple or resampling add noise no model of the motor "
            "explains"
        )
    if isinstance(f, rs.Unjudged):
        return f"{c.cause} cannot be judged: {lacks(f.why)}"
    return _untold(f)


def _ms(x: float) -> str:
    """A time (s) in whole ms: '42 ms'."""
    return f"{x * 1e3:.0f} ms"


def _span(x: float) -> str:
    """A duration (s) as the check's sentences write it: in ms under a second."""
    return _ms(x) if x < 1.0 else f"{x:.3g} s"


@dataclass(frozen=True)
class ClaimWords:
    """How a cause's evidence words its claim against a rival (:attr:`.effects.Candidate.claim`):
    ``bare`` with no figure, ``holds`` and ``weak`` with the ratio the rival leaves (it holds,
    or the log hardly tells the two apart), ``void`` when the log cannot rule the rival out."""

    bare: str
    holds: Callable[[float], str]
    weak: Callable[[float], str]
    void: str


CLAIMS: dict[str, Said[ClaimWords]] = {
    "dead_time": Said(
        ClaimWords(
            "(a pure delay; an extra pole would start at once, only more slowly)",
            lambda r: (
                f"(a pure delay: an extra pole in its place leaves {r:.1f} times the whitened "
                "residual)"
            ),
            lambda r: (
                f"(a delay, though an extra pole in its place leaves only {r:.2f} times "
                "the whitened residual: this log hardly tells a delay from a pole)"
            ),
            "(a delay, or in this log an extra pole or an average about as well)",
        ),
        student=ClaimWords(
            "(a pure delay; a second time constant would start at once, only more slowly)",
            lambda r: (
                f"(a pure delay: a second time constant in its place leaves {r:.1f} times the "
                "error)"
            ),
            lambda r: (
                f"(a delay, though a second time constant in its place leaves only {r:.2f} "
                "times the error: this run hardly tells a delay from a lag)"
            ),
            "(a delay, or in this run a second time constant or an averaged speed about as well)",
        ),
    ),
    "second_pole": Said(
        ClaimWords(
            " (a pure delay would show a corner)",
            lambda r: f" (a pure delay in its place leaves {r:.1f} times the whitened residual)",
            lambda r: (
                f" (though a pure delay in its place leaves only {r:.2f} times the "
                "whitened residual: this log hardly tells a pole from a delay)"
            ),
            "",
        ),
        student=ClaimWords(
            " (a pure delay would show a corner)",
            lambda r: f" (a pure delay in its place leaves {r:.1f} times the error)",
            lambda r: (
                f" (though a pure delay in its place leaves only {r:.2f} times the error: "
                "this run hardly tells a lag from a delay)"
            ),
            "",
        ),
    ),
}
"""Each claim in words, by the cause that makes it; told to a student (the lab's details and
the report) with the same figures, the error the check weighs called the error, a pole a
second time constant."""


def _claim(b: rs.Because, plain: bool = False) -> str:
    """The claim of ``b``'s cause against its rival, with the figure behind it when the
    rival was fitted in its place, or taken back when the log cannot rule the rival out
    (``plain``: in a student's words)."""
    w = CLAIMS[b.cause].to(plain)
    if b.void:
        return w.void
    r = b.rival_ratio
    if r is None:
        return w.bare
    return w.holds(r) if b.holds else w.weak(r)


def _friction_stop(f: fx.FrictionStop) -> str:
    how = "coasts and " if f.coast else ""
    text = (
        f"after the drive drops at t = {f.t:.3f} s the wheel {how}stands still "
        f"{_ms(f.after)} later (measured, from {f.speed:.3g} rad/s, its mean over the "
        f"{_ms(f.before)} before the drop)"
    )
    if f.left is not None:
        text += f", where the first-order model still turns at {f.left:.2f} rad/s"
    return text + f": dry friction stops a wheel in finite time (u_c = {format_number(f.uc)} V)"


def _friction_levels(f: fx.FrictionLevels) -> str:
    text = (
        "the settled speeds are not proportional to the voltage"
        + (f": a straight line through them meets zero speed at {f.off:.2f} V" if f.off else "")
        + f"; dry friction with u_c = {format_number(f.uc)} V does that (a voltage lost in the "
        "brushes or the driver looks the same in steady state)"
    )
    if not f.falls:
        text += "; the log has no step-down, so a finite stop cannot be seen"
    return text


def _delay(f: fx.Delay, claim: str, plain: bool = False) -> str:
    seen = (
        f"after the step{'s' if f.steps > 1 else ''} the measured speed first moves "
        f"{_ms(f.lag)} later"
        if f.lag is not None
        else "the response starts late"
    )
    if f.slow:
        return (
            f"{seen}: a first-order response that starts {_ms(f.d)} after the command fits, "
            "but the speed moves before that delay ends, so the start is slow rather than "
            f"late ({'a second time constant' if plain else 'an extra pole'} or an average of "
            "the speed starts so; the delay stands in "
            "for it)"
        )
    return f"{seen}: a first-order response that starts {_ms(f.d)} after the command fits " + claim


def _averaged(f: fx.Averaged, plain: bool = False) -> str:
    n = f.n
    which = "every edge becomes" if f.edges > 1 else "the step becomes"
    ramp = f"{which} a ramp about {n} samples ({_ms(n * f.ts)}) long"
    if f.smooth:
        return (
            f"{'the rises are' if f.edges > 1 else 'the rise is'} smoothed as an average of the "
            f"speed over {n} samples ({_ms(n * f.ts)}) would smooth it; "
            f"{'a second time constant' if plain else 'an extra pole'} in the motor would look "
            "alike in this smooth signal"
        )
    if f.floor is not None:
        return (
            f"the speed scatters only {f.noise:.3g} rad/s where one count per sample alone "
            f"gives a noise floor of {f.floor:.3g} rad/s, and {ramp}: the speed is an average "
            f"over {n} samples, which divides the encoder noise by {n}"
        )
    if f.step is not None:
        return (
            f"the speed's values come in steps of only {f.step:.3g} rad/s and it scatters "
            f"{f.noise:.3g} rad/s, and {ramp}: the speed is an average over {n} samples"
        )
    return f"{ramp}: the speed looks averaged over {n} samples"


def _coast(f: fx.Coast, plain: bool = False) -> str:
    """``plain``: told to a student, the voltage at 0 V and the driver (not a zero command and
    the bridge)."""
    zero = "at 0 V" if plain else "at zero command"
    if f.t is None:
        return f"the wheel runs down slowly {zero} (time constant {_span(f.tc)})"
    after = _ms(f.after)
    line = (
        f"from the row before the drop to the first reading under half, {after} after the drop"
        if f.half
        else f"from the row before the drop over the {after} after it, the speed staying above "
        f"half of its {f.w0:.3g} rad/s throughout"
    )
    drops, lets = (
        ("the voltage drops to 0 V", "the driver lets the wheel coast (run down freely)")
        if plain
        else ("the command drops to 0", "the bridge lets the wheel coast")
    )
    return (
        f"right after {drops} at t = {f.t:.3f} s the speed falls at "
        f"{f.decel:.3g} rad/s^2 (a line through the speed {line}), where a braked motor (T = "
        f"{_ms(f.T)}) would fall at {f.w0 / f.T:.3g} rad/s^2 at first: {lets}, with a time "
        f"constant of {_span(f.tc)} {zero}"
    )


POLE_BESIDE: dict[str, str] = {
    "coulomb_friction": "the wheel stops",
    "coast_on_zero": "it coasts",
    "current_limit": "the cap holds",
}
"""Where a pole on the measurement shows beside each nonlinear cause (on the drive it fits
worse there)."""


SLOW_START = 0.9
"""Beside a cap, a rise that reaches less than this share of its own straight ramp (at its
mean slope) in the pole's span is said to start slowly; otherwise it starts at once."""


def _pole_start(f: fx.Pole, note: str = "") -> str:
    """How each rise starts, with the figures that show it: against the first-order model,
    or beside a cap against the speed's own ramp (the cap explains the first-order model's
    steeper start; a pole shows only as a start slower than the ramp). ``note`` follows the
    first clause."""
    if f.ramp is not None and f.got is not None and f.model is not None:
        ramp = f"a straight ramp at its own mean slope ({f.ramp:.3g} rad/s^2, measured)"
        if f.got < SLOW_START * f.model:
            return (
                f"each rise starts with zero slope (an S-shaped start){note}: {_ms(f.after)} "
                f"after the step the speed has risen {f.got:.3g} rad/s where {ramp} rises "
                f"{f.model:.3g} rad/s"
            )
        return (
            f"each rise starts at once, not with zero slope{note}: {_ms(f.after)} after the step the "
            f"speed has risen {f.got:.3g} rad/s, as {ramp} rises {f.model:.3g} rad/s; the "
            "pole shapes the bend into the plateau, not the start"
        )
    text = "each rise starts with zero slope (an S-shaped start)" + note
    if f.got is not None:
        text += (
            f": {_ms(f.after)} after the step the speed has risen {f.got:.3g} rad/s "
            f"where the first-order model rises {f.model:.3g} rad/s"
        )
    return text


def _pole(f: fx.Pole, claim: str) -> str:
    smooth = " (in this smooth signal an average of the speed would look alike)"
    text = _pole_start(f, smooth if f.smooth else "")
    if f.way == "filtered":
        return text + (
            "; the speed column is smooth, not a difference of encoder counts, so an extra pole "
            "on the measurement is a filter of that column, run sample by sample as a logger "
            f"runs it (each reading takes {f.share:.2f} of the new speed and keeps the rest of "
            f"the one before: a first-order filter of {_ms(f.t2)}); a pole on the drive fits "
            f"this log worse{claim}"
        )
    if f.way == "measured":
        where = [POLE_BESIDE[c] for c in f.beside]
        return text + (
            f"; an extra pole of {_ms(f.t2)} on the measurement (a compliant coupling to the "
            "encoder, or a first-order filter of the speed) lags what the encoder reads: on "
            f"the drive it fits worse where {' and where '.join(where) or 'the effects act'}"
            f"{claim}"
        )
    if f.way == "driver":
        return text + (
            f"; an extra pole of {_ms(f.t2)} in the driver lags its command and runs on while "
            "the wheel coasts: its output has fallen towards zero when the bridge closes, so "
            "the wheel is braked at first, which the armature's own lag (no current while "
            f"coasting) does not do{claim}"
        )
    if f.way == "ringing":
        swing = (
            f"; fitted so, it swings with a period of {_ms(f.period)} and would overshoot a "
            f"step by about {100.0 * f.overshoot:.2g} % of it"
            if math.isfinite(f.period) and f.overshoot >= 0.001
            else ""
        )
        source = (
            "the armature's inductance delays the current, and with the back-EMF its pole and "
            "the wheel's make a complex pair"
            if f.t2 <= WINDING_LAG_MAX
            else "a second lag and the wheel's make a complex pair (not the armature's "
            f"inductance: the current in a small motor's winding builds up within a few ms, "
            f"not {_ms(f.t2)})"
        )
        return text + (
            f"; {source}: the speed fits best as a pair that dies away with one time "
            f"constant, T2 = T = {_ms(f.t2)}{swing}; two real poles fit this log worse{claim}"
        )
    return text + f"; an extra pole of {_ms(f.t2)} delays the torque{claim}"


def _cap(f: fx.Cap) -> str:
    seen = f"the speed ramps at about {f.rate:.3g} rad/s^2" if f.rate else "the speed ramps"
    top = (
        f"; the same motor without a cap would start at K u/T = {f.uncapped:.3g} rad/s^2, "
        "steepest at once"
        if f.uncapped is not None
        else ""
    )
    both = (
        " both ways (braking after a step down is capped too: the speed falls along a ramp "
        "as well, which a cap on accelerating alone does not fit as well)"
        if f.both
        else ""
    )
    return (
        f"{seen} (the mean slope between 20 % and 70 % of the rise, measured) and then bends "
        f"into the plateau{top}: the drive caps the current{both}, a_max = {f.a_max:.3g} rad/s^2"
    )


def _pole_plain(f: fx.Pole, claim: str) -> str:
    """A second pole's evidence told to a student: a second time constant, and where it
    acts, in everyday words (the figures of :func:`_pole`)."""
    text = _pole_start(f)
    if f.way == "filtered":
        where = (
            "the logged speed is filtered: each reading takes "
            f"{f.share:.2f} of the new speed and keeps the rest of the one before, a lag of "
            f"{_ms(f.t2)}"
        )
    elif f.way == "measured":
        where = (
            f"a lag of {_ms(f.t2)} between the wheel and its speed reading (a flexible "
            "coupling to the encoder, or a filtered speed)"
        )
    elif f.way == "driver":
        where = f"a lag of {_ms(f.t2)} in the driver: its output follows the command late"
    elif f.t2 > WINDING_LAG_MAX:  # walk 16's D8 pass: 165 ms (rtl brake), 285 ms (UBC 9 V)
        where = (
            f"a second, slow lag, T2 = {_ms(f.t2)}: the torque follows the voltage that much "
            "later, too late for the current in the winding, which in a small motor builds up "
            "within a few ms"
        )
    elif f.way == "ringing":
        where = (
            "the current builds up in the winding as the speed does, a second time constant "
            f"T2 = {_ms(f.t2)}"
        )
    else:
        where = (
            f"a second time constant of {_ms(f.t2)}: the current, and so the torque, builds "
            "up that much later than the voltage"
        )
    return f"{text}; {where}{claim}"


def shown(b: rs.Because, plain: bool = False) -> str:
    """What a cause's evidence reads off the log, in words, with its claim against a rival
    (every number read off the log). ``plain``: told to a student (the lab's details and
    the report), a pole as a second time constant and the claims in :data:`CLAIMS`' words for a
    student."""
    f = b.shown
    if plain and isinstance(f, fx.Pole):
        return _pole_plain(f, _claim(b, plain=True))
    if plain and isinstance(f, fx.Delay):
        return _delay(f, _claim(b, plain=True), plain=True)
    if plain and isinstance(f, fx.Averaged):
        return _averaged(f, plain=True)
    if plain and isinstance(f, fx.Coast):
        return _coast(f, plain=True)
    if isinstance(f, fx.FrictionStop):
        return _friction_stop(f)
    if isinstance(f, fx.FrictionLevels):
        return _friction_levels(f)
    if isinstance(f, fx.Delay):
        return _delay(f, _claim(b))
    if isinstance(f, fx.Averaged):
        return _averaged(f)
    if isinstance(f, fx.Coast):
        return _coast(f)
    if isinstance(f, fx.Pole):
        return _pole(f, _claim(b))
    if isinstance(f, fx.Cap):
        return _cap(f)
    raise TypeError(f"no words for {type(f).__name__}")


NONE_NAMED: dict[rs.FitSaid, Said[str]] = {
    "unexplained": Said(
        "no cause from the list explains what the first-order model misses",
        student="no cause the check knows explains what the simple model misses",
    ),
    "fits": Said("the first-order model fits the log", student="the simple model fits the run"),
    "turning": Said(
        "where the wheel turns ({p.turning} of {p.rows} rows; it stands still in the others) the "
        "first-order model misses by {p.left_turning:.2g} rad/s rms above the noise ({p.level:.3g} "
        "rad/s)",
        student="where the wheel turns ({p.turning} of {p.rows} rows; it stands still in the "
        "others) the simple model misses by {p.left_turning:.2g} rad/s rms more than the noise "
        "({p.level:.3g} rad/s)",
    ),
    "at_noise": Said(
        "the first-order model's rms error is at the level of the speed's noise: {p.rms:.3g} rad/s "
        "against a noise of {p.level:.3g} rad/s",
        student="the simple model's average speed error is about the speed's noise: {p.rms:.3g} "
        "rad/s rms against a noise of {p.level:.3g} rad/s",
    ),
    "above": Said(
        "the first-order model misses by {p.left:.2g} rad/s rms above the noise ({p.level:.3g} "
        "rad/s), but no cause from the list is clear enough to name",
        student="the simple model misses by {p.left:.2g} rad/s rms more than the noise "
        "({p.level:.3g} rad/s), but no cause the check knows is clear enough to name",
    ),
}
"""The evidence when no cause is named, by how the first-order model does
(:attr:`~minseg_tui.model.check.result.Plain.how`), a template of the record's fields (``p``)."""

LOW_FIT = Said(
    " (its fit is only {p.low_fit:.0f} % because that noise is large against the speed's "
    "changes, not because the model is wrong)",
    student=" (the noise is large beside how much the speed changes, so the model only seems "
    "to follow the speed loosely: that is the noise, not a wrong model)",
)
"""After :data:`NONE_NAMED`'s words (but "unexplained"'s) when the fit is low
(:attr:`.result.Plain.low_fit`): the lab assistant is told the fit (a percentage a student
has not met: 100 (1 - |error| / |speed - its mean|)), a student what it means."""


def none_named(p: rs.Plain, plain: bool = False) -> str:
    """The evidence when no cause is named (``plain``: told to a student, the figures of the
    assistant's but the fit's)."""
    said = NONE_NAMED[p.how].to(plain).format(p=p)
    if p.how == "unexplained" or p.low_fit is None:
        return said
    return said + LOW_FIT.to(plain).format(p=p)


def evidence(f: rs.Finding) -> str:
    """The finding's evidence in words: what the cause shows in the log and how much of the
    residual it removes, and why the runner-up lost; or, when no cause is named, how the
    first-order model does and why no cause was."""
    e = f.evidence
    if isinstance(e, rs.Plain):
        text = none_named(e)
        return f"{text}; {runner_up_why(f)}" if f.runner_up_why is not None else text
    text = (
        f"{shown(e)}. It removes {100 * e.reduction:.1f} % of the "
        f"whitened residual the model leaves without it (criterion gain {e.gain:.0f})"
    )
    if uncertain(f):
        over = 100 * (e.reduction - MIN_REDUCTION)
        text += (
            f", only {over:.1f} points over the {100 * MIN_REDUCTION:.0f} % a cause needs: a "
            "few rows more or fewer can put it under, so the cause is uncertain"
        )
    return f"{text}; {runner_up_why(f)}" if f.runner_up else text


def uncertain(f: rs.Finding) -> bool:
    """The cause of ``f`` is named only just over the bar (by less than
    :data:`NEAR_THE_BAR`): a few rows more or fewer can put it under, and every audience is
    told it is uncertain."""
    e = f.evidence
    return isinstance(e, rs.Because) and e.reduction < MIN_REDUCTION + NEAR_THE_BAR


NEAR_THE_BAR = 0.01
"""A first cause that removes less than this share more than a cause needs
(:data:`~minseg_tui.model.check.decide.MIN_REDUCTION`, 25 %) is said to be uncertain: the
share moves by more than that with a few rows (ev3-large-duty100 names nothing, its best a
cap at 17.5 %; with its data rows 74-76 dropped a cap at 25.3 %, with rows 73-75 none), so
a finding this near the bar is a toss-up, and any other bar would have its own. Not wider:
at 5 points micromouse-n20-duty100's dead time (29.2 %) would be called uncertain, though
its 40 ms of standing still after the step are plain in the data."""


def other(o: rs.Other) -> str:
    """A further effect's evidence in words: what it shows, and what taking it out costs."""
    e = o.evidence
    return (
        f"{shown(e)}; taking it out of the model leaves "
        f"{1 / max(1 - e.reduction, 1e-12):.1f} times the whitened residual"
    )


def lead_why(g: Lead) -> str:
    """Why the figure that leads means most for this log, in words."""
    named = g.named
    if g.kind == "turning":
        return (
            f"the wheel stands still in {g.still} of {g.rows} rows, which makes the rms speed "
            f"error ({g.error:.3g} rad/s) small; where it turns the error is {g.turning:.3g} "
            f"rad/s rms against a noise of {g.noise:.3g} rad/s. The angle error adds up "
            + (
                "each model's misses over the run, so it tells them apart"
                if named
                else "the model's misses over the run, so it judges the model"
            )
        )
    if g.kind == "noisy":
        return (
            f"the speed error ({g.error:.3g} rad/s rms) is mostly the noise of the speed "
            f"({g.noise:.3g} rad/s), which hides "
            + (
                "the models' difference; the angle is known far better, so the angle error "
                "tells them apart"
                if named
                else "what the model misses; the angle is known far better, so the angle error "
                "judges the model"
            )
        )
    if g.kind == "heldout":
        why = "the models predict steps they were not fitted on: the honest judge of a gain"
        if g.worse is not None:
            hb, he = g.worse
            why += (
                f"; here the extended model predicts them worse ({hb:.3g} -> {he:.3g} rad/s): "
                "what the named cause gains on the rows it was fitted on does not carry over "
                "to the steps it was not fitted on"
            )
        return why
    if g.kind == "above":
        return (
            f"this log's speed has a noise of {g.noise:.3g} rad/s rms that no model can "
            "remove; only the part of the error above it "
            + ("tells the models apart" if named else "judges the model")
        )
    if g.kind == "small_noise":
        return f"the speed's noise ({g.noise:.3g} rad/s rms) is small against the " + (
            "models' errors, so the rms error itself tells them apart"
            if named
            else "model's error, so the rms error itself judges the model"
        )
    return "the noise of this speed is not known, so the plain rms error is all there is"


WINDOW: dict[Window, str] = {
    "stretch": "the stretch where something braked the wheel",
    "fall": "a step-down, where the wheel slows and stops",
    "rise": "a rise, where the response starts",
    "whole": "the whole log",
}
"""What a close-up shows, in words."""


def close_up_what(c: CloseUp) -> str:
    """What close-up ``c`` shows, in words."""
    return WINDOW[c.shows]


def every(s: Sampling) -> str:
    """How often the log was sampled, in plain words: "a sample every 25 ms" when every
    interval reads the same (to 3 digits), else "a sample every 24.2-25.8 ms (mostly
    25 ms)", or for a loop without a fixed clock "irregular, a sample every 12-40 ms
    (nominal 25 ms)"."""
    lo, hi, ts = (f"{x * 1e3:.3g}" for x in (s.interval_min, s.interval_max, s.ts))
    if s.how == "even":
        return f"a sample every {ts} ms"
    if lo == hi:
        return f"a sample every {lo} ms"
    if s.regular:
        return f"a sample every {lo}-{hi} ms (mostly {ts} ms)"
    return f"irregular, a sample every {lo}-{hi} ms (nominal {ts} ms)"


def resolution_how(s: Sampling) -> str:
    """Where the speed's resolution came from, in words ('' when unknown): the header's
    ``# cpr:`` line as it reads, or the lattice it was read off (one count in rad, or the
    speed's step in rad/s)."""
    if s.count_from is CountFrom.CPR:
        return f"# cpr: {s.cpr}"
    if s.resolution is None:
        return ""
    if s.count_from is CountFrom.INTERVAL_LATTICE:
        q = s.resolution * s.ts
        return f"each speed times its interval lies on a lattice of {q:.3g} rad, one count"
    return f"the speeds lie on a lattice of {s.resolution:.3g} rad/s"


FEW_UNEVEN = 3
"""Fewer rows after an uneven interval than this cannot show over which time a row's speed
was taken (:func:`sampling` says the choice is assumed)."""


def late_speed(log: RunLog) -> float | None:
    """How late (s) the log's speed column runs behind its theta column
    (:func:`~minseg_tui.model.runlog.speed_lag`), when more than
    :data:`~minseg_tui.model.identify.identification.LAG_SAMPLES` sample periods (the median
    interval); None otherwise or without a theta column. The check reads the speed column
    alone, so it cannot see this itself."""
    if "theta" not in log.extra or len(log) < 3:
        return None
    lag = speed_lag(log.t, log.omega, log.extra["theta"])
    ts = float(np.median(np.diff(np.asarray(log.t, dtype=float))))
    return lag if lag is not None and lag > LAG_SAMPLES * ts else None


def speed_lag_said(lag: float) -> str:
    """What the check cannot say on a log whose speed column runs ``lag`` (s) behind its
    angle column (:func:`late_speed`): one wording for ``analyze``'s caveats, the screen's
    details and the report's (an EV3 under ev3dev, whose speed is the driver's own estimate:
    8.8 / 12.7 ms behind, where the check named a 16 / 21 ms delay)."""
    return (
        f"the speed column runs about {format_constant(lag, 's')} behind the log's angle "
        "column (theta): summed over the sample intervals it falls behind the angle as a "
        "speed that late would, where a mean speed over each interval would not. The check "
        "reads the speed column only, so a delay or a filter it finds may be the speed's "
        "reading (a filtered speed, as a driver's own estimate), not the motor"
    )


def sampling(s: Sampling, lag: float | None = None) -> str:
    """One sentence on the sample times and the speed column; ``lag`` (s): how late the
    log's speed column runs behind its angle column (:func:`late_speed`), None when not: then
    its speed is no mean over an interval, whatever the data fit better."""
    times = every(s)
    if s.how != "even" and lag is not None and s.coarse is None:
        # ev3dev's speed attribute fits "over its own interval" better than "over the nominal
        # period", yet it is neither: "(detected from the data)" was said of it
        over, other = ("its own interval", "the nominal period")[:: 1 if s.over_interval else -1]
        why = (
            "as the header says"
            if s.how == "header"
            else f"which fits the data better than {other}"
        )
        if not s.regular:
            times += (
                ": a loop without a fixed clock; the long intervals are jitter, not lost samples"
            )
        times += (
            f"; each row's speed is simulated as the mean over {over} ({why}), but the speed "
            f"column is no such mean: it runs about {format_constant(lag, 's')} behind the "
            "angle column (below)"
        )
    elif s.how != "even":
        over = "its own interval" if s.over_interval else "the nominal period"
        src = "as the header says" if s.how == "header" else "detected from the data"
        if s.how == "detected" and s.uneven < FEW_UNEVEN:
            # one uneven interval (an EV3 log with three rows dropped) cannot show over which
            # time its speed was taken: the choice is a guess, not a detection
            src = (
                f"assumed: {s.uneven} uneven interval{'s' if s.uneven != 1 else ''} in the "
                "log, too few to tell"
            )
        if not s.regular:
            times += (
                ": a loop without a fixed clock; the long intervals are jitter, not lost samples"
            )
        if s.coarse is not None:
            # a coarse clock (millis()): the longer stamps are the clock's, not the count's
            times += (
                f"; each row's speed is taken over the nominal period ({src}) on a clock "
                "that stamps whole ticks: a row stamped after a longer interval reads "
                f"{100 * s.coarse:+.0f} % of the extra time above its neighbours, where a count "
                "over that interval would read +100 %, so each row is simulated as the mean "
                "speed over its interval"
            )
        else:
            times += f"; each row's speed is taken over {over} ({src}) and simulated so"
    if s.lost:
        times += f"; {s.lost} sample(s) lost"
    if s.resolution is not None:
        res = (
            f"one count per sample is {s.resolution:.3g} rad/s ({resolution_how(s)}), "
            f"a noise floor of {s.floor:.3g} rad/s"
        )
    elif s.smooth:
        res = "the speed is smooth, not a difference of counts (a tachometer or a filtered signal)"
    else:
        res = "the encoder's resolution is unknown (no # cpr: line, no count steps in the speed)"
    return f"{times}; {res}"


SAME = 1.2
"""A region whose rms is within this factor of the steady state's is not called the worst."""


def where(devs: list[Deviation]) -> str:
    """One sentence: where the model is worst, against the steady state (about equally good
    everywhere when no region is ``SAME`` times worse than the steady state)."""
    if not devs:
        return "no rows to compare"
    worst = max(devs, key=lambda d: d.rms)
    steady = next((d for d in devs if d.region == "steady_state"), None)
    words = region_words(worst.region, worst.edges)
    if steady is None or worst is steady:
        return (
            f"the model is about equally good everywhere (worst {words}: rms {worst.rms:.3f} rad/s)"
        )
    if worst.rms < SAME * steady.rms:
        return (
            f"the model is about equally good everywhere ({words}: rms {worst.rms:.3f} rad/s, "
            f"steady state {steady.rms:.3f} rad/s)"
        )
    ratio = f"{worst.rms / steady.rms:.1f}x" if steady.rms > 0 else "exact in steady state"
    return (
        f"the model is worst {words}: rms {worst.rms:.3f} rad/s there against "
        f"{steady.rms:.3f} rad/s in steady state ({ratio})"
    )


def runner_up_why(f: rs.Finding) -> str:
    """Why the runner-up of finding ``f`` lost, in words ('' without one)."""
    return lost(f.runner_up_why)


def lost(r: rs.RunnerUp | None) -> str:
    """Why a runner-up lost, in words ('' without one): with no cause named, the best
    extension by its contract name; with one, the next best explanation in words."""
    if r is None:
        return ""
    name, why = r.name, (reason(r.reason) if r.reason is not None else "")
    if r.kind == "held_back":
        return f"the best extension ({name}) is held back: {why}"
    share = f"{100 * max(r.share, 0.0):.1f} %"
    if r.kind == "too_small":
        return (
            f"the best extension ({name}) removes only {share} of the whitened residual, and a "
            f"cause needs at least {100 * r.needs:.0f} %"
        )
    if r.kind == "short_of_gain":
        return (
            f"the best extension ({name}) removes {share} of the whitened residual, but its "
            f"criterion gain {r.gain:.0f} is below the {r.threshold:.0f} a cause needs on a log "
            "this long"
        )
    said = in_words(name)  # the sentence names it in words, never by its contract name
    if r.kind == "misses_more":
        b_rms, e_rms = r.rms
        # digits enough to show the two apart (gen15 printed 'rmse 1.8 against 1.8')
        n = next((d for d in range(3, 7) if f"{b_rms:.{d}g}" != f"{e_rms:.{d}g}"), 6)
        return (
            f"the next best explanation ({said}) leaves less whitened residual, but its "
            f"simulated speed misses the measured speed by more (rmse {b_rms:.{n}g} rad/s "
            f"against {e_rms:.{n}g} rad/s)" + (f", and {why}" if why else "")
        )
    if r.kind == "not_named":
        return (
            f"the next best explanation ({said}) leaves less whitened residual but is not "
            f"named: {why}"
        )
    if r.needs > 0:
        short = (
            f"it removes {share} of the whitened residual, where a cause needs at least "
            f"{100 * r.needs:.0f} %"
            if r.share < r.needs
            else f"its criterion gain {r.gain:.0f} is below the {r.threshold:.0f} a cause needs"
        )
        return (
            f"the next best explanation ({said}) fits about as well: it leaves {r.ratio:.3g} "
            "times the whitened residual, and is not named only because on its own against the "
            f"first-order model {short}; this log hardly tells the two apart"
        )
    return (
        f"the next best explanation ({said}) leaves {r.ratio:.1f} times as much whitened "
        "residual" + (f" ({why})" if why else "")
    )


# -- told to a student: the lab's details and the report (the CLI keeps the words above) ------
def reason_plain(r: Reason) -> str:
    """Why a clear cause was left out, told to a student: causes in words, never by their
    contract names (the figures of :func:`reason`)."""
    if r.kind in REASON:
        return REASON[r.kind].to(plain=True)
    if r.kind == "within_sample" and r.cause in PLAIN_LABELS:
        return _within(r, f"a {PLAIN_LABELS[r.cause]}")
    if r.kind == "swapped":
        return (
            f"{in_words(r.causes[0], plain=True)} explains the log better together with the others"
        )
    if r.kind == "together":
        return f"{' and '.join(in_words(c, plain=True) for c in r.causes)} together explain the log better"
    if r.kind == "rival_better":
        return f"{in_words(r.causes[0], plain=True)} matches the speed itself far better"
    if r.kind in ("third_small", "taken_over"):
        return reason(replace(r, causes=tuple(in_words(c, plain=True) for c in r.causes)))
    return reason(r)


def lost_plain(r: rs.RunnerUp | None) -> str:
    """Why the runner-up lost, told to a student ('' without one): the error the check
    weighs (its whitened residual) is called the model's error, its criterion gain a score."""
    if r is None:
        return ""
    said = in_words(r.name, plain=True)
    why = reason_plain(r.reason) if r.reason is not None else ""
    share = f"{100 * max(r.share, 0.0):.1f} %"
    if r.kind == "held_back":
        return f"The best addition the check tried, {said}, is held back: {why}."
    if r.kind == "too_small":
        return (
            f"The best addition the check tried, {said}, removes only {share} of the simple "
            f"model's error; a cause must remove at least {100 * r.needs:.0f} %."
        )
    if r.kind == "short_of_gain":
        return (
            f"The best addition the check tried, {said}, removes {share} of the simple "
            f"model's error, but on a run this long that is too little to be sure of it "
            f"(a score of {r.gain:.0f} where {r.threshold:.0f} is needed)."
        )
    if r.kind == "misses_more":
        b_rms, e_rms = r.rms
        n = next((d for d in range(3, 7) if f"{b_rms:.{d}g}" != f"{e_rms:.{d}g}"), 6)
        return (
            f"The next best explanation, {said}, scores slightly better on the error the "
            f"check weighs, but its speed misses the measured one by more ({b_rms:.{n}g} "
            f"rad/s rms against {e_rms:.{n}g} rad/s)" + (f"; and {why}" if why else "") + "."
        )
    if r.kind == "not_named":
        return f"The next best explanation, {said}, fits better but is not named: {why}."
    if r.needs > 0:
        short = (
            f"alone it removes {share} of the simple model's error, short of the "
            f"{100 * r.needs:.0f} % a cause needs"
            if r.share < r.needs
            else "alone it is too small a gain to be sure of on a run this long"
        )
        return (
            f"The next best explanation, {said}, fits about as well ({r.ratio:.3g} times the "
            f"error) and is not named only because {short}: this run hardly tells the two "
            "apart."
        )
    text = f"The next best explanation, {said}, leaves {r.ratio:.1f} times as much error"
    if r.reason is not None and r.reason.kind == "refused":
        return f"{text}, and this run could not show it anyway: {why}."
    return text + (f" ({why})." if why else ".")


def caveat_plain(c: rs.Caveat) -> str:
    """Caveat ``c`` told to a student: what this run cannot show, in everyday words (the
    figures of :func:`caveat`; causes in words, never by their contract names)."""
    f = c.facts
    name = in_words(c.cause, plain=True) if c.cause else ""
    if isinstance(f, rs.OnBound):
        return (
            f"{name[:1].upper()}{name[1:]} fitted clearly ({params(f.params)}), but "
            f"{reason_plain(f.why)}: the run does something that cause cannot quite express, "
            "so it is not named."
        )
    if isinstance(f, rs.Misses):
        against = (
            f"{f.size / f.level:.0f} times what the noise leaves there ({f.level:.3g} rad/s)"
            if f.level > 0
            else "where the speed has no noise at all"
        )
        return (
            f"Even the best model still misses {region_words(f.region, f.edges)}, by "
            f"{f.size:.3g} rad/s (averaged over 9 samples), {against}: something the check "
            "does not know acts in this run, so the causes named explain only part of it."
        )
    if isinstance(f, rs.Smooth):
        return SMOOTH[f.alike].to(plain=True)
    if isinstance(f, rs.Unjudged):
        return f"Whether there is {name} cannot be judged: {lacks(f.why)}."
    if isinstance(f, rs.Untold):
        named, other = (
            in_words("+".join(f.named), plain=True),
            in_words("+".join(f.other), plain=True),
        )
        extra = [x for x in f.other if x not in f.named]
        if f.moves > 0.0 and len(extra) == 1:
            return (
                f"This run cannot tell whether {in_words(extra[0], plain=True)} acts beside {named}: with "
                f"it the model's error is {f.ratio:.2f} times as large, and it changes the "
                f"simulated speed by {100 * f.moves:.2g} % of the largest speed at most, about "
                "what any model of a real motor misses by; "
                f"{what_would_tell(f.named, f.other, plain=True)}."
            )
        if f.compared == "split":
            return (
                f"This run cannot tell {named} from {other}: by one measure the second's error "
                f"is {f.ratio:.2f} times the first's, by another {f.squared:.2f} times; "
                f"{what_would_tell(f.named, f.other, plain=True)}."
            )
        return (
            f"This run cannot tell {named} from {other}: the second leaves {f.ratio:.2f} times "
            f"the error of the first, about the same; "
            f"{what_would_tell(f.named, f.other, plain=True)}."
        )
    text = caveat(c)
    return f"{text[:1].upper()}{text[1:]}."


class _Says:
    """The sentences here, as the result's JSON asks for them (:class:`~.result.Says`)."""

    anomaly = staticmethod(anomaly)
    caveat = staticmethod(caveat)
    evidence = staticmethod(evidence)
    other = staticmethod(other)
    lead_why = staticmethod(lead_why)
    close_up_what = staticmethod(close_up_what)
    sampling = staticmethod(sampling)
    resolution_how = staticmethod(resolution_how)
    where = staticmethod(where)
    runner_up_why = staticmethod(runner_up_why)


def as_json(r: CheckResult) -> dict[str, object]:
    """The JSON object of ``minseg-tui analyze --json``, its sentences made here."""
    return r.to_dict(_Says())
