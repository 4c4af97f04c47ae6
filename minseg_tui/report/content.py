"""What a session's report says, as data: sections of paragraphs, tables and figures.

:func:`build` reads a :class:`~minseg_tui.lab.state.session.Session` (its entries, the results it
computes, its recorded runs) and returns a :class:`Report`; :mod:`.markdown` and
:mod:`.html` only render it. The report is the one place where derived numbers are
written down.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from datetime import datetime, timedelta

import numpy as np
from numpy.typing import ArrayLike

from minseg_tui.errors import InputError
from minseg_tui.lab.content import identify_says
from minseg_tui.lab.content import steps as lab_steps
from minseg_tui.lab.content.keys import in_palette, key_name
from minseg_tui.lab.content.needs import needs
from minseg_tui.lab.saving.runs import RunInfo
from minseg_tui.lab.state.entries import Entry
from minseg_tui.lab.state.results import Notice
from minseg_tui.lab.state.session import Session, TableRow
from minseg_tui.lab.views import check_says, check_text, check_words, own_first
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.check_says import in_words
from minseg_tui.lab.views.session import rise_zoom
from minseg_tui.model.check import CheckResult
from minseg_tui.model.identify import ResponseResult, Rise
from minseg_tui.model.runlog import RunLog
from minseg_tui.quantities import (
    MISSING,
    axis_label,
    format_number,
    format_quantity,
    format_reading,
    format_spread,
)
from minseg_tui.report.svg import Band, Line, Mark, plot, stack

TIME = axis_label("t", "s")
"""The time axis of the report's figures: seconds into the run."""

SPEED = axis_label("omega", "rad/s")
"""The speed axis of the report's figures of a run."""

RESIDUAL = axis_label("measured - model", "rad/s")
"""The axis of a figure of the model check's residual: the speed measured less the model's."""


@dataclass(frozen=True)
class Table:
    """A table: column headers and rows of cell texts."""

    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]


@dataclass(frozen=True)
class Figure:
    """A figure: one SVG text (its panels stacked, axis labels with units, the legend off
    the data), its natural ``width`` in px, and a caption."""

    svg: str
    width: int
    caption: str


@dataclass(frozen=True)
class Figures:
    """Figures side by side where the page is wide enough (one below the other where not)."""

    figures: tuple[Figure, ...]


@dataclass
class Fold:
    """Blocks a reader opens when they want them (HTML: a <details> fold; Markdown: a
    subsection), under ``title``; ``blocks`` as in :class:`Section` (no Fold in a Fold)."""

    title: str
    blocks: list[object] = field(default_factory=list)


@dataclass
class Section:
    """A titled part of the report; ``blocks`` in order: str (a paragraph), Table, Figure,
    Figures, a list of str (bullet points), or a Fold of such blocks."""

    title: str
    blocks: list[object] = field(default_factory=list)


@dataclass
class Report:
    """The whole report: title, a line of who/when, and sections; ``landscape``: printed
    on landscape pages (a table too wide for a portrait one)."""

    title: str
    byline: str
    sections: list[Section]
    landscape: bool = False


def _reading(value: float | None, unit: str, missing: str = MISSING) -> str:
    """What the group typed, captured or read off the meter, with the digits it has
    (``missing`` when there is none)."""
    return missing if value is None or not math.isfinite(value) else format_reading(value, unit)


NOT_ENTERED = "not entered"
"""A reading of the table the group has not entered."""

EDITED_CELL = "not what its text reads as in session.json: counts for nothing (see the warnings)"
"""A reading whose entry session.json holds edited by hand (the warnings say what it holds)."""


def _not_there(session: Session, key: str) -> str:
    """What stands for the reading of ``key`` when it has none in effect: :data:`EDITED_CELL`
    for an entry edited by hand, else :data:`NOT_ENTERED`."""
    e = session.entry(key)
    return EDITED_CELL if e is not None and e.edited else NOT_ENTERED


NOT_COMPUTED = "not computed"
"""k_v or f of a row not computed though nothing is missing (the warnings say why); with a
reading missing, what it needs follows (:func:`_row_value`)."""


