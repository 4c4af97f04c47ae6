"""What the lab's screens show, as plain data ready to render.

Each builder reads a :class:`~minseg_tui.lab.state.session.Session` (or live samples) through its
public methods and returns frozen data: the live speed and Task 4's steady-state indicator,
the verdict on an entry, the table of Tasks 6-9 with the formula behind every cell, the
recorded runs with their T readings (Task 10), the results of Tasks 11-15 and the model
check. Every number comes from :mod:`minseg_tui.signals`, :mod:`minseg_tui.model` or the
session; the UI only lays the text and arrays out. Units: V, A, ohm, rad, rad/s, s.

The slow builders (:func:`runs`, :func:`results`, :func:`check`, up to half a second on a
long run) are meant for a worker thread; a Session is not thread-safe, so the caller holds
it for one thread at a time.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from minseg_tui import signals
from minseg_tui.errors import InputError
from minseg_tui.lab.content import identify_says
from minseg_tui.lab.content import needs as lab_needs
from minseg_tui.lab.content.keys import USE_RUN, key_name
from minseg_tui.lab.content.steps import FIELDS, STEPS, step
from minseg_tui.lab.content.u_ss_says import u_ss_words
from minseg_tui.lab.saving.files import TABLE_COLUMNS
from minseg_tui.lab.saving.runs import RESPONSE_KINDS, RunInfo
from minseg_tui.lab.state import capture as lab_capture
from minseg_tui.lab.state import compare as lab_compare
from minseg_tui.lab.state import shown as lab_shown
from minseg_tui.lab.state.entries import choice_words, read_entry
from minseg_tui.lab.state.results import Comparison, Notice
from minseg_tui.lab.state.session import Entry, Session, TableRow
from minseg_tui.lab.views import check_says, check_words
from minseg_tui.lab.views.check_says import in_words
from minseg_tui.model import identify as model_identify
from minseg_tui.model.identify.identification import determined
from minseg_tui.model.identify.rises import E63
from minseg_tui.model.runlog import RunLog
from minseg_tui.quantities import (
    DIGITS,
    MISSING,
    NOT_DETERMINED,
    axis_label,
    format_constant_interval,
    format_difference,
    format_number,
    format_quantity,
    format_reading,
    format_spread,
    format_typed,
    format_value,
    parse_quantity,
    shown_unit,
)

FloatArray = NDArray[np.float64]

PLOT_SPAN: float = 8.0
"""Seconds of the live stream on screen."""

CAPTURE_VELOCITY_WINDOW: float = 0.1
"""Speed used for the steady-state indicator and the capture of omega_ss: the mean speed over
the last 0.1 s from the board's timestamps (:func:`signals.timestamp_velocity`), s. Four 25 ms
samples: quiet enough to judge steadiness, and without the manual's 0.5 s lag."""

CAPTURE_WINDOW: float = lab_capture.DEFAULT_WINDOW
"""The window the indicator judges and a capture averages over, s."""

TABLE_HEADERS: tuple[str, ...] = (
    *(f"{'u' if name == 'u_req' else name}\n{unit}" for name, unit in TABLE_COLUMNS.items()),
    "k_v\nV s/rad",
    "f\nmN m s/rad",
)
"""The table's headers: name over unit (the cells hold bare numbers in these units), the
readings' units those of the table's file (:data:`~minseg_tui.lab.saving.files.TABLE_COLUMNS`)."""

_FORMULAS = dict(step("table").formulas)


def _empty() -> FloatArray:
    return np.zeros(0)


def _fmt_milli(v: float | None, unit: str, digits: int = DIGITS) -> str:
    """``v`` in thousandths of ``unit`` (f in mN m s/rad, as the table's column shows it)."""
    return format_value(None if v is None else v * 1e3, f"m{unit}", digits)


def _ci(ci: tuple[float, float], unit: str) -> str:
    """ ", 95 % interval lo – hi unit" for a finite interval (SI ``unit``, shown in the unit
    people read it in: T in ms); '' when it is not known."""
    lo, hi = ci
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return ""
    return f", 95 % interval {format_constant_interval(lo, hi, unit)}"


# -- Task 4: the live stream ------------------------------------------------------------------
@dataclass(frozen=True)
class LiveView:
    """The last :data:`PLOT_SPAN` s of the stream: x (s from the first sample shown), the
    angle theta (rad), the speed from the board's timestamps ``omega`` and the manual's
    ``omega_lab`` (rad/s). Empty arrays with fewer than two samples."""

    x: FloatArray = field(default_factory=_empty)
    theta: FloatArray = field(default_factory=_empty)
    omega: FloatArray = field(default_factory=_empty)
    omega_lab: FloatArray = field(default_factory=_empty)


def live(t: ArrayLike, count: ArrayLike, span: float = PLOT_SPAN) -> LiveView:
    """The live plots from board times ``t`` (s) and encoder counts, the last ``span`` s."""
    tt = np.asarray(t, dtype=float)
    cc = np.asarray(count, dtype=np.int64)
    if tt.size < 2:
        return LiveView()
    keep = tt >= tt[-1] - span
    tt, cc = tt[keep], cc[keep]
    return LiveView(
        tt - tt[0],
        signals.angle(cc),
        signals.timestamp_velocity(tt, cc),
        signals.lab_velocity(cc),
    )


def recording(t: ArrayLike, count: ArrayLike, t0: float) -> LiveView:
    """A run as it arrives (Task 10): the live samples (board time s, counts) from the run's
    first sample at ``t0`` (s) on, x in s from ``t0``."""
    tt = np.asarray(t, dtype=float)
    keep = tt >= t0 - 1e-9
    v = live(tt[keep], np.asarray(count, dtype=np.int64)[keep], span=math.inf)
    return v if v.x.size == 0 else replace(v, x=v.x + (tt[keep][0] - t0))


def _capture_speed(t: ArrayLike, count: ArrayLike) -> FloatArray:
    return signals.timestamp_velocity(t, count, window=CAPTURE_VELOCITY_WINDOW)


def steady(t: ArrayLike, count: ArrayLike) -> lab_capture.Steadiness:
    """Task 4's indicator on live samples (board time s, counts): settled, and the mean and
    spread (rad/s) over the last :data:`CAPTURE_WINDOW` s."""
    return lab_capture.steadiness(t, _capture_speed(t, count))


# -- entries ------------------------------------------------------------------------------------
@dataclass(frozen=True)
class EntryView:
    """The lab's verdict on what was entered: ``ok`` False with a one-line ``message``, else
    stored (``message`` then says how it was read, if anything). ``warnings`` are shown but
    never refuse; ``feedback`` is a checker's verdict on an answer."""

    ok: bool
    message: str = ""
    warnings: tuple[str, ...] = ()
    feedback: str = ""


ROW_READINGS: tuple[str, ...] = ("u_ss", "omega_ss", "i_ss")
"""The readings of the table's rows, one row per requested voltage ('i_ss@2.5')."""

SAME_LEVEL = 0.05
"""Two requested voltages closer than this (V) are the same row's."""


def typed_at_another_level(key: str, requested: float | None) -> str:
    """The line under a reading of one row (u_ss, omega_ss or i_ss at L V) typed while the
    motor runs at another requested voltage: 'typed while the motor runs at 4.5 V, not 2.5 V:
    a reading taken now is the 4.5 V one (F3 steps to the next voltage)'; '' for any other
    field, with the motor off (``requested`` None or 0), or at the row's own voltage. Said, not
    stored: the session does not know what the motor ran at when a value was typed (walk 18,
    D2: the meter's 4.5 V current went into the 2.5 V row without a word)."""
    name, at, level = key.partition("@")
    if not at or name not in ROW_READINGS or not requested:
        return ""
    try:
        row = float(level)
    except ValueError:
        return ""
    if abs(requested - row) < SAME_LEVEL:
        return ""
    return (
        f"typed while the motor runs at {requested:g} V, not {row:g} V: a reading taken now is "
        f"the {requested:g} V one ({key_name('set_voltage')} steps to the next voltage)"
    )


STATUS_MARKS: tuple[tuple[str, str, str], ...] = (
    ("done", "✓", "done"),
    ("wrong", "✗", "answered but wrong"),
    ("refused", "?", "an entry refused"),
    ("warned", "!", "stored with a warning: look again"),
    ("unjudged", "○", "stored, not judged yet"),
    ("started", "…", "started"),
)
"""The marks of a step's status (:meth:`Session.step_status`) in the list of steps, and of a
value under its entry and in the report: (status, a character, not a colour; what it means).
A step with no mark has nothing to say (not begun, or nothing to enter)."""

