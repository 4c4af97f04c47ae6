"""Exact simulation of the first-order model and its effects on a piecewise-constant input.

The input of a run log is held between samples: ``u[k]`` is in force from ``t[k]`` to
``t[k+1]``. Every effect the check knows keeps the motor piecewise linear: dry friction
(a constant deceleration while the wheel turns, sticking at rest), coasting at zero
command (its own time constant), an extra pole on the drive, and a current limit (a cap
on the acceleration the drive gives in the direction of motion, or both ways: braking
capped too). Within one *mode*
(coasting, stuck, capped, or driven linearly) the speed is a constant plus at most two
exponentials, or a straight ramp (capped, on a wheel without viscous drag), so the simulation walks the constant-input stretches
once, finds when the mode changes (a stop, a breakaway, the cap starting or ending: in
closed form, or by bisection on a function with at most one extremum, which is found in
closed form) and writes down a table of *pieces*; each gives the wheel angle from its
start:

    theta(tau) = theta0 + c tau + q tau^2 + A1 T1 (1 - exp(-tau/T1)) + A2 T2 (1 - exp(-tau/T2))

Evaluating the angle at the sample instants is then one vectorised expression, at any
instants: a dead time is the same table read ``delay`` seconds earlier, and an extra pole
on the measurement (a compliant coupling, a filtered speed) is the table's angle through a
first-order lag (:func:`lag`; the angle taken straight between the instants it is read at).

Everything is computed with K = 1 (speeds in V, angles in V s, the current limit as a
rate in V/s): every response is proportional to K, which the fit solves for linearly.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

FAR = 1.0e6
"""s: start of the piece that stands for "before the log", and the length of the last stretch."""


@dataclass(frozen=True)
class Stretches:
    """The input as constant stretches: start time (s) and value (V) of each."""

    start: FloatArray
    value: FloatArray

    @classmethod
    def from_samples(cls, t: FloatArray, u: FloatArray) -> Stretches:
        """Stretches of a log whose input ``u[k]`` (V) holds from ``t[k]`` (s) on."""
        change = np.flatnonzero(np.diff(u) != 0) + 1
        idx = np.concatenate(([0], change))
        return cls(start=np.asarray(t, float)[idx], value=np.asarray(u, float)[idx])


Drive = Callable[[FloatArray, float], FloatArray]
"""A cause's own simulation piece when it acts on the input: (the input levels in force,
V; its parameter) -> the levels the motor gets (V at K = 1)."""


@dataclass(frozen=True)
class Extra:
    """A cause that brings its own simulation piece (:attr:`.effects.Candidate.drive`):
    its contract name, its parameter (K = 1 units) and the piece."""

    cause: str
    value: float
    drive: Drive


@dataclass(frozen=True)
class Effects:
    """The effects on top of the first-order model (absent: 0, 1, None or infinity).

    u_c: dry friction as a breakaway voltage, V; delay: dead time, s; taps: the measured
    speed is a moving average over this many samples; T_coast: time constant at zero
    command (the bridge open), s; T2: extra pole on the drive, s; rate: the current limit
    as the largest acceleration the drive gives, in K = 1 units (V/s; a_max = K rate).
    """

    u_c: float = 0.0
    delay: float = 0.0
    taps: int = 1
    T_coast: float | None = None
    T2: float = 0.0
    rate: float = math.inf
    cap_both: bool = False
    """The cap holds while braking too (the drive limits the current's size both ways), not
    only while it accelerates the wheel in its direction of motion."""
    pole_measured: bool = False
    """The extra pole acts on the measurement (a compliant coupling to the encoder, a
    first-order filter of the speed), after the friction, the coast and the cap, instead
    of on the drive."""
    pole_filtered: bool = False
    """With ``pole_measured``: the pole is a first-order filter the logger runs on the speed
    column, sample by sample (y_k = a y_k-1 + (1 - a) m_k, a = exp(-ts/T2), m_k the speed
    of counts), not a lag of the angle (a compliant coupling)."""
    pole_driver: bool = False
    """The extra pole on the drive is a driver's lag of its command, which runs on while the
    bridge is open: through a coast the driver's output falls towards the zero command with
    T2, and the wheel, still turning, meets that output when the bridge closes (braked
    until it rises past the speed). Without it the pole is the armature's L/R: no current
    flows while coasting, and it builds from zero when the bridge closes. The two differ
    only after a coast."""
    pole_ring: bool = False
    """The extra pole on the drive is the armature's L/R, coupled to the wheel through the
    back-EMF, with the motor's two poles a complex pair (an inductance over about a quarter
    of the mechanical time constant): the speed rings, both poles decay with T (s) and
    ``T2`` is that same decay time. The pair's own numbers: the electrical time constant
    T/2 and the mechanical one 2 T/(1 + ring) on a wheel without drag (:func:`ring_constants`).
    Stuck, the current builds with the electrical one; coasting, no current flows; capped,
    the current is held."""
    ring: float = 0.0
    """With ``pole_ring``: (omega T)^2, the pair's angular frequency omega (rad/s) times its
    decay time T (s), squared (0: the two poles together at T, no swing)."""
    drag: float = 0.0
    """The share of the driven damping that is the wheel's own viscous drag (T/J_b with
    J/b the drag's time constant in s, 0 to below 1; the rest is the back-EMF). While the
    current is capped the back-EMF no longer brakes but the drag still does, so the capped
    speed bends: w' = rate - drag w/T (not a straight ramp), and the cap lets go when the
    torque the drive asks for, (v - (1 - drag) w)/T, falls to the cap."""
    extra: tuple[Extra, ...] = ()
    """The causes that bring their own piece: each acts on the input before the modes above
    (in this order)."""


class Pieces:
    """Growing table of closed-form pieces (see the module docstring). A piece of a ringing
    pair of poles (:attr:`Effects.pole_ring`) has, in place of its second exponential, a
    damped oscillation of the speed: exp(-tau/t2) (ra cos(om tau) + rb sin(om tau)) (V at
    K = 1; om in rad/s), whose angle is its integral from the piece's start."""

    def __init__(self) -> None:
        self.rows: list[tuple[float, float, float, float, float, float, float, float]] = []
        self.ring: list[tuple[int, float, float, float]] = []
        """(row, ra, rb, om) of each piece with a damped oscillation (its decay time in t2)."""
        self.quadratic = False
        """Some piece has a quadratic term (q != 0)."""
        self.two_exp = False
        """Some piece has a second exponential (a2 != 0)."""

    def add(
        self,
        t0: float,
        th0: float,
        c: float,
        q: float = 0.0,
        a1: float = 0.0,
        t1: float = 1.0,
        a2: float = 0.0,
        t2: float = 1.0,
    ) -> None:
        self.rows.append((t0, th0, c, q, a1, t1, a2, t2))
        if q:
            self.quadratic = True
        if a2:
            self.two_exp = True

    def add_ring(
        self, t0: float, th0: float, c: float, ra: float, rb: float, decay: float, om: float
    ) -> None:
        """A piece whose speed is c + exp(-tau/decay) (ra cos(om tau) + rb sin(om tau))."""
        self.ring.append((len(self.rows), ra, rb, om))
        self.rows.append((t0, th0, c, 0.0, 0.0, 1.0, 0.0, decay))

    def angle(self, tau: FloatArray) -> FloatArray:
        """Angle (V s at K = 1) at the instants ``tau`` (s, ascending or not)."""
        t0, th0, c, q, a1, t1, a2, t2 = np.asarray(self.rows, dtype=float).T
        i = np.searchsorted(t0, tau, side="right") - 1
        np.maximum(i, 0, out=i)
        dt = tau - t0[i]
        # th0 + (c + q dt) dt - a1 t1 expm1(-dt/t1) - a2 t2 expm1(-dt/t2); the quadratic
        # and the second exponential left out when they are 0 in every piece (the same
        # numbers, fewer passes)
        lin = c[i] + q[i] * dt if self.quadratic else c[i]
        out: FloatArray = th0[i] + lin * dt
        out -= (a1 * t1)[i] * np.expm1(-dt / t1[i])
        if self.two_exp:
            out -= (a2 * t2)[i] * np.expm1(-dt / t2[i])
        if self.ring:
            idx, ra, rb, om = (np.asarray(x) for x in zip(*self.ring, strict=True))
            at = np.full(t0.size, -1)
            at[idx.astype(int)] = np.arange(idx.size)
            j = at[i]
            on = j >= 0
            if np.any(on):
                k = j[on]
                out[on] += ring_integral(ra[k], rb[k], t2[i[on]], om[k], dt[on])
        return out


