"""The lab as data: every step's goal, what to do, what to enter, and what a right answer is.

The text is ours (the manual's steps retold for the terminal, without Simulink). A step
is a :class:`Step`; what a group enters is a :class:`Field` (keyed by a string that is
also the key in the session's entries); a checkable answer has a :class:`Check`. The UI
renders these and the session stores what was typed; neither needs a case per step.
:mod:`minseg_tui.lab.content.answers` tells a right answer from a wrong one by these checks.

Field kinds:
- ``quantity``: a number with a unit, parsed by :mod:`minseg_tui.quantities` (value in SI);
- ``formula``: a formula in the names the field allows, read by :mod:`minseg_tui.lab.content.expr`;
- ``choice``: one (or, with ``multiple``, several) of ``options``, stored as indices;
- ``text``: free text, never checked.

Actions name what a step lets the group *do* besides typing (the UI binds them):
``connect`` (pick the board or the virtual MinSeg), ``live_velocity`` (Task 3's velocity
next to the timestamped one), ``meter`` (read the virtual MinSeg's multimeter),
``capture_omega`` (Task 4's steady-state capture), ``run_square_wave`` (Task 10),
``results`` (Tasks 11-15 figures), ``model_check``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from minseg_tui.errors import InputError
from minseg_tui.lab.content.expr import parse_formula
from minseg_tui.lab.content.keys import in_palette, key_name
from minseg_tui.quantities import Plausible

FieldKind = Literal["quantity", "formula", "choice", "text"]
Status = Literal["right", "wrong", "missing"]

CONSISTENT = "consistent with your readings"
"""What a check says of an answer it can only compare with the group's own readings (the
figure of Preparation 7 is not in the program, so its readings cannot be checked)."""

CONSISTENT_GRADER = "consistent with the group's readings"
""":data:`CONSISTENT` as the report says it to an instructor."""

LEVELS: tuple[float, ...] = (2.5, 3.5, 4.5)
"""Requested voltages u_req (V) of Tasks 4-5, one table row each."""


@dataclass(frozen=True)
class Shows:
    """What a handheld multimeter can show on one setting, in magnitude (SI): from ``lo`` to
    ``hi``, ``words`` that span as the refusal says it. A reading outside it is no reading of
    the meter (beyond ``hi`` it shows OL; below ``lo``, 0): a slip of the keyboard, refused."""

    setting: str
    lo: float
    hi: float
    words: str


METER_OHMS = Shows("on Ω", 1e-3, 500e6, "1 mΩ to 500 MΩ")
"""R (Task 2): the finest resolution of a handheld meter's lowest Ω range to its highest."""

METER_VOLTS = Shows("on V=", 1e-6, 1000.0, "1 µV to 1000 V")
"""u_ss (Tasks 4-5): the finest resolution of the mV range to the top of the V= range."""

METER_AMPS = Shows("on mA or A", 1e-8, 20.0, "0.01 µA to 20 A")
"""i_ss (Task 5): the finest resolution of the µA range to the top of the A input."""


@dataclass(frozen=True)
class Field:
    """One thing to enter.

    key: the entry's key in the session (``"R"``, ``"u_ss@2.5"``, ``"prep8.T"``);
    label: short name shown beside the input; unit: the form unit of a quantity (a symbol
    of :data:`minseg_tui.quantities.UNITS`; a bare number is read in it); names: the
    names a formula may use; options: the choices; compare: for a student's own reading,
    the path of the computed value in :meth:`Session.results` to show beside it
    (``"step.K"``); level: the requested voltage (V) of a table field; meter: for a
    multimeter's reading, what the meter can show (a value outside it is refused).
    """

    key: str
    label: str
    kind: FieldKind = "quantity"
    unit: str = ""
    hint: str = ""
    names: tuple[str, ...] = ()
    options: tuple[str, ...] = ()
    multiple: bool = False
    allow_negative: bool = False
    allow_zero: bool = False
    plausible: tuple[Plausible, ...] = ()
    optional: bool = False
    compare: str = ""
    level: float | None = None
    meter: Shows | None = None


