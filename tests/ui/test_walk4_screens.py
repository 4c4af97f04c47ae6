"""Walk 4's defects on the screens (issue 20; a new group at 80x24): the model check's ✓,
the focus seen without colour, the whole of "What to do" on one key, the cursor and the
zooms of Tasks 11-12, the virtual multimeter's R."""

from __future__ import annotations

from textual.widgets import OptionList, RadioSet

from minseg_tui.lab.content.steps import STEPS
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import settle, start_with_a_run, typing_box


def _mark(app, step_id: str) -> str:
    """The mark before ``step_id`` in the list of steps."""
    nav = app.screen.query_one("#nav", OptionList)
    k = [s.id for s in STEPS].index(step_id)
    return str(nav.get_option_at_index(k).prompt)[0]


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one("#" + field_id(key), FieldRow)


async def test_the_model_check_is_done_when_the_group_ticks_done_not_by_a_note(quiet):
    """The model check's ✓ came only once a note was typed, and nothing said why. The step
    now says what makes it done, and its done? choice does it, as on the steps that ask the
    group to read or to see for themselves; a note alone starts it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        todo = app.screen.query_one(".todo").render()
        assert "done when you tick done?" in " ".join(str(todo).split())
        assert _mark(app, "model_check") == " "
        assert app.screen.pane.scroll_y == 0  # it still lands at the top, on the plots
        notes = _row(app, "model_check.notes")
        notes.input.focus()
        await pilot.press(*"slower", "enter")
        await settle(pilot)
        assert _mark(app, "model_check") == "…"  # a note alone: started, not done
        done = _row(app, "model_check.done")
        assert app.focused is done.query_one(RadioSet)  # Enter in the notes moved on to it
        await pilot.press("space")
        await settle(pilot)
        assert _mark(app, "model_check") == "✓"
        with app.session as s:
            assert s.step_status("model_check") == "done"
        assert typing_box(app) is None
