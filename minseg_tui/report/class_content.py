"""The class report as data: the table of groups, what stands out, one figure per quantity.

:func:`build` turns a :class:`~minseg_tui.lab.views.classview.ClassView` into a
:class:`~minseg_tui.report.content.Report`, so :mod:`.markdown` and :mod:`.html` render it
as they render a session's report; :func:`csv_text` writes the table as CSV (SI units,
full precision). The numbers are the class view's, which are the sessions' own
(:meth:`~minseg_tui.lab.state.session.Session.results`): nothing is computed here but layout.
"""

from __future__ import annotations

import csv
import io

from minseg_tui.lab.views import own_first
from minseg_tui.lab.views.classview import (
    JUDGED,
    MARKED,
    NOT_MARKED,
    OWN_VS_COMPUTED,
    QUANTITIES,
    THRESHOLD,
    ClassView,
    members,
    nothing_marked,
    own_cell,
)
from minseg_tui.quantities import MISSING, format_quantity
from minseg_tui.report.content import Figure, Figures, Report, Section, Table
from minseg_tui.report.svg import Band, Line, Mark, plot

FLAGGED_COLOR = "#d62728"
GROUP_COLOR = "#1f77b4"


def table(view: ClassView) -> Table:
    """The class table: one row per group, the numbers in the units of the header."""
    header = (
        "#",
        "group",
        "members",
        "date",
        "step",
        *(q.shown_label for q in QUANTITIES),
        "model check",
        OWN_VS_COMPUTED,
        "flags",
    )
    rows = []
    for k, g in enumerate(view.groups, 1):
        rows.append(
            (
                str(k),
                g.id,
                members(g),
                g.date or MISSING,
                g.step or MISSING,
                *(g.text(q.key) for q in QUANTITIES),
                (g.cause or MISSING) + (f" (on {g.check_on})" if g.check_on else ""),
                own_cell(g),
                str(len(g.flags)) if g.flags else "",
            )
        )
    return Table(header, tuple(rows))


def _figure(view: ClassView, key: str) -> Figure | None:
    """One quantity across the class: each group a point at its number in the table, the
    class median and its band (median ± THRESHOLD robust standard deviations)."""
    q = next(q for q in QUANTITIES if q.key == key)
    pts = [(k, g.value(key), g) for k, g in enumerate(view.groups, 1)]
    have = [(k, v, g) for k, v, g in pts if v is not None]
    if not have:
        return None
    s = view.spreads.get(key)
    lines = []
    flagged = False
    for n, (k, v, _) in enumerate(have):
        out = s is not None and not (s.band[0] <= v <= s.band[1])
        flagged |= out
        lines.append(
            Line(
                "" if n else "a group",
                [float(k)],
                [q.number(v)],
                color=FLAGGED_COLOR if out else GROUP_COLOR,
                dots=True,
            )
        )
    if flagged:
        lines.append(Line("stands out", [], [], color=FLAGGED_COLOR, dots=True))
    x = [0.5, len(view.groups) + 0.5]
    bands, marks = [], []
    if s is not None:
        lo, hi = (q.number(b) for b in s.band)
        bands.append(Band(f"band: ± {THRESHOLD:g} robust std", x, [lo, lo], [hi, hi]))
        marks.append(Mark(f"median {format_quantity(s.median, q.display)}", y=q.number(s.median)))
    svg = plot(
        lines,
        bands=bands,
        marks=marks,
        title=f"{q.key}: {q.words}",
        xlabel="group (# in the table)",
        ylabel=q.shown_label,
        width=440,
        height=230,
    )
    caption = (
        f"{q.key} of {len(have)} groups"
        + (
            f"; class median {format_quantity(s.median, q.display)}, the band holds what lies "
            f"within {THRESHOLD:g} robust standard deviations of it"
            if s is not None
            else "; too few groups for a class median"
        )
        + "."
    )
    return Figure(svg, 440, caption)


def stand_out(view: ClassView) -> Table | None:
    """What stands out, one row per group that has something (the group named once, its
    number in the class table beside it), each flag a sentence on a line of its own (one
    paragraph in Markdown), then its notes (an interrupted run in use: not marked '!', but
    what K, T and J rest on); None when nothing does."""
    rows = tuple(
        (str(k), f"{members(g)}\n{g.id}", "\n".join((*g.flags, *(f"note: {x}" for x in g.notes))))
        for k, g in enumerate(view.groups, 1)
        if g.flags or g.notes
    )
    return Table(("#", "group", "what stands out"), rows) if rows else None