def _row_value(session: Session, name: str, r: TableRow, value: float | None, unit: str) -> str:
    """A row's computed ``name`` (k_v, f) in ``unit``, or why there is none: 'not computed:
    needs R (Task 2)' (:func:`~minseg_tui.lab.views.session.waits_for`)."""
    if value is not None:
        return format_quantity(value, unit)
    why = needs(views.waits_for(session, f"{name}@row", r))
    return f"{NOT_COMPUTED}: {why}" if why else NOT_COMPUTED


def _verdicts(session: Session) -> dict[str, lab_steps.Feedback]:
    return {fb.key: fb for fb in session.feedback("*")}


def _answers(session: Session, part: str) -> Section:
    verdicts = _verdicts(session)
    rows = []
    for st in lab_steps.STEPS:
        if st.part != part:
            continue
        for fld in st.fields:
            e = session.entry(fld.key)
            if fld.kind == "choice":
                shown = (
                    "; ".join(fld.options[k] for k in e.value)
                    if e and e.ok and isinstance(e.value, tuple)
                    else (e.text if e else "")
                )
            else:  # a number as the tables give it: the digits typed, "3,79" as "3.79";
                # a formula as typed with its value: "1-exp(-1) = 0.6321"
                shown = (views.answer(session, fld.key) or e.text) if e else ""
            fb = verdicts.get(fld.key)
            verdict = (
                "not checked"
                if fb is None
                else {"right": "✓ ", "wrong": "✗ ", "missing": ""}[fb.status] + fb.for_grader
            )
            if e is not None and not e.ok:
                verdict = e.edited or f"refused; {own_first.TOLD} {e.message}"
            rows.append((st.title, fld.label, shown.strip() or own_first.NOT_ANSWERED, verdict))
    title = "Preparation" if part == "Preparation" else "Summary and reflections"
    return Section(title, [Table(("step", "question", "answer", "feedback"), tuple(rows))])


def _board_section(session: Session) -> Section:
    """Tasks 1 and 3: the board checks made (F10, the hand turn, the live speed watched)."""
    got = session.board_checks()
    sec = Section("Set-up: the board checks")
    if not got:
        sec.blocks.append(
            f"No board check was made ({key_name('board_check')} checks that the count follows "
            f"the motor; {in_palette('count_revolution')} checks the encoder's counts per "
            "revolution)."
        )
        return sec
    rows = tuple(
        (
            what,
            ("✓ passed" if got[key]["ok"] else "✗ failed")
            + (f" ({got[key]['counts']} counts)" if "counts" in got[key] else ""),
            str(got[key]["text"]),
            str(got[key]["at"]),
        )
        for key, what in lab_steps.BOARD_CHECKS.items()
        if key in got
    )
    sec.blocks.append(Table(("check", "result", "what it found", "when"), rows))
    return sec


CAPTURE_CLOCK = (
    "Capture window: the seconds of the live speed that omega_ss is the mean of, on the "
    "board's clock, which starts near 0 s when the program connects to the board (the board "
    "restarts then, so a session resumed later starts again near 0 s); the time of day beside "
    "it is when the group captured it."
)
"""What the table's capture windows count from (said under the table)."""


def _window(window: tuple[float, float], entry: Entry | None) -> str:
    """A capture's window on the board's clock (s) and, when the entry holding it says, the
    time of day it was captured: "222–224 s, captured 10:03:12 UTC"."""
    said = f"{format_number(window[0], 3)}–{format_number(window[1], 3)} s"
    try:
        at = datetime.fromisoformat(entry.at) if entry is not None and entry.at else None
    except ValueError:
        at = None
    if at is None:
        return said
    zone = " UTC" if at.utcoffset() == timedelta(0) else at.strftime(" %z") if at.tzinfo else ""
    return f"{said}, captured {at.strftime('%H:%M:%S')}{zone}"


