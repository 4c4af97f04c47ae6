"""A :class:`~minseg_tui.report.content.Report` as one self-contained HTML page.

Inline CSS and inline SVG figures only: no scripts, no external style sheets, images or
fonts, so the file can be mailed or opened offline.
"""

from __future__ import annotations

from html import escape

from minseg_tui.quantities import join_units
from minseg_tui.report.content import Figure, Figures, Fold, Report, Table


def _text(text: str) -> str:
    """``text`` escaped, with no line break between a number and its unit."""
    return escape(join_units(text))


_CSS = """
body { font-family: sans-serif; max-width: 72em; margin: 2em auto; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; border-bottom: 1px solid #ccc; margin-top: 2em; }
.table { overflow-x: auto; }
table { border-collapse: collapse; margin: 0.8em 0; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f2f2f2; }
.figures { display: flex; flex-wrap: wrap; gap: 1em 1.5em; align-items: flex-start; }
figure { margin: 1em 0; } figcaption { font-style: italic; color: #555; }
figure svg { display: block; width: 100%; height: auto; }
.byline { color: #555; }
details { margin: 1em 0; } summary { cursor: pointer; font-weight: bold; }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 9pt; }
  .table { overflow: visible; } th, td { padding: 0.1em 0.3em; }
  figure, tr { break-inside: avoid; } h2 { break-after: avoid; }
  details > * { display: block; }
}
"""


_LANDSCAPE = """
body { max-width: none; }
@page { size: A4 landscape; margin: 12mm; }
@media print {
  figure { flex: 1 1 40% !important; max-width: 48% !important; }
  h2:has(+ .figures) { break-before: page; }
}
"""
"""For a report with a wide table: the window's width on screen; landscape pages, the
figures from a new page (else their heading could end a page alone), two side by side."""


def _cell(text: str) -> str:
    """A table cell: each line of ``text`` on a line of its own."""
    return "<br>".join(_text(line) for line in text.split("\n"))


def _table(t: Table) -> str:
    head = "".join(f"<th>{escape(h)}</th>" for h in t.header)
    rows = "".join(
        "<tr>" + "".join(f"<td>{_cell(c)}</td>" for c in row) + "</tr>" for row in t.rows
    )
    return (
        f'<div class="table"><table><thead><tr>{head}</tr></thead><tbody>{rows}</tbody>'
        "</table></div>"
    )


def _figure(f: Figure) -> str:
    """A figure at most as wide as drawn, narrower (scaled) on a narrow page."""
    svg = f.svg.replace(' xmlns="http://www.w3.org/2000/svg"', "")
    return (
        f'<figure style="flex: 1 1 {f.width}px; max-width: {f.width}px">{svg}'
        f"<figcaption>{_text(f.caption)}</figcaption></figure>"
    )


def _block(b: object) -> str:
    """One block of a section as HTML (a Fold: a <details> the reader opens)."""
    if isinstance(b, Table):
        return _table(b)
    if isinstance(b, Figure):
        return _figure(b)
    if isinstance(b, Figures):
        return '<div class="figures">' + "".join(_figure(f) for f in b.figures) + "</div>"
    if isinstance(b, Fold):
        inner = "\n".join(_block(x) for x in b.blocks)
        return f"<details><summary>{escape(b.title)}</summary>\n{inner}\n</details>"
    if isinstance(b, list):
        return "<ul>" + "".join(f"<li>{_text(str(i))}</li>" for i in b) + "</ul>"
    return f"<p>{_text(str(b))}</p>"


def render(report: Report) -> str:
    """The report as an HTML document (text)."""
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{escape(report.title)}</title><style>{_CSS}"
        + (_LANDSCAPE if report.landscape else "")
        + "</style></head><body>",
        f"<h1>{escape(report.title)}</h1>",
        f'<p class="byline">{escape(report.byline)}</p>',
    ]
    for sec in report.sections:
        out.append(f"<h2>{escape(sec.title)}</h2>")
        out += [_block(b) for b in sec.blocks]
    out.append("</body></html>")
    return "\n".join(out)
