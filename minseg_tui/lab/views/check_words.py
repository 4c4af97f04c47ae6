"""The model check told to a second-year student: two or three sentences about the close-up
they look at, the details after them.

The model layer (:mod:`minseg_tui.model.check`) gives records: the cause and the others,
the gain figures, the figure that leads, the close-up's rows. This module reads them, and
the run's input voltage, and writes what the lab screen and the report both lead with:

1. what the simple (first-order) model gets wrong in the close-up, at the step it shows,
   naming the model it simulated (the check's own fit of the run, with its T and K);
2. the likely cause in everyday words;
3. how much better the extended model does, in one figure.

The full text for lab assistants is :func:`minseg_tui.lab.views.check_text.text`
(``minseg-tui analyze``); the gain figures' names are written for both there, and a model's
parameters by :mod:`minseg_tui.lab.views.check_params`. Units: s, V, rad/s, rad (said: T and the
delays in ms).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from minseg_tui.lab.views.check_params import params
from minseg_tui.lab.views.check_says import (
    CAUSE_WORDS,
    WINDING_LAG_MAX,
    anomaly,
    caveat_plain,
    close_up_what,
    every,
    in_words,
    lost_plain,
    none_named,
    shown,
    speed_lag_said,
    uncertain,
)
from minseg_tui.lab.views.check_text import FIGURES, GAIN_DIGITS, figure, figure_words, stem
from minseg_tui.model.check import CheckResult
from minseg_tui.model.check.decide import MIN_REDUCTION
from minseg_tui.model.check.effects import CANDIDATES, FrictionLevels, Pole
from minseg_tui.model.check.result import Because, Plain
from minseg_tui.model.check.sampling import Sampling
from minseg_tui.quantities import (
    format_constant,
    format_fixed,
    format_number,
    format_percent,
    format_typed,
    format_value,
)

FloatArray = NDArray[np.float64]

EVERYDAY: dict[str, str] = {c: w.everyday for c, w in CAUSE_WORDS.items()}
"""Each cause the check can name, in the words of someone who has not met it yet (its
``everyday`` in :data:`~minseg_tui.lab.views.check_says.CAUSE_WORDS`)."""

SHORT: dict[str, str] = {c: w.short for c, w in CAUSE_WORDS.items()}
"""Each cause in two or three words (for 'with ... added' and 'or ...')."""

SLOWER: dict[str, int] = {c.cause: c.slower for c in CANDIDATES}
"""Which way each cause makes the first-order model miss in its close-up (its ``slower``)."""

MIN_STILL_ROWS = 3
"""A wheel stands still from a row on when it reads still there and in at least this many
rows after it, to the end of the close-up."""


@dataclass(frozen=True)
class Moment:
    """What the close-up shows at its step: ``kind`` 'drop' (the voltage falls), 'rise', or
    '' (no step in it); the step's time ``edge`` and the voltages around it (V); the row
    described (``at``, s) with the measured, first-order and extended speeds there (rad/s);
    ``still``: the wheel stands still from ``at`` on (a drop that stops it)."""

    kind: str
    edge: float
    u_from: float
    u_to: float
    at: float
    measured: float
    first_order: float
    extended: float
    still: bool = False


def _w(x: float) -> str:
    return format_value(abs(x) if abs(x) >= 0.005 else 0.0, "rad/s", 2)


def _at(x: float) -> str:
    """A step's board time to the millisecond, as the details write it ('4.625 s')."""
    return format_fixed(x, 3, "s")


def _later(x: float) -> str:
    """A time after a step: '175 ms', '1.2 s'."""
    return format_fixed(x * 1e3, 0, "ms") if x < 1.0 else format_value(x, "s", 2)


