"""The causes the model check can name: each one's every piece, registered in one list.

Each cause is one effect with one parameter on top of the first-order model
T w' = -w + K u; several can act at once. A :class:`Candidate` holds all of one cause: its
contract names (the cause and its parameter: the JSON contract, never renamed), the
:class:`~.simulate.Effects` field it sets and the value at which it is absent, its search
range on a log (worked out from the log's steps, levels and time constant), where the
search starts, what a log needs to show it, the sentence of its evidence, and its words for
people. :data:`CANDIDATES` is the list; nothing else lists the causes.

Six causes are modes of the motor, coupled to each other, and simulated together in closed
form by :mod:`.simulate` (their ``field``). A cause that acts on the input can bring its own
simulation piece instead, ``drive`` (:class:`~.simulate.Extra`), and needs no other module.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, fields, replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check import evidence as ev
from minseg_tui.model.check.guess import first_motion, levels_offset, rises, steepest_rate
from minseg_tui.model.check.simulate import Drive, Effects, Extra
from minseg_tui.model.plant import PlantParams
from minseg_tui.quantities import format_number

if TYPE_CHECKING:
    from minseg_tui.model.check.fit import Fit, Problem

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Range:
    """Search range of one cause's Effects field on this log (lo, hi), and its scale."""

    lo: float
    hi: float
    log_scale: bool


@dataclass(frozen=True)
class Shape:
    """What the search ranges are worked out from, read off one log: the nominal period ts
    (s), the first-order time constant T (s), the smallest level driven at u_min (V), the
    shortest and longest stretch of constant input that follows a step (s; the last one may
    be cut short and does not count), the longest in rows, the largest step (V), and the
    largest |u| (V)."""

    ts: float
    T: float
    u_min: float
    shortest: float
    longest: float
    rows_long: int
    jump: float
    u_top: float


@dataclass(frozen=True)
class Seen:
    """What the starts of a search are read off: the log (t in s, u in V, y the measured
    speed in rad/s), its nominal period ts (s), the model's T (s) and K (rad/s/V), the
    speed's scatter (rad/s) and the cause's search range."""

    t: FloatArray
    u: FloatArray
    y: FloatArray
    ts: float
    T: float
    K: float
    noise: float
    rng: Range


@dataclass(frozen=True)
class Second:
    """A second parameter fitted with a cause and not reported (the current limit's drag):
    its key among a fit's values, the :class:`Effects` field it sets (K = 1 units), and its
    linear search range from 0 to ``hi``; 0 is the cause without it."""

    key: str
    field: str
    hi: float


@dataclass(frozen=True)
class Claim:
    """A claim a cause's evidence makes against one rival cause (a delay is pure, a pole
    shows no corner). text: the words of the claim in the sentence; rival: the cause fitted
    in its place to back it; said: the words that replace ``text`` with the figure behind
    it, from (r, holds): r the whitened residual the rival leaves in its place over the
    cause's, holds r >= :data:`.pipeline.POLE_OR_DELAY`; voided_by: the rivals that take
    the claim back when the log cannot rule them out, and ``void`` the words left then."""

    text: str
    rival: str
    said: Callable[[float, bool], str]
    voided_by: tuple[str, ...]
    void: str


@dataclass(frozen=True)
class Judged:
    """What a cause's own test of a fit reads (:attr:`Candidate.refuse`): the log's problem
    (its levels in force, the period ts in s, the start speed z0), the fit that holds the
    cause, the noise floor (rad/s) the speed column would have were it an average over N
    samples (None: not known), and the speed's noise around the fit (rad/s, worked out when
    asked)."""

    prob: Problem
    fit: Fit
    floor: Callable[[int], float | None]
    own_noise: Callable[[], float]


@dataclass(frozen=True)
class Again:
    """A joint fit beside ``partner`` started again from raised starts: ``start`` makes,
    from one start's {cause: Effects field value} and its T (s), the values of the second
    start (None: no second start from it); the partner is polished in that fit."""

    partner: str
    start: Callable[[dict[str, float], float], dict[str, float] | None]


@dataclass(frozen=True)
class Hidden:
    """How :mod:`minseg_tui.model.synth` hides the cause in a generated log: the realistic
    range its parameter is drawn from (lo, hi, in the contract parameter's unit; a whole
    number when ``whole``), and ``plant``: the plant with it, from the plant without it
    and the parameter. None: it is not in the plant: a cause with a ``drive`` acts on the
    voltage the motor gets (the log keeps the voltage before it), a counted cause is the
    average the speed is measured over."""

    lo: float
    hi: float
    plant: Callable[[PlantParams, float], PlantParams] | None
    whole: bool = False


Way = dict[str, bool]
"""One way a cause can act: the :class:`Effects` flags it sets (an extra pole on the
measurement, a cap that brakes too); {} is its plain way."""

Words = Callable[[ev.Log, "Fit", float | None], str]
"""The sentence of a cause's evidence in one log: (the log, the fit that holds the cause,
the speed's noise floor in rad/s when known) -> words, every number read off the log."""