def _table_section(session: Session) -> Section:
    res = session.results()
    rows = []
    for r in session.table():
        omega = (  # typed: its digits; captured: the mean, as the capture gave it
            session.reading(f"omega_ss@{r.level:g}") or _not_there(session, f"omega_ss@{r.level:g}")
            if r.spread is None
            else _reading(r.omega_ss, "rad/s", NOT_ENTERED)
        )
        if r.spread is not None and r.omega_ss is not None:
            omega += f" {format_spread(r.spread)}"
        window = (
            _window(r.window, session.entry(f"omega_ss@{r.level:g}"))
            if r.window
            else "typed"
            if r.omega_ss is not None
            else "no capture"
        )
        rows.append(
            (
                f"{r.level:g} V",
                session.reading(f"u_ss@{r.level:g}") or _not_there(session, f"u_ss@{r.level:g}"),
                omega,
                window,
                session.reading(f"i_ss@{r.level:g}") or _not_there(session, f"i_ss@{r.level:g}"),
                _row_value(session, "k_v", r, r.k_v, "V s/rad"),
                _row_value(session, "f", r, r.f, _F_UNIT),
            )
        )
    sec = Section("Steady state (Tasks 2 and 4-9)")
    R = session.reading("R")
    sec.blocks.append(f"R = {R} (Task 2)." if R else f"R (Task 2): {_not_there(session, 'R')}.")
    sec.blocks.append(
        "The group's readings (Tasks 4-5) and, in the last two columns, k_v and f that the "
        "program computed from them for each row (Tasks 6 and 9):"
    )
    sec.blocks.append(
        Table(
            (
                "requested u",
                "u_ss",
                "omega_ss (± spread)",
                "capture window (board clock)",
                "i_ss",
                "k_v, computed (Task 6)",
                "f, computed (Task 9)",
            ),
            tuple(rows),
        )
    )
    if any(r.window for r in session.table()):
        sec.blocks.append(CAPTURE_CLOCK)
    misread = [
        f"✗ {lab_steps.FIELDS[fb.key].label}: {fb.for_grader}"
        for st in ("task2", "task4", "task5")
        for fb in session.feedback(st)
        if fb.status == "wrong" and fb.key in lab_steps.FIELDS
    ]
    if misread:  # the virtual MinSeg's meter was read by the program too: a slip is known
        sec.blocks.append(
            "Readings that are not what the virtual multimeter showed while the group was on "
            "their step: " + "; ".join(misread) + "."
        )
    if res.identification is not None:
        sec.blocks.append("The motor constants, the group's own value first:")
        sec.blocks.append(
            Table(own_first.TABLE_HEADER, tuple(r.cells for r in own_first.table_rows(session)))
        )
        sec.blocks.append(own_first.MARKS_SAID)
    else:
        why = needs(views.waits_for(session, "f"))
        if why:
            sec.blocks.append(f"The motor constants k_v, k_a and f: {NOT_COMPUTED}, {why}.")
    return sec


_F_UNIT = lab_steps.FIELDS["own.f"].unit
"""f in the unit the group types it in (Task 9's entry)."""


_STEP_TITLE = "Step response and model (Tasks 10-15)"


def _step_section(session: Session) -> Section:
    res = session.results()
    sec = Section(_STEP_TITLE)
    sec.blocks.append(own_first.run_used(session))
    ident = res.identification
    # the run alone (the table gives no k_v: walk 7, D14) gives omega_ss, K and T as the
    # screen shows them; only J waits for the table
    s = ident.step if ident is not None and ident.step is not None else res.response
    if s is None:
        # what the run's results wait for (a run, a u_ss), and why a run gave none; not the
        # table's R and rows, which only J needs (walk 10, D4)
        if res.speed_only is None:
            why = needs(views.waits_for(session, "K"))
            said = [*res.run_problems, why] if why else list(res.run_problems)
            sec.blocks.append("No step result yet" + (": " + "; ".join(said) if said else "") + ".")
            return sec
        # omega_ss and T need only the run, as the screen shows them (walk 18, D4)
        s = res.speed_only
        sec.blocks.append(views.speed_only_waits(session) + ".")
    rows = own_first.step_rows(session)
    sec.blocks.append(
        "Each value the group worked out, first as the group gave it, then the group's way "
        "(J from their own T, K from their omega_ss and u_ss, ...; T as the program reads it "
        "by the group's method, at 63 % of each rise of the same run), then the program's "
        "least-squares value:"
    )
    sec.blocks.append(Table(own_first.STEP_HEADER, tuple(r.cells for r in rows)))
    sec.blocks.append(own_first.MARKS_SAID)
    sec.blocks.append(own_first.policy_in_force(session)[0])
    # T's why is the one sentence on the two readings of T (the model's own note, which
    # the CLI gives, would say it a second time)
    sec.blocks.extend(f"{own_first.TASK[r.key]}: {r.why}" for r in rows if r.why)
    if s is res.response:
        why = needs(views.waits_for(session, "J"), own_first.GROUPS)
        sec.blocks.append(
            (
                f"J {why}"
                if why
                else "J waits for R, k_v and f from the table of Tasks 2-9, which gives none "
                "yet (" + "; ".join(res.problems) + ")"
            )
            + "; omega_ss in the steps, K and T need only the run and u_ss."
        )
    sec.blocks.append(f"How T was fitted: {identify_says.fit_why(s.fit.why)}.")
    zoom = _zoom_figure(session, res.run, s)
    if zoom is not None:
        sec.blocks.append(zoom)
    return sec