def build(view: ClassView) -> Report:
    """The class report of ``view``."""
    n = len(view.groups)
    sections = [Section("Groups", [table(view)])]
    sections[0].blocks.append(
        "Numbers in the units of the header (SI, but f in mN m s/rad and T in ms as in the lab; R as typed); T_63 is the 63 % reading, T the "
        "least-squares fit on the encoder angle. "
        f"'{OWN_VS_COMPUTED}' is how far the group's own values are from the computed ones. "
        "'–': not computed yet (see What is missing)."
    )
    sections.append(
        Section(
            "What stands out",
            [
                stand_out(view) or nothing_marked(view),
                f"A group is listed here for {MARKED} (the '!' of the class view). " + NOT_MARKED,
                f"A value stands out when it lies more than {THRESHOLD:g} robust standard "
                "deviations (1.4826 times the median absolute deviation) from the class "
                "median: one group's typo moves neither, so it cannot hide another's. The "
                "slips the lab manual warns about are named on their own, and the values "
                "that rest on a slipped reading are left out of the class median and its "
                "spread (they are still judged against them).",
            ],
        )
    )
    lacks = [
        f"#{k} {g.id}: "
        + "; ".join((*g.lacks, *([f"not answered yet: {g.unanswered}"] if g.unanswered else [])))
        for k, g in enumerate(view.groups, 1)
        if g.lacks or g.unanswered
    ]  # walk 14: "Every session is complete." stood over groups that had reached Task 12
    sections.append(
        Section("What is missing", [lacks or "Every session is complete and every task answered."])
    )
    own_section = own_values(view)
    if own_section is not None:
        sections.append(own_section)
    figs = tuple(f for key in ("R", *JUDGED[1:]) if (f := _figure(view, key)) is not None)
    if figs:
        sections.append(Section("The class per quantity", [Figures(figs)]))
    return Report(
        title="DC-motor lab: the class at a glance",
        byline=f"{n} group{'s' if n != 1 else ''} in {view.root}",
        sections=sections,
        landscape=True,  # seventeen columns do not fit a portrait page
    )


def own_values(view: ClassView) -> Section | None:
    """The values each group worked out, in the rows and words of the session's report
    (:mod:`~minseg_tui.lab.views.own_first`): the group's value, the value computed the
    group's way, the difference, the program's (least squares for Tasks 11-15) and when the
    group was shown it; only the values a group entered. None when no group entered one."""
    groups = list(enumerate(view.groups, 1))

    def rows(keys: frozenset[str]) -> tuple[tuple[str, ...], ...]:
        return tuple(
            (f"#{k} {g.id}", *r.cells) for k, g in groups for r in g.own_rows if r.key in keys
        )

    table_keys = frozenset(("own.k_v", "own.k_a", "own.f"))
    steady = rows(table_keys)
    step = rows(frozenset(own_first.TASK) - table_keys)
    if not steady and not step:
        return None
    blocks: list[object] = []
    if steady:
        blocks.append(Table(("group", *own_first.TABLE_HEADER), steady))
    if step:
        blocks.append(Table(("group", *own_first.STEP_HEADER), step))
        blocks.extend(
            f"#{k} {g.id}, {own_first.TASK[r.key]}: {r.why}"
            for k, g in groups
            for r in g.own_rows
            if r.why
        )
    return Section("The groups' own values against the computed ones", blocks)


def csv_text(view: ClassView) -> str:
    """The class table as CSV: one row per group, numbers in SI units at full precision
    (empty where not computed), flags and what is missing joined by ' | '."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(
        (
            "id",
            "members",
            "date",
            "step",
            *(q.label for q in QUANTITIES),
            "model check cause",
            OWN_VS_COMPUTED,
            "flags",
            "lacks",
        )
    )
    for g in view.groups:
        w.writerow(
            (
                g.id,
                "; ".join(g.members),
                g.date,
                g.step,
                *("" if (v := g.value(q.key)) is None else repr(v) for q in QUANTITIES),
                g.cause,
                own_cell(g) if g.own else "",
                " | ".join(g.flags),
                " | ".join(g.lacks),
            )
        )
    return buf.getvalue()
