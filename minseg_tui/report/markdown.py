"""A :class:`~minseg_tui.report.content.Report` as Markdown (figures as inline SVG data URIs)."""

from __future__ import annotations

import base64

from minseg_tui.report.content import Figure, Report, Table


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _table(t: Table) -> str:
    lines = ["| " + " | ".join(_cell(h) for h in t.header) + " |", "|" + "---|" * len(t.header)]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in t.rows]
    return "\n".join(lines)


def _figure(f: Figure) -> str:
    imgs = []
    for k, svg in enumerate(f.panels):
        data = base64.b64encode(svg.encode("utf-8")).decode("ascii")
        imgs.append(f"![{f.caption} ({k + 1})](data:image/svg+xml;base64,{data})")
    return "\n\n".join(imgs) + f"\n\n*{f.caption}*"


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
            elif isinstance(b, list):
                out.append("\n".join(f"- {_cell(str(i))}" for i in b))
            else:
                out.append(str(b))
            out.append("")
    return "\n".join(out)
