"""A :class:`~minseg_tui.report.content.Report` as Markdown (figures as inline SVG data URIs)."""

from __future__ import annotations

import base64

from minseg_tui.report.content import Figure, Figures, Report, Table


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
            if isinstance(b, Table):
                out.append(_table(b))
            elif isinstance(b, Figure):
                out.append(_figure(b))
            elif isinstance(b, Figures):
                out.append("\n\n".join(_figure(f) for f in b.figures))
            elif isinstance(b, list):
                out.append("\n".join(f"- {_cell(str(i))}" for i in b))
            else:
                out.append(str(b))
            out.append("")
    return "\n".join(out)