MARK: dict[str, str] = {status: mark for status, mark, _ in STATUS_MARKS}
"""The mark of each status that has one."""

NOT_JUDGED = "stored, not judged yet: nothing computed to compare it with"
"""Said under one of the group's own values (Tasks 6-9, 11-15) while the program has no
value to judge it by (no table, no run yet), after its mark (:data:`MARK` ``unjudged``);
its step is then marked so too, not ✓."""


def marks_legend() -> str:
    """What the marks mean, in one line: '✓ done, ✗ answered but wrong, ...'."""
    return ", ".join(f"{mark} {words}" for _, mark, words in STATUS_MARKS)


def _feedback(session: Session, key: str) -> str:
    for fb in session.feedback("*"):
        if fb.key == key and fb.status != "missing":
            return fb.message
    fld = FIELDS.get(key)
    if fld is not None and fld.compare and key in session.answered():
        owner = next(st.id for st in STEPS if fld in st.fields)
        for c in session.comparisons(owner):
            if c.key == key and (
                fld.kind != "text" or c.right is not None or c.verdict or waits_for(session, key)
            ):
                again = judged_again(session, key) if c.right is not None else ""
                return under_entry(session, c) + (f"\n{again}" if again else "")
    return ""


def judged_again(session: Session, key: str, whose: str = "you", back: bool = True) -> str:
    """One line for an answer of Tasks 11-15 given while another run was in use than the one
    Tasks 11-15 use now (the group chose another, or a new run took over): it is judged
    again, against the run in use now; which run it was given on; and how to go back to that
    one while the session has it ("judged again, against run steps-2: you gave it while run
    steps-1 was in use; Ctrl+P 'Use run steps-1' judges it there"). '' otherwise: no answer,
    given on the run in use, or not known on which (before any run, or in a session of an
    older program). ``whose``: who gave it ("you" on the screen, "the group" in the report);
    ``back``: with the key that goes back (the screen's, not the report's)."""
    e = session.entry(key)
    run = session.response_run()
    if e is None or not e.run or run is None or e.run == run.name:
        return ""
    if key not in session.answered():
        return ""
    said = f"judged again, against run {run.name}: {whose} gave it while run {e.run} was in use"
    if back and any(r.name == e.run for r in session.runs):
        said += f"; {key_name('palette')} '{USE_RUN} {e.run}' judges it there"
    return said


def _shown_unit(session: Session, c: Comparison) -> str:
    """The unit a comparison shows ``c``'s values in: one unit per quantity, the field's form
    unit, T and f in the one unit each is shown in (:func:`~minseg_tui.quantities.shown_unit`),
    whatever unit the group typed theirs in (80 rpm is compared as 8.378 rad/s)."""
    del session  # what the group typed does not change the unit
    return shown_unit(c.unit)


_AGAINST: dict[str, str] = {
    "own.omega_step": "the program's steady speed (median over the rises)",
    "own.T": "the program's 63 % reading (median over the rises)",
}
"""What a reading off the plot is compared with, under its entry (the other values are
compared with the value computed the group's way)."""


def _R_changed_after(session: Session, key: str) -> str:
    """Why a J the group gave turned wrong without being touched: R, which J is computed
    from the group's way, was changed after it ("R was changed from '3,5 ohms' to '5,3 ohm'
    after you gave it"); "" otherwise (walk 17's D5: J went from ✓ to ✗ when the group
    corrected a misread R three steps later, and nothing said why)."""
    if key != "own.J":
        return ""
    own, r = session.entry(key), session.entry("R")
    if own is None or r is None or not r.history or not own.at or r.at <= own.at:
        return ""
    return (
        f"R was changed from {r.history[-1][0].strip()!r} to {r.text.strip()!r} after you gave it"
    )


def under_entry(session: Session, c: Comparison) -> str:
    """The verdict on the group's value ``c`` right under its entry, after its mark: right or
    wrong, the difference from the value computed the group's way, and the least-squares
    value beside it ('✓ right: +2 % from 2.010 rad/s/V, computed your way; least squares
    1.996 rad/s/V'); ○ :data:`NOT_JUDGED` while nothing is computed to compare it with. The
    panel under the entries says how each was computed and why the two differ."""
    if c.right is None:
        if c.verdict:
            return f"{MARK['unjudged']} not judged: {c.verdict}"
        why = lab_needs.needs(waits_for(session, c.key)) if c.computed is None else ""
        if why:  # say what keeps the value it is judged by from being computed
            return f"{MARK['unjudged']} {NOT_JUDGED.split(':')[0]}: the value to compare with {why}"
        return f"{MARK['unjudged']} {NOT_JUDGED}"
    mark, word = (MARK["done"], "right") if c.right else (MARK["wrong"], "wrong")
    unit = _shown_unit(session, c)
    if c.rel_diff is not None and isinstance(c.computed, float):
        said = (
            f"{word}: {format_difference(c.own, c.computed)} from {format_quantity(c.computed, unit)}, "
            + _AGAINST.get(c.key, "computed your way")
        )
        why = c.verdict.removeprefix("wrong:").strip()
        if why:
            said += f", {why}"
        if not c.right:
            changed = _R_changed_after(session, c.key)
            if changed:
                said += f"; {changed}"
    else:
        said = c.verdict or word
    if c.caveat:
        said += f"; {c.caveat}"
    if c.least_squares is not None:
        lsq = c.least_squares
        said += f"; least squares {lsq if isinstance(lsq, str) else format_quantity(lsq, unit)}"
    return f"{mark} {said}"


def _verdict(e: Entry, feedback: str) -> EntryView:
    if e.edited:  # session.json edited by hand: what it holds, not judged
        return EntryView(False, e.edited, (), feedback)
    if e.older and not e.refused:  # as an older program read it, said so
        return EntryView(True, e.older, tuple(e.warnings), feedback)
    if e.refused:  # a refused attempt over an accepted entry: say so, and what still counts
        fld = FIELDS.get(e.key)
        if fld is not None and fld.options and isinstance(e.value, tuple):
            using = choice_words(fld, e.value)  # the answers' words, not the file's letters
        else:
            using = repr(e.text.strip())
        return EntryView(
            False, f"{e.refused[1]} (still using {using})", tuple(e.warnings), feedback
        )
    return EntryView(e.ok, _echo(e), tuple(e.warnings), feedback)


def _echo(e: Entry) -> str:
    """How accepted entry ``e`` was read, in this program's words: read again from its text,
    so that a session saved by an older version shows what the program says now (its '85 ms'
    for T was "read as 0.085 s" then, no echo now: T is in ms throughout); the stored
    message when the text no longer reads as the value kept."""
    fld = FIELDS.get(e.key)
    if fld is None or not e.ok:
        return e.message
    again = read_entry(fld, e.text)
    return again.message if again.ok and again.value == e.value else e.message


def entry(session: Session, key: str) -> EntryView | None:
    """The verdict on the stored entry for field ``key`` (None when nothing was entered),
    with the warnings its row raises beside the others (a current that falls as the voltage
    rises, on Task 5)."""
    e = session.entry(key)
    if e is None:
        return None
    view = _verdict(e, _feedback(session, key))
    beside = tuple(n.message for n in session.falling_currents() if n.source == key)
    return replace(view, warnings=view.warnings + beside) if beside and view.ok else view


def typed(session: Session, key: str) -> str:
    """What field ``key`` shows: the text typed last (a refused attempt too), or ''."""
    e = session.entry(key)
    return e.typed if e else ""


def held(session: Session, key: str) -> str:
    """The text in effect for field ``key`` (an accepted answer, not a refused attempt over
    it), or '' when nothing was entered: what Escape brings back in the field."""
    e = session.entry(key)
    return e.text if e else ""


def step_u_ss(session: Session) -> str:
    """The text the group typed as u_ss in the row of Task 10's steps (''
    for none): the digits :func:`~minseg_tui.lab.state.compare.format_u_ss` writes K's u_ss
    with."""
    return held(session, f"u_ss@{lab_compare.STEP_LEVEL:g}")