def _read_step(steps: tuple[Rise, ...], T_63: float | None) -> Rise:
    """The step whose 63 % reading is nearest the median reading (the first without one)."""
    read = [x for x in steps if x.T_63 is not None]
    if not read or T_63 is None:
        return steps[0]
    return min(read, key=lambda x: abs((x.T_63 or 0.0) - T_63))


def _zoom_figure(session: Session, run: str | None, s: ResponseResult) -> Figure | None:
    """Tasks 11-12 on one rise: the samples from a little before the edge to several T
    after it, the speed before and the settled speed, the 63 % level and the time the
    samples (joined by straight lines, as the manual reads them) cross it."""
    if run is None or not s.rises:
        return None
    try:
        log = session.load_run(run)
    except (InputError, KeyError):
        return None
    st = _read_step(s.rises, s.T_63)
    t = np.asarray(log.t, dtype=float)
    w = np.asarray(log.omega, dtype=float)
    zoom = rise_zoom(st, s.T, log.ts)  # the same window as the TUI's zoom
    sel = (t >= zoom.z0 - 1e-9) & (t <= zoom.z1 + 1e-9)
    level = zoom.level
    marks = [
        Mark(f"the step, t = {format_number(st.t)} s", x=st.t, color="#555555", dash=False),
        Mark(f"omega before = {format_number(st.omega0)} rad/s", y=st.omega0, color="#999999"),
        Mark(f"omega_ss = {format_number(st.omega_ss)} rad/s", y=st.omega_ss, color="#999999"),
        Mark(f"63 % level = {format_number(level)} rad/s", y=level, color="#ff7f0e"),
    ]
    if st.T_63 is not None:
        marks.append(
            Mark(
                f"crossing at t = {format_number(st.t + st.T_63)} s: T_63 = {format_number(st.T_63 * 1e3)} ms",
                x=st.t + st.T_63,
                color="#d62728",
                dot=level,
            )
        )
    svg = plot(
        [Line("omega, measured samples", t[sel], w[sel], dots=True)],
        marks=marks,
        title=f"run {run}: the rise at t = {format_number(st.t)} s, read by the program as in Tasks 11-12",
        xlabel=TIME,
        ylabel=SPEED,
        width=640,
        height=300,
    )
    crossed = (
        f"it crosses the 63 % level {format_number(st.T_63 * 1e3)} ms after the step (T_63 of this "
        f"step; the median over {len(s.rises)} steps is {format_number((s.T_63 or 0.0) * 1e3)} ms)"
        if st.T_63 is not None
        else "it does not reach the 63 % level within the step"
    )
    return Figure(
        svg,
        640,
        f"The program's reading of one rise of run {run} (Tasks 11-12, as the manual "
        "reads it; the group's own values are in the table above): the measured speed goes from "
        f"{format_number(st.omega0)} to {format_number(st.omega_ss)} rad/s; {crossed}. The least-squares T is "
        f"{format_number(s.T * 1e3)} ms.",
    )


def _where(key: str) -> str | None:
    """Where an entry stands, in the lab's words ("Task 4, omega_ss at 2.5 V"); None for a
    key that is no entry (a finding's code: its sentence says what it is about)."""
    for st in lab_steps.STEPS:
        for fld in st.fields:
            if fld.key == key:
                return f"{st.title.split(':')[0]}, {_label(fld.label)}"
    return None


