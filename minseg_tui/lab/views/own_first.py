"""The group's own values first, as a grader reads them in the report.

For each value a group may work out (k_v, k_a and f of Tasks 7-9; omega_ss in the steps, K,
T, J, the model and omega at 5 V of Tasks 11-15) one :class:`OwnRow`: what the group
entered (or :data:`NOT_ANSWERED`), the value computed the group's way (J from their own T,
K from their omega_ss, ...), the difference, the program's value (least squares for Tasks
11-15) and whether, and when, the group was shown the computed value (:func:`shown`). Every
cell says something: none is left blank. Also :func:`run_used`, the run behind Tasks 11-15
and the model check, and what interrupted it. Plain data built from a
:class:`~minseg_tui.lab.state.session.Session`; units as the fields' form units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from datetime import datetime, timedelta

from minseg_tui.errors import InputError
from minseg_tui.lab.content import identify_says
from minseg_tui.lab.content.answers import check_answer
from minseg_tui.lab.content.expr import Formula
from minseg_tui.lab.content.keys import USE_RUN, key_name
from minseg_tui.lab.content.model_eq import read_model
from minseg_tui.lab.content.needs import needs
from minseg_tui.lab.content.steps import FIELDS, STEPS, RunPlan
from minseg_tui.lab.content.u_ss_says import u_ss_words
from minseg_tui.lab.state import compare as lab_compare
from minseg_tui.lab.state import shown as lab_shown
from minseg_tui.lab.state.entries import choice_words, parsed_values, read_entry
from minseg_tui.lab.state.results import Comparison, Results
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.state.shown import PolicyRecord
from minseg_tui.lab.views.session import (
    MARK,
    NOT_JUDGED,
    REVEAL_KEY,
    USES_RUN,
    answer,
    judged_again,
    step_u_ss,
    waits_for,
)
from minseg_tui.model.identify import U_TASK15
from minseg_tui.quantities import (
    NOT_DETERMINED,
    UNITS,
    format_difference,
    format_interval,
    format_quantity,
    format_reading,
    format_typed,
    shown_unit,
)

GROUPS = "the group's"
"""How the report's texts name the group's values (the screen says "your" to the group)."""

TOLD = "the program told the group:"
"""Before a message the group was shown (a refusal speaks to them): quoted as said."""

NOT_ANSWERED = "not answered"
"""The group's cell of a value the group has not entered."""

TABLE_STEP = "table"
"""The step of Tasks 6-9, whose values the program's table shows from the start."""

SHOWN_IN_TABLE = (
    "shown in the program's Task 4-9 table from the start (the table computes it; the "
    "group's own value is optional)"
)
SHOWN_AFTER = "after the group answered"
NOT_SHOWN = "not shown on the group's screen in this session"
REVEALED = f"{lab_compare.REVEALED_EARLY} (with {REVEAL_KEY}, the lab assistant's key)"
NOT_KNOWN = (
    "not known: the session was begun with an older program, which did not record when the "
    "computed values were shown"
)
_BY: dict[str, str] = {
    lab_shown.REVEAL: f"with {REVEAL_KEY}, the lab assistant's key",
    lab_shown.POLICY: f"at once, by the lab's policy ({lab_compare.POLICY_FILE}: answers_first = "
    "false)",
    lab_shown.MODEL_CHECK: "by the model check (it writes the fitted T and K)",
    lab_shown.AFTER_ANSWER: "on Tasks 11-15",
}
"""What put a computed value on the group's screen, in words."""

TASK: dict[str, str] = {
    "own.k_v": "k_v (Task 7)",
    "own.k_a": "k_a (Task 8)",
    "own.f": "f (Task 9)",
    "own.omega_step": "omega_ss in the steps (Task 11)",
    "own.K": "K (Task 11)",
    "own.T": "T (Task 12)",
    "own.J": "J (Task 13)",
    "own.model": "the model (Task 14)",
    "own.omega_5": "omega at u_A = 5 V (Task 15)",
}
"""Each value the group may work out, named with its task, in the lab's order."""

TABLE_HEADER: tuple[str, ...] = (
    "quantity",
    "the group's value",
    "computed from the group's table",
    "difference",
    "shown to the group",
)
"""The columns of Tasks 7-9's rows (the program's value is the one from the group's table)."""