def moment(r: CheckResult, u: ArrayLike | None) -> Moment | None:
    """What happens at the step the close-up shows, read off the rows of ``r`` and the
    run's input ``u`` (V, one value per row of ``r.t``): the row where the wheel stands
    still after a drop (when it does), else the row where the first-order model misses the
    measured speed most (a mean over three rows, so one noisy sample does not decide).
    None: no close-up, no input of the same length, or no step in the close-up."""
    cu = r.close_up
    t = np.asarray(r.t, dtype=float)
    if cu is None or u is None:
        return None
    uu = np.asarray(u, dtype=float)
    if uu.size != t.size:
        return None
    a, b = cu.start, min(cu.end, t.size)
    edge = next((k for k in range(max(a, 1), b) if uu[k] != uu[k - 1]), None)
    if edge is None:
        return None
    # the sentence speaks of this step only: up to the next one, when the close-up holds it
    b = next((k for k in range(edge + 1, b) if uu[k] != uu[k - 1]), b)
    w = np.asarray(r.omega, dtype=float)
    base = np.asarray(r.baseline_pred, dtype=float)
    ext = np.asarray(r.extended_pred, dtype=float)
    drop = abs(uu[edge]) < abs(uu[edge - 1])
    res = r.sampling.resolution if r.sampling is not None else None
    zero = 0.5 * res if res else max(cu.noise, 1e-9)

    def at(k: int, still: bool = False) -> Moment:
        return Moment(
            "drop" if drop else "rise",
            float(t[edge]),
            float(uu[edge - 1]),
            float(uu[edge]),
            float(t[k]),
            float(w[k]),
            float(base[k]),
            float(ext[k]),
            still,
        )

    slower = SLOWER.get(r.finding.cause, 1)
    if drop and slower > 0:  # a stop the cause makes early (a coast makes it late)
        moving = np.flatnonzero(np.abs(w[edge:b]) > zero)
        k = edge + (int(moving[-1]) + 1 if moving.size else 0)
        if k <= b - MIN_STILL_ROWS and abs(w[edge - 1]) > zero:
            return at(k, still=True)
    # the largest miss the way the cause makes it (|speed| below the model's for most),
    # else the largest either way
    sign = slower * np.sign(base[edge:b] + w[edge:b])
    miss = np.convolve(sign * (base[edge:b] - w[edge:b]), np.ones(3) / 3.0, mode="same")
    if not miss.size:
        return None
    k = int(np.argmax(miss)) if np.max(miss) > 0 else int(np.argmax(np.abs(miss)))
    return at(edge + k)


def simulated(r: CheckResult) -> str:
    """The first-order model the check simulated, named with its numbers: it is the check's
    own fit of the run, neither the group's model (Task 14) nor the least-squares one of
    Tasks 11-12, and a student must not read it as theirs: 'the first-order model the check
    fitted to this run (T = 40.52 ms, K = 1.919 rad/s/V)' (T in ms, K in rad/s/V, with
    the digits of the details)."""
    T, K = r.baseline.params.get("T"), r.baseline.params.get("K")
    numbers = ", ".join(
        x
        for x in (
            f"T = {format_constant(T, 's')}" if T is not None else "",
            f"K = {format_value(K, 'rad/s/V')}" if K is not None else "",
        )
        if x
    )
    return "the first-order model the check fitted to this run" + (
        f" ({numbers})" if numbers else ""
    )


def steps_down(u: ArrayLike | None) -> bool:
    """The run's input ``u`` (V, one value per row) has a step down (its size falls at an
    edge); False when it cannot be read."""
    if u is None:
        return False
    a = np.abs(np.asarray(u, dtype=float))
    return bool(a.size > 1 and np.any(a[1:] < a[:-1]))


def two_fits(T: float, T_ls: float, K_ls: float, rising: bool = True, down: bool = False) -> str:
    """Why the check's first-order ``T`` (s) is not the program's least-squares reading of
    the same run, ``T_ls`` (s) and ``K_ls`` (rad/s/V), the one Tasks 11-12 show beside the
    group's own values: whose reading it is, said so that no one takes it for the group's.
    ``down``: the run has a step down (:func:`steps_down`), said as fitted too (walk 16's
    D8: "steps down included" on an EV3 log with one step up and none down)."""
    where = " over its rises" if rising else ""
    included = ", steps down included" if down else ""
    return (
        "The program's least-squares reading of the run used in Tasks 11-12 (not the group's "
        f"own values) gives T = {format_constant(T_ls, 's')} and "
        f"K = {format_value(K_ls, 'rad/s/V')}: "
        f"it fits the wheel's angle{where}, allowing for the moment each sample was taken, while "
        f"the model check fits the speed over the whole run{included}; here the "
        f"two T differ by {format_value(100.0 * abs(T / T_ls - 1.0), '', 2)} %."
    )