def _label(label: str) -> str:
    """A field's label as an instructor reads it: "your K" (the group's screen) is "the
    group's K"."""
    return own_first.GROUPS + label[4:] if label.startswith("your ") else label


GRADER_TITLE = "For the grader"
"""The report's first section: what a grader of many reports reads first."""


def _steps_line(session: Session) -> str:
    """The steps as the group's list of steps marks them, in one line: "31 of 33 steps done
    (✓); ✗ answered but wrong: Task 13; not begun: Summary and reflections (section 3.2)"."""
    by: dict[str, list[str]] = {}
    for st in lab_steps.STEPS:
        status = session.step_status(st.id)
        if status != "info":
            by.setdefault(status, []).append(st.title.split(":")[0])
    n = sum(len(v) for v in by.values())
    said = [f"{len(by.get('done', []))} of {n} steps done ({views.MARK['done']})"]
    said += [
        f"{mark} {words}: {', '.join(by[status])}"
        for status, mark, words in views.STATUS_MARKS
        if status != "done" and by.get(status)
    ]
    if by.get("todo"):
        said.append(f"not begun: {', '.join(by['todo'])}")
    return "; ".join(said)


def _grader_section(session: Session) -> Section:
    """What decides a grade, first: the steps' marks, the values shown to the group before it
    answered, the answers changed after the program showed its value, and the checked
    answers first given wrong (each in full further down)."""
    early = own_first.revealed_early(session)
    changed = own_first.changed_after_shown(session)
    first = own_first.wrong_before(session)
    gap = own_first.shown_gap(session)  # a session of an older program: "none" not known

    def listed(said: list[str]) -> str:
        if not gap:
            return "; ".join(said) if said else "none"
        return "; ".join([*said, gap]) if said else gap

    items = [
        f"Steps: {_steps_line(session)}.",
        f"Computed values shown before the group answered (Tasks 11-15): {listed(early)}.",
        f"Answers changed after the program showed its values (Tasks 11-15): {listed(changed)}.",
        "Checked answers first given wrong, then changed (the preparations and the summary; "
        "the program's verdict on the first, as it judges it now): "
        + ("; ".join(first) if first else "none")
        + ".",
    ]
    return Section(GRADER_TITLE, [items])


def _warnings_section(session: Session) -> Section:
    res = session.results()
    # the findings on the two readings of T give the facts; why the two differ is said once,
    # under the table of Tasks 11-15 (own_first.step_rows: T's why)
    items = views.with_two_T(
        [
            Notice(n.source, f"{where}: {n.message}" if (where := _where(n.source)) else n.message)
            for n in session.warnings()
        ],
        f"see {_STEP_TITLE}, the line T (Task 12) under its table",
    )
    items += [
        f"{_where(e.key) or e.key}: {e.edited}"
        if e.edited
        else f"refused entry {_where(e.key) or e.key}: {e.text!r} ({own_first.TOLD} {e.message})"
        for e in session.entries.values()
        if not e.ok
    ]
    items += [f"{_where(e.key) or e.key}: {e.older}" for e in session.entries.values() if e.older]
    items += [
        f"refused entry {_where(e.key) or e.key}: {e.refused[0]!r} ({own_first.TOLD} {e.refused[1]}; "
        f"the answer in effect stays {e.text!r})"
        for e in session.entries.values()
        if e.refused
    ]
    items += list(res.problems)
    missing = views.unanswered(session)
    if missing:  # marked where each stands too ("not answered"); said first here, together
        items.insert(
            0,
            "not answered when this report was written: "
            + "; ".join(
                f"{where}: {_label(label)}" if label else where for _, where, label in missing
            ),
        )
    # the grader reads which policy the "shown to the group" cells rest on
    items += own_first.policy_in_force(session)[1]
    return Section("Warnings", [items if items else "None."])