def answer(session: Session, key: str) -> str:
    """The group's accepted answer in field ``key`` as the report and the results quote it
    back: a number in the one unit of its quantity with the digits typed
    (:meth:`~minseg_tui.lab.state.session.Session.reading`: '3,79' is "3.79", '80 rpm'
    "8.378 rad/s"); a formula or arithmetic worked out keeps the group's text with its value
    beside it ('1-exp(-1)' is "1-exp(-1) = 0.6321"); any other text as typed; '' when
    nothing was accepted."""
    e = session.entry(key)
    if e is None or not e.ok:
        return ""
    text = e.text.strip()
    reading = session.reading(key)
    if reading is None:
        return text
    fld = FIELDS[key]
    try:  # a plain number, perhaps with a unit: its reading says it all
        parse_quantity(text, fld.unit, allow_negative=True, allow_zero=True)
    except InputError:
        return f"{text} = {reading}"
    return reading


def previous_answer(session: Session, key: str, skip: Sequence[str] = ()) -> str | None:
    """The answer stored for field ``key`` before the one in effect: the newest earlier
    text that reads as an answer and differs from it and from those in ``skip`` (the ones
    Ctrl+Z already took back, so that Ctrl+Z again goes further back); None: there is none.
    Ctrl+Z in the field enters it again."""
    e = session.entry(key)
    if e is None or key not in FIELDS:
        return None
    passed = {e.text.strip(), *(t.strip() for t in skip)}
    for text, _at in reversed(e.history):
        if text.strip() not in passed and text.strip() and read_entry(FIELDS[key], text).ok:
            return text
    return None


def judged(session: Session, key: str) -> str:
    """How the answer in effect for field ``key`` is judged, in words for a notice: "marked
    wrong (why)", the check's words when it holds ("right: ..."), or "" for a field nothing
    judges (or no answer yet)."""
    for fb in session.feedback("*"):
        if fb.key == key and fb.status != "missing":
            return f"marked wrong ({fb.message})" if fb.status == "wrong" else fb.message
    fld = FIELDS.get(key)
    if fld is not None and fld.compare:
        owner = next(st.id for st in STEPS if fld in st.fields)
        for c in session.comparisons(owner):
            if c.key == key and c.right is not None:
                return "marked right" if c.right else "marked wrong"
    return ""


def chosen(session: Session, key: str) -> tuple[int, ...]:
    """The options (0-based) stored for choice field ``key``."""
    e = session.entry(key)
    return e.value if e is not None and e.ok and isinstance(e.value, tuple) else ()


def capture_live(session: Session, level: float, t: ArrayLike, count: ArrayLike) -> EntryView:
    """Task 4: capture omega_ss at requested ``level`` (V) from live samples (board time s,
    counts) into ``session`` (autosaved), refused while the speed is not settled."""
    w = _capture_speed(t, count)
    if not lab_capture.steadiness(t, w).settled:
        return EntryView(False, "not settled yet: wait until the indicator says SETTLED")
    try:
        e = session.capture_omega(level, np.asarray(t, dtype=float).tolist(), w.tolist())
    except ValueError as exc:
        return EntryView(False, str(exc))
    return _verdict(e, "")


def read_only(session: Session) -> str:
    """The opening of each sentence that refuses a change of a session opened read-only, with
    why it is: "this session is open read-only (its file is damaged)" for a damaged one (the
    start screen opens it so), "(opened to look, not to change)" for one opened from the
    class view, whose file is sound (walk 14, D2: F5 there called it damaged)."""
    why = "its file is damaged" if session.damaged else "opened to look, not to change"
    return f"this session is open read-only ({why})"


REVEAL_KEY = key_name("reveal")

REVEALED_ON_PLOT = f"{lab_compare.REVEALED_EARLY}, {REVEAL_KEY}"
"""Said on the plot of Tasks 11-12 beside a reading a lab assistant revealed before the group
answered (:attr:`ResultsView.revealed`): the reveal leaves that plot in view, and the
comparisons that say it lie below the screen at 80x24 until the group answers."""
"""The key a lab assistant presses to show a step's computed values before the group answers."""


def hidden(session: Session) -> set[str]:
    """The fields of Tasks 11-15 whose computed value is still hidden from the group (the
    lab's policy, :func:`minseg_tui.lab.state.compare.concealed`)."""
    return lab_compare.concealed(policy(session), session.answered(), session.revealed())


def policy(session: Session) -> lab_compare.Policy:
    """The lab's policy, from lab.toml in the folder that holds the session."""
    return lab_compare.read_policy(session.folder.parent)


_WAY: dict[str, str] = {
    "own.omega_step": "the program's steady speed",
    "own.T": "read your way",
}
"""How the value a group's reading is compared with was had, before it (the others: computed
your way, from their own values; Tasks 7-9: from their table)."""

_T_WHY = "The fit models the sampling, which moves the 63 % reading (the two T: under the results)."
"""Task 12's one sentence on why the least-squares T is not the 63 % reading (the whole
reason stands once under the results)."""


def comparisons(session: Session, step_id: str) -> tuple[tuple[str, str, str], ...]:
    """The group's own readings on step ``step_id`` beside the values computed their way:
    (label, yours, then how the value it is compared with was had, the value, the relative
    difference; on a second line, the least-squares value and one sentence on why the two
    differ): 'computed your way 2.069 rad/s/V (...): -3 %', 'read your way 56.14 ms (the
    program's reading by your method: ...): +2 %'. A value still hidden says how to see it."""
    out = []
    conceal = hidden(session)
    for c in session.comparisons(step_id):
        typed_ = session.entry(c.key)
        own = (
            MISSING
            if c.own is None
            else c.own
            if isinstance(c.own, str)
            else answer(session, c.key) or typed_.text.strip()
            if typed_ is not None and typed_.ok
            else format_quantity(c.own, c.unit)
        )
        if c.key in conceal:
            out.append(
                (
                    c.label,
                    own,
                    f"computed: shown once you enter yours ({REVEAL_KEY}: lab assistant)",
                )
            )
            continue
        if c.computed is None and c.right is None and c.verdict:  # waits for an entry
            out.append((c.label, own, f"{MARK['unjudged']} not judged: {c.verdict}"))
            continue
        unit = _shown_unit(session, c)
        way = _WAY.get(
            c.key, "computed from your table" if step_id == "table" else "computed your way"
        )
        why = lab_needs.needs(waits_for(session, c.key)) if c.computed is None else ""
        comp = (
            f"{way}: not yet, {why}"
            if why
            else way
            + " "
            + (
                MISSING
                if c.computed is None
                else (
                    c.computed if isinstance(c.computed, str) else format_quantity(c.computed, unit)
                )
            )
        )
        if c.how:
            comp += f" ({c.how})"
        if c.rel_diff is not None:
            comp += f": {format_difference(c.own, c.computed)}"
        if c.verdict:
            comp += f"\n  {c.verdict}"
        if c.caveat:
            comp += f"\n  {c.caveat}"
        if c.revealed_early:  # what Ctrl+R's notice said (it covered the plot read)
            recorded = "" if session.readonly else ": the report says so"
            comp += f" · {lab_compare.REVEALED_EARLY} ({REVEAL_KEY}){recorded}"
        if c.least_squares is not None:
            lsq = (
                c.least_squares
                if isinstance(c.least_squares, str)
                else format_quantity(c.least_squares, unit)
            )
            # T's whole why is the long sentence on the two readings of T: it stands under the
            # results (:func:`results`), so the comparison keeps one short sentence
            comp += f"\n  least squares: {lsq}. {_T_WHY if c.key == 'own.T' else c.why}".rstrip()
        out.append((c.label, own, comp))
    return tuple(out)


# -- Tasks 6-9: the table ------------------------------------------------------------------------
@dataclass(frozen=True)
class Cell:
    """A value in the table: the text shown and the formula with numbers behind it."""

    text: str
    formula: str = ""


@dataclass(frozen=True)
class TableView:
    """Columns, rows of cells, the final values, the warnings the numbers raise (one line
    each) and the group's own values beside the computed ones (label, yours, computed)."""

    columns: tuple[str, ...]
    rows: tuple[tuple[Cell, ...], ...]
    results: tuple[tuple[str, Cell], ...] = ()
    warnings: tuple[str, ...] = ()
    compare: tuple[tuple[str, str, str], ...] = ()
    waiting: str = ""
    """While the final k_v, k_a and f cannot be computed: which inputs they need and where
    to enter them, one line ('' otherwise)."""


WORKED_DIGITS: int = 10
"""The most significant digits of a number in a formula worked out with the row's numbers
(:func:`_worked_inputs`)."""