@dataclass(frozen=True)
class Check:
    """How the answer in field ``key`` is checked.

    For a formula field with names, ``expected`` is the right formula in the same names
    and both are compared at seeded sample points (positive values 0.5-2): equal
    everywhere within the tolerance means the same formula. Otherwise ``expected`` is a
    formula whose value (SI) the answer must match; it may use other entries through
    ``env`` (name -> entry key), e.g. the oven's K from the final temperature typed.
    ``mistakes`` are typical wrong answers (formula, what to say); ``correct`` are the
    right option indices of a choice; ``explain`` is said when the answer is right;
    ``holds``: the word for an answer that passes, "right", or :data:`CONSISTENT` where the
    check can only compare the answer with the group's own readings, not with the truth.
    """

    key: str
    expected: str = ""
    rel_tol: float = 1e-3
    abs_tol: float = 0.0
    env: tuple[tuple[str, str], ...] = ()
    mistakes: tuple[tuple[str, str], ...] = ()
    correct: tuple[int, ...] = ()
    explain: str = ""
    holds: str = "right"


@dataclass(frozen=True)
class Feedback:
    """The verdict on one checked field: ``status`` and a one-line ``message`` to the group;
    ``grader``: the same verdict worded for an instructor reading the report, where the
    message speaks to the group ('' when the message reads as it is)."""

    key: str
    status: Status
    message: str
    grader: str = ""

    @property
    def for_grader(self) -> str:
        """The verdict as the report words it."""
        return self.grader or self.message


@dataclass(frozen=True)
class RunPlan:
    """The step experiment of Task 10: a board-timed square wave.

    low/high: requested voltages (V); half_period: time at each level (s); periods: how
    many high-low periods; ts: sample period (s).
    """

    low: float = 0.0
    high: float = 4.5
    half_period: float = 1.5
    periods: int = 4
    ts: float = 0.025

    @property
    def duration(self) -> float:
        """Length of the whole sequence in s."""
        return 2.0 * self.half_period * self.periods


@dataclass(frozen=True)
class Step:
    """One step of the lab: ``id``, the ``part`` it belongs to, a ``title``, its ``goal``
    and ``todo`` (our words), the fields to enter, the checks, the actions it offers and,
    for Task 10, the run plans (the manual's and a fast one); ``done_when``: for a step
    without fields, the board checks (keys of :data:`BOARD_CHECKS`) that, passed, make it
    done; ``nav``: its name in the list of steps when the title's head (up to its colon) is
    too long for it."""

    id: str
    part: str
    title: str
    goal: str
    todo: str
    fields: tuple[Field, ...] = ()
    checks: tuple[Check, ...] = ()
    actions: tuple[str, ...] = ()
    plans: tuple[tuple[str, RunPlan], ...] = ()
    formulas: tuple[tuple[str, str], ...] = ()
    done_when: tuple[str, ...] = ()
    nav: str = ""


BOARD_CHECKS: dict[str, str] = {
    "board_check": f"board check ({key_name('board_check')}): does the count follow the motor",
    "revolution": "one revolution by hand: 720 counts",
    "speed_watched": "live speed watched while the wheel turned",
}
"""What the session records of the board besides entries and runs, by key: what each is,
in words (the report's table). Steps name them in ``done_when``."""

SPEED_WATCHED_COUNTS = 360
"""Task 3 is done once the live speed was shown while the wheel turned at least this many
counts (half a revolution) within :data:`SPEED_WATCHED_S`."""

SPEED_WATCHED_S = 2.0
"""...within this many seconds of board time, s."""


def _note(key: str) -> Field:
    return Field(key, "notes", kind="text", optional=True, hint="your own notes (not checked)")


def _done(step_id: str, what: str) -> Field:
    """The field of a step that asks only to read, or to see for oneself what its text already
    says: the group picks ``what`` (what they did) once they did it, and the step is done."""
    return Field(f"{step_id}.done", "done?", kind="choice", options=(what,))


_MOTOR = ("R", "J", "f", "k_v", "k_a")