@dataclass(frozen=True)
class Candidate:
    """One cause, every piece of it.

    cause / param / unit: contract names (the cause, its parameter) and the parameter's
    unit; field: the :class:`Effects` field it sets (K = 1 units: V, s, V/s); null: the
    value at which it is absent (0, 1 or infinity); meaning: one sentence of what it is;
    log_scale: searched on a log scale; label: a few words for people; everyday: what a
    student who has not met it is told; short: two or three words ('with ... added').

    range: its search range on a log; starts: the start values of its field; needs: what
    a log must hold to show it (None: every log); words: the sentence of its evidence;
    scale: the unit of a linear search axis, 'V' (the log's largest |u|) or 's' (ts);
    reported: the contract parameter from the field and K (default: the field itself);
    nonlinear: the wheel stops, coasts or is capped (an extra pole on the drive and one on
    the measurement differ then); stop: the step-downs that show it (the close-up and its
    evidence speak of the fastest; None: it is shown at a rise); drive: see below.
    """

    cause: str
    param: str
    unit: str
    field: str
    null: float
    meaning: str
    range: Callable[[Shape], Range]
    starts: Callable[[Seen], list[float]]
    words: Words
    log_scale: bool = False
    label: str = ""
    everyday: str = ""
    short: str = ""
    needs: ev.Needs | None = None
    scale: str = "s"
    reported: Callable[[float, float], float] = lambda value, K: value
    nonlinear: bool = False
    stop: Callable[[ev.Fall], bool] | None = None
    slower: int = 1
    """Which way it makes the first-order model miss in its close-up: +1 the measured wheel
    is slower than the model says (it stops sooner, starts later, rises more gently), -1
    faster (it runs down more slowly)."""
    excludes: frozenset[str] = frozenset()
    """Causes one model never holds beside this one: the log cannot tell them apart when both
    act (their sum is all it shows), so a fit of both would split one effect in two."""
    drive: Drive | None = None
    """Its own simulation piece, for a cause that acts on the input (then ``field`` is
    empty): the levels the motor gets from the levels in force and the parameter."""
    counted: bool = False
    """Its parameter is a whole number of samples (an average's length, :attr:`Effects.taps`):
    the fit scans it over whole numbers beside its search instead of making it an axis."""
    second: tuple[Second, ...] = ()
    """Parameters the fit finds with it that the contract does not report."""
    flags: tuple[str, ...] = ()
    """The :class:`Effects` flags its ways set (:attr:`ways`)."""
    ways: Callable[[tuple[str, ...], bool], list[Way]] | None = None
    """The ways it can act, each fitted and the best kept: (the causes of the model, whether
    the speed column is smooth) -> the flags of each way, the first tried first; None: one."""
    carry: Callable[[Way, Effects, dict[str, float], float], dict[str, float] | None] | None = None
    """A start of the way ``way`` from a fit of another way: (way, that fit's effects, its
    {cause: Effects field value}, the period ts in s) -> the values to start from besides
    (None: none)."""
    claim: Claim | None = None
    """A claim its evidence makes against a rival cause, stated with the figure behind it."""
    smooth: Callable[[Fit], str] | None = None
    """It acts on the reading, so in a smooth speed column (not a difference of counts) the
    other causes that do cannot be told from it: the words of that caveat for the fit
    (the first such cause in a model speaks)."""
    refuse: Callable[[Judged], str | None] | None = None
    """Its own reason it cannot be named in a fit although clear (None: it can), tested
    before the test of the speed's own error."""
    within_sample: str = ""
    """Its parameter is a time, and one under :data:`.decide.SUB_SAMPLE` of the sample period
    is not named (it acts inside the first sample): what it is in words ('a delay'); '' no
    such test."""
    lag: bool = False
    """It holds the response back after a step (a delay, a pole, an average): at the sample
    period, with a second cause beside it, one such cause can stand in for another."""
    again: Again | None = None
    """A joint fit holding it and :attr:`Again.partner` is fitted again from other starts
    and the better kept."""
    hidden: Hidden | None = None
    """How a generated log (:mod:`minseg_tui.model.synth`) holds it; None: it cannot."""


# -- the causes ---------------------------------------------------------------------------


def _friction_starts(s: Seen) -> list[float]:
    vals = [s.rng.hi * f for f in (0.05, 0.15, 0.35, 0.6)]
    off = levels_offset(s.u, s.y, s.T, s.ts)
    if off is not None and 0 < off < s.rng.hi:
        vals.append(off)
    return vals


