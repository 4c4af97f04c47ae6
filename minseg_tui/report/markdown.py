"""A :class:`~minseg_tui.report.content.Report` as Markdown (figures as inline SVG data URIs)."""

from __future__ import annotations

import base64

from minseg_tui.report.content import Figure, Figures, Fold, Report, Table


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _table(t: Table) -> str:
    lines = ["| " + " | ".join(_cell(h) for h in t.header) + " |", "|" + "---|" * len(t.header)]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in t.rows]
    return "\n".join(lines)


def _figure(f: Figure) -> str:
    data = base64.b64encode(f.svg.encode("utf-8")).decode("ascii")
    return f"![{_alt(f.caption)}](data:image/svg+xml;base64,{data})\n\n*{f.caption}*"


def _alt(text: str) -> str:
    return text.replace("[", "(").replace("]", ")")


def render(report: Report) -> str:
    """The report as one Markdown document."""
    out = [f"# {report.title}", "", report.byline, ""]
    for sec in report.sections:
        out += [f"## {sec.title}", ""]
        for b in sec.blocks:
            if isinstance(b, Fold):  # a subsection of the section
                out += [f"### {b.title}", ""]
                for x in b.blocks:
                    out += [_block(x), ""]
            else:
                out += [_block(b), ""]
    return "\n".join(out)


def _block(b: object) -> str:
    """One block of a section as Markdown."""
    if isinstance(b, Table):
        return _table(b)
    if isinstance(b, Figure):
        return _figure(b)
    if isinstance(b, Figures):
        return "\n\n".join(_figure(f) for f in b.figures)
    if isinstance(b, list):
        return "\n".join(f"- {_cell(str(i))}" for i in b)
    return str(b)
