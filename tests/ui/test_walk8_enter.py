"""Walk 8, D6: on Task 2, '5,3' Enter, then Shift+Tab (the focus leaves R for the list of
steps), Ctrl+U, '53', Enter: the '53' went into R (a character typed on the list lands in
the entry) but the Enter was lost once, and R stayed '5,3' with its old verdict.

The window: Shift+Tab handled, the focus on the list; then '53' Enter arrive in one read.
The app hands all three keys to the list, the focused widget, before the list has handled
the '5' that moves the focus into R; the list took the Enter as its own. Each group of keys
below is one burst, the app settled after each."""

from __future__ import annotations

import pytest

from tests.ui.helpers import burst, goto, settle, start, stored_text


@pytest.mark.parametrize(
    "bursts",
    [
        (("shift+tab",), ("ctrl+u", "5", "3", "enter")),  # walk 8's: lost before the fix
        (("shift+tab",), ("ctrl+u",), ("5", "3", "enter")),  # lost before the fix
        (("shift+tab",), ("5", "3", "enter")),  # lost before the fix
        (("shift+tab", "ctrl+u", "5", "3", "enter"),),
        (("shift+tab",), ("ctrl+u",), ("5",), ("3",), ("enter",)),
    ],
    ids=["st|^u53E", "st|^u|53E", "st|53E", "st^u53E", "one key each"],
)
async def test_enter_after_keys_redirected_into_the_entry_stores_them(quiet, bursts):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await burst(pilot, *"5,3", "enter")
        assert stored_text(app, "R") == "5,3"
        for keys in bursts:
            await burst(pilot, *keys)
            await settle(pilot)
        assert stored_text(app, "R") == "53"