def coulomb_words(log: ev.Log, ext: Fit) -> str:
    uc = ext.params["u_c"]
    shown = ev.shown_stop(log, ev.stands_still)
    coast = "coast_on_zero" in ext.causes
    if shown is not None:
        s = shown
        after = s.after if s.after is not None else 0.0
        k = int(np.searchsorted(log.t, log.t[s.row] + after))
        k = min(k, log.t.size - 1)
        left = abs(float(log.base_pred[k]))
        how = "coasts and " if coast else ""
        text = (
            f"after the drive drops at t = {log.t[s.row]:.3f} s the wheel {how}stands still "
            f"{ev.ms(after)} later (measured, from {abs(s.speed):.3g} rad/s, its mean over the "
            f"{ev.ms(ev.before_s(log, s))} before the drop)"
        )
        if left > max(log.zero, 2.0 * log.noise):
            text += f", where the first-order model still turns at {left:.2f} rad/s"
        return text + f": dry friction stops a wheel in finite time (u_c = {format_number(uc)} V)"
    off = levels_offset(log.u, log.y, ext.T, log.ts)
    text = (
        "the settled speeds are not proportional to the voltage"
        + (f": a straight line through them meets zero speed at {off:.2f} V" if off else "")
        + f"; dry friction with u_c = {format_number(uc)} V does that (a voltage lost in the brushes or "
        "the driver looks the same in steady state)"
    )
    if not ev.falls(log):
        text += "; the log has no step-down, so a finite stop cannot be seen"
    return text


COULOMB_FRICTION = Candidate(
    "coulomb_friction",
    "u_c",
    "V",
    "u_c",
    0.0,
    "dry friction: the motor needs u_c volts to break away, and a wheel left to itself stops "
    "in finite time",
    range=lambda s: Range(0.0, 0.98 * s.u_min, False),
    starts=_friction_starts,
    words=lambda log, f, floor: coulomb_words(log, f),
    label="dry friction",
    everyday=(
        "dry friction in the gearbox and the brushes: a constant braking torque, so the "
        "wheel stops sooner than the model says (the model only knows a friction that "
        "shrinks with the speed)"
    ),
    short="dry friction",
    needs=ev.NEEDS_TWO_LEVELS,
    scale="V",
    nonlinear=True,
    hidden=Hidden(0.1, 0.4, lambda p, v: replace(p, tau_c=v * p.motor.k_a / p.motor.R)),
    stop=ev.stands_still,
)


def _delay_starts(s: Seen) -> list[float]:
    lags = first_motion(s.t, s.u, s.y, s.noise)
    vals = [f * s.ts for f in (0.5, 1.0, 2.0)] + [0.5 * s.T]
    if lags:
        lag = float(np.median(lags))
        vals += [max(lag - 1.5 * s.ts, 0.0), max(lag - s.ts - 0.3 * s.T, 0.0)]
    return vals


PURE_DELAY = "(a pure delay; an extra pole would start at once, only more slowly)"
"""The claim of a delay's evidence against a pole."""


def dead_time_words(log: ev.Log, ext: Fit) -> str:
    """The delay's evidence: when the speed first moves after the steps it was settled
    before (a speed still moving at a step says nothing of the delay), and the fitted
    delay; a pure delay only when the speed does not move before that delay ends (at
    least half a sample earlier: then the start is slow rather than late)."""
    d = ext.params["delay"]
    lags = first_motion(log.t, log.u, log.y, log.noise, settled=True)
    lag = float(np.median(lags)) if lags else None
    seen = (
        f"after the step{'s' if len(lags) > 1 else ''} the measured speed first moves "
        f"{ev.ms(lag)} later"
        if lag is not None
        else "the response starts late"
    )
    if lag is not None and lag < d - 0.5 * log.ts:
        return (
            f"{seen}: a first-order response that starts {ev.ms(d)} after the command fits, "
            "but the speed moves before that delay ends, so the start is slow rather than "
            "late (an extra pole or an average of the speed starts so; the delay stands in "
            "for it)"
        )
    return (
        f"{seen}: a first-order response that starts {ev.ms(d)} after the command fits "
        + PURE_DELAY
    )


DEAD_TIME = Candidate(
    "dead_time",
    "delay",
    "s",
    "delay",
    0.0,
    "a pure delay between command and motor",
    range=lambda s: Range(0.0, max(0.8 * s.shortest, 3.0 * s.ts), False),
    starts=_delay_starts,
    words=lambda log, f, floor: dead_time_words(log, f),
    label="dead time",
    everyday=(
        "a delay: the motor answers a little after the command, as if the voltage arrived late"
    ),
    short="a delay",
    needs=ev.NEEDS_RISE,
    claim=Claim(
        PURE_DELAY,
        "second_pole",
        lambda r, holds: (
            f"(a pure delay: an extra pole in its place leaves {r:.1f} times the whitened residual)"
            if holds
            else f"(a delay, though an extra pole in its place leaves only {r:.2f} times "
            "the whitened residual: this log hardly tells a delay from a pole)"
        ),
        ("second_pole", "velocity_filter"),
        "(a delay, or in this log an extra pole or an average about as well)",
    ),
    hidden=Hidden(0.010, 0.060, lambda p, v: replace(p, dead_time=v)),
    within_sample="a delay",
    lag=True,
)