def other_T(T_ls: float) -> str:
    """The sentence set after the first ones on screen when the check's first-order T is not
    the least-squares one Tasks 11-12 showed for the same run (``T_ls``, s): a student met a
    third T here, its reason folded away in Details (walk 13)."""
    return (
        f"(Tasks 11-12's least-squares T of this run is {format_constant(T_ls, 's')}: "
        "Details says why the two differ.)"
    )


FRICTION_LEVELS = (
    "dry friction: a constant braking torque (for example from a gearbox or the motor's "
    "brushes), which takes about {u_c} off the drive at every voltage, so the settled speeds "
    "are not in proportion to the voltage as the model says (the model only knows a friction "
    "that shrinks with the speed)"
)
"""Dry friction told to a student when the log shows it in its settled speeds, not in a
stop (a log with no step down to 0: 'the wheel stops sooner' would not be of it)."""

DELAY = "a delay: the motor answers about {delay} after the command, as if the voltage arrived late"
"""A dead time told to a student, with its size (345 ms read 'a little after' on a log)."""

LATE_READING = (
    "a delay: the logged speed answers about {delay} after the command; but this log's speed "
    "column itself runs about {lag} behind its angle column, so {part} of that delay may be "
    "the speed reading's, not the motor's"
)
"""A dead time told to a student when the log's speed column runs ``lag`` behind its angle
column (:func:`~minseg_tui.lab.views.check_says.late_speed`): the delay is of the logged
speed, and the reading's own lag may be most of it (an EV3 under ev3dev: 8.8 of 16 ms), so
the motor's delay is not stated as fact."""

POLE_WAYS: dict[str, tuple[str, str]] = {
    "filtered": (
        "a lag in the speed reading: the logged speed is filtered, so it follows the wheel "
        "late and rises gently",
        "a lag in the speed reading",
    ),
    "measured": (
        "a lag between the wheel and its speed reading (a flexible coupling to the encoder, "
        "or a filtered speed), so the reading rises gently",
        "a lag in the speed reading",
    ),
    "driver": (
        "a lag in the driver: its output follows the command late, so the speed starts "
        "rising gently instead of at once",
        "a lag in the driver",
    ),
}
"""A second pole told to a student by where the check finds it acts (the evidence's
``way``), everyday and short; a pole of the drive itself keeps :data:`CAUSE_WORDS`'s
current build-up."""

SLOW_LAG = (
    "a second, slow lag in the drive: the torque follows the command late, so the speed "
    "follows it more slowly than the model's one lag allows (too slow for the current in a "
    "small motor's winding, which builds up within a few ms)",
    "a slow second lag",
)
"""A pole of the drive longer than :data:`~minseg_tui.lab.views.check_says.WINDING_LAG_MAX`,
everyday and short: not the winding's current build-up, which no small motor makes that
slow."""


UNFITTED: dict[str, str] = {"second_pole": "a second lag"}
"""A cause the run cannot tell the named one from, in words that claim nothing its fit did not
show: a second pole's time is not known there, and "a slow current build-up" (the winding's)
was said on a micromouse log where it would stand in for an 18 ms delay, far longer than a
small motor's winding takes (:data:`~minseg_tui.lab.views.check_says.WINDING_LAG_MAX`)."""


def everyday(r: CheckResult, lag: float | None = None) -> str:
    """The cause of ``r`` in everyday words, true of this log: dry friction by what the log
    shows of it (a stop, or settled speeds), a delay with its size (of the logged speed, with
    the part the reading may take, when the speed column runs ``lag`` s behind the angle
    column), a second pole by where it acts."""
    f = r.finding
    e = f.evidence
    shown = e.shown if isinstance(e, Because) else None
    if f.cause == "coulomb_friction" and isinstance(shown, FrictionLevels):
        return FRICTION_LEVELS.format(u_c=format_value(shown.uc, "V", 2))
    if f.cause == "dead_time" and "delay" in r.extended.params and lag is not None:
        delay = r.extended.params["delay"]
        said = format_value(lag * 1e3, "ms", 2)
        part = f"about {said}" if lag < delay else "all"
        return LATE_READING.format(delay=_later(delay), lag=said, part=part)
    if f.cause == "dead_time" and "delay" in r.extended.params:
        return DELAY.format(delay=_later(r.extended.params["delay"]))
    if f.cause == "second_pole" and isinstance(shown, Pole) and shown.way in POLE_WAYS:
        return POLE_WAYS[shown.way][0]
    if f.cause == "second_pole" and isinstance(shown, Pole) and shown.t2 > WINDING_LAG_MAX:
        return SLOW_LAG[0]
    return EVERYDAY.get(f.cause, f.cause)