_PREPARATION: tuple[Step, ...] = (
    Step(
        "prep1",
        "Preparation",
        "Preparation 1: reading",
        "Know what a first-order system and its step response are before the lab.",
        "Read sections 2.1 and 2.6 of Ljung & Glad and jot down questions; nothing is checked "
        "here. Say when you have read them.",
        fields=(_note("prep1.notes"), _done("prep1", "we have read sections 2.1 and 2.6")),
    ),
    Step(
        "prep2",
        "Preparation",
        "Preparation 2: the step response solves the equation",
        "Convince yourself that y(t) = K(1 - e^(-t/T))c satisfies T y' = -y + K u for a step of size c.",
        "Differentiate the proposed y(t), put y and y' into the equation and see that both sides "
        "agree for t > 0; check y(0) = 0 too. Do not solve the equation from scratch. Say when "
        "it checks out.",
        fields=(
            _note("prep2.notes"),
            _done("prep2", "both sides agree, and y(0) = 0"),
        ),
    ),
    Step(
        "prep3",
        "Preparation",
        "Preparation 3: where the output settles",
        "See two ways that the step response ends at K c.",
        "Let t grow without bound in the solution; then, separately, set y' = 0 in the equation "
        "(nothing changes any more in steady state) and solve for y. Say when both give K c.",
        fields=(_note("prep3.notes"), _done("prep3", "both ways give K c")),
    ),
    Step(
        "prep4",
        "Preparation",
        "Preparation 4: the output after one time constant",
        "Know how far the step response has come at t = T.",
        "Put t = T into y(t) = K(1 - e^(-t/T))c. Type y(T) as a fraction of its final value K c "
        "(a number, or a formula such as 1 - exp(-1)).",
        fields=(
            Field("prep4.fraction", "y(T) / (K c)", kind="formula", hint="e.g. 0.5 or 1 - exp(-2)"),
        ),
        checks=(
            Check(
                "prep4.fraction",
                "1 - exp(-1)",
                abs_tol=0.005,
                mistakes=(
                    ("exp(-1)", "0.368 is the part still missing at t = T, not the part reached"),
                ),
                explain="y(T) = K c (1 - e^-1), about 0.632 K c",
            ),
        ),
    ),
    Step(
        "prep5",
        "Preparation",
        "Preparation 5: the time constant as a percentage",
        "Turn the previous answer into the usual rule for reading T off a plot.",
        "The time constant is the time the output needs to cover a certain share of its total "
        "change after a step. Type that share in percent.",
        fields=(Field("prep5.percent", "share of the final value", unit="%"),),
        checks=(
            Check(
                "prep5.percent",
                "1 - exp(-1)",
                abs_tol=0.01,
                mistakes=(("exp(-1)", "37 % is what is still missing at t = T"),),
                explain="63 %: the output has covered 1 - e^-1 of its change after one T",
            ),
        ),
    ),
    Step(
        "prep6",
        "Preparation",
        "Preparation 6: sketch a step response",
        "Draw y(t) = K(1 - e^(-t/T))c for K = 3, T = 10, c = 2 and mark t = 10.",
        "Sketch it on paper: it starts at 0 with slope K c / T and levels off at K c. "
        "Type the value at t = 10.",
        fields=(Field("prep6.y10", "y(10)", kind="formula"),),
        checks=(
            Check(
                "prep6.y10",
                "3*2*(1 - exp(-1))",
                abs_tol=0.02,
                mistakes=(
                    ("3*2", "6 is where the curve ends (K c), not its value at t = T"),
                    ("3*(1 - exp(-1))", "the step has size c = 2: multiply by c too"),
                    ("2*(1 - exp(-1))", "the gain K = 3 is missing"),
                ),
                explain="y(10) = 6 (1 - e^-1), about 3.79",
            ),
        ),
    ),
    # Preparation 7: Figure 2.1 (the oven's step response) is not in the text we have, so
    # its numbers cannot be checked against the figure. What can be checked is the method,
    # from the group's own readings of the figure: the gain is the final temperature over
    # the 1000 W step (K = y_final / 1000 W, in degC/W, the room being at 0 degC), and the
    # time constant is counted from the switch-on at t = 4 min to the moment 63 % of the
    # final temperature is reached (T = t_63 - 4 min). The typical slips (forgetting the
    # 4 min, or not dividing by the power) get their own message.
    Step(
        "prep7",
        "Preparation",
        "Preparation 7: an oven's time constant and gain",
        "Read T and K of a first-order system off a recorded step response.",
        "In Figure 2.1 the heater goes from 0 to 1000 W at t = 4 min. Read the final temperature "
        "and the time at which 63 % of it is reached, then give T and K. The program does not "
        "have the figure: it checks that your T and K follow from your readings, not the "
        "readings themselves.",
        fields=(
            Field("prep7.y_final", "final temperature", unit="°C"),
            Field("prep7.t_63", "time at 63 % (figure's axis)", unit="min"),
            Field("prep7.T", "T", unit="min"),
            Field("prep7.K", "K", unit="°C/W"),
        ),
        checks=(
            Check(
                "prep7.T",
                "t_63 - 240",
                rel_tol=0.02,
                abs_tol=6.0,
                env=(("t_63", "prep7.t_63"),),
                mistakes=(
                    ("t_63", "the heater came on at t = 4 min, not at 0: count T from there"),
                ),
                explain="T is the time from the step to 63 % of the final value",
                holds=CONSISTENT,
            ),
            Check(
                "prep7.K",
                "y_final/1000",
                rel_tol=0.02,
                env=(("y_final", "prep7.y_final"),),
                mistakes=(
                    ("y_final", "divide the final temperature by the step in power, 1000 W"),
                ),
                explain="K = final temperature / input step (the room is at 0 °C)",
                holds=CONSISTENT,
            ),
        ),
    ),
    Step(
        "prep8",
        "Preparation",
        "Preparation 8: T and K from another form",
        "Bring a y' + b y = c u into the standard form T y' = -y + K u.",
        "Divide through so that y has coefficient 1, then read off T and K as formulas in a, b, c.",
        fields=(
            Field("prep8.T", "T", kind="formula", names=("a", "b", "c")),
            Field("prep8.K", "K", kind="formula", names=("a", "b", "c")),
        ),
        checks=(
            Check(
                "prep8.T",
                "a/b",
                mistakes=(("b/a", "upside down: divide the equation by b"),),
                explain="T = a/b",
            ),
            Check(
                "prep8.K",
                "c/b",
                mistakes=(
                    ("c/a", "divide by b (the coefficient of y), not by a"),
                    ("b/c", "upside down"),
                ),
                explain="K = c/b",
            ),
        ),
    ),
    Step(
        "prep9",
        "Preparation",
        "Preparation 9: read the whole lab",
        "Arrive knowing every task and which answers the preparations feed into.",
        "Read through all the steps of this program; the remaining preparations are met on the "
        "way. Say when you have read them.",
        fields=(_note("prep9.notes"), _done("prep9", "we have read every step")),
    ),
    Step(
        "prep10",
        "Preparation",
        "Preparation 10: counts to radians",
        "Scale the encoder so one wheel turn (720 counts) reads 2 pi rad.",
        "Give the gain that multiplies a count to give radians (a number or a formula).",
        fields=(Field("prep10.gain", "rad per count", kind="formula"),),
        checks=(
            Check(
                "prep10.gain",
                "2*pi/720",
                rel_tol=0.005,
                mistakes=(
                    ("720/(2*pi)", "upside down: that turns radians into counts"),
                    ("360/720", "that is degrees per count; the lab works in radians"),
                    ("2*pi/48", "48 is per turn of the encoder shaft; the wheel turn gives 720"),
                ),
                explain="2 pi / 720, about 0.00873 rad per count (0.5 degree)",
            ),
        ),
    ),
    Step(
        "prep11",
        "Preparation",
        "Preparation 11: k_v from steady state",
        "Find the steady-state form of the electrical equation and solve it for k_v.",
        "With L = 0 and everything constant, u_A = R i + k_v omega. Give k_v as a formula in "
        "u_ss, R, i_ss and omega_ss.",
        fields=(
            Field("prep11.k_v", "k_v", kind="formula", names=("u_ss", "R", "i_ss", "omega_ss")),
        ),
        checks=(
            Check(
                "prep11.k_v",
                "(u_ss - R*i_ss)/omega_ss",
                mistakes=(
                    ("u_ss/omega_ss", "the voltage across R (R i_ss) must come off first"),
                    ("(u_ss + R*i_ss)/omega_ss", "sign: the resistor takes R i_ss away from u_ss"),
                ),
                explain="k_v = (u_ss - R i_ss) / omega_ss",
            ),
        ),
    ),
    Step(
        "prep12",
        "Preparation",
        "Preparation 12: f from steady state",
        "Use the mechanical equation at constant speed to get the friction coefficient.",
        "At constant speed omega' = 0, so k_a i = f omega. Give f in k_a, i_ss and omega_ss.",
        fields=(Field("prep12.f", "f", kind="formula", names=("k_a", "i_ss", "omega_ss")),),
        checks=(
            Check(
                "prep12.f",
                "k_a*i_ss/omega_ss",
                mistakes=(
                    ("k_a*omega_ss/i_ss", "upside down: torque k_a i_ss over speed"),
                    ("i_ss/omega_ss", "the torque is k_a i_ss, not i_ss"),
                ),
                explain="f = k_a i_ss / omega_ss",
            ),
        ),
    ),
    Step(
        "prep13",
        "Preparation",
        "Preparation 13: one equation for the motor",
        "Eliminate the current between the electrical and the mechanical equation.",
        "Solve the electrical equation (L = 0) for i, put it into k_a i = J omega' + f omega and "
        "multiply by R; you should reach R J omega' = -(R f + k_v k_a) omega + k_a u_A. Say "
        "when you have.",
        fields=(_note("prep13.notes"), _done("prep13", "we reached that equation")),
    ),
    Step(
        "prep14",
        "Preparation",
        "Preparation 14: the motor's T and K",
        "Write the motor equation in the form T omega' + omega = K u_A.",
        "Divide the combined equation by (R f + k_v k_a). Give T and K as formulas in R, J, f, k_v, k_a.",
        fields=(
            Field("prep14.T", "T", kind="formula", names=_MOTOR),
            Field("prep14.K", "K", kind="formula", names=_MOTOR),
        ),
        checks=(
            Check(
                "prep14.T",
                "R*J/(R*f + k_v*k_a)",
                mistakes=(
                    (
                        "J/(R*f + k_v*k_a)",
                        "R is missing in the numerator: the equation starts with R J omega'",
                    ),
                ),
                explain="T = R J / (R f + k_v k_a)",
            ),
            Check(
                "prep14.K",
                "k_a/(R*f + k_v*k_a)",
                mistakes=(("R*k_a/(R*f + k_v*k_a)", "only k_a multiplies u_A"),),
                explain="K = k_a / (R f + k_v k_a)",
            ),
        ),
    ),
    Step(
        "prep15",
        "Preparation",
        "Preparation 15: J from the time constant",
        "Plan how Task 13 turns a measured T into the inertia J.",
        "Solve your T formula for J. Give J in T, R, f, k_v and k_a.",
        fields=(Field("prep15.J", "J", kind="formula", names=("T", "R", "f", "k_v", "k_a")),),
        checks=(
            Check(
                "prep15.J",
                "T*(R*f + k_v*k_a)/R",
                mistakes=(("T*R/(R*f + k_v*k_a)", "upside down: J = T (R f + k_v k_a) / R"),),
                explain="J = T (R f + k_v k_a) / R",
            ),
        ),
    ),
)