def ring_integral(
    ra: FloatArray | float,
    rb: FloatArray | float,
    decay: FloatArray | float,
    om: FloatArray | float,
    tau: FloatArray | float,
) -> FloatArray:
    """The integral from 0 to ``tau`` (s) of exp(-s/decay) (ra cos(om s) + rb sin(om s)):
    Re(C (exp(z tau) - 1)/z) with C = ra - j rb and z = -1/decay + j om."""
    z = -1.0 / np.asarray(decay, dtype=float) + 1j * np.asarray(om, dtype=float)
    cc = np.asarray(ra, dtype=float) - 1j * np.asarray(rb, dtype=float)
    out: FloatArray = np.real(cc * np.expm1(z * np.asarray(tau, dtype=float)) / z)
    return out


def ring_integral_at(ra: float, rb: float, decay: float, om: float, tau: float) -> float:
    """:func:`ring_integral` for one piece at one instant, in plain floats: the same steps as
    numpy takes for it (its complex expm1, exp(x) - 1 as expm1(x) cos(y) - 2 sin(y/2)^2 +
    j exp(x) sin(y), and Smith's division), so the same number, without numpy's cost on
    scalars (about 6 of the 7 us a call took)."""
    zr, zi = -1.0 / decay, om
    x, y = zr * tau, zi * tau
    if not (math.isfinite(x) and math.isfinite(y)):
        return float(ring_integral(ra, rb, decay, om, tau))
    half = math.sin(0.5 * y)
    er, ei = math.expm1(x) * math.cos(y) - 2.0 * half * half, math.exp(x) * math.sin(y)
    nr, ni = ra * er - (-rb) * ei, ra * ei + (-rb) * er  # (ra - j rb) (exp(z tau) - 1)
    if abs(zr) >= abs(zi):
        rat = zi / zr
        return (nr + ni * rat) * (1.0 / (zr + zi * rat))
    rat = zr / zi
    return (nr * rat + ni) * (1.0 / (zi + zr * rat))