def _run_figure(log: RunLog, name: str) -> Figure:
    t = np.asarray(log.t, float)
    lines = [Line("omega, mean over each sample interval", t, log.omega)]
    if "omega_lab" in log.extra:
        lines.append(
            Line("omega, the manual's Euler + 20-tap average", t, log.extra["omega_lab"], dash=True)
        )
    top = plot(lines, ylabel=SPEED, title=f"run {name}", show_xlabel=False, height=220)
    ul = [Line("u_A, applied", t, log.u, steps=True)]
    if "u_req" in log.extra:
        ul.append(Line("u_req, requested", t, log.extra["u_req"], dash=True, steps=True))
    bottom = plot(ul, xlabel=TIME, ylabel=axis_label("u", "V"), height=160)
    return Figure(stack((top, bottom)), 720, f"Run {name}: speed and voltage against time.")


def _gain_rows(r: CheckResult) -> tuple[tuple[str, ...], ...]:
    g = r.gain
    named = r.finding.cause != "none"
    lead = check_text.stem(r.lead.figure) if r.lead else ""
    rows = []
    for key in sorted(check_text.FIGURES, key=lambda k: k != lead):
        c = check_text.compared(g, key, named)
        if c is None:
            continue
        unit = c.words.unit
        rows.append(
            (
                c.words.name + (" (leads)" if key == lead else ""),
                f"{c.first} {unit}",
                f"{c.extended} {unit}" if c.extended is not None else MISSING,
            )
        )
    return tuple(rows)


def _model_check_figures(name: str, r: CheckResult, log: RunLog | None) -> Figures:
    """The whole run against both models with the residuals, and beside it the close-up
    where the cause acts with the noise floor marked."""
    t = np.asarray(r.t, float)
    model = f"extended ({in_words(r.extended.model)})" if r.finding.cause != "none" else ""
    lines = [
        Line("measured", t, r.omega),
        Line("first-order model", t, r.baseline_pred, color="#d62728", dash=True),
    ]
    if model:
        lines.append(Line(model, t, r.extended_pred, color="#2ca02c", dash=True))
    top = plot(
        lines,
        title=f"run {name}: measured against the models",
        ylabel=SPEED,
        show_xlabel=False,
        width=640,
    )
    res = [Line("measured - first order", t, r.omega - r.baseline_pred, color="#d62728")]
    if model:
        res.append(Line("measured - extended", t, r.omega - r.extended_pred, color="#2ca02c"))
    bottom = plot(res, xlabel=TIME, ylabel=RESIDUAL, height=170, width=640)
    whole = Figure(
        stack((top, bottom)),
        640,
        f"Run {name}: the measured speed, the first-order model"
        + (f" and the {model} model" if model else "")
        + " simulated on the recorded voltage, and what each leaves (measured - model).",
    )
    cu = r.close_up
    if cu is None:
        return Figures((whole,))
    a, b = cu.start, cu.end  # row0, row1 of the JSON
    tt, w = t[a:b], np.asarray(r.omega, float)[a:b]
    base, ext = np.asarray(r.baseline_pred, float)[a:b], np.asarray(r.extended_pred, float)[a:b]
    edge = None
    if log is not None and len(log) == t.size:
        u = np.asarray(log.u, float)
        edge = next((float(t[k]) for k in range(max(a, 1), b) if u[k] != u[k - 1]), None)
    fit = ext if model else base
    cu_lines = [
        Line("measured", tt, w, dots=True),
        Line("first-order model", tt, base, color="#d62728", dash=True),
    ]
    if model:
        cu_lines.append(Line("extended model", tt, ext, color="#2ca02c"))
    band = Band(
        f"{'extended' if model else 'model'} ± noise ({format_number(cu.noise, 3)} rad/s)",
        tt,
        fit - cu.noise,
        fit + cu.noise,
        color="#2ca02c" if model else "#d62728",
    )
    top_cu = plot(
        cu_lines,
        bands=(band,),
        marks=()
        if edge is None
        else (Mark(f"the input changes, t = {format_number(edge)} s", x=edge),),
        title=f"close-up: {check_says.close_up_what(cu)}",
        ylabel=SPEED,
        show_xlabel=False,
        width=440,
        height=260,
    )
    res_cu = [Line("measured - first order", tt, w - base, color="#d62728", dots=True)]
    if model:
        res_cu.append(Line("measured - extended", tt, w - ext, color="#2ca02c", dots=True))
    floor = Band(f"± noise ({format_number(cu.noise, 3)} rad/s)", tt, -cu.noise, cu.noise)
    on_angle = r.lead is not None and r.lead.figure.endswith("angle_rms")
    bottom_cu = plot(
        res_cu,
        bands=(floor,),
        marks=() if edge is None else (Mark("", x=edge),),
        xlabel=TIME,
        ylabel=RESIDUAL,
        width=440,
        height=190,
        show_xlabel=not on_angle,
    )
    panels = [top_cu, bottom_cu]
    angle_floor = r.gain.angle_floor
    if on_angle:  # the figure that leads: the angle shows what the speed's noise hides
        dt = np.diff(t, prepend=t[0] - (t[1] - t[0] if t.size > 1 else 0.0))[a:b]
        ang = [Line("first order", tt, np.cumsum((w - base) * dt), color="#d62728", dots=True)]
        if model:
            ang.append(Line("extended", tt, np.cumsum((w - ext) * dt), color="#2ca02c", dots=True))
        panels.append(
            plot(
                ang,
                bands=()
                if angle_floor is None
                else (
                    Band(
                        f"± the angle's floor {format_number(angle_floor, 3)} rad",
                        tt,
                        -angle_floor,
                        angle_floor,
                    ),
                ),
                marks=() if edge is None else (Mark("", x=edge),),
                title="angle error: measured - model, summed over the window",
                xlabel=TIME,
                ylabel=axis_label("angle error", "rad"),
                width=440,
                height=190,
            )
        )
    close = Figure(
        stack(panels),
        440,
        f"Run {name}, {check_words.close_up_title(r)}"
        + (f" ({in_words(cu.cause)})" if cu.cause != "none" else "")
        + f". The shaded band is ± the noise there ({format_number(cu.noise, 3)} rad/s): a model whose "
        "miss (measured - model) stays inside it explains the log down to its noise."
        + (
            " Below, that miss summed over the window: the angle error, which the speed's "
            "noise does not hide."
            if on_angle
            else ""
        ),
    )
    return Figures((whole, close))