_R_PLAUSIBLE = Plausible(
    1.0,
    20.0,
    low="below 1 Ω: a short, or the probes touch each other; this motor usually reads 3-6 Ω",
    high="above 20 Ω: a decimal comma lost (53 for 5,3)? Else a loose motor cable or the "
    "current jumper missing; this motor usually reads 3-6 Ω",
)


_F_PLAUSIBLE = Plausible(
    5e-5,
    0.05,
    low="below 0.05 mN m s/rad, a thousandth of this motor's usual few mN m s/rad: typed in "
    "N m s/rad? Write the unit after the number",
    high="above 50 mN m s/rad, a thousand times this motor's usual few mN m s/rad: is the unit "
    "right? The table's f is in mN m s/rad",
)


_T_PLAUSIBLE = Plausible(
    0.005,
    0.5,
    low="below 5 ms, a tenth of this motor's usual tens of ms: is the unit right? Write ms or s "
    "after the number",
    high="above 500 ms, ten times this motor's usual tens of ms: typed in s where ms was meant? "
    "T runs from the rising edge to 63 % of the rise",
)
"""Task 12's T (s): this motor's time constant is tens of ms (43-57 ms on the virtual board);
outside 5-500 ms the unit or the reading is wrong."""


def _u_ss(level: float) -> Field:
    return Field(
        f"u_ss@{level:g}",
        f"u_ss at {level:g} V",
        unit="V",
        level=level,
        hint="multimeter on V=, between M1A and M1B",
        meter=METER_VOLTS,
        plausible=(
            Plausible(
                level - 1.5,
                level,
                low=f"more than 1.5 V below the requested {level:g} V: is the voltage really set, and the meter on V=?",
                high=f"above the requested {level:g} V: the driver only loses voltage; check the meter and the request",
            ),
        ),
    )