def _exp(x: float) -> float:
    return math.exp(x) if x > -700.0 else 0.0


Form = tuple[float, ...]
"""The coefficients of a function whose sign change a stretch's event is: 10 numbers
(s, k, a1, t1, m, k2, a2, t2, r, off) for

    s (k + a1 exp(-tau/t1) - m (k2 + a2 exp(-tau/t2) + r tau)) - off

(:func:`_exp` for exp; t1, t2 in s, the rest in the units of the quantity) or 5 numbers
(k, -sig, p, q, om) for a damped swing about a constant,

    k + exp(-sig tau) (p cos(om tau) + q sin(om tau))

(sig in 1/s, om in rad/s). The searches evaluate these inline: a Python call per evaluation
(a closure, and _exp twice in it) cost as much as the arithmetic."""


def _value(c: Form, tau: float) -> float:
    """The function of the coefficients ``c`` (:data:`Form`) at ``tau`` (s)."""
    if len(c) == 5:
        k, ns, p, q, om = c
        x = ns * tau
        return k + (math.exp(x) if x > -700.0 else 0.0) * (
            p * math.cos(om * tau) + q * math.sin(om * tau)
        )
    s, k, a1, t1, m, k2, a2, t2, r, off = c
    x1, x2 = -tau / t1, -tau / t2
    e1 = math.exp(x1) if x1 > -700.0 else 0.0
    e2 = math.exp(x2) if x2 > -700.0 else 0.0
    return s * (k + a1 * e1 - m * (k2 + a2 * e2 + r * tau)) - off


def _first_zero(c: Form, t_ext: float | None, length: float) -> float | None:
    """First tau in (0, length] where the function of ``c`` (:data:`Form`) changes sign, for
    one with at most one extremum in between (at ``t_ext`` when given); None when it does
    not."""
    cuts = [0.0]
    if t_ext is not None and 0.0 < t_ext < length:
        cuts.append(t_ext)
    cuts.append(length)
    return _zero_between(c, cuts)


def _zero_between(c: Form, cuts: list[float], f0: float | None = None) -> float | None:
    """First tau after ``cuts[0]`` (s, 0 or later) where the function of ``c`` (:data:`Form`)
    changes sign, for one monotonic between neighbouring ``cuts`` (ascending; the last is the
    end of the span); None when it does not. ``f0``: its value at ``cuts[0]``, if known.
    Where it changes sign, regula falsi (Illinois) to 1e-10 s gives the end on the far side.

    The function is written out where it is evaluated, at the cuts and in the search, once
    per form: a call per evaluation cost about as much as the arithmetic."""
    exp, cos, sin = math.exp, math.cos, math.sin
    ring = len(c) == 5
    if ring:
        k, ns, p, q, om = c
        sg = k1 = a1 = t1 = mm = k2 = a2 = t2 = r = off = 0.0
    else:
        sg, k1, a1, t1, mm, k2, a2, t2, r, off = c
        k = ns = p = q = om = 0.0
    # each cut's value is computed once and handed on as the next span's start
    fb = 0.0 if f0 is None else f0
    a = cuts[0]
    for i in range(0 if f0 is None else 1, len(cuts)):
        b = cuts[i]
        fa = fb
        if ring:
            x = ns * b
            fb = k + (exp(x) if x > -700.0 else 0.0) * (p * cos(om * b) + q * sin(om * b))
        else:
            x1, x2 = -b / t1, -b / t2
            e1 = exp(x1) if x1 > -700.0 else 0.0
            e2 = exp(x2) if x2 > -700.0 else 0.0
            fb = sg * (k1 + a1 * e1 - mm * (k2 + a2 * e2 + r * b)) - off
        if i == 0:
            continue
        if a == 0.0 and fa == 0.0:
            fa = _value(c, min(1e-12, b))
        if fa == 0.0 or (fa > 0.0) == (fb > 0.0):
            a = b
            continue
        side = 0
        for _ in range(60):
            m = (a * fb - b * fa) / (fb - fa)
            if not a < m < b:
                m = 0.5 * (a + b)
            if ring:
                x = ns * m
                fm = k + (exp(x) if x > -700.0 else 0.0) * (p * cos(om * m) + q * sin(om * m))
            else:
                x1, x2 = -m / t1, -m / t2
                e1 = exp(x1) if x1 > -700.0 else 0.0
                e2 = exp(x2) if x2 > -700.0 else 0.0
                fm = sg * (k1 + a1 * e1 - mm * (k2 + a2 * e2 + r * m)) - off
            if (fm > 0.0) == (fa > 0.0):
                a, fa = m, fm
                if side == -1:
                    fb *= 0.5
                side = -1
            else:
                b, fb = m, fm
                if side == 1:
                    fa *= 0.5
                side = 1
            if b - a < 1e-10 * max(1.0, b) or fm == 0.0:
                break
        return b
    return None


def _two_exp_extremum(k1: float, t1: float, k2: float, t2: float) -> float | None:
    """Where d/dtau (k1 exp(-tau/t1) + k2 exp(-tau/t2)) = 0, if anywhere after 0."""
    if k1 == 0.0 or k2 == 0.0 or t1 == t2:
        return None
    r = -(k2 / t2) / (k1 / t1)
    if r <= 0.0:
        return None
    x = math.log(r) / (1.0 / t2 - 1.0 / t1)
    return x if x > 0.0 else None