STEP_HEADER: tuple[str, ...] = (
    "quantity",
    "the group's value",
    "computed or read the group's way",
    "difference",
    "the program's value (least squares)",
    "shown to the group",
)
"""The columns of Tasks 11-15's rows."""

_TABLE_HOW: dict[str, str] = {
    "own.k_v": "median of the rows, Task 6's formula",
    "own.k_a": "0.65 k_v",
    "own.f": "median of the rows",
}

_YOURS: dict[str, str] = {
    "own.K": "K@yours",
    "own.omega_5": "omega_5@yours",
    "own.J": "J@yours",
    "own.model": "model@yours",
}
"""The value worked out the group's way (:data:`~minseg_tui.lab.content.needs.NEEDS`) of
each field whose group's way may wait for another of the group's values."""


def _yours_waits(session: Session, key: str) -> str:
    """Why the group's way of field ``key`` has no value, from the one table of inputs:
    'needs the group's K (Task 11)'; 'not computed' when it names nothing."""
    name = _YOURS.get(key)
    return (needs(waits_for(session, name), GROUPS) if name else "") or "not computed"


_READ_OFF = "read off the run: nothing to compute"
"""The group's way of omega_ss in the steps (a reading, not a computation)."""


@dataclass(frozen=True)
class OwnRow:
    """One value, the group's first: ``cells`` in the order of :data:`TABLE_HEADER` or
    :data:`STEP_HEADER`; ``why``: one sentence on why the group's way and the program's value
    differ ('' when they do not, or there is no group's way)."""

    key: str
    cells: tuple[str, ...]
    why: str = ""


def when(iso: str) -> str:
    """An ISO time as a grader reads it: "2026-11-22 10:00:12 UTC" (as it stands when it
    cannot be read)."""
    try:
        t = datetime.fromisoformat(iso)
    except ValueError:
        return iso
    zone = " UTC" if t.utcoffset() == timedelta(0) else t.strftime(" %z") if t.tzinfo else ""
    return t.strftime("%Y-%m-%d %H:%M:%S") + zone


DAMAGED = "not known: the session file is damaged, and its record of this may be what was lost"


def _not_known(session: Session) -> str:
    """Why the report cannot say when a value was shown."""
    return DAMAGED if session.damaged else NOT_KNOWN


def _answered(session: Session, key: str) -> str:
    e = session.entry(key)
    if key not in session.answered() or e is None:
        return "not answered"
    return f"answered {when(e.at)}" if e.at else "answered"


def shown(session: Session, key: str) -> str:
    """When the group was first shown the computed value of field ``key``, in words a grader
    reads, and only as far as the session recorded it: from the start in the table (Tasks
    6-9); for Tasks 11-15 after the group answered (with its answer then, and a later change
    of it), revealed before answering (by a lab assistant, the lab's policy or the model
    check), not shown, or not known (a session of an older program)."""
    if key not in lab_compare.ANSWERED_FIRST:
        return SHOWN_IN_TABLE
    since = session.shown_since
    rec = session.shown().get(key)
    if since is None or (rec is None and key in session.revealed()):
        return REVEALED if key in session.revealed() else _not_known(session)
    if rec is None and session.damaged:  # its record may be what was left out
        return _not_known(session)
    late = (
        ""
        if since <= session.created
        else f" (recorded since {when(since)}; not known before: the session was begun with "
        "an older program)"
    )
    if rec is None:
        return f"{NOT_SHOWN} ({_answered(session, key)}){late}"
    by = _BY.get(rec.by, rec.by)
    if rec.answer is None:
        return (
            f"{lab_compare.REVEALED_EARLY}: shown {by}, {when(rec.at)}; {_answered(session, key)}"
        )
    if late:  # an unrecorded showing may have come before the answer
        return (
            f"not known whether before or after answering: first recorded {by}, "
            f"{when(rec.at)}, with the group's answer {rec.answer!r} in place{late}"
        )
    e = session.entry(key)
    now = e.text.strip() if e is not None and e.ok else ""
    changed = (
        f"; the answer was changed after that, to {now!r}, {when(e.at)}"
        if e is not None and now and now != rec.answer
        else ""
    )
    return f"{SHOWN_AFTER} ({rec.answer!r}): shown {by}, {when(rec.at)}{changed}"