def _two_fits(
    session: Session, run: str | None, params: dict[str, float], u: ArrayLike | None
) -> list[str]:
    """Why the model check's first-order T and K are not the program's least-squares reading
    used in Tasks 11-12 when both come from the same run (one sentence, or none); ``u``: the
    run's input (V), None when it cannot be read."""
    res = session.results()
    ident = res.identification
    if run is None or res.run != run or ident is None or ident.step is None:
        return []
    st = ident.step
    T, K = params.get("T"), params.get("K")
    if T is None or K is None or not st.T:
        return []
    return [
        check_words.two_fits(
            T,
            st.T,
            st.K,
            rising=st.fit.method == "rising_steps",
            down=check_words.steps_down(u),
        )
    ]


CHECK_NOTES = "model_check.notes"
"""The group's notes on the model check: they lead its section (not among the Notes)."""


def _check_notes(session: Session) -> str:
    e = session.entry(CHECK_NOTES)
    text = e.text.strip() if e is not None else ""
    return (
        f"The group's notes on the model check: {text}"
        if text
        else "The group wrote no notes on the model check; what follows is the program's."
    )


def _model_check_section(session: Session) -> Section | None:
    mc = session.model_check()
    if mc.run is None:
        return None
    sec = Section("Model check")
    sec.blocks.append(_check_notes(session))  # the group's own first
    r = mc.result
    if r is None:
        elsewhere = views.check_elsewhere(session, mc.run)
        of = f" ({elsewhere})" if elsewhere else ""
        sec.blocks.append(f"The model check could not run on {mc.run}{of}: {mc.problem}")
        return sec
    try:
        log: RunLog | None = session.load_run(mc.run)
    except (InputError, KeyError):
        log = None
    u = np.asarray(log.u, float) if log is not None and len(log) == np.asarray(r.t).size else None
    lag = check_says.late_speed(log) if log is not None else None  # its speed behind its angle
    # as on the screen: the run and what the close-up shows, then the sentences about it
    elsewhere = views.check_elsewhere(session, mc.run)  # an import at the model check
    of = f" (a log imported at the model check; {elsewhere})" if elsewhere else ""
    sec.blocks.append(f"Run {mc.run}{of}, {check_words.close_up_title(r)}.")
    sec.blocks.append(check_words.join(check_words.lead(r, u, lag)))
    sec.blocks.append(_model_check_figures(mc.run, r, log))
    # the details as the screen's fold gives them, each figure with what it measures and
    # why it matters; here the intervals too, and the figures in a table
    told = check_words.details(
        r, "".join(_two_fits(session, mc.run, r.baseline.params, u)), True, lag
    )
    details = Fold("Details")
    details.blocks.extend(told.said)
    e, named = r.extended, r.finding.cause != "none"
    head = (
        "figure",
        "first-order model",
        f"extended model ({in_words(e.model)})" if named else "extended",
    )
    details.blocks.append(Table(head, _gain_rows(r)))
    if told.cannot:
        details.blocks += [check_words.CANNOT_SHOW, list(told.cannot)]
    if told.in_log:
        details.blocks += [check_words.IN_THE_LOG, list(told.in_log)]
    sec.blocks.append(details)
    return sec


