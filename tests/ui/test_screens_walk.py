"""Screen defects found by a new student's walk of the lab in tmux at 80x24: notes typed on
the model check, the footer of Tasks 11-15, the applied voltage in the zoomed rise, an entry
Tab moves to under the readout of Tasks 4-5. Each through the real TUI (Pilot)."""

from __future__ import annotations

from textual.widgets import Input

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import settle, start_with_a_run


async def test_tab_on_the_model_check_reaches_the_notes_before_the_log_to_load(quiet):
    """The first text box Tab reached on the model check was 'load a step log': the notes a
    group typed there were taken for a file's path."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        for _ in range(10):
            await pilot.press("tab")
            await settle(pilot)
            if isinstance(app.focused, Input):
                break
        notes = app.screen.query_one("#" + field_id("model_check.notes"), FieldRow)
        assert app.focused is notes.input
        await pilot.press(*"slower")
        await settle(pilot)
        assert notes.input.value == "slower"
        assert app.screen.query_one("#import-path", Input).value == ""


async def test_typing_on_the_model_checks_fold_goes_into_its_notes(quiet):
    """Letters typed while the details' fold had the focus went nowhere."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        await pilot.press("tab")  # the fold's title
        await settle(pilot)
        await pilot.press(*"ok")
        await settle(pilot)
        notes = app.screen.query_one("#" + field_id("model_check.notes"), FieldRow)
        assert notes.input.value == "ok"
        assert app.screen.query_one("#import-path", Input).value == ""
