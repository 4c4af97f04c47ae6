"""What a group typed stands in report.md as typed: never read as Markdown."""

from __future__ import annotations

from html import unescape
from pathlib import Path

from markdown_it import MarkdownIt

from minseg_tui.lab.state.session import Session
from minseg_tui.report import content, markdown
from minseg_tui.report.content import Report, Section, Table

TYPED = "*x* | y _z_ [l](http://e.vil) <b>b</b> `c` ~~s~~ &amp; \\"
"""Emphasis, a table cell's end, a link, HTML, code, strikethrough, an entity, a backslash."""


def _html(md: str) -> str:
    """GitHub's Markdown without its autolinks (a bare URL typed is a link there, as typed)."""
    return MarkdownIt("commonmark").enable(["table", "strikethrough"]).render(md)


def _text(html: str) -> str:
    """The rendered text, tags dropped, entities read."""
    out, inside = [], False
    for ch in html:
        if ch == "<":
            inside = True
        elif ch == ">":
            inside = False
        elif not inside:
            out.append(ch)
    return unescape("".join(out))


def test_names_and_answers_a_group_typed_are_shown_as_typed(tmp_path: Path) -> None:
    s = Session.create(tmp_path, [TYPED, "Bo"], date="2026-11-22")
    s.enter("summary.unclear", TYPED)
    s.enter("prep1.notes", "# not a heading")
    s.enter("prep3.notes", "1. not a list")
    md = markdown.render(content.build(s))
    s.close()
    html = _html(md)
    for tag in ("<em", "<strong", "<a ", "<b>", "<code", "<s>", "<del", "<ol", "<blockquote"):
        assert tag not in html, tag
    assert html.count("<h1>") == 1  # the title, no answer
    text = _text(html)
    assert f"Group: {TYPED}, Bo" in text  # the byline, as typed
    assert TYPED in text and "Preparation 1: reading: # not a heading" in text
    assert "1. not a list" in text
    # the summary table keeps its four columns in the row that holds the answer
    summary = html.split("<h2>Summary")[1]
    row = next(r for r in summary.split("<tr>") if "e.vil" in r)
    assert row.count("<td>") == 4


def test_our_own_text_keeps_its_names_readable() -> None:
    rep = Report(
        "t",
        "by",
        [Section("s", ["k_v = 0.4938 V s/rad, T_63 = 56.8 ms", Table(("R (Ω)",), (("5.26",),))])],
    )
    md = markdown.render(rep)
    assert "k_v = 0.4938 V s/rad, T_63 = 56.8 ms" in md and "| 5.26 |" in md
    for line in ("# a", "> b", "- c", "+ d", "2) e", "    f"):
        html = _html(markdown.render(Report("t", "by", [Section("s", [line])])))
        assert html.count("<h1>") == 1 and "<blockquote" not in html and "<li" not in html
        assert "<pre" not in html and line.strip() in _text(html)