def _omega_ss(level: float) -> Field:
    return Field(
        f"omega_ss@{level:g}",
        f"omega_ss at {level:g} V",
        unit="rad/s",
        level=level,
        allow_negative=True,
        hint="captured from the live velocity (or typed)",
        plausible=(
            Plausible(
                0.5,
                15.0,
                low=f"the wheel hardly turns (or turns backwards): {key_name('board_check')} runs the board "
                "check, which says what is wrong",
                high="faster than this motor goes (about 7 rad/s at 4.5 V): typed in rpm? Write 'rpm' after "
                "the number. Else check the counts-to-radians scaling",
            ),
        ),
    )


def _i_ss(level: float) -> Field:
    return Field(
        f"i_ss@{level:g}",
        f"i_ss at {level:g} V",
        unit="mA",
        level=level,
        hint="multimeter on mA, in series through the jumper pins",
        meter=METER_AMPS,
        plausible=(
            Plausible(
                0.005,
                0.100,
                low="below 5 mA: is the meter in series through the jumper pins, on the mA range?",
                high="above 100 mA: probably the wrong thing measured or the meter in the wrong mode "
                "(expect 20-50 mA)",
            ),
        ),
    )


_LAB: tuple[Step, ...] = (
    Step(
        "task1",
        "Set-up",
        "Task 1: connect the MinSeg",
        "Have a board (or the virtual MinSeg) talking to this program.",
        "Plug the MinSeg in by USB before starting this program: it finds the board by itself, "
        "and without one it runs the virtual MinSeg to practise on (the top line says which). "
        "The program already runs the board's code: there is nothing to build or download. "
        f"Then press {key_name('board_check')}: "
        "the board check turns the wheel for half a second and says whether the count follows, "
        f"and what to look at if it does not. {in_palette('count_revolution')} checks the "
        "encoder's 720 counts.",
        actions=("connect",),
        done_when=("board_check",),
    ),
    Step(
        "task2",
        "Set-up",
        "Task 2: motor resistance R",
        "Measure the armature resistance directly.",
        "Unplug the USB cable so the board has no power. Put the multimeter on Ω and hold the probes "
        "on M1A and M1B (next to the motor cable); wait a few seconds for the value to settle. With "
        "the virtual MinSeg, read its multimeter panel.",
        fields=(
            Field(
                "R",
                "R",
                unit="Ω",
                plausible=(_R_PLAUSIBLE,),
                meter=METER_OHMS,
                hint="multimeter on Ω, M1A-M1B, board unpowered",
            ),
        ),
        actions=("meter",),
    ),
    Step(
        "task3",
        "Set-up",
        "Task 3: estimating the speed",
        "See how the speed is computed from the encoder angle, and what the manual's estimate costs.",
        "Spin the wheel or set a voltage. The manual's estimate takes the change in angle over one "
        "nominal 25 ms sample and averages the last 20 such values (half a second). Beside it is one "
        "that divides by the board's own timestamps. Compare how smooth and how late each is.",
        actions=("connect", "live_velocity"),
        done_when=("speed_watched",),
    ),
    Step(
        "task4",
        "Steady state",
        "Task 4: u_ss and omega_ss",
        "For three requested voltages, record the voltage at the motor and the speed it settles at.",
        "Plug the USB cable back in. For 2.5, 3.5 and 4.5 V: set the voltage, wait until the speed "
        "is steady, capture omega_ss, and type the multimeter's reading u_ss (V=, M1A-M1B). Expect "
        "u_ss a little below the request and speeds up to about 7 rad/s.",
        fields=tuple(f for level in LEVELS for f in (_omega_ss(level), _u_ss(level))),
        actions=("capture_omega", "meter"),
    ),
    Step(
        "task5",
        "Steady state",
        "Task 5: i_ss",
        "Record the steady current at the same three voltages.",
        "Pull the current jumper, put the multimeter (mA range) across the two pins, and repeat the "
        "three voltages, typing i_ss each time. Expect 20-50 mA. If the wheel stops with the jumper "
        "out, the meter does not close the circuit: it must be on mA, in series across the two "
        "pins. Put the jumper back afterwards.",
        fields=tuple(_i_ss(level) for level in LEVELS),
        actions=("meter",),
    ),
    Step(
        "table",
        "Table",
        "Tasks 6-9: k_v, k_a and f",
        "Turn the table's readings into the motor constants.",
        "The table fills in k_v for each row from Preparation 11, takes the median, sets "
        "k_a = 0.65 k_v, and computes f per row from Preparation 12 with its median. Check the "
        "numbers; you may type your own values to compare.",
        fields=(
            Field("own.k_v", "your k_v", unit="V s/rad", optional=True, compare="k_v"),
            Field("own.k_a", "your k_a", unit="N m/A", optional=True, compare="k_a"),
            Field(
                "own.f",
                "your f",
                unit="mN m s/rad",
                optional=True,
                compare="f",
                plausible=(_F_PLAUSIBLE,),
            ),
        ),
        formulas=(
            ("k_v", "k_v = (u_ss - R i_ss) / omega_ss, per row; final k_v = median of the rows"),
            ("k_a", "k_a = 0.65 k_v"),
            ("f", "f = k_a i_ss / omega_ss, per row; final f = median of the rows"),
        ),
    ),
    Step(
        "task10",
        "Step response",
        "Task 10: the step experiment",
        "Record the speed while the voltage jumps between 0 and 4.5 V a few times.",
        "Start the run: the board switches the request between 0 and 4.5 V on its own clock and the "
        "program records every sample. You can stop at any time; the motor is switched off. The fast "
        "variant samples every 5 ms, to show what the 25 ms samples and the averaging hide.",
        actions=("run_square_wave",),
        plans=(("manual", RunPlan()), ("fast", RunPlan(ts=0.005))),
    ),
    Step(
        "task11",
        "Results",
        "Task 11: the static gain K",
        "Read the steady speed of the steps and turn it into K from u_A to omega.",
        "Zoom in on one step. Note its final speed and the u_ss you measured at 4.5 V; K is their ratio.",
        fields=(
            Field(
                "own.omega_step",
                "your omega_ss in the steps",
                unit="rad/s",
                optional=True,
                compare="step.omega_ss",
                hint="in rad/s, e.g. 4.6",
            ),
            Field(
                "own.K",
                "your K",
                unit="rad/s/V",
                optional=True,
                compare="step.K",
                hint="in rad/s/V, e.g. 1.2",
            ),
        ),
        actions=("results",),
    ),
    Step(
        "task12",
        "Results",
        "Task 12: the time constant T",
        "Read T off the step response.",
        "On one rise, find when the speed has covered 63 % of its change; T is the time from "
        "the rising edge to that moment. The program also fits T by least squares, with its interval.",
        fields=(
            Field(
                "own.T",
                "your T",
                unit="ms",
                optional=True,
                compare="step.T_63",
                hint="in ms, e.g. 120 ms (or 0.12 s)",
                plausible=(_T_PLAUSIBLE,),
            ),
        ),
        actions=("results",),
    ),
    Step(
        "task13",
        "Results",
        "Task 13: the inertia J",
        "Get J from T and the constants of Tasks 2-9.",
        "Use Preparation 15: J = T (R f + k_v k_a) / R.",
        fields=(
            Field(
                "own.J",
                "your J",
                unit="kg m^2",
                optional=True,
                compare="step.J",
                hint="in kg m^2, e.g. 0.0008",
            ),
        ),
        actions=("results",),
    ),
    Step(
        "task14",
        "Results",
        "Task 14: the model",
        "Write the motor as one first-order equation with numbers.",
        "Fill T and K into T omega' = -omega + K u_A.",
        fields=(Field("own.model", "your model", kind="text", optional=True, compare="model"),),
        actions=("results",),
    ),
    Step(
        "task15",
        "Results",
        "Task 15: speed at 5 V",
        "Use the model to predict.",
        "With u_A = 5 V held, where does the speed settle? (The static gain answers it.)",
        fields=(
            Field(
                "own.omega_5",
                "your omega at 5 V",
                unit="rad/s",
                optional=True,
                compare="omega_at_5V",
                hint="in rad/s, e.g. 5.8",
            ),
        ),
        actions=("results",),
    ),
    Step(
        "model_check",
        "Model check",
        "Model check: what the first-order model misses",
        "Compare the recorded steps with the model's simulation and see where they differ.",
        "The program simulates the model on the recorded voltage and shows the measured speed, the "
        "model's, an extended model's, and the residuals, with the most likely cause named. "
        "The step is done when you tick done? (the notes are your own, not needed for it).",
        fields=(
            _note("model_check.notes"),
            _done("model_check", "we have seen where the run and the model differ"),
        ),
        actions=("model_check",),
    ),
)

