"""What a session's report says, as data: sections of paragraphs, tables and figures.

:func:`build` reads a :class:`~minseg_tui.lab.session.Session` (its entries, the results it
computes, its recorded runs) and returns a :class:`Report`; :mod:`.markdown` and
:mod:`.html` only render it. The report is the one place where derived numbers are
written down.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from minseg_tui.errors import InputError
from minseg_tui.lab import steps as lab_steps
from minseg_tui.lab.entry import format_quantity
from minseg_tui.lab.session import Session
from minseg_tui.model.steplog import StepLog
from minseg_tui.report.svg import Line, plot


@dataclass(frozen=True)
class Table:
    """A table: column headers and rows of cell texts."""

    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]


@dataclass(frozen=True)
class Figure:
    """A figure: panels (SVG texts, stacked) and a caption."""

    panels: tuple[str, ...]
    caption: str


@dataclass
class Section:
    """A titled part of the report; ``blocks`` in order: str (a paragraph), Table, Figure,
    or a list of str (bullet points)."""

    title: str
    blocks: list[object] = field(default_factory=list)


@dataclass
class Report:
    """The whole report: title, a line of who/when, and sections."""

    title: str
    byline: str
    sections: list[Section]


def _q(value: float | None, unit: str, digits: int = 4) -> str:
    return (
        "–" if value is None or not math.isfinite(value) else format_quantity(value, unit, digits)
    )


def _num(value: float | None, digits: int = 4) -> str:
    return "–" if value is None or not math.isfinite(value) else f"{value:.{digits}g}"


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
            else:
                shown = e.text if e else ""
            fb = verdicts.get(fld.key)
            verdict = (
                ""
                if fb is None
                else {"right": "✓ ", "wrong": "✗ ", "missing": ""}[fb.status] + fb.message
            )
            if e is not None and not e.ok:
                verdict = f"refused: {e.message}"
            rows.append(
                (st.title if fld.kind != "choice" else "", fld.label, shown.strip() or "–", verdict)
            )
    title = "Preparation" if part == "Preparation" else "Summary and reflections"
    return Section(title, [Table(("step", "question", "answer", "feedback"), tuple(rows))])


def _table_section(session: Session) -> Section:
    res = session.results()
    rows = []
    for r in session.table():
        omega = _q(r.omega_ss, "rad/s")
        if r.spread is not None and r.omega_ss is not None:
            omega += f" ± {r.spread:.2g}"
        window = (
            f"{r.window[0]:.3g}–{r.window[1]:.3g} s"
            if r.window
            else "typed"
            if r.omega_ss is not None
            else "–"
        )
        rows.append(
            (
                f"{r.level:g} V",
                _q(r.u_ss, "V"),
                omega,
                window,
                _q(r.i_ss, "mA", 3),
                _num(r.k_v),
                _num(r.f),
            )
        )
    sec = Section("Steady state (Tasks 2 and 4-9)")
    sec.blocks.append(f"R = {_q(session.value('R'), 'Ω')} (Task 2).")
    sec.blocks.append(
        Table(
            (
                "requested u",
                "u_ss",
                "omega_ss (± spread)",
                "capture window",
                "i_ss",
                "k_v (V s/rad)",
                "f (N m s/rad)",
            ),
            tuple(rows),
        )
    )
    ident = res.identification
    if ident is not None:
        sec.blocks.append(
            [
                f"k_v = {ident.k_v:.4g} V s/rad (median of the rows, Task 7)",
                f"k_a = 0.65 k_v = {ident.k_a:.4g} N m/A (Task 8)",
                f"f = {ident.f:.4g} N m s/rad (median of the rows, Task 9)",
            ]
        )
    return sec


def _step_section(session: Session) -> Section:
    res = session.results()
    sec = Section("Step response and model (Tasks 10-15)")
    ident = res.identification
    if ident is None or ident.step is None:
        sec.blocks.append(
            "No step result yet" + (": " + "; ".join(res.problems) if res.problems else ".")
        )
    else:
        s = ident.step
        t63 = "–" if s.T_63 is None else f"{s.T_63:.4g} s"
        sec.blocks.append(f"From run {res.run}:")
        sec.blocks.append(
            Table(
                ("quantity", "value"),
                (
                    ("omega_ss in the steps", f"{s.omega_ss:.4g} rad/s"),
                    ("u_ss used for K", f"{s.u_ss:.4g} V ({s.u_ss_how})"),
                    ("K (Task 11)", f"{s.K:.4g} rad/s/V"),
                    ("T, 63 % reading (Task 12)", t63),
                    (
                        "T, least squares (95 % interval)",
                        f"{s.T:.4g} s ({s.T_ci[0]:.4g} – {s.T_ci[1]:.4g} s)",
                    ),
                    ("J (Task 13)", f"{s.J:.4g} kg m^2"),
                    ("model (Task 14)", f"{s.T:.4g} omega' = -omega + {s.K:.4g} u_A"),
                    ("omega at u_A = 5 V (Task 15)", f"{ident.omega_at_5V:.4g} rad/s"),
                ),
            )
        )
    comps = session.comparisons()
    if any(c.own is not None for c in comps):
        rows = []
        for c in comps:
            if c.own is None:
                continue
            own = c.own if isinstance(c.own, str) else _q(c.own, c.unit)
            comp = (
                c.computed
                if isinstance(c.computed, str) or c.computed is None
                else _q(c.computed, c.unit)
            )
            diff = "" if c.rel_diff is None else f"{c.rel_diff * 100:+.0f} %"
            rows.append((c.label, own, comp or "–", diff))
        sec.blocks.append("The group's own readings beside the computed values:")
        sec.blocks.append(Table(("reading", "yours", "computed", "difference"), tuple(rows)))
    return sec


def _warnings_section(session: Session) -> Section:
    res = session.results()
    items = [f"{n.source}: {n.message}" for n in session.warnings()]
    items += [
        f"refused entry {e.key}: {e.text!r} — {e.message}"
        for e in session.entries.values()
        if not e.ok
    ]
    items += [
        f"refused entry {e.key}: {e.refused[0]!r} — {e.refused[1]} (still using {e.text!r})"
        for e in session.entries.values()
        if e.refused
    ]
    items += list(res.problems)
    return Section("Warnings", [items if items else "None."])


def _run_figure(log: StepLog, name: str) -> Figure:
    t = np.asarray(log.t, float)
    lines = [Line("omega (timestamps)", t, log.omega)]
    if "omega_lab" in log.extra:
        lines.append(Line("omega (manual's 20-tap)", t, log.extra["omega_lab"], dash=True))
    top = plot(lines, ylabel="omega (rad/s)", title=f"run {name}", show_xlabel=False, height=220)
    ul = [Line("u applied (u_A)", t, log.u, steps=True)]
    if "u_req" in log.extra:
        ul.append(Line("u requested", t, log.extra["u_req"], dash=True, steps=True))
    bottom = plot(ul, xlabel="t (s)", ylabel="u (V)", height=160)
    return Figure((top, bottom), f"Run {name}: speed and voltage against time.")


def _params(p: dict[str, float]) -> str:
    units = {
        "T": "s",
        "K": "rad/s/V",
        "u_c": "V",
        "delay": "s",
        "taps": "samples",
        "T_coast": "s",
        "T2": "s",
    }
    return ", ".join(f"{k} = {v:.4g} {units.get(k, '')}".rstrip() for k, v in p.items())


def _model_check_section(session: Session) -> Section | None:
    mc = session.model_check()
    if mc.run is None:
        return None
    sec = Section("Model check")
    r = mc.result
    if r is None:
        sec.blocks.append(f"The model check could not run on {mc.run}: {mc.problem}")
        return sec
    t = np.asarray(r.t, float)
    top = plot(
        [
            Line("measured", t, r.omega),
            Line("first-order model", t, r.baseline_pred, dash=True),
            Line(f"extended ({r.extended.model})", t, r.extended_pred, dash=True),
        ],
        title=f"run {mc.run}: measured against the models",
        ylabel="omega (rad/s)",
        show_xlabel=False,
    )
    bottom = plot(
        [
            Line("measured - first order", t, r.omega - r.baseline_pred, color="#d62728"),
            Line("measured - extended", t, r.omega - r.extended_pred, color="#2ca02c"),
        ],
        xlabel="t (s)",
        ylabel="residual (rad/s)",
        height=170,
    )
    b, e, f = r.baseline, r.extended, r.finding
    items = [
        f"First-order model fitted to {mc.run}: {_params(b.params)}; simulated on the recorded voltage "
        f"it misses by {b.rmse:.3g} rad/s rms (fit {b.fit_percent:.1f} %).",
        f"Where it deviates: {r.where}.",
        f"Most likely cause: {f.cause}. {f.evidence[:1].upper() + f.evidence[1:]}",
    ]
    items += [f"Also: {o.cause} ({_params(o.params)}): {o.evidence}" for o in f.others]
    if f.cause != "none":
        items.append(
            f"Extended model ({e.model}): {_params(e.params)}; {e.rmse:.3g} rad/s rms (fit "
            f"{e.fit_percent:.1f} %), {r.gain.get('rmse_reduction_percent', float('nan')):.1f} % lower rms."
        )
    items += [f"Anomaly: {a.text}" for a in r.anomalies]
    sec.blocks.append(items)
    sec.blocks.append(
        Figure(
            (top, bottom),
            "Measured speed, the first-order and the extended model, and their residuals.",
        )
    )
    return sec


def _runs_section(session: Session) -> Section:
    sec = Section("Recorded runs")
    if not session.runs:
        sec.blocks.append("No run recorded.")
        return sec
    rows = tuple(
        (
            r.name,
            r.kind,
            f"{r.samples}",
            f"{r.ts * 1e3:g} ms",
            f"{r.dropped}",
            "yes" if r.interrupted else "no",
            r.file,
        )
        for r in session.runs
    )
    sec.blocks.append(
        Table(
            ("run", "kind", "samples", "Ts", "dropped", "recovered after a crash", "CSV file"), rows
        )
    )
    for r in session.runs:
        try:
            log = session.load_run(r.name)
        except (InputError, KeyError) as exc:
            sec.blocks.append(f"Run {r.name} cannot be read: {exc}")
            continue
        sec.blocks.append(_run_figure(log, r.name))
    return sec


def _notes_section(session: Session) -> Section | None:
    items = []
    for st in lab_steps.STEPS:
        for fld in st.fields:
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
        _warnings_section(session),
        _answers(session, "Preparation"),
        _table_section(session),
        _step_section(session),
    ]
    check = _model_check_section(session)
    if check is not None:
        sections.append(check)
    sections.append(_runs_section(session))
    sections.append(_answers(session, "Summary"))
    notes = _notes_section(session)
    if notes is not None:
        sections.append(notes)
    return Report(
        title="DC-motor modelling and parameter identification: lab report",
        byline=f"Group: {members} · date {session.date} · session {session.id} · last change {session.modified}",
        sections=sections,
    )