def filter_words(log: ev.Log, ext: Fit, floor: float | None) -> str:
    n = int(ext.params["taps"])
    edges = int(np.count_nonzero(np.diff(log.u)))
    which = "every edge becomes" if edges > 1 else "the step becomes"
    ramp = f"{which} a ramp about {n} samples ({ev.ms(n * log.ts)}) long"
    if log.smooth:
        return (
            f"{'the rises are' if edges > 1 else 'the rise is'} smoothed as an average of the "
            f"speed over {n} samples ({ev.ms(n * log.ts)}) would smooth it; an extra pole in the "
            "motor would look alike in this smooth signal"
        )
    if floor is not None:
        return (
            f"the speed scatters only {log.noise:.3g} rad/s where one count per sample alone "
            f"gives a noise floor of {floor:.3g} rad/s, and {ramp}: the speed is an average "
            f"over {n} samples, which divides the encoder noise by {n}"
        )
    if log.step is not None:
        return (
            f"the speed's values come in steps of only {log.step:.3g} rad/s and it scatters "
            f"{log.noise:.3g} rad/s, and {ramp}: the speed is an average over {n} samples"
        )
    return f"{ramp}: the speed looks averaged over {n} samples"


FILTER_NOISE = 3.0
"""An average over N samples of counts leaves noise floor/N; a speed that scatters more than
this many times that is not such an average."""


def _filter_refuse(j: Judged) -> str | None:
    n = j.fit.effects.taps
    fl = j.floor(n)
    own = j.own_noise() if fl is not None and n >= 2 else 0.0
    if fl is not None and n >= 2 and own > FILTER_NOISE * fl:
        return (
            f"the speed scatters {own:.3g} rad/s around that model's simulation, far more "
            f"than an average of counts over {n} samples leaves ({fl:.3g} rad/s)"
        )
    return None


VELOCITY_FILTER = Candidate(
    "velocity_filter",
    "taps",
    "samples",
    "taps",
    1.0,
    "the measured speed is a moving average of the Euler velocity over N samples",
    # an average longer than a short stretch still shows, as a ramp cut off by the next step
    range=lambda s: Range(1.0, float(min(40, s.rows_long)), False),
    starts=lambda s: [1.0],
    words=filter_words,
    label="averaged speed (velocity filter)",
    everyday=(
        "the logged speed is an average over several samples, which turns every jump into a ramp"
    ),
    short="an averaged speed",
    needs=ev.NEEDS_RISE,
    counted=True,
    smooth=lambda ext: SMOOTH_ALIKE,
    hidden=Hidden(3, 20, None, whole=True),
    refuse=_filter_refuse,
    lag=True,
)


def _span(x: float) -> str:
    """A duration (s) as the check's sentences write it: in ms under a second."""
    return ev.ms(x) if x < 1.0 else f"{x:.3g} s"


def coast_words(log: ev.Log, ext: Fit) -> str:
    tc = ext.params["T_coast"]
    s = ev.shown_stop(log, ev.drops_to_zero)
    if s is None:
        return f"the wheel runs down slowly at zero command (time constant {_span(tc)})"
    decel, span, half = _fall_rate(log, s)
    a, w0 = s.row, abs(s.speed)
    after = ev.ms(span - float(log.t[a] - log.t[a - 1]))
    line = (
        f"from the row before the drop to the first reading under half, {after} after the drop"
        if half
        else f"from the row before the drop over the {after} after it, the speed staying above "
        f"half of its {w0:.3g} rad/s throughout"
    )
    return (
        f"right after the command drops to 0 at t = {log.t[a]:.3f} s the speed falls at "
        f"{decel:.3g} rad/s^2 (a line through the speed {line}), where a braked motor (T = "
        f"{ev.ms(ext.T)}) would fall at {w0 / ext.T:.3g} rad/s^2 at first: the bridge lets the "
        f"wheel coast, with a time constant of {_span(tc)} at zero command"
    )


FALL_TO = 0.5
"""The share of the speed before a step-down that the fall rate is measured down to: far
enough that one-count readings (20 % of a slow wheel's speed) do not set the rate."""


def _fall_rate(log: ev.Log, s: ev.Fall) -> tuple[float, float, bool]:
    """How fast the speed falls after the step-down ``s`` (rad/s^2, the slope of a straight
    line through the speed before it and the readings until the first under FALL_TO of it,
    40 at most, none after the next step), the span that covers (s, from the row before the
    step) and whether a reading fell under FALL_TO of the speed in it."""
    a, w0 = s.row, abs(s.speed)
    edges = np.flatnonzero(np.diff(log.u[a:]) != 0)
    end = a + 1 + int(edges[0]) if edges.size else log.u.size
    seg = np.abs(log.y[a : min(a + 40, end)])
    below = np.flatnonzero(seg < FALL_TO * w0)
    n = min(max(int(below[0]) + 1 if below.size else seg.size, 2), seg.size)
    tt = log.t[a - 1 : a + n] - log.t[a - 1]
    slope = float(np.polyfit(tt, np.concatenate(([w0], seg[:n])), 1)[0]) if tt[-1] > 0 else 0.0
    return -slope, float(tt[-1]), bool(below.size)


COAST_RATIO = 1.5
"""A coast must be this many times slower than the driven time constant to be named."""


