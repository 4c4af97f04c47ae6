"""Enter in the command palette runs the command picked for everything typed before it, and
the keys typed after it, in the same burst, reach the screen under the palette (issue 20's
leftovers: 'Ctrl+P Task 5 Enter 5,3 Enter' in one burst on Task 2 went to Preparation 1,
the command listed first before the search for 'Task 5' was done, and '5,3' went into the
palette's box). Pilot at 80x24 on a real session folder."""

from __future__ import annotations

import pytest
from textual.command import CommandList, CommandPalette

from minseg_tui.ui.screens.lab import LabScreen
from tests.ui.helpers import box_text, burst, goto, settle, shown, start, stored_text


def _step(app) -> str:
    with app.session as s:
        return s.current_step


@pytest.mark.parametrize(
    ("search", "in_one_burst"),
    [
        ([*"Task 5"], True),
        ([*"Task 5"], False),
        ([*"Task 55", "backspace"], True),
        ([*"Tsk 5", "home", "right", "a"], True),
    ],
    ids=["one-burst", "search-looked-at", "backspace-in-the-burst", "edited-in-the-burst"],
)
async def test_keys_after_the_palette_s_enter_land_in_the_step_it_went_to(
    quiet, search, in_one_burst
):
    """'Ctrl+P Task 5 Enter 5,3 Enter': Task 5 shown, '5,3' in its first entry (i_ss at
    2.5 V) and stored; R on Task 2 untouched; one lab screen, no palette left. The search's
    editing keys (Backspace, the arrows) act before Enter, in the order typed."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        if in_one_burst:
            await burst(pilot, "ctrl+p", *search, "enter", *"5,3", "enter")
        else:
            await pilot.press("ctrl+p")
            await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
            await pilot.press(*search)
            await settle(pilot, lambda: bool(app.screen.query_one(CommandList).option_count))
            await burst(pilot, "enter", *"5,3", "enter")
        await settle(pilot)
        assert isinstance(app.screen, LabScreen) and shown(app, "task5")
        assert [type(s) for s in app.screen_stack[1:]] == [LabScreen]
        assert _step(app) == "task5"
        assert stored_text(app, "i_ss@2.5") == "5,3"
        assert box_text(app, "i_ss@2.5") == "5,3"
        assert stored_text(app, "R") == ""


async def test_enter_runs_the_command_the_group_moved_to(quiet):
    """Down to the second command listed, then Enter and keys in one burst: that command
    runs (Enter runs the one highlighted, not always the best match), the keys land after it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await pilot.press("ctrl+p")
        await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
        await pilot.press(*"Task 1")
        listing = app.screen.query_one(CommandList)
        await settle(pilot, lambda: listing.option_count > 1)
        second = str(listing.get_option_at_index(1).prompt).split("\n")[0]
        await burst(pilot, "down", "enter")
        await settle(pilot)
        assert isinstance(app.screen, LabScreen)
        titles = {
            "Go to: Task 1: connect the MinSeg": "task1",
            "Go to: Task 10: the step experiment": "task10",
            "Go to: Task 11: the static gain K": "task11",
        }
        assert second in titles, second
        assert _step(app) == titles[second]