Written = tuple[float, int, Callable[[float, int], str]]
"""A number of a worked formula: its value, the fewest digits it is written with, and how
(:func:`format_number`: 0.0280 A, its zeros kept; :func:`format_typed`: R as typed)."""


def _worked_inputs(
    inputs: Sequence[Written], work: Callable[[Sequence[float]], float], shown: str
) -> tuple[list[str], str]:
    """The ``inputs`` of a formula written so that ``work`` on the numbers as written gives
    the result as it is ``shown`` (:func:`format_number`), and '=': each with its fewest
    digits, and a number those do not write exactly (a captured omega_ss, k_a) with one more
    digit at a time until the result follows; '≈' when none up to :data:`WORKED_DIGITS`
    does. Walk 4: omega_ss captured as 3.8247 rad/s was shown 3.82, and the arithmetic on the
    line gave 0.4953 beside the 0.4947 printed."""

    def write(value: float, fewest: int, how: Callable[[float, int], str], digits: int) -> str:
        text = how(value, fewest)
        if math.isclose(float(text), value, rel_tol=1e-12):
            return text
        return how(value, max(fewest, digits))

    texts: list[str] = []
    for digits in range(3, WORKED_DIGITS + 1):
        texts = [write(v, fewest, how, digits) for v, fewest, how in inputs]
        if format_number(work([float(t) for t in texts])) == shown:
            return texts, "="
    return texts, "≈"


def _row_formula(name: str, r: TableRow, R: float | None, k_a: float | None) -> str:
    """The formula of a computed cell of row ``r`` with the row's numbers in it (R in ohm,
    i_ss in A, k_a in N m/A, the final one), each with the digits the result needs: worked
    out from the numbers shown, the line gives the result it prints (:func:`_worked_inputs`)."""
    if name == "k_v" and r.k_v is not None and r.u_ss is not None and r.i_ss is not None:
        if r.omega_ss is not None and R is not None:
            shown = format_number(r.k_v)
            (u, res, i, w), eq = _worked_inputs(
                (
                    (r.u_ss, 3, format_number),
                    (R, DIGITS, format_typed),  # as typed: 5,3 is 5.3 Ω, never 5.30 Ω
                    (r.i_ss, 3, format_number),
                    (r.omega_ss, 3, format_number),
                ),
                lambda x: (x[0] - x[1] * x[2]) / x[3],
                shown,
            )
            return (
                f"k_v = (u_ss - R i_ss) / omega_ss = ({u} V - {res} Ω × {i} A) / {w} rad/s "
                f"{eq} {shown} V s/rad"
            )
    if name == "f" and r.f is not None and r.i_ss is not None and r.omega_ss is not None:
        if k_a is not None:
            shown = format_number(r.f * 1e3)
            (ka, i, w), eq = _worked_inputs(
                (
                    (k_a, DIGITS, format_number),
                    (r.i_ss, 3, format_number),
                    (r.omega_ss, 3, format_number),
                ),
                lambda x: x[0] * x[1] / x[2] * 1e3,
                shown,
            )
            return (
                f"f = k_a i_ss / omega_ss = {ka} N m/A × {i} A / {w} rad/s {eq} {shown} "
                "mN m s/rad (k_a = 0.65 × median k_v)"
            )
    return _FORMULAS[name]


def _derived_cell(
    name: str,
    value: float | None,
    text: str,
    r: TableRow,
    R: float | None,
    k_a: float | None,
    has: Callable[[str], bool],
) -> Cell:
    """The cell of a row's computed ``name`` (k_v or f): ``text`` with its worked formula, or,
    while an input is missing, what it needs ('needs R'), F7 saying which inputs and where
    to enter them before the formula."""
    if value is not None:
        return Cell(text, _row_formula(name, r, R, k_a))
    miss = lab_needs.missing(f"{name}@row", has)
    if not miss:
        return Cell(MISSING, _row_formula(name, r, R, k_a))
    return Cell(
        lab_needs.needs_short(miss),
        f"{name} here {lab_needs.needs(miss)}. {_FORMULAS[name]}",
    )


def _has(session: Session, row: TableRow | None) -> Callable[[str], bool]:
    """Which inputs of :data:`~minseg_tui.lab.content.needs.INPUTS` the session has
    (:meth:`~minseg_tui.lab.state.session.Session.has_input`), ``row``'s own readings
    among them."""
    return lambda name: session.has_input(name, row)


_DERIVED: dict[str, str] = {
    "own.k_v": "k_v",
    "own.k_a": "k_a",
    "own.f": "f",
    "own.omega_step": "omega_step",
    "own.K": "K",
    "own.T": "T",
    "own.J": "J",
    "own.model": "model",
    "own.omega_5": "omega_5",
}
"""The derived value (:data:`~minseg_tui.lab.content.needs.NEEDS`) each of the group's own
values is compared with."""


def _unless_concealed(
    conceal: set[str], step_id: str, key: str, line: str, what: str, task: str
) -> str:
    """``line`` (a result of Tasks 11-15, field ``key``), or, while it is concealed until the
    group answers, what it waits for: the group's answer on step ``step_id`` (with the lab
    assistant's key) or on ``task``."""
    if key not in conceal:
        return line
    if key in {f.key for f in step(step_id).fields}:
        return f"{what}: shown once you enter yours ({REVEAL_KEY}: lab assistant)"
    return f"{what}: shown once you enter yours on {task}"


def speed_only_waits(session: Session) -> str:
    """What Tasks 11-15 wait for while the run gives omega_ss and T but no u_ss is given
    (walk 18, D4): the screen's line and the report's."""
    return (
        "K, J, the model and omega at 5 V: not yet, "
        + lab_needs.needs(waits_for(session, "K"))
        + "; omega_ss and T need only the speed"
    )


def waits_for(session: Session, key: str, row: TableRow | None = None) -> tuple[str, ...]:
    """The inputs (:data:`~minseg_tui.lab.content.needs.INPUTS` keys) the value that field
    ``key`` (own.k_v, ...) or derived value ``key`` (k_v, J, k_v@row with ``row``, ...) is
    computed from still waits for; () when none is missing."""
    name = _DERIVED.get(key, key)
    if name not in lab_needs.NEEDS:
        return ()
    miss = lab_needs.missing(name, _has(session, row))
    if "run" in miss and any(r.kind in ("steps", "fast") for r in session.runs):
        # step runs there, each interrupted (a complete one would be in use; an imported
        # log is the model check's unless chosen): what to do
        miss = tuple("run.complete" if k == "run" else k for k in miss)
    return miss


def _typed(value: float | None, scale: float, text: str) -> str:
    """A reading of the table (SI ``value`` times ``scale``: the column's unit) with the
    digits it was typed with (``text``), as the report gives it (i_ss typed 14 is "14",
    never "14.0"; u_ss typed 4,0 is "4.0", never "4"); "—" when there is none. A captured
    omega_ss is a mean, written with 3 digits beside its spread."""
    return format_number(None) if value is None else format_reading(value * scale, "", typed=text)


def _table_row(
    r: TableRow,
    R: float | None,
    k_a: float | None,
    has: Callable[[str], bool],
    typed: Callable[[str], str],
) -> tuple[Cell, ...]:
    """The cells of row ``r``; typed(name): the text its reading ``name`` (u_ss, ...) was
    typed as."""
    spread = "" if r.spread is None else f" {format_spread(r.spread)}"
    omega_how = (
        "omega_ss: captured, the mean over the settled window ± its spread (rad/s)"
        if r.spread is not None
        else "omega_ss: typed in (rad/s)"
        if r.omega_ss is not None
        else ""
    )
    return (
        Cell(f"{r.level:g}", f"u = {r.level:g} V: the voltage requested on the board"),
        Cell(
            _typed(r.u_ss, 1.0, typed("u_ss")),
            "u_ss: read on the multimeter (V)" if r.u_ss is not None else "",
        ),
        Cell(
            _typed(r.omega_ss, 1.0, typed("omega_ss"))
            if r.spread is None
            else format_number(r.omega_ss, 3) + spread,
            omega_how,
        ),
        Cell(
            _typed(r.i_ss, 1e3, typed("i_ss")),
            "i_ss: read on the multimeter (mA)" if r.i_ss is not None else "",
        ),
        _derived_cell("k_v", r.k_v, format_number(r.k_v), r, R, k_a, has),
        _derived_cell("f", r.f, format_number(None if r.f is None else r.f * 1e3), r, R, k_a, has),
    )