def short(cause: str, because: object) -> str:
    """A cause in two or three words (for 'with ... added' and 'The check finds ... too'),
    a second pole by where its evidence (``because``) says it acts."""
    shown = because.shown if isinstance(because, Because) else None
    if cause == "second_pole" and isinstance(shown, Pole) and shown.way in POLE_WAYS:
        return POLE_WAYS[shown.way][1]
    if cause == "second_pole" and isinstance(shown, Pole) and shown.t2 > WINDING_LAG_MAX:
        return SLOW_LAG[1]
    return SHORT.get(cause, cause)


def _what_is_wrong(r: CheckResult, m: Moment | None, lag: float | None = None) -> str:
    """Sentence 1: what the first-order model gets wrong in the close-up; the model is
    named (:func:`simulated`) so that no group takes it for its own. What the log's speed
    reads is said of the logged speed, not the wheel, where the speed averages (a velocity
    filter) or runs ``lag`` s behind the angle column."""
    model = simulated(r)
    cu = r.close_up
    if cu is not None and cu.cause == "disturbance":
        return (
            "In this close-up something braked the wheel (a hand on it, or the wheel "
            "touching something): no model of the motor explains that, so the check leaves "
            "this stretch out."
        )
    named = r.finding.cause != "none"
    plain = r.finding.evidence if isinstance(r.finding.evidence, Plain) else None
    if not named and plain is not None and plain.how in ("above", "turning"):
        # no cause is clear, yet the miss stands above the noise: never "to within its noise"
        left = plain.left_turning if plain.how == "turning" else plain.left
        where = "where the wheel turns " if plain.how == "turning" else ""
        return (
            f"{model[0].upper()}{model[1:]} misses the measured speed {where}by "
            f"{format_value(left, 'rad/s', 2)} rms more than its noise "
            f"({format_value(plain.level, 'rad/s', 2)}), and none of the effects the check "
            "knows is clear enough to name (the details say more)."
        )
    if not named:
        if r.finding.explained:
            # the noise is an rms: about a third of the samples lie beyond it, so never "±"
            noise = f" ({format_value(cu.noise, 'rad/s', 2)} rms)" if cu is not None else ""
            return (
                f"{model[0].upper()}{model[1:]} follows the measured speed to within its "
                f"noise{noise}: nothing needs adding for this run."
            )
        return (
            f"{model[0].upper()}{model[1:]} misses the measured speed by more than its noise, "
            "and none of the effects the check knows explains it (the details say more)."
        )
    if m is None:
        return (
            f"{model[0].upper()}{model[1:]} misses the measured speed in this close-up by more "
            "than its noise."
        )
    step = (
        f"the voltage drops from {format_value(m.u_from, 'V', 3)} to {format_value(m.u_to, 'V', 3)} at t = {_at(m.edge)}"
        if m.kind == "drop"
        else f"the voltage steps from {format_value(m.u_from, 'V', 3)} to {format_value(m.u_to, 'V', 3)} at t = {_at(m.edge)}"
    )
    after = _later(m.at - m.edge)
    if m.still and abs(m.first_order) > abs(m.measured) and lag is None:
        return (
            f"After {step}, the wheel stands still {after} later; {model} says it still "
            f"turns at {_w(m.first_order)} then."
        )
    # an averaged speed lags the wheel: say what the log reads, not what the wheel does
    logged = r.finding.cause == "velocity_filter" or lag is not None
    wheel = (
        ("the logged speed has not moved yet" if logged else "the wheel has not moved yet")
        if m.kind == "rise" and _w(m.measured) == _w(0.0)
        else (
            f"the logged speed reads {_w(m.measured)}"
            if logged
            else f"the wheel turns at {_w(m.measured)}"
        )
    )
    return f"After {step}, {after} later {wheel} where {model} says {_w(m.first_order)}."