class _State:
    """Speed w (V), drive after the extra pole v (V) and angle th (V s) at time t (s)."""

    __slots__ = ("capping", "t", "th", "v", "w")

    def __init__(self, t: float, w: float, v: float, th: float) -> None:
        self.t, self.w, self.v, self.th = t, w, v, th
        self.capping = False  # the last piece ended where the cap starts to hold


def pieces(st: Stretches, T: float, fx: Effects, z0: float | None = 0.0) -> Pieces:
    """The angle table of the model (T, fx) on the input ``st`` (K = 1).

    ``z0`` is the initial speed (V at K = 1); None means steady state under the first input.
    The dead time and the measurement (``fx.delay``, ``fx.taps``) are applied when the
    table is read (:func:`response`). The causes with their own piece (``fx.extra``) change
    the levels the motor gets; whether the bridge is open (a coast) follows the command.
    """
    command = st.value
    for x in fx.extra:
        st = Stretches(st.start, x.drive(st.value, x.value))
    T2 = fx.T2 if fx.T2 > 0.0 and not fx.pole_measured else 0.0
    tq = 0.0
    if T2 and fx.pole_ring:
        T2, tq = ring_constants(T, fx.ring, fx.drag)
    elif T2 and abs(T2 - T) < 1e-6 * T:
        T2 = T * (1.0 + 1e-6)
    steady = z0 is None
    if z0 is None:
        u0 = float(st.value[0])
        coasting = fx.T_coast is not None and command[0] == 0.0
        z0 = 0.0 if coasting else u0 - math.copysign(min(fx.u_c, abs(u0)), u0)
    out = Pieces()
    out.add(float(st.start[0]) - FAR, -z0 * FAR, z0)
    ends = [*st.start[1:].tolist(), math.inf]
    if not T2 and fx.u_c == 0.0 and fx.T_coast is None and math.isinf(fx.rate):
        # plain first order: one exponential piece per stretch, no events
        w, th = z0, 0.0
        for t0, t1, u in zip(st.start.tolist(), ends, st.value.tolist(), strict=True):
            a = w - u
            out.rows.append((t0, th, u, 0.0, a, T, 0.0, 1.0))
            if math.isfinite(t1):
                e = _exp(-(t1 - t0) / T)
                th += u * (t1 - t0) + a * T * (1.0 - e)
                w = u + a * e
        return out
    v0 = z0 if T2 else float(st.value[0])
    if tq and fx.T2 > 0.0:
        # the ringing pair's drive is the current's voltage plus the back-EMF: steady, the
        # level in force; with no current, the back-EMF
        v0 = float(st.value[0]) if steady else (1.0 - fx.drag) * z0
    s = _State(float(st.start[0]), z0, v0, 0.0)
    levels = zip(st.start.tolist(), ends, st.value.tolist(), command.tolist(), strict=True)
    for t0, t1, u, asked in levels:
        s.t = t0
        if not T2:
            s.v = u
        coast = fx.T_coast is not None and asked == 0.0
        _stretch(out, s, t1 - t0 if math.isfinite(t1) else FAR, u, T, T2, fx, coast, tq)
    return out


def _stretch(
    out: Pieces,
    s: _State,
    left: float,
    u: float,
    T: float,
    T2: float,
    fx: Effects,
    coast: bool,
    tq: float = 0.0,
) -> None:
    """Advance ``s`` by ``left`` s under the input u (V), adding the pieces to ``out``;
    ``coast``: the bridge is open (zero command, a coasting driver); ``tq`` (s): the
    ringing pair's mechanical time constant (0: no ringing pair; then T2 is its electrical
    one)."""
    uc, rate = fx.u_c, fx.rate
    for _ in range(12):  # a stretch changes mode a few times at most
        if left <= 0.0:
            return
        if coast:
            assert fx.T_coast is not None
            v0, before = s.v, left
            left = _coast(out, s, left, max(fx.T_coast, T), uc / T)
            if T2 and fx.pole_driver:
                s.v = v0 * _exp(-(before - left) / T2)
            elif tq:
                s.v = (1.0 - fx.drag) * s.w  # no current: the drive is the back-EMF
            continue
        drive = s.v
        if s.w == 0.0 and (abs(drive) < uc or drive == 0.0 and (u == 0.0 or not T2)):
            left = _stuck(out, s, left, u, uc, T2)
            continue
        sign = math.copysign(1.0, s.w if s.w != 0.0 else drive if drive != 0.0 else u)
        push = sign * (drive - (1.0 - fx.drag) * s.w)  # the torque asked for
        tm = tq or T
        over = tm * rate * (1.0 + 1e-9)
        if math.isfinite(rate) and (s.capping or push > over or (fx.cap_both and -push > over)):
            s.capping = False
            d = 1.0 if push > 0.0 else -1.0
            left = _capped(out, s, left, u, sign, tm, 0.0 if tq else T2, uc, rate, d, fx.drag)
            if tq and (left <= 0.0 or s.w == 0.0):
                # the current still held at the cap
                s.v = (1.0 - fx.drag) * s.w + d * sign * tm * rate
        elif tq:
            left = _ring(out, s, left, u, sign, T, tq, uc, rate, fx, T2)
        else:
            left = _linear(out, s, left, u, sign, T, T2, uc, rate, fx.cap_both, fx.drag)
    out.add(s.t, s.th, 0.0)  # pathological chattering: hold (never met in practice)