COAST_ON_ZERO = Candidate(
    "coast_on_zero",
    "T_coast",
    "s",
    "T_coast",
    math.inf,
    "at zero command the bridge is open and the wheel coasts with its own time constant",
    range=lambda s: Range(max(0.5 * s.T, 0.002), 30.0, True),
    starts=lambda s: [s.T * f for f in (1.5, 3.0, 8.0)] + [1.0, 5.0],
    words=lambda log, f, floor: coast_words(log, f),
    log_scale=True,
    label="coasting at zero command",
    everyday=(
        "at 0 V the driver lets the wheel spin freely instead of braking it, so it runs down "
        "at its own pace, not at the pace of a braked motor"
    ),
    short="coasting at 0 V",
    needs=ev.NEEDS_DROP_TO_ZERO,
    nonlinear=True,
    stop=ev.drops_to_zero,
    slower=-1,
    hidden=Hidden(
        0.3,
        3.0,
        lambda p, v: replace(p, zero_mode="coast", motor=replace(p.motor, f=p.motor.J / v)),
    ),
    refuse=lambda j: (
        "it would be a coast no slower than braking"
        if j.fit.value("coast_on_zero") < COAST_RATIO * j.fit.T
        else None
    ),
)


NO_CORNER = " (a pure delay would show a corner)"
"""The claim of a pole's evidence against a delay."""

SMOOTH_ALIKE = (
    "this speed is smooth, not a difference of encoder counts: an averaging filter on the "
    "speed and an extra pole in the motor look alike here, so the log cannot tell them "
    "apart; the fit prefers the one named"
)


def _pole_smooth(ext: Fit) -> str:
    if ext.effects.pole_measured:
        return (
            "this speed is smooth, not a difference of encoder counts: an average of the "
            "speed and a first-order filter of it (a pole on the measurement) are both "
            "filters of the reading, and the pole named acts there; the fit prefers it"
        )
    return SMOOTH_ALIKE


def _pole_ways(causes: tuple[str, ...], smooth: bool) -> list[Way]:
    """The sides of an extra pole worth fitting: on the drive always; on the measurement where
    the side shows (a cause that is not linear acts with it), or as the logger's filter of a
    smooth speed column (with no average among the causes: then the average smooths it);
    with a coast, as a driver's lag too (:func:`.fit.fit_causes`)."""
    filt = smooth and not any(BY_CAUSE[c].counted for c in causes)
    out: list[Way] = [{}]
    if NONLINEAR & set(causes):
        out.append({"pole_measured": True, "pole_filtered": filt})
    elif filt:
        out.append({"pole_measured": True, "pole_filtered": True})
    if "coast_on_zero" in causes:
        out.append({"pole_driver": True})
    return out


def _pole_carry(
    way: Way, fx: Effects, values: dict[str, float], ts: float
) -> dict[str, float] | None:
    """A fit's lag of the angle T2 (s) turned into the filter of the speed column that delays
    the reading as much (ts a/(1 - a) = T2 with a = exp(-ts/T2_filter)), to start the filter
    from, when ``way`` is the filter and that fit's was not."""
    if not way.get("pole_filtered") or fx.pole_filtered:
        return None
    t2 = values.get("second_pole", 0.0)
    if t2 <= 0.0:
        return values
    return {**values, "second_pole": ts / math.log1p(ts / t2)}


def pole_words(log: ev.Log, ext: Fit) -> str:
    t2 = ext.params["T2"]
    w = max(2, int(math.ceil(max(t2, ext.T / 2) / log.ts)))
    got, model = [], []
    for a, b in rises(log.u):
        if b - a <= w:
            continue
        got.append(abs(float(log.y[a + w - 1] - log.y[a - 1])))
        model.append(abs(float(log.base_pred[a + w - 1] - log.base_pred[a - 1])))
    text = "each rise starts with zero slope (an S-shaped start)"
    if log.smooth:
        text += " (in this smooth signal an average of the speed would look alike)"
    if got:
        text += (
            f": {ev.ms(w * log.ts)} after the step the speed has risen {np.median(got):.3g} rad/s "
            f"where the first-order model rises {np.median(model):.3g} rad/s"
        )
    if ext.effects.pole_filtered:
        share = 1.0 - math.exp(-log.ts / t2)
        return text + (
            "; the speed column is smooth, not a difference of encoder counts, so an extra pole "
            "on the measurement is a filter of that column, run sample by sample as a logger "
            f"runs it (each reading takes {share:.2f} of the new speed and keeps the rest of "
            f"the one before: a first-order filter of {ev.ms(t2)}); a pole on the drive fits "
            "this log worse (a pure delay would show a corner)"
        )
    if ext.effects.pole_measured:
        where = [
            w
            for c, w in (
                ("coulomb_friction", "the wheel stops"),
                ("coast_on_zero", "it coasts"),
                ("current_limit", "the cap holds"),
            )
            if c in ext.causes
        ]
        return text + (
            f"; an extra pole of {ev.ms(t2)} on the measurement (a compliant coupling to the "
            "encoder, or a first-order filter of the speed) lags what the encoder reads: on "
            f"the drive it fits worse where {' and where '.join(where) or 'the effects act'} "
            "(a pure delay would show a corner)"
        )
    if ext.effects.pole_driver:
        return text + (
            f"; an extra pole of {ev.ms(t2)} in the driver lags its command and runs on while "
            "the wheel coasts: its output has fallen towards zero when the bridge closes, so "
            "the wheel is braked at first, which the armature's own lag (no current while "
            "coasting) does not do (a pure delay would show a corner)"
        )
    return (
        text
        + f"; an extra pole of {ev.ms(t2)} delays the torque (a pure delay would show a corner)"
    )