def _cause(r: CheckResult, lag: float | None = None) -> str:
    """Sentence 2: the likely cause in everyday words (and what the log cannot tell it from);
    ``lag``: as :func:`everyday`."""
    f = r.finding
    if f.cause == "none":
        return ""
    text = (
        f"Possible cause, uncertain (it only just clears the check's bar, and a few rows more "
        f"or fewer could change that): {everyday(r, lag)}."
        if uncertain(f)
        else f"Likely cause: {everyday(r, lag)}."
    )
    also = [short(o.cause, o.evidence) for o in f.others]
    if also:
        text += f" The check finds {' and '.join(also)} too."
    alike = [
        " with ".join(UNFITTED.get(c, SHORT.get(c, c)) for c in group)
        for group in f.ambiguous_with
        if group and group[0] != "none"
    ]
    if alike:
        text += f" This run cannot tell it from {' or '.join(alike)}."
    return text


def _gain(r: CheckResult) -> str:
    """Sentence 3: how much better the extended model does, in the one figure that leads."""
    f = r.finding
    if f.cause == "none" or r.lead is None:
        return ""
    key = stem(r.lead.figure)
    b, e = figure(r.gain, key)
    if b is None or e is None:
        return ""
    added = " and ".join(
        short(c, b) for c, b in [(f.cause, f.evidence), *((o.cause, o.evidence) for o in f.others)]
    )
    words, unit = figure_words(key).said, figure_words(key).unit
    if e >= b:
        return (
            f"With {added} added (the extended model), {words} is no smaller "
            f"({format_value(e, unit, GAIN_DIGITS)} against {format_value(b, unit, GAIN_DIGITS)})."
        )
    if e == 0:
        return f"With {added} added (the extended model), {words} falls to within the noise."
    how = (
        f"{format_typed(b / e, 2)} times smaller"
        if b >= 1.5 * e
        else f"{format_percent(1 - e / b)} smaller"
    )
    return (
        f"With {added} added (the extended model), {words} falls from "
        f"{format_value(b, unit, GAIN_DIGITS)} to {format_value(e, unit, GAIN_DIGITS)}, {how}."
    )


def lead(r: CheckResult, u: ArrayLike | None, lag: float | None = None) -> tuple[str, ...]:
    """The two or three sentences a student reads first: what the first-order model gets
    wrong at the step the close-up shows, the likely cause in everyday words, and how much
    better the extended model does (one figure). ``u``: the run's input (V, one per row of
    ``r.t``), or None when it cannot be read (then the first sentence is general). ``lag``
    (s): how late the log's speed column runs behind its angle column
    (:func:`~minseg_tui.lab.views.check_says.late_speed`), None when it does not: then what
    the speed reads is the logged speed's, and a delay partly the reading's."""
    m = moment(r, u)
    return tuple(s for s in (_what_is_wrong(r, m, lag), _cause(r, lag), _gain(r)) if s)


def close_up_title(r: CheckResult) -> str:
    """What the close-up shows, with its time span: 'close-up 1.38-1.78 s: a step-down,
    where the wheel slows and stops'."""
    cu = r.close_up
    if cu is None:
        return "the whole log"
    # a log whose time starts before 0 (the EV3's at -0.1 s): "-0.100-0.480 s" read as a
    # span from 0.100 s
    to = " to " if cu.t0 < 0 else "-"
    return (
        f"close-up {format_value(cu.t0, '', 3)}{to}{format_value(cu.t1, 's', 3)}: "
        f"{close_up_what(cu)}"
    )


def join(sentences: Sequence[str]) -> str:
    """The sentences as one paragraph."""
    return " ".join(sentences)


# -- the details, told to a student (the screen's fold and the report's) -------------------------
@dataclass(frozen=True)
class FigureMeans:
    """A gain figure told to a student: ``what`` it measures, and ``why`` it matters."""

    what: str
    why: str


