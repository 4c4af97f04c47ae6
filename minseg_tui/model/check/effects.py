"""The causes the model check can name: each one's every piece, registered in one list.

Each cause is one effect with one parameter on top of the first-order model
T w' = -w + K u; several can act at once. A :class:`Candidate` holds all of one cause: its
contract names (the cause and its parameter: the JSON contract, never renamed), the
:class:`~.simulate.Effects` field it sets and the value at which it is absent, its search
range on a log (worked out from the log's steps, levels and time constant), where the
search starts, what a log needs to show it, and what its evidence reads off a log (its own
:class:`Shown` record). :data:`CANDIDATES` is the list; nothing else in the model lists the
causes. Its words (a label, its sentences) are made outside the model, by
:mod:`minseg_tui.lab.views.check_says` (:data:`~minseg_tui.lab.views.check_says.CAUSE_WORDS`
and one branch of ``shown()``).

Six causes are modes of the motor, coupled to each other, and simulated together in closed
form by :mod:`.simulate` (their ``field``). A cause that acts on the input can bring its own
simulation piece instead, ``drive`` (:class:`~.simulate.Extra`), and needs no other module.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, fields, replace
from typing import TYPE_CHECKING, Literal

import numpy as np
from numpy.typing import NDArray

from minseg_tui.model.check import evidence as ev
from minseg_tui.model.check.guess import first_motion, levels_offset, rises, steepest_rate
from minseg_tui.model.check.simulate import Drive, Effects, Extra
from minseg_tui.model.plant import PlantParams

if TYPE_CHECKING:
    from minseg_tui.model.check.fit import Fit, Problem
    from minseg_tui.model.check.result import Alike

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
    shows no corner): rival: the cause fitted in its place to back it (the figure the
    sentence states, :attr:`.result.Because.rival_ratio`); voided_by: the rivals that take
    the claim back when the log cannot rule them out (:attr:`.result.Because.void`)."""

    rival: str
    voided_by: tuple[str, ...]


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
    plain: float = 0.0
    """The speed's scatter (rad/s) around the first-order model an average's noise test is
    relaxed against (0: not relaxed; see :data:`FILTER_NOISE`)."""


RefusalKind = Literal["ramp_under_sample", "scatters", "no_slower"]
"""A cause's own reason not to be named (:attr:`Candidate.refuse`): a cap whose ramp lasts
under a sample period after every step; an average that leaves far more scatter than an
average of counts leaves; a coast no slower than braking."""


@dataclass(frozen=True)
class Refusal:
    """A cause's own reason not to be named (``kind``), with its figures: for 'scatters' the
    speed's scatter around the model (rad/s), the average's length (samples) and what an
    average of counts over it leaves (rad/s)."""

    kind: RefusalKind
    scatter: float = 0.0
    taps: int = 0
    floor: float = 0.0


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


@dataclass(frozen=True)
class Shown:
    """What a cause's evidence reads off one log, every number its sentence needs (each
    cause has its own kind; the sentence is written outside the model, in
    :mod:`minseg_tui.lab.views.check_says`)."""


Words = Callable[[ev.Log, "Fit", float | None], Shown]
"""What a cause's evidence reads off one log: (the log, the fit that holds the cause, the
speed's noise floor in rad/s when known) -> its :class:`Shown` record."""


