"""What a second walk of the lab in tmux found (after issue 9 was merged): keys typed faster
than the focus moves, the u_A of the zoomed rise drawn as the board applies it, titles and
answers that fit 80 columns."""

from __future__ import annotations

from textual import events

from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, settle, start


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _stored(app, key: str):
    with app.session as s:
        return s.entry(key)


async def test_keys_typed_faster_than_the_focus_moves_all_land_in_the_entry(quiet):
    """On the list of steps, a burst of keys (a quick typist, a busy app, tmux send-keys)
    arrives before the entry has taken the focus: every key lands, none replaces the one
    before it (it stored " 2.6" for "read 2.1 and 2.6")."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2", focus=None)
        app.screen.query_one("#nav").focus()
        await settle(pilot)
        for c in "5,3 ohm":
            app.post_message(events.Key(c if c != " " else "space", c))  # one burst
        await settle(pilot)
        assert _row(app, "R").input.value == "5,3 ohm"
        await pilot.press("enter")
        await settle(pilot)
        assert _stored(app, "R").text == "5,3 ohm"
