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

from minseg_tui.lab.views.check_says import CAUSE_WORDS, close_up_what
from minseg_tui.lab.views.check_text import GAIN_DIGITS, figure, figure_words, stem
from minseg_tui.model.check import CheckResult
from minseg_tui.model.check.effects import CANDIDATES
from minseg_tui.quantities import (
    format_constant,
    format_fixed,
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

    if drop:
        moving = np.flatnonzero(np.abs(w[edge:b]) > zero)
        k = edge + (int(moving[-1]) + 1 if moving.size else 0)
        if k <= b - MIN_STILL_ROWS and abs(w[edge - 1]) > zero:
            return at(k, still=True)
    # the largest miss the way the cause makes it (|speed| below the model's for most),
    # else the largest either way
    sign = SLOWER.get(r.finding.cause, 1) * np.sign(base[edge:b] + w[edge:b])
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


def two_fits(T: float, T_ls: float, K_ls: float, rising: bool = True) -> str:
    """Why the check's first-order ``T`` (s) is not the program's least-squares reading of
    the same run, ``T_ls`` (s) and ``K_ls`` (rad/s/V), the one Tasks 11-12 show beside the
    group's own values: whose reading it is, said so that no one takes it for the group's."""
    where = " over its rises" if rising else ""
    return (
        "The program's least-squares reading of the run used in Tasks 11-12 (not the group's "
        f"own values) gives T = {format_constant(T_ls, 's')} and "
        f"K = {format_value(K_ls, 'rad/s/V')}: "
        f"it fits the encoder angle{where} with a time shift for the sampling, while the model "
        "check fits the speed it simulates over the whole run, steps down included; here the "
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


def _what_is_wrong(r: CheckResult, m: Moment | None) -> str:
    """Sentence 1: what the first-order model gets wrong in the close-up; the model is
    named (:func:`simulated`) so that no group takes it for its own."""
    model = simulated(r)
    cu = r.close_up
    if cu is not None and cu.cause == "disturbance":
        return (
            "In this close-up something braked the wheel (a hand on it, or the wheel "
            "touching something): no model of the motor explains that, so the check leaves "
            "this stretch out."
        )
    named = r.finding.cause != "none"
    if not named:
        if r.finding.explained:
            noise = format_value(cu.noise, "rad/s", 2) if cu is not None else "its noise"
            return (
                f"{model[0].upper()}{model[1:]} follows the measured speed to within its "
                f"noise (± {noise}): nothing needs adding for this run."
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
    if m.still and abs(m.first_order) > abs(m.measured):
        return (
            f"After {step}, the wheel stands still {after} later; {model} says it still "
            f"turns at {_w(m.first_order)} then."
        )
    wheel = (
        "the wheel has not moved yet"
        if m.kind == "rise" and _w(m.measured) == _w(0.0)
        else f"the wheel turns at {_w(m.measured)}"
    )
    return f"After {step}, {after} later {wheel} where {model} says {_w(m.first_order)}."


def _cause(r: CheckResult) -> str:
    """Sentence 2: the likely cause in everyday words (and what the log cannot tell it from)."""
    f = r.finding
    if f.cause == "none":
        return ""
    text = f"Likely cause: {EVERYDAY.get(f.cause, f.cause)}."
    also = [SHORT.get(o.cause, o.cause) for o in f.others]
    if also:
        text += f" The check finds {' and '.join(also)} too."
    alike = [
        " with ".join(SHORT.get(c, c) for c in group)
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
    added = " and ".join(SHORT.get(c, c) for c in [f.cause, *(o.cause for o in f.others)])
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


def lead(r: CheckResult, u: ArrayLike | None) -> tuple[str, ...]:
    """The two or three sentences a student reads first: what the first-order model gets
    wrong at the step the close-up shows, the likely cause in everyday words, and how much
    better the extended model does (one figure). ``u``: the run's input (V, one per row of
    ``r.t``), or None when it cannot be read (then the first sentence is general)."""
    m = moment(r, u)
    return tuple(s for s in (_what_is_wrong(r, m), _cause(r), _gain(r)) if s)


def close_up_title(r: CheckResult) -> str:
    """What the close-up shows, with its time span: 'close-up 1.38-1.78 s: a step-down,
    where the wheel slows and stops'."""
    cu = r.close_up
    if cu is None:
        return "the whole log"
    return (
        f"close-up {format_value(cu.t0, '', 3)}-{format_value(cu.t1, 's', 3)}: {close_up_what(cu)}"
    )


def join(sentences: Sequence[str]) -> str:
    """The sentences as one paragraph."""
    return " ".join(sentences)