@dataclass(frozen=True)
class Candidate:
    """One cause, every piece of it.

    cause / param / unit: contract names (the cause, its parameter) and the parameter's
    unit; field: the :class:`Effects` field it sets (K = 1 units: V, s, V/s); null: the
    value at which it is absent (0, 1 or infinity); log_scale: searched on a log scale. What
    it is, in a sentence, is the entry's docstring; its words for people (a label, what a
    student who has not met it is told, two or three words) are its row of
    :data:`minseg_tui.lab.views.check_says.CAUSE_WORDS`, outside the model.

    range: its search range on a log; starts: the start values of its field; needs: what
    a log must hold to show it (None: every log); words: what its evidence reads off a log;
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
    range: Callable[[Shape], Range]
    starts: Callable[[Seen], list[float]]
    words: Words
    log_scale: bool = False
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
    smooth: Callable[[Fit], Alike] | None = None
    """It acts on the reading, so in a smooth speed column (not a difference of counts) the
    other causes that do cannot be told from it: why, for the fit (the caveat's
    :class:`~.result.Smooth`; the first such cause in a model speaks)."""
    refuse: Callable[[Judged], Refusal | None] | None = None
    """Its own reason it cannot be named in a fit although clear (None: it can), tested
    before the test of the speed's own error."""
    within_sample: bool = False
    """Its parameter is a time, and one under :data:`.decide.SUB_SAMPLE` of the sample period
    is not named (it acts inside the first sample); False: no such test."""
    lag: bool = False
    """It holds the response back after a step (a delay, a pole, an average): at the sample
    period, with a second cause beside it, one such cause can stand in for another."""
    again: Again | None = None
    """A joint fit holding it and :attr:`Again.partner` is fitted again from other starts
    and the better kept."""
    tie: Callable[[Effects, float], Effects] | None = None
    """In some of its ways its field is T itself (the ringing pair's T2, both poles decaying
    with T), and a second parameter of another way means nothing: (the effects, T in s) ->
    the effects with its field set to T where its way ties it, and the other way's second
    parameter at its null. Its interval is then T's."""
    worth: Callable[[Way, Fit], bool] | None = None
    """A way of it fitted only when the best fit of the ways before says so: (the way, that
    fit) -> fit it (None: every way is fitted)."""
    hidden: Hidden | None = None
    """How a generated log (:mod:`minseg_tui.model.synth`) holds it; None: it cannot."""


# -- the causes ---------------------------------------------------------------------------


def _friction_starts(s: Seen) -> list[float]:
    vals = [s.rng.hi * f for f in (0.05, 0.15, 0.35, 0.6)]
    off = levels_offset(s.u, s.y, s.T, s.ts)
    if off is not None and 0 < off < s.rng.hi:
        vals.append(off)
    return vals


@dataclass(frozen=True)
class FrictionStop(Shown):
    """Dry friction seen at a step-down: the drive drops at ``t`` (s) and the wheel stands
    still ``after`` s later (measured, from ``speed`` rad/s, its mean over the ``before`` s
    before the drop), where the first-order model still turns at ``left`` rad/s (None: not
    clearly); ``coast``: it coasts too; ``uc`` (V)."""

    t: float
    after: float
    speed: float
    before: float
    left: float | None
    coast: bool
    uc: float


@dataclass(frozen=True)
class FrictionLevels(Shown):
    """Dry friction seen in the settled speeds: a straight line through them meets zero
    speed at ``off`` (V; None or 0: not said), ``uc`` (V); ``falls``: the log has a
    step-down."""

    off: float | None
    uc: float
    falls: bool


def coulomb_words(log: ev.Log, ext: Fit) -> Shown:
    uc = ext.params["u_c"]
    shown = ev.shown_stop(log, ev.stands_still)
    coast = "coast_on_zero" in ext.causes
    if shown is not None:
        s = shown
        after = s.after if s.after is not None else 0.0
        k = int(np.searchsorted(log.t, log.t[s.row] + after))
        k = min(k, log.t.size - 1)
        left = abs(float(log.base_pred[k]))
        return FrictionStop(
            float(log.t[s.row]),
            after,
            abs(s.speed),
            ev.before_s(log, s),
            left if left > max(log.zero, 2.0 * log.noise) else None,
            coast,
            uc,
        )
    off = levels_offset(log.u, log.y, ext.T, log.ts)
    return FrictionLevels(off, uc, bool(ev.falls(log)))


COULOMB_FRICTION = Candidate(
    "coulomb_friction",
    "u_c",
    "V",
    "u_c",
    0.0,
    range=lambda s: Range(0.0, 0.98 * s.u_min, False),
    starts=_friction_starts,
    words=lambda log, f, floor: coulomb_words(log, f),
    needs=ev.NEEDS_TWO_LEVELS,
    scale="V",
    nonlinear=True,
    hidden=Hidden(0.1, 0.4, lambda p, v: replace(p, tau_c=v * p.motor.k_a / p.motor.R)),
    stop=ev.stands_still,
)
"""Dry friction: the motor needs u_c volts to break away, and a wheel left to itself stops in
finite time."""


