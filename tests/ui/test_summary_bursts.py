"""Walk 6, defects 1 and 2: the Summary step's questions answered with quick keys at 80x24.

1. Keys typed in a burst after an Enter that picked an answer were lost or acted on the
   question left: 'Enter Tab Enter Tab' answered Q3 and left Q4 blank; 'Down Enter Down Enter
   Tab Enter Tab' ticked one answer of Q5 and left Q6 blank; 'Enter Tab Down Enter' on Q1
   showed two answers of Q1 marked (a model and a system) and Q2 stayed blank, and Q1 was
   stuck until the step was left. Every key must act in order, where it would have acted had
   the app been infinitely fast, and a question of one answer shows one dot.
2. Unticking every box of Q5 showed no box ticked while the old answer stayed stored, with
   a message in the lab's internal letters ("expected one or more of a/b/c; got '' (still
   using 'b')"). What is shown must be what is stored, said in the answers' own words.

Each burst is handed over as a terminal hands over keys typed quickly (all queued on the app
at once, :func:`~tests.ui.helpers.burst`)."""

from __future__ import annotations

from minseg_tui.lab.content.steps import step
from minseg_tui.ui.widgets.fields import AnswerList, FieldRow, field_id
from tests.ui.helpers import (
    answering,
    burst,
    goto,
    settle,
    shown,
    start,
    stored_text,
    typing_box,
)

ONE_ANSWER = ("summary.1", "summary.2", "summary.3", "summary.4", "summary.6")


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _shown_ticked(row: FieldRow) -> tuple[int, ...]:
    """The answers the row shows ticked (0-based): X in a list to tick, ● in a list of one."""
    answers = row.query_one(AnswerList)
    if answers.multiple:
        return answers.chosen
    lines = answers.render().plain.splitlines()
    dots = tuple(k for k, line in enumerate(lines) if "●" in line)
    values = answers.chosen
    assert dots == values, (dots, values)
    return values


def _letters(indices: tuple[int, ...]) -> str:
    return ", ".join(chr(ord("a") + k) for k in indices)


def _check(app, expected: dict[str, tuple[int, ...]]) -> None:
    """Each question stores and shows ``expected`` (0-based answers; () unanswered), and a
    question of one answer shows at most one dot."""
    for key, want in expected.items():
        row = _row(app, key)
        assert stored_text(app, key) == _letters(want), key
        assert _shown_ticked(row) == want, key
    for key in ONE_ANSWER:
        assert len(_shown_ticked(_row(app, key))) <= 1, key


async def _on_summary(pilot) -> None:
    await start(pilot)
    await goto(pilot, "summary")
    row = _row(pilot.app, "summary.1")
    await settle(pilot, lambda: answering(pilot.app) is row.answers)


async def test_the_walks_bursts_on_the_summary_answer_every_question(quiet):
    """The walk's keys, burst by burst: Q1 'a system', Q2 'a model', Q3 and Q4 their first
    answer, Q5 'the input amplitude' and 'the static gain', Q6 its first; then typing goes
    into the box of what is still unclear."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_summary(pilot)
        await burst(pilot, "down", "enter")
        _check(app, {"summary.1": (1,)})
        await burst(pilot, "tab", "enter", "tab")
        _check(app, {"summary.1": (1,), "summary.2": (0,)})
        await burst(pilot, "enter", "tab", "enter", "tab")
        _check(app, {"summary.1": (1,), "summary.2": (0,), "summary.3": (0,), "summary.4": (0,)})
        await burst(pilot, "down", "enter", "down", "enter", "tab", "enter", "tab")
        _check(
            app,
            {
                "summary.1": (1,),
                "summary.2": (0,),
                "summary.3": (0,),
                "summary.4": (0,),
                "summary.5": (1, 2),
                "summary.6": (0,),
            },
        )
        assert typing_box(app) is _row(app, "summary.unclear").input
        await burst(pilot, *"T and K")
        assert _row(app, "summary.unclear").input.value == "T and K"
        assert shown(app, "summary")


async def _enter_tab_down_enter_then_q1_again(pilot, app) -> None:
    """'Enter Tab Down Enter' in one burst from Q1 (cursor on 'a model'): Q1 'a model', Q2
    'a system'; then back on Q1 a slow Down and Enter moves its one dot to 'a system'."""
    await burst(pilot, "enter", "tab", "down", "enter")
    _check(app, {"summary.1": (0,), "summary.2": (1,), "summary.3": ()})
    await burst(pilot, "shift+tab")
    await burst(pilot, "down")
    await burst(pilot, "enter")
    _check(app, {"summary.1": (1,), "summary.2": (1,)})


async def test_enter_tab_down_enter_answers_two_questions_with_one_dot_each(quiet):
    """'Enter Tab Down Enter' on Q1: Q1 'a model', Q2 'a system'. Then Q1 is not stuck: a
    slow Down and Enter (Shift+Tab back to it) picks 'a system' there, one dot."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_summary(pilot)
        await _enter_tab_down_enter_then_q1_again(pilot, app)


