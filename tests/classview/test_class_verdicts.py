"""The class view marks a group's own value that the lab judged wrong (walk 14, D4: "the
group's T: +111 % from the value computed the group's way" stood with no mark, and the CLI
said "Nothing stands out.", while the group's screen and report said wrong)."""

from __future__ import annotations

from minseg_tui.cli.classview import text
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import classread
from minseg_tui.lab.views.classview import own_cell, read_group
from minseg_tui.report import class_content, markdown
from minseg_tui.ui.screens.classview import detail

from .build import group


def _own_T(folder, factor: float) -> None:
    """The group types its own T: ``factor`` times the 63 % reading."""
    with Session.open(folder) as s:
        ident = s.results().identification
        assert ident is not None and ident.step is not None and ident.step.T_63 is not None
        s.enter("own.T", f"{ident.step.T_63 * factor:.6f} s")


def test_a_wrong_own_value_is_marked_and_a_right_one_said_right(tmp_path):
    root = tmp_path / "sessions"
    wrong = group(root, ["Ada", "Bo"], seed=4)
    right = group(root, ["Cy", "Di"], seed=5)
    _own_T(wrong, 2.11)
    _own_T(right, 1.003)
    g_wrong, g_right = read_group(wrong), read_group(right)
    assert own_cell(g_wrong) == "T +111 % ✗", own_cell(g_wrong)
    assert own_cell(g_right) == "T +0.3 %", own_cell(g_right)  # right: the number alone
    said = str(detail(1, g_wrong))
    assert "T: +111 % from the value computed the group's way, ✗ wrong" in said, said
    assert ", ✓ right" in str(detail(2, g_right))
    view = classread.build(root, workers=1)
    assert not any(g.flags for g in view.groups)  # nothing marked '!' ...
    out = text(view)
    assert "T +111 % ✗" in out and "Nothing stands out." not in out, out
    assert "Nothing marked '!'." in out
    page = markdown.render(class_content.build(view))
    assert "T +111 % ✗" in page and "Nothing stands out." not in page


def test_the_verdict_survives_the_class_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))
    root = tmp_path / "sessions"
    folder = group(root, ["Ada", "Bo"], seed=4)
    _own_T(folder, 2.11)
    first = classread.build(root, workers=1)
    again = classread.build(root, workers=1)  # read from the cache this time
    assert [o.right for o in again.groups[0].own] == [o.right for o in first.groups[0].own]
    assert own_cell(again.groups[0]) == "T +111 % ✗"


def test_the_class_report_and_text_say_what_is_not_answered_yet(tmp_path):
    """Walk 14 (lead's try of F8 on the class view): the class report said "Every session is
    complete." of two groups that had reached Task 12, and `minseg-tui class` said nothing
    of what they had not answered; the class screen already said it."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=4)
    view = classread.build(root, workers=1)
    (g,) = view.groups
    assert g.unanswered.startswith("Task "), g.unanswered
    page = markdown.render(class_content.build(view))
    assert "Every session is complete" not in page
    assert f"#1 {g.id}: not answered yet: {g.unanswered}" in page, page
    assert f"  - not answered yet: {g.unanswered}" in text(view)