def _delay_starts(s: Seen) -> list[float]:
    lags = first_motion(s.t, s.u, s.y, s.noise)
    vals = [f * s.ts for f in (0.5, 1.0, 2.0)] + [0.5 * s.T]
    if lags:
        lag = float(np.median(lags))
        vals += [max(lag - 1.5 * s.ts, 0.0), max(lag - s.ts - 0.3 * s.T, 0.0)]
    return vals


@dataclass(frozen=True)
class Delay(Shown):
    """A delay: the measured speed first moves ``lag`` s after the steps it was settled
    before (None: not read; ``steps`` how many), the fitted delay ``d`` (s); ``slow``: the
    speed moves before that delay ends (the start is slow rather than late; else the claim
    of a pure delay stands, :attr:`Candidate.claim`)."""

    lag: float | None
    steps: int
    d: float
    slow: bool


def dead_time_words(log: ev.Log, ext: Fit) -> Shown:
    """The delay's evidence: when the speed first moves after the steps it was settled
    before (a speed still moving at a step says nothing of the delay), and the fitted
    delay; a pure delay only when the speed does not move before that delay ends (at
    least half a sample earlier: then the start is slow rather than late)."""
    d = ext.params["delay"]
    lags = first_motion(log.t, log.u, log.y, log.noise, settled=True)
    lag = float(np.median(lags)) if lags else None
    return Delay(lag, len(lags), d, lag is not None and lag < d - 0.5 * log.ts)


DEAD_TIME = Candidate(
    "dead_time",
    "delay",
    "s",
    "delay",
    0.0,
    range=lambda s: Range(0.0, max(0.8 * s.shortest, 3.0 * s.ts), False),
    starts=_delay_starts,
    words=lambda log, f, floor: dead_time_words(log, f),
    needs=ev.NEEDS_RISE,
    claim=Claim("second_pole", ("second_pole", "velocity_filter")),
    hidden=Hidden(0.010, 0.060, lambda p, v: replace(p, dead_time=v)),
    within_sample=True,
    lag=True,
)
"""A pure delay between command and motor."""


@dataclass(frozen=True)
class Averaged(Shown):
    """An average of the speed over ``n`` samples of ``ts`` s; ``edges``: how many edges the
    log has; ``smooth``: the speed is a smooth signal; ``noise``: its scatter (rad/s);
    ``floor``: the noise floor one count per sample gives (rad/s, None: not known);
    ``step``: the step its values come in (rad/s, None: not read off)."""

    n: int
    ts: float
    edges: int
    smooth: bool
    noise: float
    floor: float | None
    step: float | None


def filter_words(log: ev.Log, ext: Fit, floor: float | None) -> Shown:
    n = int(ext.params["taps"])
    edges = int(np.count_nonzero(np.diff(log.u)))
    return Averaged(n, log.ts, edges, log.smooth, log.noise, floor, log.step)


FILTER_NOISE = 3.0
"""An average over N samples of counts leaves noise floor/N; a speed that scatters more than
this many times that is not such an average, unless the average also scatters this many
times less than around the first-order model (:attr:`Judged.plain`: the smaller of the
scatter the search was given and the baseline's own, so that a hand's rows do not count):
then the scatter the average leaves is something no model here follows (a load's ripple,
the loop's timing), and the average has taken away most of what the speed scattered by. On
the independent generator's tuning seed 8 (a 9-tap average at 25 ms samples, 1440 counts
per turn) the true average left 0.049 rad/s against a floor of 0.0079 rad/s while the
first-order model left 0.54 and the delay and pole named in its place 0.35; a raw column
scatters as much around an average as around the first-order model. Relaxed only once the
rows of every disturbance are left out (decide.select's relax): a hand the baseline did
not see, left in the rows, let a 13-tap average with T 16 % short (tuning seed 1036, a
9-tap average) scatter 0.14 rad/s against the first-order model's 1.41, and that
average's miss at 4.06 s was reported as a second disturbance beside the hand."""