def _runs_section(session: Session) -> Section:
    sec = Section("Recorded runs")
    if not session.runs:
        sec.blocks.append("No run recorded.")
        return sec
    logs: dict[str, RunLog | InputError | KeyError] = {}
    for r in session.runs:
        try:
            logs[r.name] = session.load_run(r.name)
        except (InputError, KeyError) as exc:
            logs[r.name] = exc

    def samples(r: RunInfo) -> str:
        log = logs[r.name]
        if isinstance(log, RunLog) and len(log) != r.samples:
            return f"{len(log)} ({r.samples} recorded)"
        return f"{r.samples}"

    rows = tuple(
        (
            r.name,
            r.kind,
            samples(r),
            f"{r.ts * 1e3:g} ms",
            f"{r.dropped}",
            r.interruption or "not interrupted",
            r.file,
        )
        for r in session.runs
    )
    sec.blocks.append(
        Table(("run", "kind", "samples", "Ts", "dropped", "interrupted by", "CSV file"), rows)
    )
    for r in session.runs:
        log = logs[r.name]
        changed = session.run_changed(r.name)  # the one rule: the lab and the class view's
        if not isinstance(log, RunLog):
            sec.blocks.append(f"Run {r.name} cannot be read: {log}")
            if changed:  # cut short after the recording: said as the class view says it
                sec.blocks.append(changed.text[0].upper() + changed.text[1:] + ".")
            continue
        if changed:
            sec.blocks.append(changed.text[0].upper() + changed.text[1:] + ".")
        sec.blocks.append(_run_figure(log, r.name))
    return sec


def _notes_section(session: Session, shown: tuple[str, ...] = ()) -> Section | None:
    """The group's notes on the steps (``shown``: keys already in another section)."""
    items = []
    for st in lab_steps.STEPS:
        for fld in st.fields:
            if fld.key in shown:
                continue
            e = session.entry(fld.key)
            if (
                fld.kind == "text"
                and st.part not in ("Summary",)
                and e
                and e.text.strip()
                and not fld.compare
            ):
                items.append(f"{st.title}: {e.text.strip()}")
    return Section("Notes", [items]) if items else None


def build(session: Session) -> Report:
    """The report of ``session`` (computed now from its entries and runs)."""
    members = ", ".join(session.members) or "(no names)"
    sections = [
        _grader_section(session),
        _warnings_section(session),
        _answers(session, "Preparation"),
        _board_section(session),
        _table_section(session),
        _step_section(session),
    ]
    check = _model_check_section(session)
    if check is not None:
        sections.append(check)
    sections.append(_runs_section(session))
    sections.append(_answers(session, "Summary"))
    notes = _notes_section(session, (CHECK_NOTES,) if check is not None else ())
    if notes is not None:
        sections.append(notes)
    return Report(
        title="DC-motor modelling and parameter identification: lab report",
        byline=f"Group: {members} · date {session.date} · session {session.id} · last change {session.modified}",
        sections=sections,
    )