SECOND_POLE = Candidate(
    "second_pole",
    "T2",
    "s",
    "T2",
    0.0,
    "an extra pole delays the torque (the armature's L/R, a driver's own lag) or lags the "
    "reading (a compliant coupling to the encoder, a first-order filter of the speed)",
    range=lambda s: Range(0.0, 3.0 * s.T, False),
    starts=lambda s: [s.T * f for f in (0.1, 0.25, 0.5, 0.9)],
    words=lambda log, f, floor: pole_words(log, f),
    label="second pole",
    everyday=(
        "the current needs time to build up in the motor's winding, so the speed starts "
        "rising gently instead of at once"
    ),
    short="a slow current build-up",
    needs=ev.NEEDS_RISE,
    flags=("pole_measured", "pole_filtered", "pole_driver"),
    ways=_pole_ways,
    carry=_pole_carry,
    claim=Claim(
        NO_CORNER,
        "dead_time",
        lambda r, holds: (
            f" (a pure delay in its place leaves {r:.1f} times the whitened residual)"
            if holds
            else f" (though a pure delay in its place leaves only {r:.2f} times the "
            "whitened residual: this log hardly tells a pole from a delay)"
        ),
        ("dead_time",),
        "",
    ),
    smooth=_pole_smooth,
    hidden=Hidden(0.010, 0.040, lambda p, v: replace(p, T2=v)),
    within_sample="a pole",
    lag=True,
)


def limit_words(log: ev.Log, ext: Fit) -> str:
    a = ext.params["a_max"]
    r = steepest_rate(log.t, log.u, log.y, 1.0)
    seen = f"the speed ramps at about {r:.3g} rad/s^2" if r else "the speed ramps"
    ups = rises(log.u)
    top = ""
    if ups:
        k, _ = ups[0]
        jump = abs(float(log.u[k] - log.u[k - 1]))
        top = (
            f"; the same motor without a cap would start at K u/T = "
            f"{abs(ext.K) * jump / ext.T:.3g} rad/s^2, steepest at once"
        )
    edges = np.flatnonzero(np.diff(log.u) != 0) + 1
    # a step down (|u| falls, or u reverses): the only place a log shows how the drive brakes
    down = any(abs(log.u[k]) < abs(log.u[k - 1]) or log.u[k] * log.u[k - 1] < 0 for k in edges)
    both = (
        " both ways (braking after a step down is capped too: the speed falls along a ramp "
        "as well, which a cap on accelerating alone does not fit as well)"
        if ext.effects.cap_both and down
        else ""
    )
    return (
        f"{seen} (the mean slope between 20 % and 70 % of the rise, measured) and then bends "
        f"into the plateau{top}: the drive caps the current{both}, a_max = {a:.3g} rad/s^2"
    )


DRAG = "cap_drag"
"""The key among a fit's values of the current limit's second parameter: the share of the
damping that is viscous drag (:attr:`Effects.drag`), which bends the capped ramp. A capped
ramp is straight only on a motor without drag; 0 is that motor."""

DRAG_MAX = 0.5
"""Largest drag share fitted (the drag as large as the back-EMF's braking; a motor's viscous drag
is far below that)."""


def _cap_range(s: Shape) -> Range:
    hi = s.jump / (0.1 * s.T)  # beyond, the cap never holds
    return Range(hi / 1000.0, hi, True)


def _cap_starts(s: Seen) -> list[float]:
    vals = [s.rng.hi * f for f in (0.01, 0.025, 0.045, 0.07, 0.1)]
    r = steepest_rate(s.t, s.u, s.y, s.K)
    if r is not None:
        vals += [0.8 * r, r, 1.25 * r]
    return vals


def cap_ramp(prob: Problem, f: Fit) -> float:
    """How long (s) the current cap of ``f`` holds after the step where it holds longest:
    from rest (or a steady level) the first-order model with the cap ramps at its rate until
    the uncapped rate (u - z)/T falls to it, |du|/rate - T later (K = 1 units). A step that
    decelerates counts only when the cap holds braking too; a step across zero counts from 0
    (braking first). It ignores the friction and a pole on the drive, which only shorten
    the ramp."""
    fx = f.effects
    if not math.isfinite(fx.rate) or fx.rate <= 0:
        return 0.0
    vals = prob.st.value
    prev = [0.0 if prob.z0 == 0.0 else float(vals[0]), *vals[:-1].tolist()]
    longest = 0.0
    for a, b in zip(prev, vals.tolist(), strict=True):
        if fx.cap_both:
            du = abs(b - a)
        elif a * b < 0:
            du = abs(b)
        else:
            du = max(abs(b) - abs(a), 0.0)
        longest = max(longest, du / fx.rate - f.T)
    return longest