def _filter_refuse(j: Judged) -> Refusal | None:
    n = j.fit.effects.taps
    fl = j.floor(n)
    own = j.own_noise() if fl is not None and n >= 2 else 0.0
    if fl is not None and n >= 2 and own > FILTER_NOISE * fl and FILTER_NOISE * own > j.plain:
        return Refusal("scatters", own, n, fl)
    return None


VELOCITY_FILTER = Candidate(
    "velocity_filter",
    "taps",
    "samples",
    "taps",
    1.0,
    # an average longer than a short stretch still shows, as a ramp cut off by the next step
    range=lambda s: Range(1.0, float(min(40, s.rows_long)), False),
    starts=lambda s: [1.0],
    words=filter_words,
    needs=ev.NEEDS_RISE,
    counted=True,
    smooth=lambda ext: "filters",
    hidden=Hidden(3, 20, None, whole=True),
    refuse=_filter_refuse,
    lag=True,
)
"""The measured speed is a moving average of the Euler velocity over N samples."""


@dataclass(frozen=True)
class Coast(Shown):
    """A coast at zero command with time constant ``tc`` (s); at the drop to 0 it shows
    (``t``, s; None: no such drop): the speed falls at ``decel`` rad/s^2 over the line from
    the row before the drop to ``after`` s after it, to the first reading under half
    (``half``) or staying above half of its ``w0`` rad/s; a braked motor of time constant
    ``T`` (s) falls at w0/T."""

    tc: float
    t: float | None = None
    decel: float = 0.0
    after: float = 0.0
    half: bool = False
    w0: float = 0.0
    T: float = 0.0


def coast_words(log: ev.Log, ext: Fit) -> Shown:
    tc = ext.params["T_coast"]
    s = ev.shown_stop(log, ev.drops_to_zero)
    if s is None:
        return Coast(tc)
    decel, span, half = _fall_rate(log, s)
    a, w0 = s.row, abs(s.speed)
    return Coast(tc, float(log.t[a]), decel, span - float(log.t[a] - log.t[a - 1]), half, w0, ext.T)


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
    range=lambda s: Range(max(0.5 * s.T, 0.002), 30.0, True),
    starts=lambda s: [s.T * f for f in (1.5, 3.0, 8.0)] + [1.0, 5.0],
    words=lambda log, f, floor: coast_words(log, f),
    log_scale=True,
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
        Refusal("no_slower") if j.fit.value("coast_on_zero") < COAST_RATIO * j.fit.T else None
    ),
)
"""At zero command the bridge is open and the wheel coasts with its own time constant."""


def _pole_smooth(ext: Fit) -> Alike:
    return "pole_measured" if ext.effects.pole_measured else "filters"


def _pole_ways(causes: tuple[str, ...], smooth: bool) -> list[Way]:
    """The sides of an extra pole worth fitting: on the drive always; on the measurement where
    the side shows (a cause that is not linear acts with it), or as the logger's filter of a
    smooth speed column (with no average among the causes: then the average smooths it);
    with a coast, as a driver's lag too (:func:`.fit.fit_causes`); last, as the armature's
    pole in a ringing pair with the wheel's (:func:`_ring_worth` says when)."""
    filt = smooth and not any(BY_CAUSE[c].counted for c in causes)
    out: list[Way] = [{}]
    if NONLINEAR & set(causes):
        out.append({"pole_measured": True, "pole_filtered": filt})
    elif filt:
        out.append({"pole_measured": True, "pole_filtered": True})
    if "coast_on_zero" in causes:
        out.append({"pole_driver": True})
    out.append({"pole_ring": True})
    return out


RING_MAX = 4.0
"""Largest (omega T)^2 of a ringing pair fitted: a damping ratio down to 0.45 (an overshoot of
about 20 %); a motor's armature rings less (an inductance of 0.6 times the mechanical time
constant gives 1.4)."""

RING_NEAR = 0.25
"""A ringing pair is fitted when the best real pair so far has its two time constants within
this factor of each other (a ringing pair is best fitted by two real poles close together:
two poles together at T is where the two kinds meet)."""