def _coast(out: Pieces, s: _State, left: float, tc: float, d: float) -> float:
    """The bridge open: w' = -w/tc - d sgn(w), no drive; the wheel stops if d > 0."""
    s.v = s.w  # no current
    if s.w == 0.0:
        out.add(s.t, s.th, 0.0)
        s.t += left
        return 0.0
    sign = math.copysign(1.0, s.w)
    c = -sign * d * tc
    a = s.w - c
    out.add(s.t, s.th, c, 0.0, a, tc)
    stop = tc * math.log(a / -c) if d > 0.0 else math.inf
    h = min(stop, left)
    e = _exp(-h / tc)
    s.th += c * h + a * tc * (1.0 - e)
    s.w = 0.0 if h == stop else c + a * e
    s.v, s.t = s.w, s.t + h
    return left - h


def _stuck(out: Pieces, s: _State, left: float, u: float, uc: float, T2: float) -> float:
    """At rest while the drive cannot break away (|v| <= u_c); with an extra pole the drive
    moves towards u and may break away later in the stretch."""
    out.add(s.t, s.th, 0.0)
    if not T2 or abs(u) <= uc or s.v == u:
        h = left
    elif uc == 0.0:
        h = 0.0
    else:
        target = math.copysign(uc, u)
        h = min(T2 * math.log((s.v - u) / (target - u)), left)
    if T2:
        s.v = u + (s.v - u) * _exp(-h / T2)
        if h < left and uc > 0.0:
            s.v = math.copysign(uc * (1.0 + 1e-12), u)
    s.t += h
    return left - h


def _capped(
    out: Pieces,
    s: _State,
    left: float,
    u: float,
    sign: float,
    T: float,
    T2: float,
    uc: float,
    rate: float,
    d: float = 1.0,
    drag: float = 0.0,
) -> float:
    """The current limit holds: w' = sign (d rate - u_c/T) - drag w/T (d = 1 while the drive
    accelerates the wheel, -1 while it brakes it): a straight ramp without drag, else an
    exponential towards T/drag times the ramp's rate, until the drive no longer asks for
    more than the cap (or, braking or with the cap below friction, the wheel stops)."""
    acc = sign * (d * rate - uc / T)
    w0, v0 = s.w, s.v
    keep = 1.0 - drag  # the share of the speed the back-EMF takes from the drive
    if drag > 0.0:
        tc = T / drag
        w_inf = acc * tc
        a = w0 - w_inf
        out.add(s.t, s.th, w_inf, 0.0, a, tc)
        ramp = (w_inf, a, tc, 0.0)  # the speed: w_inf + a exp(-tau/tc)
    else:
        out.add(s.t, s.th, w0, 0.5 * acc)
        ramp = (w0, 0.0, 1.0, acc)  # the speed: w0 + acc tau
    events = []
    stop = math.inf
    if sign * acc < 0.0:
        stop = abs(w0 / acc) if drag == 0.0 else tc * math.log(a / -w_inf)
        events.append(stop)
    if not T2:
        # d sign (u - keep w) = T rate at w = w_end
        w_end = (u - d * sign * T * rate) / keep
        if drag == 0.0:
            if d * sign * acc > 0.0:
                events.append((d * sign * (u - w0) - T * rate) / (d * sign * acc))
        elif d * sign * a < 0.0:
            # the torque asked for falls only while the speed moves towards w_inf this way
            ratio = (w_end - w_inf) / a
            if 0.0 < ratio <= 1.0:
                events.append(-tc * math.log(ratio))
    else:
        # d sign (u + (v0 - u) exp(-tau/T2) - keep w) - T rate
        g = (d * sign, u, v0 - u, T2, keep, *ramp, T * rate)
        if drag > 0.0:
            ext = _two_exp_extremum(v0 - u, T2, -keep * a, tc)
        else:
            ext = None
            if (v0 - u) != 0.0 and -acc * T2 / (v0 - u) > 0.0:
                x = -T2 * math.log(-acc * T2 / (v0 - u))
                ext = x if x > 0.0 else None
        hit = _first_zero(g, ext, min(left, 50.0 * T2 + 50.0 * T))
        if hit is not None:
            events.append(hit)
    h = min([left, *[e for e in events if e >= 0.0]])
    if drag > 0.0:
        e = _exp(-h / tc)
        s.th += w_inf * h + a * tc * (1.0 - e)
        s.w = w_inf + a * e
    else:
        s.th += w0 * h + 0.5 * acc * h * h
        s.w = w0 + acc * h
    if h == stop:
        s.w = 0.0
    if T2:
        s.v = u + (v0 - u) * _exp(-h / T2)
    s.t += h
    if h < left and s.w != 0.0:
        # nudge past the switch so the next mode is the linear one
        s.v = s.v if T2 else u
        if math.isfinite(rate) and d * sign * (s.v - keep * s.w) > T * rate:
            s.w = (s.v - d * sign * T * rate) / keep
    return left - h