def _rule(p: PolicyRecord) -> str:
    """A recorded policy in words."""
    if p.problem:
        return p.problem
    if not p.file:
        return f"answers first (no {lab_compare.POLICY_FILE}: the default)"
    if p.answers_first:
        return f"answers first ({lab_compare.POLICY_FILE}: answers_first = true)"
    return f"computed values at once ({lab_compare.POLICY_FILE}: answers_first = false)"


def policy_in_force(session: Session) -> tuple[str, tuple[str, ...]]:
    """The lab's policy while the group worked, as the session recorded it (one sentence),
    and the warnings a grader needs: the file now says otherwise, or nothing was recorded
    (a session of an older program), or the file could not be read."""
    got = session.policies()
    now = lab_compare.read_policy(session.folder.parent)
    current = _rule(PolicyRecord("", now.answers_first, now.problem, now.file))
    if not got:
        why = (
            "the session file is damaged, and its record of the policy may be what was lost"
            if session.damaged
            else "the session was begun with an older program, which did not record it"
        )
        return (
            f"The lab's policy while the group worked is not known: {why} "
            f"({lab_compare.POLICY_FILE} now says: {current}).",
            (
                f"the lab's policy is not recorded in this session; {lab_compare.POLICY_FILE} "
                "read now may not be what was in force while the group worked",
            ),
        )
    said = "; ".join(f"{_rule(p)}, from {when(p.at)}" for p in got)
    warnings = [p.problem for p in got if p.problem]
    last = got[-1]
    if not last.same_rule(PolicyRecord("", now.answers_first, now.problem, now.file)):
        warnings.append(
            f"{lab_compare.POLICY_FILE} now says: {current}; while the group worked it was: "
            f"{_rule(last)} (recorded {when(last.at)}). The report follows what was recorded."
        )
    return (
        f"The lab's policy while the group worked, as the session recorded it: {said}.",
        tuple(dict.fromkeys(warnings)),
    )


def _value(v: float | str | None, unit: str) -> str | None:
    if v is None or isinstance(v, str):
        return v
    return format_quantity(v, unit) if math.isfinite(v) else None


def _unit(session: Session, c: Comparison) -> str:
    """The unit ``c``'s values are shown in: one unit per quantity, the field's form unit,
    T and f in the one unit each is shown in (:func:`~minseg_tui.quantities.shown_unit`),
    whatever unit the group typed theirs in."""
    del session
    return shown_unit(c.unit)


def _own(session: Session, c: Comparison, unit: str) -> str:
    """What the group entered, with the digits and in the unit they typed it with;
    :data:`NOT_ANSWERED`, with a refused text named."""
    e = session.entry(c.key)
    if e is None or not e.text.strip():
        return NOT_ANSWERED
    if e.edited:
        return f"{NOT_ANSWERED} ({e.edited})"
    if not e.ok:
        return f"{NOT_ANSWERED} ({e.text.strip()!r} was refused; {TOLD} {e.message})"
    if isinstance(c.own, float):
        return answer(session, c.key) or format_reading(c.own, unit)
    if c.key == "own.model":
        return _own_model(e.text.strip())
    return e.text.strip()


def _own_model(text: str) -> str:
    """The group's model written T omega' = -omega + K u_A with their T (s) and K (rad/s/V),
    their digits, as every other value of theirs is normalised ('0,057 omega' = -omega + 1,93
    u_A' is "0.057 omega' = -omega + 1.93 u_A": walk 10, D7); written another way, the text
    they typed beside it; one that is no first-order model, as typed (its verdict says why)."""
    try:
        got = read_model(text)
    except InputError:
        return text
    said = lab_compare.model_text(format_typed(got.T), format_typed(got.K))
    if " ".join(text.replace(",", ".").split()) == said:
        return said
    return f"{said} (typed {text!r})"


MARKS_SAID = (
    f"Marks: {MARK['done']} right; {MARK['wrong']} wrong, farther from the value computed or "
    "read the group's way than reading or rounding explains; "
    f"{MARK['unjudged']} {NOT_JUDGED}."
)
"""What the marks in the difference column mean (said under the tables of the group's values;
the same marks as the list of steps and the entries on the group's screen)."""