def _ring_worth(way: Way, f: Fit) -> bool:
    if not way.get("pole_ring"):
        return True
    # Fitted beside a cap too, though while the cap holds the armature's current is held
    # (L di/dt = 0) and a capped stretch cannot show the inductance ringing with the wheel:
    # the cap holds only on the larger steps, and only until the back-EMF has risen so far
    # that the drive's voltage keeps the current under it; from there the pair runs free,
    # from the cap's current with the wheel still accelerating, and rings on the rest of the
    # rise as after a step; steps that never reach the cap ring in full. Measured (s34-gate):
    # tuning logs of second_pole + current_limit, seeds 0-59, hold 11 with the generator's
    # inductance ringing beside a cap; with no ringing way beside a cap 6 of them went from
    # right to wrong (31, 34, 39, 43: T 23-52 % short; 41, 45: an average named with the cap)
    t2 = f.effects.T2
    return t2 > 0.0 and RING_NEAR <= t2 / f.T <= 1.0 / RING_NEAR


def _ring_tie(fx: Effects, T: float) -> Effects:
    if fx.pole_ring:
        return replace(fx, T2=T) if fx.T2 != T else fx
    return replace(fx, ring=0.0) if fx.ring else fx


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


PoleWay = Literal["filtered", "measured", "driver", "drive", "ringing"]
"""Where an extra pole acts: a filter of a smooth speed column, on the measurement, in the
driver, on the drive (the torque), or the armature's, ringing with the wheel's."""


@dataclass(frozen=True)
class Pole(Shown):
    """An extra pole of ``t2`` s, acting where ``way`` says; ``smooth``: a smooth speed
    column; ``after``: the span (s) after each rise where the speed has risen ``got``
    rad/s (median) against the first-order model's ``model`` (None: no rise long enough);
    ``share``: the share of the new speed each reading of a filter takes; ``beside``: the
    nonlinear causes it acts beside (on the measurement)."""

    t2: float
    way: PoleWay
    smooth: bool
    after: float
    got: float | None
    model: float | None
    share: float = 0.0
    beside: tuple[str, ...] = ()
    period: float = math.inf
    """The ringing pair's period of swing, s (infinite: not a ringing pair, or no swing)."""
    overshoot: float = 0.0
    """The ringing pair's overshoot after a step, as a share of the step (0: none)."""
    ramp: float | None = None
    """Beside a current limit, the speed's own mean slope between 20 % and 70 % of the rise
    (rad/s^2, measured): then ``model`` is what a straight ramp at that slope rises in
    ``after``, not the first-order model (whose shortfall is the cap's evidence, not the
    pole's). None: no cap named, or no rise to read it from."""


def pole_words(log: ev.Log, ext: Fit) -> Shown:
    t2 = ext.params["T2"]
    w = max(2, int(math.ceil(max(t2, ext.T / 2) / log.ts)))
    fx = ext.effects
    if fx.pole_ring:
        # the pair's swing: its period and the overshoot of one step's settling
        om = math.sqrt(max(fx.ring, 0.0)) / ext.T
        period = 2.0 * math.pi / om if om > 0.0 else math.inf
        over = math.exp(-math.pi / (om * ext.T)) if om > 0.0 else 0.0
    else:
        period, over = math.inf, 0.0
    # beside a cap the first-order model's steeper start is the cap's evidence: the pole's
    # is whether the speed starts slower than its own ramp (ubc-motor-9V: 153 rad/s after
    # 285 ms against 212 for the first-order model, but 147 for its own ramp: no slow start)
    ramp = steepest_rate(log.t, log.u, log.y, 1.0) if "current_limit" in ext.causes else None
    got, model = [], []
    for a, b in rises(log.u):
        if b - a <= w:
            continue
        got.append(abs(float(log.y[a + w - 1] - log.y[a - 1])))
        if ramp is not None:
            model.append(ramp * (float(log.t[a + w - 1] - log.t[a]) + 0.5 * log.ts))
        else:
            model.append(abs(float(log.base_pred[a + w - 1] - log.base_pred[a - 1])))
    said_got = float(np.median(got)) if got else None
    said_model = float(np.median(model)) if got else None
    way: PoleWay = (
        "ringing"
        if fx.pole_ring
        else "filtered"
        if fx.pole_filtered
        else "measured"
        if fx.pole_measured
        else "driver"
        if fx.pole_driver
        else "drive"
    )
    beside = tuple(
        c for c in ("coulomb_friction", "coast_on_zero", "current_limit") if c in ext.causes
    )
    share = 1.0 - math.exp(-log.ts / t2) if way == "filtered" else 0.0
    return Pole(
        t2, way, log.smooth, w * log.ts, said_got, said_model, share, beside, period, over, ramp
    )


