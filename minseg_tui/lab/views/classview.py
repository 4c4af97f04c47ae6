"""The class at a glance: one row per group of a sessions folder, and what stands out.

:func:`read_group` opens a session read-only (:meth:`Session.open` with
``readonly=True``: no lock taken, nothing written) and takes its numbers from the session
itself: :meth:`Session.results` (Tasks 6-15, the same numbers ``minseg-tui report``
writes), :meth:`Session.model_check` and :meth:`Session.comparisons`; only K, T and the
63 % reading of a session whose table lacks an i_ss (or R) are taken from its step run
here (:func:`~minseg_tui.model.identify.response_alone`), since they need neither. The model
check's cause and Tasks 11-13's numbers come from what the session file keeps of its run
(:meth:`Session.kept`, written by the lab when it computed them) whenever that was computed
from this very run and table: the run is then neither checked nor fitted again, which is
most of the cost of a row. Nothing here computes a motor parameter a second time; it only
sets the groups side by side and says, in words, what stands out:

- the slips the lab manual warns about (:func:`slips`): i_ss above 100 mA (or a current
  typed in amperes into the mA column), R outside 3-6 Ω, an omega_ss that looks like rpm,
  a u_ss above the requested voltage, the group's K divided by the requested step height
  (4.5 V) rather than by its measured u_ss;
- a value far from the rest of the class (:func:`spread` and :func:`outliers`), judged by
  the median and the median absolute deviation.

A session that cannot be read, is damaged or is unfinished is listed with what it lacks
(:attr:`Group.lacks`); it never hides another. Units: SI throughout (V, A, Ω, rad/s, s,
V s/rad, N m/A, N m s/rad, rad/s/V, kg m^2).
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

from minseg_tui.errors import InputError
from minseg_tui.lab.content import steps as lab_steps
from minseg_tui.lab.content.steps import LEVELS
from minseg_tui.lab.saving.kept import Kept
from minseg_tui.lab.saving.runs import RunInfo, read_run
from minseg_tui.lab.saving.store import (
    SESSION_FILE,
    SessionsUnreadable,
    folder_holds,
    names_key,
)
from minseg_tui.lab.state.compare import STEP_LEVEL, K_by_request
from minseg_tui.lab.state.entries import NOT_AS_READ
from minseg_tui.lab.state.results import Results
from minseg_tui.lab.state.session import NO_RUN_YET, Session
from minseg_tui.lab.views import own_first
from minseg_tui.lab.views import session as session_views
from minseg_tui.lab.views.check_says import in_words
from minseg_tui.lab.views.own_first import OwnRow
from minseg_tui.model.identify import IdentifyRefused, ZeroVoltRefusal, response_alone
from minseg_tui.model.runlog import LogRefused
from minseg_tui.quantities import (
    F_UNIT,
    MISSING,
    RPM,
    format_difference,
    format_fixed,
    format_number,
    format_reading,
    format_typed,
    in_unit,
)


@dataclass(frozen=True)
class Quantity:
    """A column of the class table: its ``key`` (also the JSON key), the ``unit`` of its SI
    value, and its ``label`` with the unit for headers (CSV, SI); ``shown`` the unit it is
    shown to people in when not ``unit`` (f in mN m s/rad, as the lab's table shows it)."""

    key: str
    unit: str
    words: str
    shown: str = ""
    reading: bool = False
    """A value the group read and typed (R): shown with the digits they gave, never padded."""

    @property
    def label(self) -> str:
        """``key (unit)``, as a column header of SI numbers."""
        return f"{self.key} ({self.unit})"

    @property
    def display(self) -> str:
        """The unit the value is shown to people in."""
        return self.shown or self.unit

    @property
    def shown_label(self) -> str:
        """``key (display unit)``, as a column header of the numbers people read."""
        return f"{self.key} ({self.display})"

    def number(self, v: float) -> float:
        """``v`` (SI) in :attr:`display`."""
        return in_unit(v, self.display)

    def text(self, v: float | None, typed: str = "") -> str:
        """``v`` (SI) as people read it, in :attr:`display` without the unit: a reading with
        the digits typed (``typed``, the text it was typed as: "5,30" is "5.30", "5.3" never
        "5.300"; :func:`~minseg_tui.quantities.format_reading`, as the lab and the report
        give readings), a computed value with :data:`DIGITS` significant digits (T 42.89 ms
        as "42.89"); :data:`MISSING` for None."""
        if v is None or not math.isfinite(v):
            return MISSING
        n = self.number(v)
        return format_reading(n, "", typed=typed) if self.reading else format_number(n)

    def with_unit(self, v: float | None, typed: str = "") -> str:
        """:meth:`text` with the unit ("5.3 Ω", "42.89 ms"); :data:`MISSING` for None."""
        t = self.text(v, typed)
        return t if t == MISSING else f"{t} {self.display}"


QUANTITIES: tuple[Quantity, ...] = (
    Quantity("R", "Ω", "motor resistance (Task 2)", reading=True),
    Quantity("k_v", "V s/rad", "back-emf constant (Task 7)"),
    Quantity("k_a", "N m/A", "torque constant (Task 8)"),
    Quantity("f", "N m s/rad", "viscous friction (Task 9)", F_UNIT),
    Quantity("K", "rad/s/V", "static gain (Task 11)"),
    Quantity("T_63", "s", "time constant, 63 % reading (Task 12)", "ms"),
    Quantity("T", "s", "time constant, least squares (Task 12)", "ms"),
    Quantity("J", "kg m^2", "inertia (Task 13)"),
)
"""The numbers of a row, in the order of the lab."""

JUDGED: tuple[str, ...] = ("R", "k_v", "f", "K", "T_63", "T", "J")
"""The quantities judged against the class (k_a is 0.65 k_v: judged with k_v)."""

THRESHOLD: float = 3.5
"""A value is far from the class when it lies more than this many robust standard
deviations from the class median (the modified z-score of Iglewicz and Hoaglin, 1993).

The robust standard deviation is 1.4826 times the median absolute deviation (MAD): for
normally scattered values it equals the standard deviation, but one group's typo (i_ss in
amperes makes k_v and f wrong by orders of magnitude) moves neither the median nor the MAD,
whereas it would inflate the mean and the standard deviation so much that the typo itself,
and any other group's slip, would look normal. 3.5 is the usual cut of the modified
z-score: a class of 30 honest groups has no value beyond it about 99 times in 100, while a
reading on the wrong range or in the wrong unit is far beyond it."""

MAD_TO_SIGMA: float = 1.4826
"""MAD times this is the standard deviation of normally scattered values."""

REL_FLOOR: float = 0.02
"""The robust spread is at least 2 % of the median's size: groups that read the same motor
alike (a MAD near 0) are not called far apart for a difference of a few per cent."""

MIN_GROUPS: int = 4
"""Fewer groups with a value than this: the class has no median worth judging by."""

R_RANGE: tuple[float, float] = (3.0, 6.0)
"""The motor resistance the manual expects, Ω (Task 2)."""

I_SS_MAX: float = 0.100
"""Above this steady-state current, A, the manual says the wrong thing is measured (Task 5)."""

I_SS_AMPERES: float = 1e-3
"""A current below this, A (under 1 mA in the mA column), was typed in amperes."""

OMEGA_MAX: float = 15.0
"""Faster than this motor turns at the lab's voltages, rad/s (it reaches about 7 rad/s)."""

OMEGA_MIN: float = 0.5
"""Below this the wheel hardly turns, rad/s."""

MARKED: str = (
    f"a slip the lab manual warns about, a refused entry, {NOT_AS_READ}, a value far from the "
    "class, or two sessions of the same names"
)
"""What the class view marks with '!' (a group's :attr:`Group.flags`), in words."""

NOT_MARKED: str = (
    "Not counted: the other warnings of each group's report (its notes on the entries, the "
    "readings and the run)."
)
"""What the class view's '!' does not count, though a group's report warns about it."""


def marked_summary(view: ClassView) -> str:
    """How many groups the class view holds and how many it marks with '!', and what the
    mark counts: "1 group, 0 marked '!' (…)"."""
    n = len(view.groups)
    k = sum(1 for g in view.groups if g.flags)
    return f"{n} group{'' if n == 1 else 's'}, {k} marked '!' ({MARKED})."


def for_grader(label: str) -> str:
    """A field's label as an instructor reads it: "your k_v" (the group's screen) is "the
    group's k_v"."""
    return "the group's " + label.removeprefix("your ") if label.startswith("your ") else label


FROM_TABLE: tuple[str, ...] = ("k_v", "k_a", "f", "J")
"""The quantities computed from the table's rows (and R): k_v = (u_ss - R i_ss) / omega_ss,
k_a = 0.65 k_v, f = k_a i_ss / omega_ss, and J from them with T."""


@dataclass(frozen=True)
class Slip:
    """One of the manual's slips in a group's readings: the sentence that says it, and the
    quantities of :data:`QUANTITIES` whose value rests on the slipped reading (they are left
    out of the class's median and MAD, so that a slip cannot move the yardstick the other
    groups are judged by)."""

    text: str
    affects: tuple[str, ...] = ()


@dataclass(frozen=True)
class Own:
    """One of the group's own values beside the computed one (SI; text for the model):
    ``rel_diff`` = own / computed - 1 when both are numbers; ``right`` the lab's verdict on
    it (True right, False wrong, None not judged), as the group's screen and report mark it."""

    key: str
    label: str
    unit: str
    own: float | str | None
    computed: float | str | None
    rel_diff: float | None
    right: bool | None = None

    @property
    def mark(self) -> str:
        """The lab's mark of the verdict ('✗' wrong, '✓' right), '' when not judged."""
        if self.right is None:
            return ""
        return session_views.MARK["done" if self.right else "wrong"]


@dataclass(frozen=True)
class Group:
    """One row of the class view.

    ``id`` is the session folder's name; ``step`` the name of the furthest step the group
    reached ("Task 12", :func:`reached`), ``at`` that of the step it is on; ``values`` the numbers of :data:`QUANTITIES` by key (SI, None when not
    computed); ``cause`` the model check's cause in words ('' when it has not run, "none"
    when the first-order model explains the log); ``own`` the group's own values against
    the computed ones; ``own_rows`` the same values as the session's report words them
    (:mod:`.own_first`: Tasks 7-9's rows, then Tasks 11-15's), the ones the group entered;
    ``lacks`` what keeps a result from being computed (one sentence
    each); ``damaged`` why the file is damaged or cannot be read (None when it is sound);
    ``readable`` False when nothing of the session could be read; ``flags`` what stands
    out, one sentence each; ``slipped`` the keys of the values that rest on one of the
    manual's slips (:class:`Slip`): left out of the class's median and MAD; ``notes``
    what a grader should know that is neither marked nor missing, one line each (the run
    Tasks 11-15 use was interrupted: :func:`run_note`); ``unanswered`` what the lab asks
    that the group has not answered yet, as F8's notice names it ('Task 4, 5, 14; Summary
    Q1 and 20 more'; '' when nothing is: walk 14, D3)."""

    id: str
    folder: Path
    members: tuple[str, ...] = ()
    date: str = ""
    step: str = ""
    at: str = ""
    values: dict[str, float | None] = field(default_factory=dict)
    cause: str = ""
    cause_code: str = ""
    own: tuple[Own, ...] = ()
    own_rows: tuple[OwnRow, ...] = ()
    lacks: tuple[str, ...] = ()
    damaged: str | None = None
    readable: bool = True
    flags: tuple[str, ...] = ()
    slipped: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    check_on: str = ""
    """When the model check used another run than Tasks 11-15 (a log imported at the model
    check): "run imported-1, a log imported at the model check; Tasks 11-15 use run
    steps-1"; '' when it used theirs."""
    typed: dict[str, str] = field(default_factory=dict)
    """The texts the group's readings (R) were typed as, by key: shown with those digits."""
    unanswered: str = ""

    def value(self, key: str) -> float | None:
        """The value of ``key`` (SI), None when not computed or not finite."""
        v = self.values.get(key)
        return v if v is not None and math.isfinite(v) else None

    def text(self, key: str) -> str:
        """The value of ``key`` as people read it, without the unit (:meth:`Quantity.text`):
        a reading with the digits the group typed."""
        return _quantity(key).text(self.value(key), self.typed.get(key, ""))

    def with_unit(self, key: str) -> str:
        """:meth:`text` with the unit ("5.30 Ω")."""
        return _quantity(key).with_unit(self.value(key), self.typed.get(key, ""))

    def to_json(self) -> dict[str, object]:
        """The group as ``minseg-tui class --json`` writes it (SI units)."""
        out: dict[str, object] = {
            "id": self.id,
            "folder": str(self.folder),
            "members": list(self.members),
            "date": self.date,
            "step": self.step,
            "at": self.at,
        }
        out.update({q.key: self.value(q.key) for q in QUANTITIES})
        out["cause"] = self.cause
        out["check_on"] = self.check_on
        out["own"] = [
            {
                "key": o.key,
                "label": o.label,
                "own": o.own,
                "computed": o.computed,
                "rel_diff": o.rel_diff,
            }
            for o in self.own
        ]
        out["lacks"] = list(self.lacks)
        out["damaged"] = self.damaged
        out["flags"] = list(self.flags)
        out["notes"] = list(self.notes)
        out["unanswered"] = self.unanswered
        out["left_out_of_class"] = [q.key for q in QUANTITIES if q.key in self.slipped]
        return out


@dataclass(frozen=True)
class Spread:
    """The class's middle for one quantity: ``median``, the robust standard deviation
    ``sigma`` (1.4826 MAD, at least :data:`REL_FLOOR` of the median), the band
    median ± :data:`THRESHOLD` sigma outside which a value stands out, and ``n`` groups."""

    key: str
    median: float
    sigma: float
    n: int

    @property
    def band(self) -> tuple[float, float]:
        """(low, high) of the band, in the quantity's SI unit."""
        return (self.median - THRESHOLD * self.sigma, self.median + THRESHOLD * self.sigma)


@dataclass(frozen=True)
class ClassView:
    """Every group of a sessions folder (sorted by id) and the class's spread per judged
    quantity (absent where fewer than :data:`MIN_GROUPS` groups have the value)."""

    root: Path
    groups: tuple[Group, ...]
    spreads: dict[str, Spread]

    @property
    def unreadable(self) -> tuple[Group, ...]:
        """The groups whose session could not be read at all."""
        return tuple(g for g in self.groups if not g.readable)

    def to_json(self) -> dict[str, object]:
        """``minseg-tui class --json``: the folder, ``groups[]`` and the class's spreads."""
        return {
            "sessions": str(self.root),
            "groups": [g.to_json() for g in self.groups],
            "class": {
                k: {"median": s.median, "sigma": s.sigma, "band": list(s.band), "n": s.n}
                for k, s in self.spreads.items()
            },
            "threshold": THRESHOLD,
        }


def reached(session: Session) -> str:
    """The id of the furthest step the group got to: the last in the lab's order with
    anything entered or recorded, or the one it is on if that comes later. A group that went
    back to Task 4 after the summary was shown as "at Task 4" (walk 9, D6)."""
    ids = [st.id for st in lab_steps.STEPS]
    here = session.current_step
    got = [k for k, i in enumerate(ids) if session.step_status(i) not in ("todo", "info")]
    k = max([ids.index(here) if here in ids else -1, *got])
    return ids[k] if k >= 0 else here


def step_name(step_id: str) -> str:
    """The name a student knows a step by: "Task 12", "Tasks 6-9", "Preparation 3"."""
    try:
        title = lab_steps.step(step_id).title
    except KeyError:
        return step_id
    return title.split(":")[0].split(" (")[0]


def members(g: Group) -> str:
    """The group's names, or why there are none."""
    return ", ".join(g.members) or ("(cannot be read)" if not g.readable else "(no names)")


OWN_VS_COMPUTED: str = "own vs computed"
"""The name of the column of :func:`own_cell`, in the class's text, its report and its CSV."""


def own_cell(g: Group) -> str:
    """The group's own values against the computed ones, in one cell: "T +12 %", and a
    value the lab judged wrong with its mark: "J +39 % ✗" (walk 14, D4: the group's screen
    and report said wrong, the class view gave the number alone)."""
    parts = [
        f"{o.key.removeprefix('own.')} {format_difference(o.own, o.computed)}"
        + (f" {o.mark}" if o.right is False else "")
        for o in g.own
        if o.rel_diff is not None
    ]
    return ", ".join(parts) or MISSING


def any_wrong(view: ClassView) -> bool:
    """Whether some group's own value is judged wrong (marked in the own vs computed column):
    then "Nothing stands out." is not said, though nothing is marked '!'."""
    return any(o.right is False for g in view.groups for o in g.own)


def nothing_marked(view: ClassView) -> str:
    """What the class's text and its report say under the groups when none is marked '!':
    "Nothing marked '!'." while a group has a note or an own value judged wrong (each is
    shown), else "Nothing stands out."."""
    shown = any(g.notes for g in view.groups) or any_wrong(view)
    return "Nothing marked '!'." if shown else "Nothing stands out."


def _quantity(key: str) -> Quantity:
    return next(q for q in QUANTITIES if q.key == key)


def _resistance_slip(R: float) -> Slip:
    """The sentence for an R outside :data:`R_RANGE`: a decimal point dropped or misplaced,
    or a reading in kΩ, when R moved by a power of ten falls in the range; else the usual
    causes."""
    lo, hi = R_RANGE
    head = f"R = {format_typed(R)} Ω is outside the 3-6 Ω this motor reads (Task 2)"
    for factor, why in (
        (0.1, "its decimal point dropped"),
        (10.0, "its decimal point one place too far left"),
        (1e3, "the meter on its kΩ range, read as Ω"),
    ):
        if lo <= R * factor <= hi:
            text = f"{head}: it looks like {format_reading(R * factor, 'Ω')} with {why}."
            break
    else:
        text = (
            f"{head}: a meter on the wrong range, a loose motor cable or the current jumper "
            "missing."
        )
    return Slip(text, ("R", *FROM_TABLE))


def _field_label(key: str) -> str:
    """The label of field ``key`` as an instructor reads it (the key when it has none)."""
    fld = lab_steps.FIELDS.get(key)
    return for_grader(fld.label) if fld is not None else key


def slip_list(session: Session) -> list[Slip]:
    """The slips the lab manual warns about in ``session``'s readings, each with the
    quantities that rest on the slipped reading; a refused entry is said too (it feeds
    nothing), and so is an entry whose value in session.json its text does not read as
    (:func:`~minseg_tui.lab.state.entries.check_stored`)."""
    out = [
        Slip(f"{_field_label(e.key)}: {e.edited}.")
        if e.edited
        else Slip(
            f"a refused entry, {_field_label(e.key)}: {e.text.strip()!r} ({own_first.TOLD} "
            f"{e.message}); nothing is computed from it."
        )
        for e in session.entries.values()
        if not e.ok
    ]
    R = session.value("R")
    if R is not None and not R_RANGE[0] <= R <= R_RANGE[1]:
        out.append(_resistance_slip(R))
    for lv in LEVELS:
        i = session.value(f"i_ss@{lv:g}")
        if i is not None and i > I_SS_MAX:
            out.append(
                Slip(
                    f"i_ss at {lv:g} V = {format_reading(i, 'mA')} is above 100 mA: the manual says "
                    "the wrong thing is measured or the meter is in the wrong mode (expect "
                    "20-50 mA).",
                    FROM_TABLE,
                )
            )
        elif i is not None and 0 < i < I_SS_AMPERES:
            out.append(
                Slip(
                    f"i_ss at {lv:g} V = {format_reading(i, 'mA')} looks like amperes typed into the "
                    f"mA column ({format_number(i * 1e6)} mA?), and k_v and f follow from it.",
                    FROM_TABLE,
                )
            )
        w = session.value(f"omega_ss@{lv:g}")
        if w is not None and abs(w) > OMEGA_MAX and OMEGA_MIN <= abs(w) * RPM <= OMEGA_MAX:
            out.append(
                Slip(
                    f"omega_ss at {lv:g} V = {format_number(w)} rad/s looks like rpm: this motor does "
                    f"not turn that fast; read as rpm it is {format_number(w * RPM)} rad/s.",
                    FROM_TABLE,
                )
            )
        u = session.value(f"u_ss@{lv:g}")
        if u is not None and u > lv:
            out.append(
                Slip(
                    f"u_ss at {lv:g} V = {format_reading(u, 'V')} is above the requested {lv:g} V: the "
                    "driver only loses voltage, so the meter or the request was wrong.",
                    (*FROM_TABLE, "K"),  # K divides by the table's u_ss
                )
            )
    own_K, own_w = session.value("own.K"), session.value("own.omega_step")
    u_step = session.value(f"u_ss@{STEP_LEVEL:g}")
    if own_K is not None and own_w is not None and u_step and K_by_request(own_K, own_w, u_step):
        out.append(
            Slip(
                f"K = {format_number(own_K)} rad/s/V is omega_ss ÷ {STEP_LEVEL:g} V (the requested step "
                f"height), not ÷ the measured u_ss = {format_number(u_step)} V (Task 11): "
                f"{format_number(own_w)} / {u_step:.3g} = {format_number(own_w / u_step)} rad/s/V."
            )
        )  # the group's own K only: the program's K, which the class is judged on, is right
    return out


def slips(session: Session) -> list[str]:
    """The slips the lab manual warns about in ``session``'s readings, one sentence each."""
    return [s.text for s in slip_list(session)]


def _values(
    session: Session, res: Results, kept: Kept | None
) -> tuple[dict[str, float | None], tuple[str, ...]]:
    ident = res.identification
    st = res.step if ident is not None else None
    values: dict[str, float | None] = {
        "R": session.value("R"),
        "k_v": ident.k_v if ident else None,
        "k_a": ident.k_a if ident else None,
        "f": ident.f if ident else None,
        "K": st.K if st else None,
        "T_63": st.T_63 if st else None,
        "T": st.T if st else None,
        "J": st.J if st else None,
    }
    lacks = list(res.problems)
    if not session.runs:
        lacks.append(NO_RUN_YET)
    elif ident is None and kept is not None and kept.step is not None:
        values.update({"K": kept.step.K, "T_63": kept.step.T_63, "T": kept.step.T})
    elif ident is None:
        values.update(_response_alone(session))
    return values, tuple(dict.fromkeys(lacks))


def _response_alone(session: Session) -> dict[str, float | None]:
    """K, T and T_63 from the session's step run and its table's u_ss alone, for a session
    whose table is not complete enough for Tasks 6-9 (an i_ss or R missing): they need
    neither. Empty when the run cannot give them (the lacks already say why)."""
    run = session.response_run()
    pairs = session.table_pairs()
    if run is None or not pairs:
        return {}
    try:
        st = response_alone(read_run(session.folder, run, pairs, require_step=True), pairs)
    except (InputError, IdentifyRefused, LogRefused, ZeroVoltRefusal):
        return {}
    return {"K": st.K, "T_63": st.T_63, "T": st.T}


def check_on(session: Session) -> str:
    """The run the model check used, when it is not the one Tasks 11-15 use (walk 16, D3:
    an import feeds the model check only): "run imported-1, a log imported at the model
    check; Tasks 11-15 use run steps-1"; '' otherwise."""
    checked = session.check_run()
    elsewhere = session_views.check_elsewhere(session, checked.name if checked else None)
    if checked is None or checked == session.response_run():
        return ""
    tasks = elsewhere or "Tasks 11-15 have no run"
    return f"run {checked.name}, a log imported at the model check; {tasks}"


def run_note(run: RunInfo | None) -> str | None:
    """The line saying that ``run``, the one Tasks 11-15 use, ended
    before its plan did: "run steps-1 interrupted (quit), 7.8 of 12 s: K, T and J rest on
    it" (seconds recorded of those planned); None for a complete run or none."""
    if run is None or not run.interrupted:
        return None
    planned = 2.0 * run.plan.get("half_period", 0.0) * run.plan.get("periods", 0.0)
    of = f" of {planned:g}" if planned > 0 else ""
    return (
        f"run {run.name} interrupted ({run.interruption}), "
        f"{format_fixed(run.samples * run.ts, 1)}{of} s: K, T and J rest on it"
    )


def _runs_used(session: Session) -> list[RunInfo]:
    """The runs a row rests on: Tasks 11-15's and the model check's (once when the same)."""
    used: list[RunInfo] = []
    for r in (session.response_run(), session.check_run()):
        if r is not None and all(u.name != r.name for u in used):
            used.append(r)
    return used


def read_group(folder: Path) -> Group:
    """The row of the session in ``folder``, opened read-only (no lock, nothing written).
    A session that cannot be read at all gives a row that says why (``readable`` False)."""
    try:
        session = Session.open(folder, readonly=True)
    except InputError as exc:
        return _unreadable(folder, exc)
    return _row(folder, session)


def read_kept(folder: Path) -> Group | None:
    """The row of the session in ``folder`` as :func:`read_group` gives it, when it costs
    no fit and no model check: the session has no step run, or its file keeps both for the
    run as it is now (:meth:`Session.kept`); None otherwise (or when it cannot be read)."""
    try:
        session = Session.open(folder, readonly=True)
    except InputError:
        return None
    if session.response_run() is not None:
        kept = session.kept()
        if kept is None or kept.step is None or kept.check is None:
            return None
    return _row(folder, session)


def _unreadable(folder: Path, exc: InputError) -> Group:
    return Group(
        folder.name,
        folder,
        lacks=(f"cannot be read: {exc}",),
        damaged=str(exc),
        readable=False,
    )


def _row(folder: Path, session: Session) -> Group:
    cause, code = "", ""
    values: dict[str, float | None] = {"R": session.value("R")}
    own: tuple[Own, ...] = ()
    own_rows: tuple[OwnRow, ...] = ()
    unanswered = ""
    try:
        unanswered = session_views.unanswered_brief(session)
        kept = session.kept()
        res = session.results(kept.step if kept is not None else None)
        values, lacks = _values(session, res, kept)
        check = kept.check if kept is not None else None
        if check is None:
            mc = session.model_check()
            code = mc.result.finding.cause if mc.result is not None else ""
            problem = mc.problem if mc.run is not None else ""
        else:
            code, problem = check.cause, check.problem
        if code:
            cause = in_words(code)
        elif problem:
            lacks = (*lacks, f"model check: {problem}")
        own = tuple(
            Own(c.key, for_grader(c.label), c.unit, c.own, c.computed, c.rel_diff, c.right)
            for c in session.comparisons(results=res)
            if c.own is not None
        )
        own_rows = tuple(
            r
            for r in (*own_first.table_rows(session, res), *own_first.step_rows(session, res))
            if r.cells[1] != own_first.NOT_ANSWERED
        )
    except (InputError, ValueError, ArithmeticError, KeyError) as exc:
        # one session's trouble never hides the others: the row says what went wrong
        lacks = (f"its numbers cannot be computed: {exc}",)
    if session.damaged:
        lacks = (f"damaged: {session.damaged}", *lacks)
    found = slip_list(session)
    changed = [c for r in _runs_used(session) if (c := session.run_changed(r.name))]
    return Group(
        id=folder.name,
        folder=folder,
        members=tuple(session.members),
        date=session.date,
        step=step_name(reached(session)),
        at=step_name(session.current_step),
        values=values,
        cause=cause,
        cause_code=code,
        own=own,
        own_rows=own_rows,
        lacks=lacks,
        damaged=session.damaged,
        flags=(*(s.text for s in found), *(c.text for c in changed if c.edited)),
        slipped=tuple(q.key for q in QUANTITIES if any(q.key in s.affects for s in found)),
        notes=(
            *(n for n in (run_note(session.response_run()),) if n),
            *(c.text for c in changed if not c.edited),
            *(f"{_field_label(e.key)}: {e.older}." for e in session.entries.values() if e.older),
        ),
        check_on=check_on(session),
        typed={q.key: e.typed for q in QUANTITIES if q.reading and (e := session.entry(q.key))},
        unanswered=unanswered,
    )


def _median(xs: Sequence[float]) -> float:
    s = sorted(xs)
    n = len(s)
    return s[n // 2] if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def spread(key: str, values: Sequence[float]) -> Spread | None:
    """The class's :class:`Spread` of ``values`` (finite ones), None with fewer than
    :data:`MIN_GROUPS`."""
    xs = [v for v in values if math.isfinite(v)]
    if len(xs) < MIN_GROUPS:
        return None
    m = _median(xs)
    mad = _median([abs(x - m) for x in xs])
    return Spread(key, m, max(MAD_TO_SIGMA * mad, REL_FLOOR * abs(m)), len(xs))


def outlier(s: Spread, value: float, typed: str = "") -> str | None:
    """The sentence for ``value`` of quantity ``s.key`` (a reading: typed as ``typed``) when
    it lies outside the class's band, else None."""
    lo, hi = s.band
    if lo <= value <= hi or s.sigma <= 0:
        return None
    q = _quantity(s.key)
    unit = q.display
    times = abs(value - s.median) / s.sigma
    side = "above" if value > s.median else "below"
    return (
        f"{s.key} = {q.with_unit(value, typed)} is far {side} the class: {format_fixed(times, 0)} robust "
        f"standard deviations from its median of {format_number(q.number(s.median))} {unit}."
    )


def judge(groups: Sequence[Group]) -> ClassView:
    """The class view of ``groups``: their spreads and each group's outlier sentences
    appended to its flags. A value that rests on one of the manual's slips (``slipped``)
    is left out of the spread: it is judged against the class, never part of it."""
    spreads: dict[str, Spread] = {}
    for key in JUDGED:
        vals = [v for g in groups if key not in g.slipped and (v := g.value(key)) is not None]
        s = spread(key, vals)
        if s is not None:
            spreads[key] = s
    by_names: dict[tuple[str, ...], list[str]] = {}
    for g in groups:
        by_names.setdefault(names_key(g.members), []).append(g.id)
    out = []
    for g in groups:
        extra = []
        twins = [i for i in by_names.get(names_key(g.members), []) if i != g.id]
        if twins and g.members:
            extra.append(
                f"another session of the same names: {', '.join(twins)} (one group's two "
                "sessions: which one holds the work?)"
            )
        for key, s in spreads.items():
            v = g.value(key)
            why = None if v is None else outlier(s, v, g.typed.get(key, ""))
            if why:
                extra.append(why)
        out.append(replace(g, flags=(*g.flags, *extra)) if extra else g)
    root = groups[0].folder.parent if groups else Path()
    return ClassView(root, tuple(out), spreads)


def session_folders(root: Path) -> list[Path]:
    """The folders under ``root`` that hold a session file, or a session's ``runs/`` folder
    without it (a session that lost its file: listed as one that cannot be read, never
    left out in silence), sorted by name.

    InputError (one line) when ``root`` does not exist, is not a folder, cannot be listed
    or holds no session."""
    root = Path(root)
    try:
        if not root.is_dir():
            why = "is not a folder" if root.exists() else "does not exist"
            raise InputError(str(root), None, f"{why}: give the sessions folder (--sessions DIR)")
        names = sorted(os.listdir(root))
    except OSError as exc:
        raise SessionsUnreadable(
            str(root), None, f"cannot list the sessions folder ({exc.strerror or exc})"
        ) from None
    found = []
    for name in names:
        folder = root / name
        try:
            # runs/ without its session.json: listed, as lost; a folder this user may not
            # look into: listed, as one that cannot be read (s38 attack: it was left out)
            if folder.is_dir() and folder_holds(folder):
                found.append(folder)
        except OSError:
            continue
    if not found:
        raise InputError(
            str(root),
            None,
            f"holds no session (no folder with a {SESSION_FILE}); is it the sessions folder?",
        )
    return found


__all__ = [
    "JUDGED",
    "MARKED",
    "NOT_MARKED",
    "OWN_VS_COMPUTED",
    "QUANTITIES",
    "THRESHOLD",
    "ClassView",
    "Group",
    "Own",
    "Quantity",
    "Slip",
    "Spread",
    "for_grader",
    "judge",
    "marked_summary",
    "members",
    "nothing_marked",
    "outlier",
    "own_cell",
    "read_group",
    "read_kept",
    "session_folders",
    "slip_list",
    "slips",
    "spread",
    "step_name",
]