def _ring_zero(k: float, p: float, q: float, sig: float, om: float, length: float) -> float | None:
    """First tau in (0, length] where k + exp(-sig tau) (p cos(om tau) + q sin(om tau))
    changes sign (sig in 1/s, om in rad/s); None when it does not. Its extrema are where
    the derivative, exp(-sig tau) (p' cos + q' sin), is zero: every pi/om from the first."""
    dp, dq = -sig * p + om * q, -sig * q - om * p
    g = (k, -sig, p, q, om)
    half = math.pi / om
    first = (math.atan2(dq, dp) + 0.5 * math.pi) % math.pi / om
    cuts = [0.0]
    x = first
    g0 = _value(g, 0.0)
    known: float | None = g0  # the value at the first cut
    if abs(g0) <= 1e-9 * (abs(k) + abs(p) + abs(q)):
        # it starts on zero (a breakaway, a cap just let go): up to its first extremum it
        # moves one way, and a crossing there would be the start itself, rounding's sign
        if first <= 1e-6 * half:
            first += half  # the start is itself an extremum (a cap just let go)
        if first >= length:
            return None
        cuts, x, known = [first], first + half, None
    while x < length and len(cuts) < 400:
        if x > 0.0:
            cuts.append(x)
        x += half
    cuts.append(length)
    return _zero_between(g, cuts, known)


RING_FLOOR = 0.004
"""Added to a ringing pair's (omega T)^2 (:attr:`Effects.ring`): its swing then lasts at most
50 T, the span over which a stretch's events are looked for, so every extremum of the speed
inside that span is found in closed form (and a pair with no swing at all is a damping
ratio of 0.998 away)."""


def ring_constants(T: float, ring: float, drag: float) -> tuple[float, float]:
    """(electrical, mechanical) time constants (s) of the ringing pair whose poles both decay
    with T (s) and swing at omega = sqrt(ring + RING_FLOOR)/T, on a wheel whose viscous drag
    is the share ``drag`` of its damping: the pair's characteristic polynomial is
    te tm s^2 + (tm + drag te) s + 1 = T^2/(1 + r) s^2 + 2 T/(1 + r) s + 1."""
    r = max(ring, 0.0) + RING_FLOOR
    a, b = T * T / (1.0 + r), 2.0 * T / (1.0 + r)
    if drag <= 0.0:
        return a / b, b
    te = (b - math.sqrt(max(b * b - 4.0 * drag * a, 0.0))) / (2.0 * drag)
    return te, a / te


def _ring(
    out: Pieces,
    s: _State,
    left: float,
    u: float,
    sign: float,
    T: float,
    tq: float,
    uc: float,
    rate: float,
    fx: Effects,
    te: float,
) -> float:
    """Driven, below the cap, the ringing pair (:attr:`Effects.pole_ring`): tq w' = q - drag w
    - u_c sgn(w) and te q' = u - q - (1 - drag) w, with q = v - (1 - drag) w the current's
    own voltage (K = 1). About the steady speed c = u - u_c sgn(w) the speed is c +
    exp(-tau/T) (A cos + B sin)(om tau); it ends at a stop or where the cap starts to hold
    (|q| reaches tq rate)."""
    drag, both = fx.drag, fx.cap_both
    f = sign * uc
    c = u - f
    sig = 1.0 / T
    om = math.sqrt(max(fx.ring, 0.0) + RING_FLOOR) / T
    a = s.w - c
    q0 = s.v - (1.0 - drag) * s.w
    b = ((q0 - drag * s.w - f) / tq + sig * a) / om
    da, db = -sig * a + om * b, -sig * b - om * a  # the speed's derivative, the same form
    # q = f + drag w + tq w': its constant and its swing
    qk, qa, qb = f + drag * c, drag * a + tq * da, drag * b + tq * db
    out.add_ring(s.t, s.th, c, a, b, T, om)
    horizon = min(left, 50.0 * T)
    events: list[float] = []
    stop_at = cap_at = math.inf
    if uc > 0.0 or math.isfinite(rate):
        hit = _ring_zero(sign * c, sign * a, sign * b, sig, om, horizon)
        if hit is not None:
            stop_at = hit
            events.append(hit)
    if math.isfinite(rate):
        for d in (1.0, -1.0) if both else (1.0,):
            k = d * sign
            hit = _ring_zero(k * qk - tq * rate, k * qa, k * qb, sig, om, horizon)
            if hit is not None:
                events.append(hit)
                cap_at = min(cap_at, hit)
    h = min([left, *events])
    s.capping = h == cap_at and h < left
    e, cs, sn = _exp(-h * sig), math.cos(om * h), math.sin(om * h)
    s.th += c * h + ring_integral_at(a, b, T, om, h)
    s.w = c + e * (a * cs + b * sn)
    q = qk + e * (qa * cs + qb * sn)
    if h == stop_at and h < left:
        s.w = 0.0
    s.v = q + (1.0 - drag) * s.w
    s.t += h
    return left - h