_OPTIONS_MSS = ("a model", "a system", "a signal")

_SUMMARY = Step(
    "summary",
    "Summary",
    "Summary and reflections (section 3.2)",
    "Check the concepts of the lab.",
    "Answer each question; one question takes more than one answer. Then write what is still unclear.",
    fields=(
        Field("summary.1", "The MinSeg DC-motor is", kind="choice", options=_OPTIONS_MSS),
        Field(
            "summary.2",
            "The differential equation describing the MinSeg DC-motor is",
            kind="choice",
            options=_OPTIONS_MSS,
        ),
        Field(
            "summary.3",
            "The time-constant describes",
            kind="choice",
            options=(
                "how fast the system reacts to changing inputs",
                "which constant value the output will converge to",
            ),
        ),
        Field(
            "summary.4",
            "The static gain K describes",
            kind="choice",
            options=(
                "the ratio between the output and input amplitudes in steady-state",
                "the final value of the output",
            ),
        ),
        Field(
            "summary.5",
            "The final amplitude of the output depends on",
            kind="choice",
            multiple=True,
            options=(
                "the time-constant",
                "the input amplitude",
                "the static gain",
            ),
        ),
        Field(
            "summary.6",
            "A first-order linear differential equation is",
            kind="choice",
            options=(
                "uniquely defined by time-constant and static gain",
                "not uniquely defined by time-constant and static gain",
            ),
        ),
        Field("summary.unclear", "Most unclear to me is still", kind="text", optional=True),
    ),
    checks=(
        Check("summary.1", correct=(1,), explain="the motor itself is the system"),
        Check(
            "summary.2", correct=(0,), explain="the equation describes the system: it is a model"
        ),
        Check("summary.3", correct=(0,), explain="T sets the speed of the response"),
        Check(
            "summary.4",
            correct=(0,),
            explain="K is output over input in steady state; the final value also needs the input",
        ),
        Check(
            "summary.5",
            correct=(1, 2),
            explain="the final value is K times the input amplitude; T only sets how fast",
        ),
        Check(
            "summary.6",
            correct=(0,),
            explain="in the form T y' = -y + K u, T and K fix the equation",
        ),
    ),
    nav="Summary",
)