async def test_a_burst_on_a_question_already_answered_moves_its_one_dot(quiet):
    """As in the walk: Q1 answered 'a system', the step left and shown again (its list's
    cursor back on 'a model'), then 'Enter Tab Down Enter': Q1 'a model' alone, Q2 'a
    system'; a slow Down and Enter back on Q1 then moves its dot to 'a system' (it was
    stuck: the box of 'a system' looked marked, so Enter did nothing)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_summary(pilot)
        await burst(pilot, "down")
        await burst(pilot, "enter")
        _check(app, {"summary.1": (1,)})
        await burst(pilot, "pageup")
        await burst(pilot, "pagedown")
        assert shown(app, "summary")
        await settle(pilot, lambda: answering(app) is _row(app, "summary.2").answers)
        await burst(pilot, "shift+tab")  # back on Q1, its cursor on 'a model'
        await settle(pilot, lambda: answering(app) is _row(app, "summary.1").answers)
        await _enter_tab_down_enter_then_q1_again(pilot, app)


async def test_unticking_every_box_shows_what_is_stored_in_the_answers_words(quiet):
    """Q5 ticked 'the input amplitude', then unticked: the box shows what the lab holds,
    and the message names answers by their words, never by the lab's letters."""
    app = quiet()
    options = next(f for f in step("summary").fields if f.key == "summary.5").options
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_summary(pilot)
        await burst(pilot, "tab", "tab", "tab", "tab")
        row = _row(app, "summary.5")
        await settle(pilot, lambda: answering(app) is row.answers)
        await burst(pilot, "down")
        await burst(pilot, "enter")
        _check(app, {"summary.5": (1,)})
        await burst(pilot, "space")  # the only ticked box unticked (Enter never unticks)
        stored = stored_text(app, "summary.5")
        shown_now = _shown_ticked(row)
        assert stored == _letters(shown_now)
        with app.session as s:
            entry = s.entry("summary.5")
        held = entry.value if entry is not None and entry.ok else ()
        assert tuple(held or ()) == shown_now
        message = row.message
        assert "a/b/c" not in message and "'b'" not in message and "''" not in message
        assert "expected" not in message
        for k in shown_now:
            assert options[k] in message
        # then ticking two others works as shown
        await burst(pilot, "down", "enter")
        _check(app, {"summary.5": tuple(sorted({*shown_now, 2}))})


async def test_picks_in_one_burst_on_one_question_leave_one_dot(quiet):
    """Q1 answered 'a system', its cursor back on 'a model' (the step shown again), then
    'Enter Down Enter' in one burst: 'a model' picked, then 'a system' again; one dot, on
    'a system'. Textual's RadioSet clears the answer picked before only when it reads the
    button's message: the second Enter turned 'a system' off, Textual turned it on again
    next to 'a model', two dots (walk 6)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_summary(pilot)
        await burst(pilot, "down")
        await burst(pilot, "enter")
        await burst(pilot, "pageup")
        await burst(pilot, "pagedown")
        await settle(pilot, lambda: answering(app) is _row(app, "summary.2").answers)
        await burst(pilot, "shift+tab")
        await settle(pilot, lambda: answering(app) is _row(app, "summary.1").answers)
        await burst(pilot, "enter", "down", "enter")
        _check(app, {"summary.1": (1,), "summary.2": ()})
        await burst(pilot, "up", "enter", "down", "enter", "up", "enter")
        _check(app, {"summary.1": (0,), "summary.2": ()})