def _diff(c: Comparison, own: str, against: str) -> str:
    if c.right is None and c.verdict:
        return f"{MARK['unjudged']} not judged: {c.verdict}"
    if c.right is not None or c.verdict:
        said = (MARK["done"] if c.right else MARK["wrong"]) + " " + (c.verdict or "right")
        if c.caveat:
            said += f"; {c.caveat}"
        return (
            said
            if c.rel_diff is None
            else f"{format_difference(c.own, c.computed)}{against}; {said}"
        )
    if c.rel_diff is not None:
        return format_difference(c.own, c.computed) + against
    if own.startswith(NOT_ANSWERED):
        return "nothing to compare: not answered"
    return f"{MARK['unjudged']} {NOT_JUDGED}"


def _judged_on(session: Session, c: Comparison) -> str:
    """The run the group's answer ``c`` is judged against, after its difference: "; judged
    against run steps-1", and when the group gave it while another run was in use, that it
    is judged again (:func:`~minseg_tui.lab.views.session.judged_again`); '' for a value not
    judged (not answered, nothing computed to compare it with)."""
    run = session.response_run()
    if run is None or c.right is None or c.key not in session.answered():
        return ""
    again = judged_again(session, c.key, "the group", back=False)
    return f"; {again}" if again else f"; judged against run {run.name}"


def _interval(ci: tuple[float, float], determined: bool, unit: str) -> str:
    """A 95 % interval ``ci`` (SI) in ``unit``, or why there is none."""
    if not determined:
        return f"95 % interval {NOT_DETERMINED}"
    scale = UNITS[unit].scale
    return f"95 % interval {format_interval(ci[0] / scale, ci[1] / scale, unit)}"


def table_rows(session: Session, results: Results | None = None) -> tuple[OwnRow, ...]:
    """Tasks 7-9: k_v, k_a and f, the group's value first (:data:`TABLE_HEADER`);
    ``results``: those to compare with (default: the session's own)."""
    out = []
    for c in session.comparisons(TABLE_STEP, results, GROUPS):
        unit = _unit(session, c)
        own = _own(session, c, unit)
        value = _value(c.computed, unit)
        computed = (
            f"{value} ({c.how or _TABLE_HOW.get(c.key, 'from the table')})"
            if value
            else "not computed: "
            + (needs(waits_for(session, c.key)) or "the table is not complete")
        )
        out.append(
            OwnRow(
                c.key,
                (TASK.get(c.key, c.label), own, computed, _diff(c, own, ""), shown(session, c.key)),
            )
        )
    return tuple(out)