STEPS: tuple[Step, ...] = (*_PREPARATION, *_LAB, _SUMMARY)
"""Every step, in the order the lab goes through them."""

PARTS: tuple[str, ...] = tuple(dict.fromkeys(s.part for s in STEPS))
"""The parts in order (Preparation, Set-up, Steady state, ...)."""

STEP_INDEX: dict[str, int] = {s.id: k for k, s in enumerate(STEPS)}
"""Position of each step id in :data:`STEPS`."""

FIELDS: dict[str, Field] = {f.key: f for s in STEPS for f in s.fields}
"""Every field by key."""

FIELD_STEP: dict[str, str] = {f.key: s.id for s in STEPS for f in s.fields}
"""The step id each field belongs to."""

CHECKS: dict[str, Check] = {c.key: c for s in STEPS for c in s.checks}
"""Every check by the key of the field it checks."""


def step(step_id: str) -> Step:
    """The step with id ``step_id``; KeyError if there is none."""
    return STEPS[STEP_INDEX[step_id]]


def validate() -> list[str]:
    """Problems in the data above (empty list when sound): used by the tests."""
    problems: list[str] = []
    seen: set[str] = set()
    for s in STEPS:
        if s.id in seen:
            problems.append(f"duplicate step {s.id}")
        seen.add(s.id)
    keys = [f.key for s in STEPS for f in s.fields]
    problems += [f"duplicate field {k}" for k in set(keys) if keys.count(k) > 1]
    for s in STEPS:
        problems += [
            f"step {s.id} is done by an unknown check {k}"
            for k in s.done_when
            if k not in BOARD_CHECKS
        ]
    for c in CHECKS.values():
        if c.key not in FIELDS:
            problems.append(f"check on unknown field {c.key}")
            continue
        fld = FIELDS[c.key]
        if fld.kind == "choice":
            if not c.correct or max(c.correct) >= len(fld.options):
                problems.append(f"choice check {c.key} has no valid correct option")
            continue
        try:
            parse_formula(c.expected, fld.names + tuple(n for n, _ in c.env))
            for wrong, _ in c.mistakes:
                parse_formula(wrong, fld.names + tuple(n for n, _ in c.env))
        except InputError as exc:
            problems.append(f"check {c.key}: {exc}")
        problems += [
            f"check {c.key} env uses unknown field {k}" for _, k in c.env if k not in FIELDS
        ]
    return problems


__all__ = [
    "BOARD_CHECKS",
    "CHECKS",
    "FIELDS",
    "FIELD_STEP",
    "LEVELS",
    "PARTS",
    "SPEED_WATCHED_COUNTS",
    "SPEED_WATCHED_S",
    "STEPS",
    "STEP_INDEX",
    "Check",
    "Shows",
    "Feedback",
    "Field",
    "RunPlan",
    "Step",
    "step",
    "validate",
]