MEANS: dict[str, FigureMeans] = {
    "angle_rms": FigureMeans(
        "how far the model's wheel angle drifts from the one the encoder counted",
        "the encoder counts the angle itself, so small speed errors that add up over the run "
        "show there even where the speed's noise hides them",
    ),
    "heldout_rmse": FigureMeans(
        "the speed error on steps each model was not fitted to",
        "the check fitted each model with those steps left out: a model that only bends to "
        "the rows it was fitted to gains nothing there, so it is the fairest test of whether "
        "the added cause is real",
    ),
    "above_noise": FigureMeans(
        "the speed error beyond the speed's own noise",
        "no model can follow the noise, the sample-to-sample scatter of the measured speed; "
        "only the error above it says something about the model",
    ),
    "above_floor": FigureMeans(
        "the speed error beyond the encoder's counting steps",
        "a speed made from whole counts jumps by a count's worth from sample to sample "
        "whatever the motor does; only the error above that says something about the model",
    ),
    "rmse": FigureMeans(
        "the average speed error",
        "it is the plainest measure of how far the model is off: the root of the mean "
        "squared difference between the model's speed and the measured one",
    ),
}
"""Each gain figure (by :func:`~minseg_tui.lab.views.check_text.stem`) told to a student:
what it measures and why it matters."""

LOGGED_ANGLE = FigureMeans(
    "how far the model's wheel angle drifts from the logged angle",
    "the angle adds up the speed over the run, so small speed errors that add up show there "
    "even where the speed's noise hides them",
)
"""The angle's figure told to a student when the log's speed is smooth, not counted in
encoder steps (a tachometer's: the rtl logs' angle is their speed added up, and "the one the
encoder counted" was not true of them)."""


def means(r: CheckResult, key: str) -> FigureMeans | None:
    """What gain figure ``key`` (a :func:`~minseg_tui.lab.views.check_text.stem`) measures and
    why it matters, for the log of ``r`` (None: a figure :data:`MEANS` does not tell)."""
    smooth = r.sampling is not None and r.sampling.smooth and r.sampling.resolution is None
    if key == "angle_rms" and smooth:
        return LOGGED_ANGLE
    return MEANS.get(key)


PARAM_MEANS: dict[str, str] = {
    "T": "the time constant",
    "K": "the static gain",
    "u_c": "the voltage dry friction takes off the drive",
    "delay": "how late the motor answers the command",
    "T2": "the second time constant",
    "taps": "how many samples each logged speed averages",
    "T_coast": "how slowly the wheel runs down while coasting",
    "a_max": "the largest acceleration the current limit allows",
}
"""What each parameter of a model is, told to a student (one a cause adds is explained)."""


def _cap(text: str) -> str:
    return text[:1].upper() + text[1:]


def _n(x: float) -> str:
    return format_number(x, GAIN_DIGITS)


def _lead_plain(r: CheckResult) -> str:
    """The figure that leads told to a student: what it measures, its two values, why it
    matters and why it leads for this run."""
    g = r.lead
    if g is None:
        return ""
    key = stem(g.figure)
    b, e = figure(r.gain, key)
    if b is None:
        return ""
    unit = figure_words(key).unit
    named = r.finding.cause != "none" and e is not None
    told = means(r, key)
    said = told or FigureMeans(figure_words(key).name, "")
    what = f"{said.what} (the {figure_words(key).name})" if told else said.what
    values = (
        f"{_n(b)} {unit} with the simple model, {_n(e)} {unit} with the extended one"
        if named and e is not None
        else f"{_n(b)} {unit} for the simple model"
    )
    them = "the models" if named else "the model"
    get = "get" if named else "gets"  # walk 16's D8: "what the model get wrong"
    if g.kind == "turning":
        here = (
            f"It leads here because the wheel stands still in {g.still} of {g.rows} rows, "
            f"which makes the average speed error ({g.error:.3g} rad/s) look small; where it "
            f"turns the error is {g.turning:.3g} rad/s against a noise of {g.noise:.3g} rad/s."
        )
    elif g.kind == "noisy":
        here = (
            f"It leads here because the speed error ({g.error:.3g} rad/s rms) is mostly the "
            f"speed's own noise ({g.noise:.3g} rad/s), which hides what {them} {get} wrong."
        )
    elif g.kind == "heldout":
        here = "It leads here because this run has steps to leave out."
        if g.worse is not None:
            hb, he = g.worse
            here += (
                f" The extended model predicts them worse ({hb:.3g} rad/s against {he:.3g}): "
                "what the named cause gains on the rows it was fitted to does not carry over."
            )
    elif g.kind == "above":
        here = (
            f"It leads here because the speed's noise ({g.noise:.3g} rad/s rms) is a good part "
            "of the error."
        )
    elif g.kind == "small_noise":
        here = (
            f"It leads here because the speed's noise ({g.noise:.3g} rad/s rms) is small "
            "against the errors, so the plain average "
            + ("tells the models apart." if named else "shows how far the model is off.")
        )
    else:
        here = "It leads here because the noise of this speed is not known."
    why = f" It matters because {said.why}." if said.why else ""
    return f"The figure that means most for this run: {what}: {values}.{why} {here}"