def table(session: Session) -> TableView:
    """The table with its units in the headers and short cells (it fits the pane at 80
    columns); each computed cell's formula carries the row's own numbers."""
    R = session.value("R")
    res = session.results()
    ident = res.identification
    k_a = None if ident is None else ident.k_a
    table_rows = session.table()

    def typed_in(level: float) -> Callable[[str], str]:
        return lambda name: held(session, f"{name}@{level:g}")

    rows = tuple(_table_row(r, R, k_a, _has(session, r), typed_in(r.level)) for r in table_rows)
    results: tuple[tuple[str, Cell], ...] = ()
    waiting = ""
    if ident is not None:
        results = (
            ("k_v", Cell(format_quantity(ident.k_v, "V s/rad"), _FORMULAS["k_v"])),
            ("k_a", Cell(format_quantity(ident.k_a, "N m/A"), _FORMULAS["k_a"])),
            ("f", Cell(_fmt_milli(ident.f, "N m s/rad"), _FORMULAS["f"])),
        )
    else:
        miss = lab_needs.missing("f", _has(session, None))
        waiting = f"k_v, k_a and f (the medians): {lab_needs.needs(miss)}" if miss else ""
    # the T findings name T, Task 12's answer: kept back until the group has given theirs
    shown = [
        n
        for n in session.warnings("table")
        if n.source not in TWO_T or "own.T" not in hidden(session)
    ]
    warnings = tuple(with_two_T(shown, "Task 12 says it")) + tuple(res.problems)
    return TableView(
        TABLE_HEADERS,
        rows,
        results,
        tuple(dict.fromkeys(warnings)),
        comparisons(session, "table"),
        waiting,
    )


# -- Task 10: the recorded runs --------------------------------------------------------------------
@dataclass(frozen=True)
class RunView:
    """A Task 10 run for the side-by-side panel: speeds (rad/s) at board times t (s), the
    manual's estimate ``omega_lab``, and the time constants read from it (s, None if none):
    T_63 on the timestamp speed, T_63_lab on the manual's filtered speed, T_ls with its 95 %
    interval T_ci (None when the log does not determine T: wider than a factor of ten, or T on
    its bound). ``kind``: steps (25 ms) or fast."""

    name: str
    kind: str
    ts: float
    samples: int
    interrupted: bool
    t: FloatArray
    omega: FloatArray
    omega_lab: FloatArray
    T_63: float | None
    T_63_lab: float | None
    T_ls: float | None
    T_ci: tuple[float, float] | None
    interruption: str = ""
    """What interrupted the run, in words ("" for a complete run)."""
    T_hidden: bool = False
    """The T readings are left out (None): Task 12's answer, hidden until the group has
    entered its own T (:func:`hidden`)."""
    in_use: bool = False
    """Tasks 11-15 use this run (:meth:`Session.response_run`; the model check too, unless it
    has a log imported there: :meth:`Session.check_run`)."""
    plotted: bool = True
    """The run its kind's plot (steps, fast) shows: the one in use if it is of that kind,
    else the newest of it."""
    fitted: bool = True
    """The T readings are worked out; False in the quick view drawn first (:func:`runs` with
    ``fits=False``: the runs' speeds only, T None), while the fits are still being made."""


def _median(values: Sequence[float | None]) -> float | None:
    vs = [v for v in values if v is not None]
    return float(np.median(vs)) if vs else None


def _t63(log: RunLog) -> float | None:
    """The manual's 63 % reading of the log's speed: the median over its rises, s."""
    try:
        return _median([s.T_63 for s in model_identify.rises(log)])
    except (InputError, ValueError):
        return None


RUN_VIEWS_KEPT = 24
"""How many run views :func:`runs` keeps (a few sessions' runs)."""

_marked_views: dict[tuple[object, ...], RunView] = {}
"""The run views as :func:`runs` hands them out (T hidden or not, in use, plotted)."""

_run_views: dict[tuple[object, ...], RunView] = {}
"""The run views built, by (session folder, run, samples, interrupted): a recorded run's log
does not change, and its three fits took about 0.4 s every time Task 10 was shown."""


def runs(session: Session, fits: bool = True) -> tuple[RunView, ...]:
    """Every run the group can choose for Tasks 11-15 (step runs of 25 ms and 5 ms, and
    imported logs), oldest first, with their T readings; the one in use marked (``in_use``,
    also when it is interrupted), and for each plot (25 ms, fast) the run it shows
    ``plotted``: the run in use if it is of that kind, else the newest of it (the plot
    showed a newer, interrupted run while another was in use). A worker's job; a run's
    view is built once. ``fits`` False: a run whose view is not built yet comes without its
    T readings (``fitted`` False), read from its log alone, for the plots to show at once
    (after a resume its three fits took about 4 s on a loaded machine: walk 7, D11)."""
    using = session.response_run()
    newest = {r.kind: r.name for r in session.runs if r.kind in ("steps", "fast")}
    if using is not None and using.kind in newest:
        newest[using.kind] = using.name
    conceal = "own.T" in hidden(session)
    out = []
    for v in _run_list(session, fits):
        in_use = using is not None and v.name == using.name
        plotted = newest.get(v.kind) == v.name
        if not v.fitted:  # a quick view, not kept
            out.append(replace(v, in_use=in_use, plotted=plotted, T_hidden=conceal))
            continue
        # each marked view made once too (the T readings are Task 12's answer: left out
        # while hidden), so a view shown again is the same object
        key = (str(session.folder), v.name, v.samples, v.interrupted, conceal, in_use, plotted)
        if key not in _marked_views:
            _marked_views[key] = (
                replace(v, T_63=None, T_63_lab=None, T_ls=None, T_ci=None, T_hidden=True)
                if conceal
                else v
            )
            _marked_views[key] = replace(_marked_views[key], in_use=in_use, plotted=plotted)
            while len(_marked_views) > 4 * RUN_VIEWS_KEPT:
                del _marked_views[next(iter(_marked_views))]
        out.append(_marked_views[key])
    return tuple(out)


def _run_list(session: Session, fits: bool = True) -> list[RunView]:
    """The view of every run Tasks 11-15 can use, oldest first (built once each; with
    ``fits`` False, a run not built yet comes without its T readings, not kept)."""
    out = []
    for r in session.runs:
        if r.kind not in RESPONSE_KINDS:
            continue
        key = (str(session.folder), r.name, r.samples, r.interrupted)
        kept = _run_views.get(key)
        if kept is not None:
            out.append(kept)
            continue
        try:
            log = session.load_run(r.name)
        except InputError:
            continue
        lab = np.asarray(log.extra.get("omega_lab", log.omega), dtype=float)
        if not fits:
            t, omega = np.asarray(log.t, dtype=float), np.asarray(log.omega, dtype=float)
            out.append(
                RunView(
                    r.name, r.kind, r.ts, r.samples, r.interrupted, t, omega, lab,
                    None, None, None, None, r.interruption, fitted=False,
                )
            )  # fmt: skip
            continue
        try:
            fit = model_identify.fit_time_constant(log)
        except (InputError, ValueError):
            fit = None
        out.append(
            RunView(
                r.name,
                r.kind,
                r.ts,
                r.samples,
                r.interrupted,
                np.asarray(log.t, dtype=float),
                np.asarray(log.omega, dtype=float),
                lab,
                _t63(log),
                _t63(replace(log, omega=lab)),
                fit.T if fit else None,
                fit.ci if fit and determined(fit.ci) and not fit.T_on_bound else None,
                r.interruption,
            )
        )
        _run_views[key] = out[-1]
        while len(_run_views) > RUN_VIEWS_KEPT:
            del _run_views[next(iter(_run_views))]
    return out


# -- Tasks 11-15: the results ---------------------------------------------------------------------
ZOOM_BEFORE_T: float = 1.0
"""The zoom to one rise starts this many time constants before the edge..."""

ZOOM_AFTER_T: float = 5.0
"""...and ends this many after it (99 % of the change)."""

ZOOM_MIN_SAMPLES: int = 3
"""At least this many samples before the edge, whatever T."""

CLOSE_BEFORE_SAMPLES: int = 2
"""The close-up to read T on (Task 12) starts this many samples before the edge..."""

CLOSE_AFTER_T: float = 3.0
"""...and ends this many time constants after it (95 % of the change), or
:data:`CLOSE_AFTER_SAMPLES` samples when they last longer: at 80 columns a column of the
0.375 s zoom was 7.2 ms of a 25 ms run, of the close-up 3.8 ms."""