RING = "pole_ring2"
"""The key among a fit's values of the ringing pair's second parameter, (omega T)^2
(:attr:`Effects.ring`)."""


SECOND_POLE = Candidate(
    "second_pole",
    "T2",
    "s",
    "T2",
    0.0,
    range=lambda s: Range(0.0, 3.0 * s.T, False),
    starts=lambda s: [s.T * f for f in (0.1, 0.25, 0.5, 0.9)],
    words=lambda log, f, floor: pole_words(log, f),
    needs=ev.NEEDS_RISE,
    flags=("pole_measured", "pole_filtered", "pole_driver", "pole_ring"),
    second=(Second(RING, "ring", RING_MAX),),
    ways=_pole_ways,
    tie=_ring_tie,
    worth=_ring_worth,
    carry=_pole_carry,
    claim=Claim("dead_time", ("dead_time",)),
    smooth=_pole_smooth,
    hidden=Hidden(0.010, 0.040, lambda p, v: replace(p, T2=v)),
    within_sample=True,
    lag=True,
)
"""An extra pole delays the torque (the armature's L/R, a driver's own lag) or lags the reading
(a compliant coupling to the encoder, a first-order filter of the speed)."""


@dataclass(frozen=True)
class Cap(Shown):
    """A current limit: the speed ramps at about ``rate`` rad/s^2 (measured; None or 0: not
    read), where the motor without a cap would start at ``uncapped`` rad/s^2 (K u/T of the
    first rise; None: no rise); ``both``: capped braking too, shown at a step down;
    ``a_max`` (rad/s^2)."""

    rate: float | None
    uncapped: float | None
    both: bool
    a_max: float


def limit_words(log: ev.Log, ext: Fit) -> Shown:
    a = ext.params["a_max"]
    r = steepest_rate(log.t, log.u, log.y, 1.0)
    ups = rises(log.u)
    top = None
    if ups:
        k, _ = ups[0]
        jump = abs(float(log.u[k] - log.u[k - 1]))
        top = abs(ext.K) * jump / ext.T
    edges = np.flatnonzero(np.diff(log.u) != 0) + 1
    # a step down (|u| falls, or u reverses): the only place a log shows how the drive brakes
    down = any(abs(log.u[k]) < abs(log.u[k - 1]) or log.u[k] * log.u[k - 1] < 0 for k in edges)
    return Cap(r, top, bool(ext.effects.cap_both and down), a)


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
    range=_cap_range,
    starts=_cap_starts,
    words=lambda log, f, floor: limit_words(log, f),
    log_scale=True,
    needs=ev.NEEDS_RISE,
    reported=lambda value, K: abs(K) * value,  # a_max = |K| rate
    nonlinear=True,
    second=(Second(DRAG, "drag", DRAG_MAX),),
    flags=("cap_both",),
    # capped while accelerating only, and capped both ways
    ways=lambda causes, smooth: [{}, {"cap_both": True}],
    refuse=lambda j: Refusal("ramp_under_sample") if cap_ramp(j.prob, j.fit) < j.prob.ts else None,
    hidden=Hidden(20.0, 60.0, lambda p, v: replace(p, i_max=v * p.motor.J / p.motor.k_a)),
    again=Again("coulomb_friction", _cap_beside_friction),
)
"""The drive caps the current, so the speed ramps at a_max (less what the wheel's own drag
takes as it speeds up) until the back-EMF takes over (on some drives braking after a step
down is capped too)."""


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


def cannot_judge(log: ev.Log) -> dict[str, ev.Lacks]:
    """The causes this log cannot show at all, and why (they are not tried)."""
    return ev.cannot_judge(log, [(c.cause, c.needs) for c in CANDIDATES])
