"""A tick typed on a list of answers right before PgDn or PgUp lands in the step being left.

Issue 20's second walk: Space then PgDn in one burst on a "done?" choice, or on a summary
question, showed the next step, and going back showed the answer unticked. The list acted
on Space through its own binding, which Textual runs only once the key has bubbled up to
the app: after PgDn's priority binding had already moved to the next step. Each test ticks
an answer and moves in one burst, comes back, and checks that the tick is stored and shown,
and that the move came after it."""

from __future__ import annotations

import pytest

from minseg_tui.ui.widgets.fields import AnswerList, FieldRow, field_id
from tests.ui.helpers import answering, burst, goto, settle, shown, start


def _chosen(app, key: str) -> str:
    with app.session as s:
        entry = s.entry(key)
    return entry.typed if entry is not None else ""


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


async def _focus_answers(pilot, key: str) -> None:
    row = _row(pilot.app, key)
    row.focus_input()
    await settle(pilot, lambda: answering(pilot.app) is row.answers)


def _ticked_on_screen(row: FieldRow) -> tuple[int, ...]:
    """The answers the row shows ticked, 0-based."""
    return row.query_one(AnswerList).chosen


@pytest.mark.parametrize(
    ("there", "key", "keys", "move", "back", "chosen", "ticked"),
    [
        # a done? choice (one answer), moving on and coming back
        ("prep1", "prep1.done", ("space",), "pagedown", "pageup", "a", (0,)),
        ("prep2", "prep2.done", ("space",), "pageup", "pagedown", "a", (0,)),
        # a summary question of one answer, the second answer ticked (an arrow first)
        ("summary", "summary.1", ("down", "space"), "pageup", "pagedown", "b", (1,)),
        # the summary question of several answers: two ticked
        (
            "summary",
            "summary.5",
            ("down", "space", "down", "space"),
            "pageup",
            "pagedown",
            "b, c",
            (1, 2),
        ),
    ],
)
async def test_a_tick_typed_right_before_a_move_is_kept(
    quiet, there, key, keys, move, back, chosen, ticked
):
    app = quiet()
    moved_with: list[str] = []
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, there)
        await _focus_answers(pilot, key)
        screen = app.screen
        move_step = screen._move

        async def move_and_note(delta: int) -> None:
            moved_with.append(_chosen(app, key))
            await move_step(delta)

        screen._move = move_and_note
        await burst(pilot, *keys, move)
        assert not shown(app, there)
        assert moved_with == [chosen]  # the tick was stored before the step moved
        assert _chosen(app, key) == chosen
        await burst(pilot, back)
        assert shown(app, there)
        assert _ticked_on_screen(_row(app, key)) == ticked


async def test_a_click_on_an_answer_picks_it_and_the_keys_go_to_its_list(quiet):
    """A click on an answer picks it (a list of one: the other cleared) or ticks it (a list of
    several), stores it at once, and makes that list the one the keys go to."""
    app = quiet()
    async with app.run_test(size=(120, 40)) as pilot:
        await start(pilot)
        await goto(pilot, "summary")
        row = _row(app, "summary.2")
        answers = row.query_one(AnswerList)
        # the list's border is one row over its first answer, its padding one column
        await pilot.click(answers, offset=(4, 2))
        await settle(pilot, lambda: answering(app) is answers)
        assert _chosen(app, "summary.2") == "b" and _ticked_on_screen(row) == (1,)
        await pilot.click(answers, offset=(4, 1))
        await settle(pilot)
        assert _chosen(app, "summary.2") == "a" and _ticked_on_screen(row) == (0,)
        await burst(pilot, "down", "space")  # the cursor stood on the answer clicked
        assert _chosen(app, "summary.2") == "b" and _ticked_on_screen(row) == (1,)