CLOSE_AFTER_SAMPLES: int = 6


@dataclass(frozen=True)
class RiseZoom:
    """One rise of the log: the edge at ``t0`` (s), the high level until ``t1`` (s),
    the speed before (``omega0``) and settled (``omega_ss``, rad/s), its 63 % reading
    ``T_63`` (s or None); the zoom to its rise from ``z0`` to ``z1`` (s: a little before the
    edge to several T after it), the 63 % level ``level`` (rad/s) and ``t_63``, the board
    time (s) the speed crosses it (None if it does not); ``c0`` to ``c1`` (s): the close-up on
    its first few T to read T on (Task 12)."""

    t0: float
    t1: float
    T_63: float | None
    omega0: float = 0.0
    omega_ss: float = 0.0
    z0: float = 0.0
    z1: float = 0.0
    c0: float = 0.0
    c1: float = 0.0

    @property
    def level(self) -> float:
        """The 63 % level of this step, rad/s."""
        return self.omega0 + E63 * (self.omega_ss - self.omega0)

    @property
    def t_63(self) -> float | None:
        """When the speed crosses the 63 % level, s (board time)."""
        return None if self.T_63 is None else self.t0 + self.T_63


def rise_zoom(rise: model_identify.Rise, T: float | None, ts: float) -> RiseZoom:
    """The window of one rise, zoomed to its rise with time constant ``T`` (s; the
    step's own 63 % reading when None) at sample period ``ts`` (s)."""
    T_ref = T if T is not None and T > 0 else rise.T_63
    if T_ref is None or not T_ref > 0:
        T_ref = rise.duration / ZOOM_AFTER_T
    t1 = rise.t + rise.duration
    z0 = rise.t - max(ZOOM_BEFORE_T * T_ref, ZOOM_MIN_SAMPLES * ts)
    z1 = min(rise.t + max(ZOOM_AFTER_T * T_ref, 4 * ZOOM_MIN_SAMPLES * ts), t1)
    c0 = rise.t - max(CLOSE_BEFORE_SAMPLES * ts, 0.5 * T_ref)
    c1 = min(rise.t + max(CLOSE_AFTER_T * T_ref, CLOSE_AFTER_SAMPLES * ts), t1)
    return RiseZoom(rise.t, t1, rise.T_63, rise.omega0, rise.omega_ss, z0, z1, c0, c1)


@dataclass(frozen=True)
class CursorReading:
    """What a cursor on the zoomed rise reads: at ``t`` (s after the edge), the speed
    ``omega`` (rad/s) of the line the plot draws there, which joins the samples at
    ``t_before`` and ``t_after`` (s after the edge; the same sample when ``t`` is on one)
    straight. A reading of the log itself, as a scope's cursor gives it: never a fitted
    T, so it does not answer Task 12 for the group."""

    t: float
    omega: float
    t_before: float
    t_after: float

    def text(self) -> str:
        """One line for people: the time in ms, the speed, the samples around it."""

        def ms(t: float) -> str:  # to the ms at least: 1375 ms, not 1380 ms
            value = 1000.0 * t
            return format_value(value, "ms", max(3, len(str(int(abs(value))))))

        between = (
            f"the sample at {ms(self.t_before)}"
            if self.t_before == self.t_after
            else f"between the samples at {ms(self.t_before)} and {ms(self.t_after)}"
        )
        return (
            f"t = {ms(self.t)} after the edge: "
            f"omega = {format_value(self.omega, 'rad/s', 3)} ({between})"
        )


def cursor_reading(t: ArrayLike, omega: ArrayLike, at: float) -> CursorReading | None:
    """The cursor's reading at ``at`` (s) of the speed ``omega`` (rad/s) sampled at ``t`` (s,
    rising; both as the plot draws them): the straight line between the two samples around
    ``at``, or the sample ``at`` is on (within a thousandth of the sample time). None outside
    the samples (or without any)."""
    ts = np.asarray(t, dtype=float)
    ws = np.asarray(omega, dtype=float)
    ok = np.isfinite(ts) & np.isfinite(ws)
    ts, ws = ts[ok], ws[ok]
    if ts.size == 0 or not ts[0] <= at <= ts[-1]:
        return None
    # on a sample within a thousandth of the time grid's step: a time after the edge is a
    # difference of board times, a hair off the sample's (50.0 ms read "between the samples
    # at 25.0 ms and 50.0 ms")
    steps = np.diff(ts)
    steps = steps[steps > 0]
    near = 1e-3 * float(steps.min()) if steps.size else 0.0
    on = np.flatnonzero(np.abs(ts - at) <= near)
    if on.size:
        k = int(on[np.argmin(np.abs(ts[on] - at))])
        return CursorReading(at, float(ws[k]), float(ts[k]), float(ts[k]))
    k = int(np.searchsorted(ts, at, side="right"))  # ts[k - 1] <= at < ts[k]
    before = k - 1
    after = min(k, ts.size - 1)
    if before == after:
        return CursorReading(at, float(ws[before]), float(ts[before]), float(ts[before]))
    share = (at - ts[before]) / (ts[after] - ts[before])
    omega_at = float(ws[before] + share * (ws[after] - ws[before]))
    return CursorReading(at, omega_at, float(ts[before]), float(ts[after]))


U_APPLIED = axis_label("u_A", "V")
"""A run's voltage once it is the applied u_A (:attr:`ResultsView.u_label`)."""

U_REQUESTED = axis_label("u requested", "V")
"""A recorded run's voltage before any u_ss maps it to u_A: the voltage asked of the board."""


def _u_label(log: RunLog | None) -> str:
    """:attr:`ResultsView.u_label` of ``log``: whether its u column is u_A or still the
    requested voltage (its metadata says how u was worked out: ``applied_voltage``)."""
    if log is not None and log.metadata.get("u", "").startswith("u = u_req"):
        return U_REQUESTED
    return U_APPLIED


@dataclass(frozen=True)
class ResultsView:
    """Tasks 11-15: the log used (t s, omega rad/s, u V), its rises, result lines and
    the group's readings beside the computed ones (``compare``: label, yours, computed);
    ``problems``: what keeps a result from being computed, one line each."""

    run: str | None
    t: FloatArray
    omega: FloatArray
    u: FloatArray
    rises: tuple[RiseZoom, ...]
    lines: tuple[str, ...]
    compare: tuple[tuple[str, str, str], ...] = ()
    problems: tuple[str, ...] = ()
    hidden: frozenset[str] = frozenset()
    """Fields of Tasks 11-15 whose computed value the group has not seen yet: the plot
    leaves their readings out too (own.omega_step: the steady speed; own.T: the crossing)."""
    shows: frozenset[str] = frozenset()
    """Fields of Tasks 11-15 whose computed value this view puts on the screen (the session
    records the first time: :func:`note_drawn`)."""
    waiting: str = ""
    """Without a step result: which inputs it needs and where to enter them ('needs a step
    run (Task 10)'; '' otherwise)."""
    u_label: str = U_APPLIED
    """What ``u`` is, as the plot's legend and right axis name it: u_A once the table's u_ss
    maps the requested voltage to the applied one (an imported log's u is its own), else
    the voltage requested of the board (:data:`U_REQUESTED`)."""
    revealed: frozenset[str] = frozenset()
    """Fields of Tasks 11-15 a lab assistant revealed before the group answered them (Ctrl+R,
    recorded): the plot's caption says so beside the reading it shows (on Tasks 11-12 the
    reveal leaves the plot in view, and the comparisons that say it are below the screen
    until the group answers)."""


TWO_T: tuple[str, ...] = ("T_short", "T_63_differs")
"""The findings (codes) that set the 63 % reading beside the least-squares T: why the two
differ is said once (:func:`~minseg_tui.lab.state.compare.two_T`), so these keep only their
first sentence, the fact, and point to it (:func:`with_two_T`)."""


def with_two_T(notices: Sequence[Notice], where: str) -> list[str]:
    """The messages of ``notices`` in order, those of :data:`TWO_T` cut to their first
    sentence and joined into one, in the place of the first, which ends by pointing to
    ``where`` the one sentence on the two readings of T stands."""
    facts = [n.message.split(". ", 1)[0].rstrip(".") + "." for n in notices if n.source in TWO_T]
    out: list[str] = []
    for n in notices:
        if n.source not in TWO_T:
            out.append(n.message)
        elif facts:
            out.append(
                " ".join(facts) + " Why the 63 % reading and the least-squares T differ, and "
                f"which one the program's model uses: {where}."
            )
            facts = []
    return out


