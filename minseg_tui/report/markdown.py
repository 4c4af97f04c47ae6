"""A :class:`~minseg_tui.report.content.Report` as Markdown.

Figures are separate SVG files beside the Markdown, linked relatively
(``![caption](report-figure-1.svg)``; :func:`figure_files` gives their names and texts), so
the Markdown stays readable text; without a file name prefix they are inline SVG data URIs
(the class report).

Every text is escaped (:func:`escape`): names, answers and notes a group typed are shown
as typed, never read as Markdown ("*x* | y" in a name neither turns italic nor splits a
table row; "# ..." at the start of an answer is no heading)."""

from __future__ import annotations

import base64
import re
from collections.abc import Iterator
from urllib.parse import quote

from minseg_tui.report.content import Figure, Figures, Fold, Report, Table

_INLINE = re.compile(
    r"[\\`*\[\]|~]"  # emphasis, code, links and images, table cells, strikethrough
    r"|(?<![A-Za-z0-9])_|_(?![A-Za-z0-9])"  # '_' that can open or close emphasis (k_v cannot)
    r"|<(?=[A-Za-z/!?])"  # an HTML tag or an autolink
    r"|&(?=[A-Za-z#])"  # an entity
)
_BLOCK = re.compile(r"^[#>+=-]")
"""A mark that makes a line a heading, a quote, a list item or a setext underline."""

_ORDERED = re.compile(r"^(\d{1,9})([.)])(?=\s|$)")
"""A number that makes a line an ordered list's item ("1. ", "2) ")."""


def escape(text: str) -> str:
    """``text`` with every character that Markdown would read as markup backslash-escaped,
    on each line (leading spaces dropped: four would make a code block)."""
    out = []
    for line in text.split("\n"):
        line = _INLINE.sub(lambda m: "\\" + m.group(0), line.lstrip())
        line = _BLOCK.sub(lambda m: "\\" + m.group(0), line)
        out.append(_ORDERED.sub(r"\1\\\2", line))
    return "\n".join(out)


def _cell(text: str) -> str:
    return escape(text.replace("\n", " "))


def _table(t: Table) -> str:
    lines = ["| " + " | ".join(_cell(h) for h in t.header) + " |", "|" + "---|" * len(t.header)]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in t.rows]
    return "\n".join(lines)


def figure_name(prefix: str, k: int) -> str:
    """The file name of the ``k``-th figure (1-based) of a report written with ``prefix``."""
    return f"{prefix}-{k}.svg"


def _figure(f: Figure, name: str | None) -> str:
    caption = _cell(f.caption)
    if name is None:
        data = base64.b64encode(f.svg.encode("utf-8")).decode("ascii")
        return f"![{caption}](data:image/svg+xml;base64,{data})\n\n*{caption}*"
    return f"![{caption}]({quote(name)})\n\n*{caption}*"


def _all_figures(report: Report) -> list[Figure]:
    """Every figure of ``report`` in the order the document shows them."""
    out: list[Figure] = []
    for sec in report.sections:
        for b in sec.blocks:
            for x in b.blocks if isinstance(b, Fold) else [b]:
                if isinstance(x, Figure):
                    out.append(x)
                elif isinstance(x, Figures):
                    out.extend(x.figures)
    return out


def figure_files(report: Report, prefix: str) -> list[tuple[str, str]]:
    """(file name, SVG text) of every figure of ``report`` as :func:`render` with ``prefix``
    links them, in the document's order."""
    return [(figure_name(prefix, k), f.svg) for k, f in enumerate(_all_figures(report), 1)]


def _heading(text: str) -> str:
    return _cell(text).replace("#", "\\#")


def render(report: Report, figures: str | None = None) -> str:
    """The report as one Markdown document; ``figures``: the prefix of the figures' file
    names (:func:`figure_files`), None for figures inline as data URIs."""
    names = iter(name for name, _ in figure_files(report, figures)) if figures is not None else None
    out = [f"# {_heading(report.title)}", "", escape(report.byline), ""]
    for sec in report.sections:
        out += [f"## {_heading(sec.title)}", ""]
        for b in sec.blocks:
            if isinstance(b, Fold):  # a subsection of the section
                out += [f"### {_heading(b.title)}", ""]
                for x in b.blocks:
                    out += [_block(x, names), ""]
            else:
                out += [_block(b, names), ""]
    return "\n".join(out)


def _block(b: object, names: Iterator[str] | None = None) -> str:
    """One block of a section as Markdown (``names``: the figures' file names, in order)."""

    def fig(f: Figure) -> str:
        return _figure(f, next(names) if names is not None else None)

    if isinstance(b, Table):
        return _table(b)
    if isinstance(b, Figure):
        return fig(b)
    if isinstance(b, Figures):
        return "\n\n".join(fig(f) for f in b.figures)
    if isinstance(b, list):
        return "\n".join(f"- {_cell(str(i))}" for i in b)
    return escape(str(b))