def _evidence_plain(r: CheckResult) -> list[str]:
    """Why the check names its cause (and each further one), told to a student: what it
    reads off the log and how much of the simple model's error adding it removes; then why
    the next best explanation lost."""
    f = r.finding
    e = f.evidence
    out: list[str] = []
    if isinstance(e, Plain):
        out.append(f"Why no cause is named: {none_named(e, plain=True)}.")
    else:
        label = in_words(f.cause, plain=True)
        bar = (
            f"; that is only {100 * (e.reduction - MIN_REDUCTION):.1f} points over the "
            f"{100 * MIN_REDUCTION:.0f} % a cause must remove, and a few rows more or fewer "
            "could put it under, so the cause is uncertain"
            if uncertain(f)
            else ""
        )
        out.append(
            f"Why {label}, over the whole run: {shown(e, plain=True)}. Adding it removes "
            f"{100 * e.reduction:.1f} % of the simple model's error (the error as the check "
            f"weighs it, each stretch against the noise there){bar}."
        )
        for o in f.others:
            out.append(
                f"The check adds {short(o.cause, o.evidence)} too: "
                f"{shown(o.evidence, plain=True)}; without it the "
                f"model's error is {1 / max(1 - o.evidence.reduction, 1e-12):.1f} times as large."
            )
    runner = lost_plain(f.runner_up_why)
    if runner:
        out.append(runner)
    return out


LATE_READING_DELAY = (
    "how late the logged speed answers the command (the motor's own delay and the speed "
    "reading's lag together)"
)
"""What a delay is, told to a student, on a log whose speed column runs behind its angle
column (:data:`LATE_READING`)."""


def _extended_plain(r: CheckResult, intervals: bool, lag: float | None = None) -> str:
    """The extended model told to a student: its parameters, what each one it adds is (a
    delay as :data:`LATE_READING_DELAY` where the speed column runs ``lag`` s behind the
    angle column)."""
    e = r.extended
    if r.finding.cause == "none":
        return "Extended model: none needed; the simple model is enough for this run."
    means = PARAM_MEANS if lag is None else {**PARAM_MEANS, "delay": LATE_READING_DELAY}
    adds = [f"{k} is {means[k]}" for k in e.params if k not in ("T", "K") and k in means]
    return (
        f"The extended model, {in_words(e.model, plain=True)}: "
        f"{params(e.params, e.intervals if intervals else None)}"
        + (f"; {', '.join(adds)}" if adds else "")
        + "."
    )


def _others_plain(r: CheckResult) -> str:
    """The figures that do not lead, simple -> extended, each named by what it measures."""
    named = r.finding.cause != "none"
    lead = stem(r.lead.figure) if r.lead is not None else ""
    said = []
    for key in FIGURES:
        if key == lead:
            continue
        b, e = figure(r.gain, key)
        if b is None or (b == 0 and not e):
            continue
        unit = figure_words(key).unit
        told = means(r, key)
        what = told.what if told else figure_words(key).name
        said.append(
            f"{what}: {_n(b)} → {_n(e)} {unit}"
            if named and e is not None
            else f"{what}: {_n(b)} {unit}"
        )
    if not said:
        return ""
    head = "The other figures, simple → extended model" if named else "The other figures"
    return f"{head}: " + "; ".join(said) + "."


def _log_plain(s: Sampling) -> str:
    """How the log was sampled and how finely its speed is counted, told to a student."""
    times = every(s) + (f"; {s.lost} sample(s) lost" if s.lost else "")
    if s.resolution is not None:
        res = f"one encoder count in a sample is {s.resolution:.3g} rad/s of speed"
    elif s.smooth:
        res = (
            "the speed is smooth, not counted in encoder steps (a tachometer or a filtered signal)"
        )
    else:
        res = "how finely the encoder counts is not known"
    return f"The log: {times}; {res}."