def step_rows(session: Session, results: Results | None = None) -> tuple[OwnRow, ...]:
    """Tasks 11-15, the group's value first (:data:`STEP_HEADER`): the group's way beside
    the program's least-squares value, with why they differ; before u_ss is given, the rows
    of omega_ss and T alone (they need only the run); empty without a step result.
    ``results``: those to compare with (default: the session's own); with the numbers the
    session file keeps (the class view), the program's values are those, without intervals."""
    res = session.results() if results is None else results
    ident = res.identification
    st = ident.step if ident is not None else None
    kept = res.kept_response if st is None else None
    if st is None and kept is None:
        st = res.response  # the run alone (the table gives no k_v): J waits, the rest stands
    speed = res.speed_only if st is None and kept is None else None
    if st is None and kept is None and speed is None:
        return ()

    def program(key: str, unit: str) -> str:
        """The program's value of field ``key`` in ``unit``, and how it was had."""
        q = format_quantity
        if speed is not None:  # no u_ss yet: only omega_ss and T (walk 18, D4)
            if key == "own.omega_step":
                return f"{q(speed.omega_ss, unit)} (the median fitted steady speed of the rises)"
            return f"{q(speed.T, unit)} ({_interval(speed.T_ci, speed.T_determined, unit)})"
        if st is None:
            return _kept(key, unit)
        if key == "own.omega_step":
            return f"{q(st.omega_ss, unit)} (the median fitted steady speed of the rises)"
        if key == "own.K":
            return (
                f"{q(st.K, unit)} ({_interval(st.K_ci, st.K_determined, unit)}; "
                f"u_ss = {lab_compare.format_u_ss(st, step_u_ss(session))}, "
                f"{u_ss_words(st.u_ss_how)})"
            )
        if key == "own.T":
            return f"{q(st.T, unit)} ({_interval(st.T_ci, st.T_determined, unit)})"
        if key == "own.J":
            if not math.isfinite(st.J):
                why = needs(waits_for(session, "J"), GROUPS)
                return "not computed: " + (
                    why or "J needs R, k_v and f from the table of Tasks 2-9"
                )
            return f"{q(st.J, unit)} (from the least-squares T)"
        if key == "own.omega_5":
            w5 = (
                _value(ident.omega_at_5V if ident is not None else st.K * U_TASK15, unit)
                or "not computed"
            )
            other = st.task15_with_friction if ident is not None else None
            if other is None:
                return f"{w5} (5 V × the least-squares K)"
            return (
                f"{w5} (5 V × the least-squares K, the lab's model; "
                f"{_value(other, unit)} with the dry friction the fit found)"
            )
        return identify_says.model_equation(st)

    def _kept(key: str, unit: str) -> str:
        """:func:`program` from the numbers the session file keeps of the fit."""
        assert kept is not None
        how = "kept from the session's least-squares fit"
        figures = {"own.omega_step": kept.omega_ss, "own.K": kept.K, "own.T": kept.T}
        figures |= {"own.J": kept.J, "own.omega_5": kept.K * U_TASK15}
        if key in figures:
            return f"{_value(figures[key], unit) or 'not computed'} ({how})"
        model = res.lookup("model")
        return f"{model} ({how})" if isinstance(model, str) else f"not computed ({how})"

    out = []
    for step in STEPS:
        if step.part != "Results":
            continue
        for c in session.comparisons(step.id, res, GROUPS):
            if speed is not None and c.key not in lab_compare.SPEED_ONLY:
                continue
            unit = _unit(session, c)
            own = _own(session, c, unit)
            computed = _value(c.computed, unit)
            if c.key == "own.omega_step":
                mine, against = _READ_OFF, " (against the program's value)"
            elif c.how and computed:
                mine, against = f"{computed} ({c.how})", ""
            elif c.right is None and c.verdict:
                mine, against = f"not computed: {c.verdict}", ""
            else:
                mine, against = _yours_waits(session, c.key), " (against the program's value)"
            why = c.why if c.how and c.least_squares is not None else ""
            out.append(
                OwnRow(
                    c.key,
                    (
                        TASK.get(c.key, c.label),
                        own,
                        mine,
                        _diff(c, own, against) + _judged_on(session, c),
                        program(c.key, unit),
                        shown(session, c.key),
                    ),
                    why,
                )
            )
    return tuple(out)


def run_used(session: Session) -> str:
    """One sentence: the run Tasks 11-15 and the model check use, why that one (the group's
    choice, or the newest complete run), and what interrupted it when it ended early; and
    the model check's, when it used a log imported there (:meth:`Session.check_run`)."""
    run, checked = session.response_run(), session.check_run()
    own = (
        f"; the model check uses run {checked.name}, a log imported at the model check"
        if checked is not None and checked != run
        else ""
    )
    if run is None and own:
        return f"Tasks 11-15 have no run to use: no run recorded yet (Task 10){own}."
    if run is None:
        return "Tasks 11-15 and the model check have no run to use: no run recorded yet (Task 10)."
    ts, manual = format_quantity(run.ts, "ms", 2), format_quantity(RunPlan().ts, "ms", 2)
    if session.chosen_run() == run.name:
        why = "chosen by the group"
    elif ts == manual:
        why = f"the newest complete {ts} run (the group chose none)"
    else:
        why = (
            f"the newest complete run, at {ts} (the group chose none, and there is no "
            f"complete {manual} run)"
        )
    text = f"{'Tasks 11-15 use run' if own else USES_RUN} {run.name}, {why}"
    if run.interrupted:
        text += (
            f"; it ended before its plan did ({run.samples} samples), interrupted by: "
            f"{run.interruption}"
        )
    return text + own + "."


def run_changed(session: Session, before: str | None) -> str:
    """One sentence for the group when the run Tasks 11-15 use is no longer ``before`` (the
    run in use when Task 10 began a new one) while answers of Tasks 11-15 stand: they are
    judged against the new run now, and how to go back to the run in use when they were
    given (walk 9, D10: Tasks 12-14 turned from ✓ to ✗ and ! after F5, with no word of
    why); '' otherwise."""
    run = session.response_run()
    if before is None or run is None or run.name == before:
        return ""
    answered = [TASK[k] for k in lab_compare.ANSWERED_FIRST if k in session.answered()]
    if not answered:
        return ""
    return (
        f"Tasks 11-15 now use run {run.name}, not {before}: your answers ("
        + ", ".join(answered)
        + f") are judged against {run.name} now; {key_name('palette')} '{USE_RUN} {before}' goes "
        "back to the run in use when you gave them"
    )