def _cap_beside_friction(vals: dict[str, float], T: float) -> dict[str, float] | None:
    """A cap fitted beside dry friction, started again raised by u_c/T. Under the cap the
    wheel ramps at rate - u_c/T, so a cap fitted without friction (the ramp seen) is that
    much below the cap with it; started from the ramp seen, the joint fit can settle on a
    small friction and a wrong T instead (the independent generator's tuning seed 2 with
    both: 12 times the true pair's residual)."""
    uc, rate = vals.get("coulomb_friction", 0.0), vals.get("current_limit", math.inf)
    if uc > 0.0 and math.isfinite(rate) and T > 0.0:
        return {**vals, "current_limit": rate + uc / T}
    return None


CURRENT_LIMIT = Candidate(
    "current_limit",
    "a_max",
    "rad/s^2",
    "rate",
    math.inf,
    "the drive caps the current, so the speed ramps at a_max (less what the wheel's own "
    "drag takes as it speeds up) until the back-EMF takes over (on some drives braking "
    "after a step down is capped too)",
    range=_cap_range,
    starts=_cap_starts,
    words=lambda log, f, floor: limit_words(log, f),
    log_scale=True,
    label="current limit",
    everyday="the driver limits the current, so the wheel can only speed up so fast at first",
    short="a current limit",
    needs=ev.NEEDS_RISE,
    reported=lambda value, K: abs(K) * value,  # a_max = |K| rate
    nonlinear=True,
    second=(Second(DRAG, "drag", DRAG_MAX),),
    flags=("cap_both",),
    # capped while accelerating only, and capped both ways
    ways=lambda causes, smooth: [{}, {"cap_both": True}],
    refuse=lambda j: (
        "the ramp that cap makes would last less than one sample period after every step: "
        "no two samples lie on it, so this log cannot show a cap"
        if cap_ramp(j.prob, j.fit) < j.prob.ts
        else None
    ),
    hidden=Hidden(20.0, 60.0, lambda p, v: replace(p, i_max=v * p.motor.J / p.motor.k_a)),
    again=Again("coulomb_friction", _cap_beside_friction),
)


CANDIDATES: tuple[Candidate, ...] = (
    COULOMB_FRICTION,
    DEAD_TIME,
    VELOCITY_FILTER,
    COAST_ON_ZERO,
    SECOND_POLE,
    CURRENT_LIMIT,
)
"""Every cause besides ``none``, in the order they are tried."""

BY_CAUSE: dict[str, Candidate] = {c.cause: c for c in CANDIDATES}

NAMES: tuple[str, ...] = tuple(c.cause for c in CANDIDATES)


def in_words(model: str) -> str:
    """A model or cause name in words: "first_order+coulomb_friction" -> "first order + dry
    friction"; ``none`` stays "none"."""
    return " + ".join(
        "first order" if p == "first_order" else (BY_CAUSE[p].label if p in BY_CAUSE else p)
        for p in model.split("+")
    )


TELL_APART: dict[frozenset[str], str] = {
    frozenset({"dead_time", "second_pole"}): "more steps, or finer speed readings in the first "
    "samples after each step (more counts per sample, a faster sampling where the counts "
    "allow it), would (a delay leaves those samples flat and then turns a corner, a pole "
    "bends smoothly from the start)",
    frozenset({"dead_time", "velocity_filter"}): "the raw encoder counts or more steps would "
    "(a delay shifts the rise, an average turns it into a ramp)",
    frozenset({"velocity_filter", "second_pole"}): "the raw encoder counts would (an average "
    "of the speed acts on the measurement only, a pole on the motor)",
    frozenset({"coulomb_friction", "coast_on_zero"}): "a step down to a small voltage other "
    "than 0 would (dry friction slows the wheel there too, a coast only at 0)",
    frozenset({"coulomb_friction", "current_limit"}): "steps of several sizes would (a cap "
    "limits the big steps only, friction takes the same volts off every level)",
    frozenset({"coast_on_zero", "second_pole"}): "steps down to a small voltage other than 0 "
    "would (a coast acts only at 0)",
}
"""What kind of log would tell two causes apart, in words, for the pairs a log often
cannot tell (the first pair that sets a cause only one model holds against a cause only
the other holds speaks; a pair not here gets the check's general words)."""

PARAM_UNITS: dict[str, str] = {"T": "s", "K": "rad/s/V", **{c.param: c.unit for c in CANDIDATES}}
"""Unit of every parameter a model reports (SI; by parameter name, where
:data:`minseg_tui.quantities.UNITS` holds the units by symbol)."""


def effects_of(values: dict[str, float]) -> Effects:
    """Effects from {cause: value of its Effects field} (taps rounded); a cause with its
    own piece goes into ``extra``."""
    kw: dict[str, float | int] = {}
    extra: list[Extra] = []
    for cause, value in values.items():
        c = BY_CAUSE[cause]
        if c.drive is not None:
            extra.append(Extra(cause, float(value), c.drive))
            continue
        kw[c.field] = int(round(value)) if c.counted else float(value)
    return Effects(**kw, extra=tuple(extra))  # type: ignore[arg-type]


