"""Issue 20, left by walk 13: the model check's fold drew "▶ Details", the glyph of the mark
before the entry the keys go to ("▶ A run log recorded elsewhere", fields.FOCUS_MARK): at
80x24 without colour two "▶" showed at once. The fold has its own marks, "+" shut and "−"
open."""

from __future__ import annotations

from textual.widgets import Collapsible

from minseg_tui.ui.panels.model_check import FOLD_OPEN, FOLD_SHUT
from minseg_tui.ui.widgets.fields import FOCUS_MARK
from tests.ui.helpers import settle, start_with_a_run


def _title_line(fold: Collapsible) -> str:
    title = fold.query_one("CollapsibleTitle")
    return "".join(s.text for s in title.render_lines(title.region.reset_offset)).strip()


async def test_the_fold_marks_are_not_the_focus_mark(quiet):
    assert FOCUS_MARK.strip() not in (FOLD_SHUT, FOLD_OPEN)
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        fold = app.screen.query_one("#check-details", Collapsible)
        assert _title_line(fold).startswith(f"{FOLD_SHUT} Details"), _title_line(fold)
        await pilot.press("tab")  # from the step's text to the fold's title
        await pilot.press("enter")
        await settle(pilot, lambda: not fold.collapsed)
        line = _title_line(fold)
        assert line.startswith(f"{FOLD_OPEN} Details") and "▶" not in line, line