def results(session: Session, step_id: str) -> ResultsView:
    """Tasks 11-15 from the session for step ``step_id`` (a worker's job: 0.4-0.5 s on long
    runs)."""
    res = session.results()
    compare = comparisons(session, step_id) if any(f.compare for f in step(step_id).fields) else ()
    log = None
    if res.run is not None:
        try:
            log = session.load_run(res.run)
        except InputError:
            log = None
    ident = res.identification
    lines: list[str] = []
    rises: tuple[RiseZoom, ...] = ()
    shows: frozenset[str] = frozenset()
    st_run = res.response_result
    conceal = hidden(session)

    def shown(key: str, line: str, what: str, task: str) -> str:
        return _unless_concealed(conceal, step_id, key, line, what, task)

    if st_run is not None:
        st = st_run
        lines += [
            shown(
                "own.omega_step",
                f"omega_ss in the steps = {format_quantity(st.omega_ss, 'rad/s')}",
                "omega_ss in the steps",
                "Task 11",
            )
            + f"   u_ss = {lab_compare.format_u_ss(st, step_u_ss(session))} "
            f"({u_ss_words(st.u_ss_how)})",
            shown(
                "own.K",
                f"K = {format_quantity(st.K, 'rad/s/V')}"
                f"{_ci(st.K_ci, 'rad/s/V') if st.K_determined else f', 95 % interval {NOT_DETERMINED}'}",
                "K",
                "Task 11",
            ),
            shown(
                "own.T",
                f"T (63 %) = {format_quantity(st.T_63, shown_unit('s'))}   "
                f"T (least squares) = {format_quantity(st.T, shown_unit('s'))}"
                f"{_ci(st.T_ci, 's') if st.T_determined else f', 95 % interval {NOT_DETERMINED}'}",
                "T",
                "Task 12",
            ),
            # why the two T differ, said once on each screen (not in Task 12's comparison)
            *([lab_compare.two_T_of(st)] if "own.T" not in conceal else []),
            shown("own.J", f"J = {format_quantity(st.J, 'kg m^2')}", "J", "Task 13")
            if ident is not None
            else "J: "
            + (
                lab_needs.needs(waits_for(session, "J"))
                or "waits for R, k_v and f from the table of Tasks 2-9, which gives none yet"
            )
            + " (why: below)",
            shown(
                "own.model", f"model: {identify_says.model_equation(st)}", "the model", "Task 14"
            ),
            shown(
                "own.omega_5",
                f"omega at 5 V = {format_quantity(st.K * model_identify.U_TASK15, 'rad/s')}"
                + (
                    f" by the lab's model, {format_quantity(st.task15_with_friction, 'rad/s')} "
                    "with the dry friction the fit found"
                    if st.task15_with_friction is not None
                    else ""
                ),
                "omega at 5 V",
                "Task 15",
            ),
        ]
        ts = log.ts if log is not None else 0.0
        rises = tuple(rise_zoom(s, st.T, ts) for s in st.rises)
        # J's value is on the screen only once R and a full row let it be computed: before,
        # its line and Task 13's comparison say what it waits for (walk 13: J typed before R
        # was recorded as shown, and the report said so)
        shows = frozenset(
            k
            for k in lab_compare.ANSWERED_FIRST
            if k not in conceal and (k != "own.J" or ident is not None)
        )
    elif res.speed_only is not None:
        # no u_ss yet: omega_ss in the steps, T and the rises need only the speed; K (which
        # divides by u_ss) and what follows from it wait (walk 18, D4)
        sp = res.speed_only
        lines += [
            shown(
                "own.omega_step",
                f"omega_ss in the steps = {format_quantity(sp.omega_ss, 'rad/s')}",
                "omega_ss in the steps",
                "Task 11",
            ),
            shown(
                "own.T",
                f"T (63 %) = {format_quantity(sp.T_63, shown_unit('s'))}   "
                f"T (least squares) = {format_quantity(sp.T, shown_unit('s'))}"
                f"{_ci(sp.T_ci, 's') if sp.T_determined else f', 95 % interval {NOT_DETERMINED}'}",
                "T",
                "Task 12",
            ),
            *([lab_compare.two_T_of(sp)] if "own.T" not in conceal else []),
            speed_only_waits(session),
        ]
        rises = tuple(rise_zoom(s, sp.T, log.ts if log is not None else 0.0) for s in sp.rises)
        shows = frozenset({"own.omega_step", "own.T"} - conceal)
    # without a step result, the table's problems are not why (K and T need only the run and a
    # u_ss: ``waiting`` says what is missing); with one, J's line points to them
    problems = list(res.problems if st_run is not None else res.run_problems)
    rule = policy(session)
    if rule.problem:
        problems.append(rule.problem)
    used = next((r for r in session.runs if r.name == res.run), None)
    changed = session.run_changed(used.name) if used is not None else None
    if changed is not None:  # the one rule, as the report and the class view say it
        problems.append(changed.text)
    if used is not None and used.interrupted:
        problems.append(
            f"run {used.name} ended before its plan did ({used.interruption}; {used.samples} samples, "
            f"{len(rises)} rises): a whole run gives more rises to read T from"
        )
    return ResultsView(
        res.run,
        np.asarray(log.t, dtype=float) if log else _empty(),
        np.asarray(log.omega, dtype=float) if log else _empty(),
        np.asarray(log.u, dtype=float) if log else _empty(),
        rises,
        tuple(lines),
        compare,
        tuple(problems),
        frozenset(hidden(session)),
        shows,
        "" if st_run is not None else lab_needs.needs(waits_for(session, "K")),
        _u_label(log),
        frozenset(session.revealed()),
    )


# -- the model check ---------------------------------------------------------------------------
@dataclass(frozen=True)
class CheckView:
    """The model check of one run: measured, baseline and extended speeds (rad/s) at t (s),
    residual = measured - baseline; the close-up where the cause acts (``close_*``: the same
    speeds over its stretch, ``close_what`` in words, ``noise`` the speed's noise level
    there, rad/s); ``cause`` (the contract name) and ``cause_words`` (every cause named, in
    words); ``problem``: why there is no result. ``story``: the two or three sentences a
    student reads first (:func:`minseg_tui.lab.views.check_words.lead`), about the close-up,
    whose title with its time span is ``close_title``; ``details``: what follows in the fold,
    one part a string (a paragraph, or a list with its heading), each figure with what it
    measures and why it matters
    (:func:`~minseg_tui.lab.views.check_words.details`), among them ``two_fits`` (why the
    check's T is not the program's least-squares one of Tasks 11-12, whose reading that is;
    '' when they are not of one run)."""

    run: str | None
    t: FloatArray = field(default_factory=_empty)
    omega: FloatArray = field(default_factory=_empty)
    baseline: FloatArray = field(default_factory=_empty)
    extended: FloatArray = field(default_factory=_empty)
    residual: FloatArray = field(default_factory=_empty)
    cause: str = ""
    problem: str = ""
    close_t: FloatArray = field(default_factory=_empty)
    close_omega: FloatArray = field(default_factory=_empty)
    close_baseline: FloatArray = field(default_factory=_empty)
    close_extended: FloatArray = field(default_factory=_empty)
    close_what: str = ""
    noise: float | None = None
    cause_words: str = ""
    story: tuple[str, ...] = ()
    close_title: str = ""
    details: tuple[str, ...] = ()
    two_fits: str = ""
    other_T: str = ""
    """With ``two_fits``: the sentence on screen after ``story`` giving Tasks 11-12's
    least-squares T beside the check's own (:func:`~minseg_tui.lab.views.check_words.other_T`)."""
    shows: frozenset[str] = frozenset()
    """Fields of Tasks 11-15 whose computed value the check puts on the screen: T and K of the
    first-order model it fitted, and so the model (none without a result)."""
    elsewhere: str = ""
    """When Tasks 11-15 use another run than the check's (an import): which
    (:func:`check_elsewhere`); ''."""


