"""Keys typed in a burst right after Escape closes the command palette (walk 8: keys after a
palette search with no match seemed lost). Reproduced with Pilot at 80x24: the keys after
Escape in the same burst were lost, not reordered (R stayed empty in every shape, a search
with a match or none alike). The app handed Escape to the palette's search box, which
passed it back up to the app's queue behind the keys after it; those went into the search
box and closed with it. Escape is now the palette's priority binding: the app runs it as it
reads the key, and the keys after it reach the step's entry."""

from __future__ import annotations

import pytest
from textual.command import CommandPalette

from minseg_tui.ui.screens.lab import LabScreen
from tests.ui.helpers import box_text, burst, goto, settle, start, stored_text


@pytest.mark.parametrize(
    ("query", "in_one_burst"),
    [("xyzzy", False), ("xyzzy", True), ("task", True)],
    ids=["no-match,escape-and-keys", "no-match,all-in-one", "a-match,all-in-one"],
)
async def test_keys_typed_after_escape_reach_the_step_s_entry(quiet, query, in_one_burst):
    """'Ctrl+P <query> Esc 5,3 Enter': the palette closes and R stores '5,3', with the search
    typed and looked at first, or all of it in one burst."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        after = ["escape", *"5,3", "enter"]
        if in_one_burst:
            await burst(pilot, "ctrl+p", *query, *after)
        else:
            await pilot.press("ctrl+p")
            await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
            await pilot.press(*query)
            await settle(pilot)
            await burst(pilot, *after)
        await settle(pilot)
        assert isinstance(app.screen, LabScreen)
        assert [type(s) for s in app.screen_stack[1:]] == [LabScreen]
        assert stored_text(app, "R") == "5,3"
        assert box_text(app, "R") == "5,3"