def _linear(
    out: Pieces,
    s: _State,
    left: float,
    u: float,
    sign: float,
    T: float,
    T2: float,
    uc: float,
    rate: float,
    both: bool = False,
    drag: float = 0.0,
) -> float:
    """Driven, below the cap: T w' = v - w - u_c sgn(w), T2 v' = u - v; ends at a stop (the
    speed reaches 0 with friction or a cap about), or when the cap starts to hold (the
    torque asked for, (v - (1 - drag) w)/T, reaches the cap)."""
    c = u - sign * uc
    w0, v0 = s.w, s.v
    if T2:
        B = (v0 - u) * T2 / (T2 - T)
        A = w0 - c - B
    else:
        B, A = 0.0, w0 - c
    out.add(s.t, s.th, c, 0.0, A, T, B, T2 if T2 else 1.0)
    events: list[float] = []
    stop_at = math.inf
    if uc > 0.0 or math.isfinite(rate):
        if not T2:
            if sign * c < 0.0 and w0 != 0.0:
                stop_at = T * math.log((w0 - c) / -c)
        else:
            # sign (c + A exp(-tau/T) + B exp(-tau/T2))
            w = (sign, c, A, T, 1.0, 0.0, -B, T2, 0.0, 0.0)
            hit = _first_zero(w, _two_exp_extremum(A, T, B, T2), min(left, 50.0 * (T + T2)))
            if hit is not None:
                stop_at = hit
        events.append(stop_at)
    cap_at = math.inf
    keep = 1.0 - drag
    if T2 and math.isfinite(rate):
        # s (v - keep w) - T rate = sign (u - keep c + kv e2 - keep A e1) - T rate
        kv = v0 - u - keep * B
        base = u - keep * c

        for d in (1.0, -1.0) if both else (1.0,):
            # d sign (base + kv exp(-tau/T2) - keep A exp(-tau/T)) - T rate
            g = (d * sign, base, kv, T2, 1.0, 0.0, keep * A, T, 0.0, T * rate)
            hit = _first_zero(
                g, _two_exp_extremum(kv, T2, -keep * A, T), min(left, 50.0 * (T + T2))
            )
            if hit is not None:
                events.append(hit)
                cap_at = min(cap_at, hit)
    elif drag > 0.0 and math.isfinite(rate) and A != 0.0:
        # with drag the torque asked for at the end of a stretch need not be below the cap
        for d in (1.0, -1.0) if both else (1.0,):
            if d * sign * A <= 0.0:
                continue  # the torque asked for falls this way: the cap cannot start
            e1 = (d * sign * (u - keep * c) - T * rate) / (d * sign * keep * A)
            if 0.0 < e1 < 1.0:
                hit = -T * math.log(e1)
                events.append(hit)
                cap_at = min(cap_at, hit)
    h = min([left, *events])
    s.capping = h == cap_at and h < left
    e1 = _exp(-h / T)
    e2 = _exp(-h / T2) if T2 else 0.0
    s.th += c * h + A * T * (1.0 - e1) + (B * T2 * (1.0 - e2) if T2 else 0.0)
    s.w = c + A * e1 + B * e2
    if T2:
        s.v = u + (v0 - u) * e2
    s.t += h
    if h == stop_at and h < left:
        s.w = 0.0
    return left - h


def measured(
    theta: FloatArray,
    t: FloatArray,
    before: FloatArray,
    ts: float,
    taps: int,
    over_interval: bool,
) -> FloatArray:
    """The measured speed on every row from the angle at the rows (``theta``) and at the
    ``taps`` nominal periods before the first row (``before``, oldest first):
    (theta_k - theta_k-N)/(N ts), or over the real interval t_k - t_k-N when
    ``over_interval``."""
    n = taps
    th = np.concatenate((before, theta))
    d = th[n:] - th[:-n]
    if not over_interval:
        out: FloatArray = d / (n * ts)
        return out
    tt = np.concatenate((t[0] - ts * np.arange(n, 0, -1), t))
    over: FloatArray = d / (tt[n:] - tt[:-n])
    return over


def response(
    st: Stretches,
    t: FloatArray,
    ts: float,
    T: float,
    fx: Effects,
    z0: float | None = 0.0,
    over_interval: bool = False,
) -> FloatArray:
    """The measured speed the model (T, fx) predicts on every row (K = 1), as the log
    measured it: the angle difference over ``fx.taps`` samples divided by the nominal
    period (or by the real interval, ``over_interval``); the angle ``fx.taps`` periods
    before the first row is taken too, so a log that starts moving reads right at once."""
    n = fx.taps
    tb = t[0] - ts * np.arange(n, 0, -1)
    theta = angle_at(pieces(st, T, fx, z0), np.concatenate((tb, t)), fx)
    out = measured(theta[n:], t, theta[:n], ts, n, over_interval)
    if fx.pole_filtered and fx.pole_measured and fx.T2 > 0.0:
        out = iir(out, math.exp(-ts / fx.T2))
    return out


def angle_at(table: Pieces, times: FloatArray, fx: Effects) -> FloatArray:
    """The angle the encoder reads at ``times`` (s, ascending; V s at K = 1): the table read
    ``fx.delay`` earlier, and through the extra pole when it acts on the measurement."""
    theta = table.angle(times - fx.delay)
    if fx.pole_measured and fx.T2 > 0.0 and not fx.pole_filtered:
        theta = lag(times, theta, fx.T2)
    return theta


_LAG_SPAN = 200.0
"""Time constants the closed-form sum of :func:`lag` covers at once (e^200 stays finite)."""