def _noise_plain(r: CheckResult) -> str:
    """How closely any model can follow this speed, told to a student (the noise figures)."""
    g = r.gain
    parts = []
    if g.noise_floor is not None:
        parts.append(
            "the speed is worked out from whole encoder counts, so one count more or less in "
            f"a sample moves it by a step; that alone scatters it by {_n(g.noise_floor)} "
            "rad/s rms"
        )
    parts.append(f"the measured speed scatters by {_n(g.noise)} rad/s from sample to sample")
    if g.angle_floor is not None:
        parts.append(f"the angle itself is known to {_n(g.angle_floor)} rad")
    return (
        "How closely any model can follow this speed: "
        + "; ".join(parts)
        + ". An error of that size says nothing about a model; only the part above it does."
    )


CANNOT_SHOW = "What this run cannot show:"
"""The heading of the caveats told to a student (the screen's details and the report's)."""

IN_THE_LOG = "What stands out in the log (left apart from the causes):"
"""The heading of the anomalies told to a student."""


@dataclass(frozen=True)
class Details:
    """The details a student opens after the lead: ``said``, one paragraph each (the simple
    model, why its T is not Tasks 11-12's, the figure that leads, the evidence, the extended
    model, the other figures, the noise); ``cannot``, what this run cannot show
    (:data:`CANNOT_SHOW`); ``in_log``, what stands out in the log (:data:`IN_THE_LOG`)."""

    said: tuple[str, ...]
    cannot: tuple[str, ...] = ()
    in_log: tuple[str, ...] = ()

    def lines(self) -> tuple[str, ...]:
        """Everything as lines: the paragraphs, then each list under its heading, one '- '
        line an item."""
        return tuple(line for block in self.blocks() for line in block.split("\n"))

    def blocks(self) -> tuple[str, ...]:
        """Everything as the parts the screen sets apart (a blank line between two): each
        paragraph, then each list with its heading, one '- ' line an item (at 80x24 the
        paragraphs ran together, one under the other)."""
        out = list(self.said)
        for head, items in ((CANNOT_SHOW, self.cannot), (IN_THE_LOG, self.in_log)):
            if items:
                out.append("\n".join([head, *(f"- {x}" for x in items)]))
        return tuple(out)


def details(
    r: CheckResult, two_fits_said: str = "", intervals: bool = False, lag: float | None = None
) -> Details:
    """The details a student opens after the lead (the screen's fold, the report's): each
    figure said with what it measures and why it matters; the simple model the check fitted
    (``two_fits_said``: why its T is not Tasks 11-12's, '' when not of one run), the figure
    that leads, the evidence, the extended model (its 95 % intervals when ``intervals``),
    the other figures, the noise, what the run cannot show and what stands out in the log.
    ``lag`` (s): how late the log's speed column runs behind its angle column
    (:func:`~minseg_tui.lab.views.check_says.late_speed`), said under what the run cannot
    show in ``analyze``'s words; None when it does not. The CLI's specialist text is
    :func:`minseg_tui.lab.views.check_text.text`."""
    b = r.baseline
    said = [
        "The simple model, the first-order line on the plots, is the first-order model the "
        "check fitted to this run itself "
        f"and ran on the recorded voltage: {params(b.params, b.intervals if intervals else None)}; "
        "neither the group's model of Task 14 nor the least-squares reading of Tasks 11-12."
    ]
    if r.sampling is not None:
        said.insert(0, _log_plain(r.sampling))
    if two_fits_said:
        said.append(two_fits_said)
    said += [x for x in (_lead_plain(r),) if x]
    said += _evidence_plain(r)
    said.append(_extended_plain(r, intervals, lag))
    said += [x for x in (_others_plain(r), _noise_plain(r)) if x]
    return Details(
        tuple(said),
        (
            *(caveat_plain(c) for c in r.finding.caveats),
            *((f"{_cap(speed_lag_said(lag))}.",) if lag is not None else ()),
        ),
        tuple(f"{_cap(anomaly(a))}." for a in r.anomalies),
    )