def field_value(fx: Effects, cause: str) -> float:
    """The value of the Effects field behind ``cause`` (the null value when absent)."""
    c = BY_CAUSE[cause]
    if c.drive is not None:
        return next((x.value for x in fx.extra if x.cause == cause), c.null)
    v = getattr(fx, c.field)
    return c.null if v is None else float(v)


_ABSENT: dict[str, object] = {f.name: f.default for f in fields(Effects)}
"""Every :class:`Effects` field at its value when absent."""


def absent(fx: Effects, cause: str) -> Effects:
    """``fx`` without ``cause``: its field, the flags of its ways and its second parameters at
    their absent values (:class:`Effects`' defaults), or its own piece dropped."""
    c = BY_CAUSE[cause]
    if c.drive is not None:
        return replace(fx, extra=tuple(x for x in fx.extra if x.cause != cause))
    names = (c.field, *c.flags, *(s.field for s in c.second))
    return replace(fx, **{n: _ABSENT[n] for n in names})  # type: ignore[arg-type]


def reported(cause: str, value: float, K: float) -> float:
    """The contract parameter of ``cause`` (its unit) from its Effects field (K = 1 units)
    and K (rad/s/V)."""
    return BY_CAUSE[cause].reported(value, K)


def excluded(cause: str, others: tuple[str, ...]) -> bool:
    """``cause`` may not join a model holding ``others`` (:attr:`Candidate.excludes`, either
    way)."""
    mine = BY_CAUSE[cause].excludes
    return any(o in mine or cause in BY_CAUSE[o].excludes for o in others)


NONLINEAR = frozenset(c.cause for c in CANDIDATES if c.nonlinear)
"""Causes after which an extra pole on the drive and one on the measurement differ."""

OWNER: dict[str, str] = {flag: c.cause for c in CANDIDATES for flag in c.flags}
"""The cause behind each :class:`Effects` flag a way sets."""


def counted(causes: tuple[str, ...]) -> str | None:
    """The cause among ``causes`` whose parameter is a whole number of samples, if any."""
    return next((c for c in causes if BY_CAUSE[c].counted), None)


def way_of(fx: Effects) -> Way:
    """The flags of every way in ``fx``."""
    return {flag: bool(getattr(fx, flag)) for flag in OWNER}


def ways(causes: tuple[str, ...], smooth: bool) -> list[Way]:
    """Every combination of the ways of ``causes`` (each cause's :attr:`Candidate.ways`,
    the causes in :data:`CANDIDATES` order, the first cause's way changing slowest)."""
    out: list[Way] = [{}]
    for c in CANDIDATES:
        if c.cause in causes and c.ways is not None:
            out = [{**a, **b} for a in out for b in c.ways(causes, smooth)]
    return out


def shape(t: FloatArray, u: FloatArray, ts: float, T: float) -> Shape:
    """What the search ranges of a log are worked out from: u (V) at t (s), nominal period
    ts (s), first-order time constant T (s)."""
    levels = np.abs(u[u != 0])
    u_min = float(np.min(levels)) if levels.size else 1.0
    change = np.flatnonzero(np.diff(u) != 0) + 1
    bounds = np.concatenate((change, [u.size]))
    ends = np.append(t, t[-1] + ts)
    lengths = [float(ends[b] - t[a]) for a, b in zip(bounds[:-1], bounds[1:], strict=True)]
    inner = lengths[:-1] if len(lengths) > 1 else lengths  # the last one may be cut short
    shortest = min(inner) if inner else float(t[-1] - t[0])
    longest = max(inner) if inner else float(t[-1] - t[0])
    rows_long = max(2, int(round(longest / ts)))
    jump = float(np.max(np.abs(np.diff(u)))) if u.size > 1 else 1.0
    top = float(np.max(np.abs(u))) if u.size else 0.0
    jump = max(jump, top, 1e-9)
    return Shape(ts, T, u_min, shortest, longest, rows_long, jump, top)


def ranges(t: FloatArray, u: FloatArray, ts: float, T: float) -> dict[str, Range]:
    """The search range of every cause on this log (:func:`shape`; each cause's ``range``)."""
    s = shape(t, u, ts, T)
    return {c.cause: c.range(s) for c in CANDIDATES}


def starts(
    cause: str,
    t: FloatArray,
    u: FloatArray,
    y: FloatArray,
    ts: float,
    T: float,
    K: float,
    noise: float,
    rng: Range,
) -> list[float]:
    """Start values of ``cause``'s Effects field for a log (t s, u V, y rad/s, period ts s)
    whose model has T (s), K (rad/s/V) and whose speed scatters ``noise`` (rad/s), within
    its range."""
    vals = BY_CAUSE[cause].starts(Seen(t, u, y, ts, T, K, noise, rng))
    return [min(max(v, rng.lo), rng.hi) for v in vals]


def cannot_judge(log: ev.Log) -> dict[str, str]:
    """The causes this log cannot show at all, and why (they are not tried)."""
    return ev.cannot_judge(log, [(c.cause, c.needs) for c in CANDIDATES])