def check(session: Session) -> CheckView:
    """The model check of its run (:meth:`Session.check_run`: Tasks 11-15's, or a log
    imported at the check) (a worker's job: up to 0.5 s)."""
    mc = session.model_check()
    r = mc.result
    elsewhere = check_elsewhere(session, mc.run)
    if r is None:
        return CheckView(mc.run, problem=mc.problem or "no result", elsewhere=elsewhere)
    f = r.finding
    omega = np.asarray(r.omega, dtype=float)
    baseline = np.asarray(r.baseline_pred, dtype=float)
    extended = np.asarray(r.extended_pred, dtype=float)
    t = np.asarray(r.t, dtype=float)
    cu = r.close_up
    window = slice(cu.start, cu.end) if cu is not None else slice(0, 0)
    u: FloatArray | None = None  # unread: the story says less about the close-up's step
    lag: float | None = None  # how late its speed column runs behind its angle column (s)
    if mc.run is not None:
        try:
            log = session.load_run(mc.run)
            u = np.asarray(log.u, dtype=np.float64)
            lag = check_says.late_speed(log)
        except (InputError, KeyError):
            u = None
    res = session.results()
    st = res.identification.step if res.identification is not None else None
    T = r.baseline.params.get("T")
    two_fits = (
        check_words.two_fits(
            T,
            st.T,
            st.K,
            rising=st.fit.method == "rising_steps",
            down=check_words.steps_down(u),
        )
        if st is not None and st.T and T is not None and res.run == mc.run
        else ""
    )
    return CheckView(
        mc.run,
        t,
        omega,
        baseline,
        extended,
        omega - baseline,
        f.cause,
        close_t=t[window],
        close_omega=omega[window],
        close_baseline=baseline[window],
        close_extended=extended[window],
        close_what=check_says.close_up_what(cu) if cu is not None else "",
        noise=cu.noise if cu is not None else r.gain.noise_floor,
        cause_words=in_words("+".join([f.cause, *(o.cause for o in f.others)]), plain=True),
        story=check_words.lead(r, u, lag),
        close_title=check_words.close_up_title(r),
        details=check_words.details(r, two_fits, lag=lag).blocks(),
        two_fits=two_fits,
        other_T=check_words.other_T(st.T) if two_fits and st is not None else "",
        # T and K of another run than Tasks 11-15's are none of their computed values
        shows=frozenset(lab_shown.MODEL_CHECK_SHOWS) if not elsewhere else frozenset(),
        elsewhere=elsewhere,
    )


def reveal_waits(session: Session, step_id: str) -> str:
    """Why a lab assistant's reveal showed nothing on step ``step_id``: '' when none of its
    values is hidden; else that they are not computed yet, and what the first waits for."""
    keys = lab_compare.reveal_keys(step(step_id).fields, session.answered())
    if not keys:
        return ""
    why = lab_needs.needs(waits_for(session, keys[0]))
    if not why:
        return "nothing to show yet: this step's values cannot be computed (the lines say why)"
    return (
        f"nothing to show yet: what this step computes {why}; press {REVEAL_KEY} again once "
        "it is there"
    )


def note_drawn(session: Session, view: object) -> list[str]:
    """A view was drawn on the group's screen: record in ``session`` (the live one, not a
    snapshot) the computed values of Tasks 11-15 it showed for the first time, and by what:
    Tasks 11-15 (:class:`ResultsView`), Task 10's runs with their T readings (a tuple of
    :class:`RunView`) or the model check (:class:`CheckView`). The fields newly recorded."""
    if isinstance(view, ResultsView):
        return session.note_shown(view.shows, "results")
    if isinstance(view, CheckView):
        return session.note_shown(view.shows, lab_shown.MODEL_CHECK)
    if isinstance(view, tuple) and any(isinstance(v, RunView) and v.T_ls is not None for v in view):
        return session.note_shown(("own.T",), "results")
    return []


# -- the run in use -----------------------------------------------------------------------------
USES_RUN = "Tasks 11-15 and the model check use run"
"""The start of every line that says which run they use when it is one run (:func:`run_in_use`,
and :func:`~minseg_tui.lab.views.own_first.run_used` with why)."""


def run_in_use(session: Session) -> str:
    """One line saying which run Tasks 11-15 and the model check use (each its own when
    the model check has an imported log, :meth:`Session.check_run`)."""
    run, checked = session.response_run(), session.check_run()
    if checked is not None and checked != run:
        return (
            f"Tasks 11-15 use run {run.name if run else '— (none yet)'}; "
            f"the model check uses run {checked.name}"
        )
    return f"{USES_RUN} {run.name if run else '— (none yet)'}"


def imported(session: Session, path: str, info: RunInfo) -> str:
    """The line after a log recorded elsewhere was imported as ``info`` (from ``path``, as
    typed): the model check uses it, Tasks 11-15 keep their run, and how to judge them on
    the import (walk 16, D3: the import took Tasks 11-15 with it)."""
    said = f"imported {path} as {info.name} ({info.samples} rows); the model check uses it"
    run = session.response_run()
    judge = f"{key_name('palette')} '{USE_RUN} {info.name}' judges them on it"
    if run is None:
        return f"{said}; Tasks 11-15 have no run of their own yet: {judge}"
    return f"{said}; Tasks 11-15 keep run {run.name} ({judge})"


def check_elsewhere(session: Session, run: str | None) -> str:
    """Said beside the model check of run ``run`` when Tasks 11-15 use another run (an
    import at the model check): "Tasks 11-15 use run steps-1"; '' when they use the same
    one, or none."""
    tasks = session.response_run()
    if run is None or tasks is None or tasks.name == run:
        return ""
    return f"Tasks 11-15 use run {tasks.name}"


# -- what is not answered yet -----------------------------------------------------------------
ASKED_PARTS: tuple[str, ...] = ("Preparation", "Set-up", "Steady state", "Model check", "Summary")
"""The parts whose required entries the lab asks for (their optional notes left out)."""


def _short(step_id: str, title: str) -> str:
    """A step's name as the list of steps writes it ('Task 12', 'Prep 7')."""
    head = title.split(":")[0]
    return head.replace("Preparation", "Prep") if step_id != "summary" else "Summary"


def unanswered(session: Session) -> tuple[tuple[str, str, str], ...]:
    """What the lab asks for that the group has not answered (an accepted entry), in the
    lab's order: (the step's short name, with the question's number on the summary, 'Summary
    Q4'; where it stands, 'Summary and reflections (section 3.2), question 4'; the field's
    label, 'The static gain K describes', or '' for a step with nothing to type). Asked:
    the required entries of the preparation, Tasks 2-5, the model check and the summary,
    the board checks of Tasks 1 and 3, a run for Task 10, and the group's own values of
    Tasks 11-15."""
    answered = session.answered()
    out: list[tuple[str, str, str]] = []
    for st in STEPS:
        short = _short(st.id, st.title)
        if "run_square_wave" in st.actions or (st.done_when and not st.fields):
            if session.step_status(st.id) != "done":  # no run recorded, a board check not passed
                out.append((short, f"{st.title}: not done yet", ""))
            continue
        for f in st.fields:
            asked = (st.part in ASKED_PARTS and not f.optional) or (
                st.part == "Results" and bool(f.compare)
            )
            if not asked or f.key in answered:
                continue
            if st.id == "summary":
                n = f.key.split(".")[-1]
                out.append((f"Summary Q{n}", f"{st.title}, question {n}", f.label))
            else:
                out.append((short, st.title, f.label))
    return tuple(out)


def unanswered_line(session: Session, most: int = 8) -> str:
    """One line for the F8 notice: what is still unanswered (:func:`unanswered_brief`);
    '' when everything is answered."""
    brief = unanswered_brief(session, most)
    return f"unanswered, marked in the report: {brief}" if brief else ""


def unanswered_brief(session: Session, most: int = 8) -> str:
    """What is still unanswered, the lab's tasks first, then the summary and the
    preparation, numbers joined ('Task 12, 15; Summary Q4, Q5; Prep 7'), at most ``most``
    numbers and how many more; '' when everything is answered."""
    names = list(dict.fromkeys(short for short, _, _ in unanswered(session)))
    if not names:
        return ""
    groups: dict[str, list[str]] = {"Task": [], "": [], "Summary Q": [], "Prep": []}
    for name in names:  # "" holds a step named without a number: the model check
        kind = next((k for k in groups if k and name.startswith(k)), "")
        groups[kind].append(name.removeprefix(kind).strip())
    said: list[str] = []
    left = most
    for kind, numbers in groups.items():
        if numbers and left > 0:
            head = "" if not kind else kind if kind.endswith("Q") else f"{kind} "
            said.append(head + ", ".join(numbers[:left]))
            left -= len(numbers[:left])
    more = f" and {len(names) - most} more" if len(names) > most else ""
    return "; ".join(said) + more
