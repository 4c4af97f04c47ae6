"""Walk 16's defects (issue 20), each as the walk met it, at 80x24 with Pilot on real session
folders (/work/coord/WALK16.md)."""

from __future__ import annotations

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.conftest import quiet_app
from tests.ui.helpers import burst, goto, settle, start, stored_text, type_in


async def test_a_letter_on_the_tick_goes_after_the_notes_not_over_them(tmp_path):
    """D2: Prep 1, 'read ch 2.1 Enter' (the notes stored, the focus on to "done?"), then a
    stray 'k': the notes' box showed "k" alone, and PgDn stored "k" over "read ch 2.1". A
    character typed outside the entries goes into the step's entry, replacing what it holds:
    right for a reading typed off a plot, wrong for free text. Now it goes on after the
    notes."""
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep1")
        await type_in(pilot, "prep1.notes", "read ch 2.1")
        # the focus went on to "done?" (a list of answers); a letter typed there
        await burst(pilot, "k")
        box = app.screen.query_one(f"#{field_id('prep1.notes')}", FieldRow).input
        assert box.value == "read ch 2.1k"
        await burst(pilot, "pagedown")
        await settle(pilot, lambda: stored_text(app, "prep1.notes") != "read ch 2.1")
        assert stored_text(app, "prep1.notes") == "read ch 2.1k"


async def test_a_short_text_typed_over_a_long_one_shows(tmp_path):
    """D2's second half: the model check's notes held a 56-character path, scrolled to its
    end in the box; the notes focused (all selected) and 'X' typed over it: the box looked
    empty, its view still scrolled one column into the new text (Home showed the "X"). A
    text that fits the box now shows from its first column."""
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep1")
        long = "/work/shared/data/real-motors/ev3-large-duty100/step.csv"
        await type_in(pilot, "prep1.notes", long)
        row = app.screen.query_one(f"#{field_id('prep1.notes')}", FieldRow)
        row.input.focus()  # the row's text all selected, as Tab or Shift+Tab leaves it
        await settle(pilot, lambda: row.input.selection == (0, len(long)))
        await burst(pilot, "X")
        assert row.input.value == "X"
        assert row.input.render_line(0).text.strip() == "X"