def shown_gap(session: Session) -> str:
    """Why the lists of what the group was shown (:func:`revealed_early`,
    :func:`changed_after_shown`) may leave something out: the session was begun with an older
    program (recorded since a later time, or not at all), or its file is damaged; '' when
    the session recorded it from its start."""
    since = session.shown_since
    if since is None:
        return _not_known(session)
    if since > session.created:
        return (
            f"recorded since {when(since)} only: the session was begun with an older program, "
            "which did not record it"
        )
    return DAMAGED if session.damaged else ""


def revealed_early(session: Session) -> list[str]:
    """The values of Tasks 11-15 the group's screen showed before the group answered (a lab
    assistant's reveal, the lab's policy, the model check), each as :func:`shown` says it:
    "T (Task 12): revealed before answering: shown with Ctrl+R, …; answered …"."""
    recs = session.shown()
    out = []
    for key in lab_compare.ANSWERED_FIRST:
        rec = recs.get(key)
        if key in session.revealed() or (rec is not None and rec.answer is None):
            out.append(f"{TASK[key]}: {shown(session, key)}")
    return out


def changed_after_shown(session: Session) -> list[str]:
    """The group's values of Tasks 11-15 changed after the program showed its value for them:
    the answer in place when it was shown, when, and the answer now ("K (Task 11): '1.72'
    when the computed values were shown on Tasks 11-15, 2026-11-28 21:02:21 UTC; changed
    to '1,91', 2026-11-28 21:02:23 UTC"). A value changed before anything was shown is the
    group's own second thought and not listed."""
    recs = session.shown()
    out = []
    for key in lab_compare.ANSWERED_FIRST:
        rec, e = recs.get(key), session.entry(key)
        if rec is None or rec.answer is None or e is None or not e.ok:
            continue
        now = e.text.strip()
        if now and now != rec.answer:
            by = _BY.get(rec.by, rec.by)
            out.append(
                f"{TASK[key]}: {rec.answer!r} when the computed values were shown {by}, "
                f"{when(rec.at)}; changed to {now!r}, {when(e.at)}"
            )
    return out


def wrong_before(session: Session) -> list[str]:
    """Checked answers (the preparations, the summary's questions) whose earlier text, in the
    entry's history, the program judges wrong, with the answer now: "Preparation 4, y(T) /
    (K c): '0,37' (0.368 is the part still missing …), 2026-11-28 20:58:54 UTC; now
    '0,632'". Judged as the program judges it now, against the group's other entries now;
    refused texts (a unit slip) are no answers and not listed; nor are the steps of a list
    ticked one answer at a time (each tick is stored), whose first ticks are no answer."""
    values = session.parsed()
    out = []
    for st in STEPS:
        for chk in st.checks:
            fld, e = FIELDS[chk.key], session.entry(chk.key)
            if e is None or not e.ok or fld.multiple:
                continue
            for text, at in e.history:
                read = read_entry(fld, text)
                if not read.ok or text.strip() == e.text.strip():
                    continue
                answer = parsed_values({chk.key: read}).get(chk.key)
                if isinstance(answer, Formula) and not fld.names:
                    answer = answer.value({})
                fb = check_answer(chk, answer, values)
                if fb.status != "wrong":
                    continue
                said = (
                    choice_words(fld, read.value)
                    if isinstance(read.value, tuple)
                    else repr(text.strip())
                )
                now = (
                    choice_words(fld, e.value)
                    if isinstance(e.value, tuple)
                    else repr(e.text.strip())
                )
                where = f"{st.title.split(':')[0]}, {fld.label}"
                out.append(f"{where}: {said} ({fb.for_grader}), {when(at)}; now {now}")
                break
    return out


__all__ = [
    "GROUPS",
    "NOT_ANSWERED",
    "STEP_HEADER",
    "TABLE_HEADER",
    "TASK",
    "TOLD",
    "OwnRow",
    "changed_after_shown",
    "shown_gap",
    "policy_in_force",
    "revealed_early",
    "run_changed",
    "run_used",
    "shown",
    "step_rows",
    "table_rows",
    "when",
    "wrong_before",
]