def lag(times: FloatArray, x: FloatArray, tau: float) -> FloatArray:
    """x (given at ``times``, s, ascending, straight between them) through a first-order
    lag of time constant ``tau`` (s), exactly for a piecewise-linear input; it starts where a
    ramp at the first interval's slope would have brought it (a log that starts moving).

    Per interval h: y_k = a y_k-1 + (1 - a) x_k-1 + (x_k - x_k-1)(1 - tau (1 - a)/h) with
    a = exp(-h/tau), summed in closed form over spans of ``_LAG_SPAN`` time constants."""
    n = x.size
    if n < 2:
        return x.copy()
    h = np.diff(times)
    h = np.where(h > 0, h, 1e-12)
    a = np.exp(-h / tau)
    dx = np.diff(x)
    b = (1.0 - a) * x[:-1] + dx * (1.0 - tau * (1.0 - a) / h)
    out = np.empty(n)
    out[0] = x[0] - tau * dx[0] / h[0]
    if float(np.min(h)) > 30.0 * tau:
        out[1:] = b  # a lag far shorter than a sample: each reading forgets the one before
        return out
    elapsed = np.concatenate(([0.0], np.cumsum(h))) / tau
    start = 0
    while start < n - 1:
        if elapsed[start + 1] - elapsed[start] > _LAG_SPAN:
            out[start + 1] = b[start]  # a gap of many time constants: nothing carries over
            start += 1
            continue
        stop = int(np.searchsorted(elapsed, elapsed[start] + _LAG_SPAN, side="right"))
        stop = min(stop, n)
        e = elapsed[start + 1 : stop] - elapsed[start]
        grow = np.exp(e)  # 1 / prod(a) from the span's start
        out[start + 1 : stop] = (out[start] + np.cumsum(b[start : stop - 1] * grow)) / grow
        start = stop - 1
    return out


def iir(y: FloatArray, a: float) -> FloatArray:
    """``y`` through y_k = a y_k-1 + (1 - a) y_k-in (a first-order filter of a speed column
    as a logger runs it, a = exp(-ts/T2)), settled on the first row: summed in closed form
    over spans of ``_LAG_SPAN`` time constants."""
    n = y.size
    if n == 0 or not 0.0 < a < 1.0:
        return y.copy()
    b = (1.0 - a) * y
    b[0] = y[0]
    out = np.empty(n)
    step = -math.log(a)  # time constants per row
    span = max(1, int(_LAG_SPAN / step))
    carry = 0.0
    for start in range(0, n, span):
        stop = min(n, start + span)
        grow = np.exp(np.arange(stop - start) * step)
        out[start:stop] = (a * carry + np.cumsum(b[start:stop] * grow)) / grow
        carry = float(out[stop - 1])
    return out


def restart(
    st: Stretches,
    t: FloatArray,
    ts: float,
    T: float,
    fx: Effects,
    row: int,
    over_interval: bool = False,
) -> FloatArray:
    """The measured speed (K = 1 units, per unit of departure) that a wheel off the model's
    speed at the start of row ``row``'s reading adds to the model's from that row on: 0 on the
    rows before it. A wheel a hand let go of picks up from the speed the hand left it at; the
    model's own speed is the same equation from another start, so the difference dies away
    with the motor's time constant T (s; while coasting, ``fx.T_coast``), through the same
    dead time, average and pole on the measurement as the model's speed. Dry friction, the
    cap and the wheel stopping are not followed: the departure is assumed to stay in the
    linear range (it has mostly died away where the rows are taken up again).

    The departure is started ``fx.delay`` before the first instant the reading of ``row``
    looks at (the sample ``fx.taps`` periods earlier); started earlier, it would only be a
    multiple of the same rows' values."""
    n = fx.taps
    out = np.zeros(t.size)
    if row >= t.size:
        return out
    tt = np.concatenate((t[0] - ts * np.arange(n, 0, -1), t))
    tau0 = float(tt[max(row, 0)]) - fx.delay
    table = Pieces()
    table.add(tau0 - FAR, 0.0, 0.0)
    starts = st.start.tolist()
    values = st.value.tolist()
    th, amp = 0.0, 1.0
    i = max(int(np.searchsorted(st.start, tau0, side="right")) - 1, 0)
    s0 = tau0
    while True:
        coast = fx.T_coast is not None and values[i] == 0.0
        tc = max(fx.T_coast, T) if coast and fx.T_coast is not None else T
        table.add(s0, th, 0.0, 0.0, amp, tc)
        if i + 1 >= len(starts):
            break
        s1 = float(starts[i + 1])
        e = _exp(-(s1 - s0) / tc)
        th += amp * tc * (1.0 - e)
        amp *= e
        s0, i = s1, i + 1
        if amp < 1e-12:
            table.add(s0, th, 0.0)
            break
    # nothing before the first instant read (one more, at rest, starts a lag at rest)
    lo = max(row - 1, 0)
    theta = np.zeros(tt.size)
    theta[lo:] = angle_at(table, tt[lo:], fx)
    out = measured(theta[n:], t, theta[:n], ts, n, over_interval)
    if fx.pole_filtered and fx.pole_measured and fx.T2 > 0.0:
        out = iir(out, math.exp(-ts / fx.T2))
    out[:row] = 0.0
    return out
