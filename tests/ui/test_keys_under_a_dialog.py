"""Walk 11's D2, the "stored empty" form (issue 20, /work/coord/WALK11.md, WALK12.md): on
Task 5 a reading typed with its Enter after F3 vanished; the entry was stored empty (once),
or kept its old refused text (once), and the reading was nowhere in the session.

The leads, each driven here at the point where it would act, never by timing:

- a screen over the lab (the board check's result, the wheel question, F1's list) that comes while the keys typed before it are still on their way to the step's
  form, in its queue: the form handled them with the screen on top and dropped them
  (``FieldForm.on_key`` returned early), and the Enter typed after them, once the screen had
  gone, stored what the entry held: nothing, or the old refused text. Both of walk 11's forms.
  Keys in the form's queue were read by the app while the lab had them (a key read once the
  screen is up goes to the screen), so they were typed for the entry: they go into it.
- the same with the screen gone again before the form handles them (it went as the keys
  came): they go into the entry (this held before).
- characters the list of steps hands over to the form (:meth:`FieldForm.take`) while a screen
  is on top: they land (this held before).
- the text read before the keys reached the box: characters still in the list of steps'
  queue when the focus moved into the step, and the Enter typed after them: stored whole
  (this held before, in the event loop's order; not proven for a list whose queue is held
  up longer than the form's).
"""

from __future__ import annotations

import pytest
from textual import events
from textual.screen import Screen
from textual.widget import Widget

from minseg_tui.ui.app import LabApp
from minseg_tui.ui.keys import help_lines
from minseg_tui.ui.screens.boardcheck import BoardCheckScreen, WheelQuestionScreen
from minseg_tui.ui.screens.help import HelpScreen
from minseg_tui.ui.screens.lab import LabScreen
from tests.ui.helpers import (
    box_text,
    burst,
    goto,
    lab_screen,
    on_the_list,
    settle,
    start,
    stored_text,
)
from tests.ui.textual_internals import key_name

SCREENS = {
    "board-check-result": lambda: BoardCheckScreen(True, "The wheel turns and the count follows."),
    "wheel-question": WheelQuestionScreen,
    "help": lambda: HelpScreen(help_lines()),
}


def _queued(app: LabApp, widget: Widget, keys: str) -> None:
    """``keys`` in ``widget``'s queue, as the app hands each key it reads to the widget focused
    then (``Widget._forward_event``: marked forwarded, posted), not handled yet."""
    for key in keys:
        event = events.Key(key_name(key), key)
        event.set_sender(app)
        widget._forward_event(event)


async def _task5_on_the_4_5_v_row(pilot, before: str) -> None:
    """Task 5, the motor at 4.5 V (F3 three times), the keys on the 4.5 V row, which holds
    nothing or the refused '0.0371' (ambiguous between A and mA), as in walk 11."""
    app = pilot.app
    await start(pilot)
    await goto(pilot, "task5")
    await burst(pilot, "f3", "f3", "tab", "f3")
    assert app.requested == 4.5
    row = lab_screen(app).pane.typing
    assert row is not None and row.field.key == "i_ss@4.5"
    if before == "refused":
        await burst(pilot, *"0.0371", "enter")
        assert stored_text(app, "i_ss@4.5") == "0.0371"
        assert lab_screen(app).pane.typing is row  # refused: the keys stay there
        await burst(pilot, "f3", "f3", "f3")  # walk 11: F3 three times, back at 4.5 V
        assert app.requested == 4.5 and lab_screen(app).pane.typing is row


async def _gone(pilot, screen: Screen[object]) -> None:
    """``screen`` closed (as its Escape closes it), the lab on top again."""
    app = pilot.app
    await settle(pilot, lambda: screen.is_mounted)
    screen.dismiss(None)
    await settle(pilot, lambda: isinstance(app.screen, LabScreen))


@pytest.mark.parametrize("before", ["empty", "refused"])
@pytest.mark.parametrize("dialog", list(SCREENS))
async def test_a_reading_on_its_way_when_a_dialog_comes_lands_in_the_entry(quiet, dialog, before):
    """'0.0372 A' read by the app with the keys on the 4.5 V row and handed to the form; a
    dialog comes before the form handles them (a board check's result arriving from its
    worker, say); it closes; Enter. The reading is in the entry and stored. Before: the
    keys were dropped with the dialog on top, and the Enter stored the entry as it stood
    (nothing, or the old refused '0.0371')."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _task5_on_the_4_5_v_row(pilot, before)
        pane = lab_screen(app).pane
        _queued(app, pane, "0.0372 A")
        screen = SCREENS[dialog]()
        app.push_screen(screen)  # before the form's queue is handled: no await between
        await settle(pilot, lambda: app.screen is screen)
        await _gone(pilot, screen)
        await burst(pilot, "enter")
        assert stored_text(app, "i_ss@4.5") == "0.0372 A"
        assert box_text(app, "i_ss@4.5") == "0.0372 A"


async def test_a_reading_on_its_way_as_a_dialog_goes_lands_in_the_entry(quiet):
    """The dialog goes while the keys are in the form's queue (they were read once it had
    gone): they land in the entry, and Enter stores them."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _task5_on_the_4_5_v_row(pilot, "empty")
        screen = BoardCheckScreen(True, "The wheel turns and the count follows.")
        app.push_screen(screen)
        await settle(pilot, lambda: screen.is_mounted)
        screen.dismiss(None)
        _queued(app, lab_screen(app).pane, "0.0372 A")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
        await burst(pilot, "enter")
        assert stored_text(app, "i_ss@4.5") == "0.0372 A"


async def test_characters_typed_on_the_list_of_steps_under_a_dialog_land_in_the_entry(quiet):
    """Task 2 with the group on the list of steps (Ctrl+L): '5,3' read there (the step's
    form has the keys while the group browses the list: they wait in its queue), a dialog
    comes before the form has handled them; it closes; Enter stores '5,3'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await burst(pilot, "ctrl+l")
        assert on_the_list(app)
        _queued(app, lab_screen(app).pane, "5,3")
        screen = SCREENS["help"]()
        app.push_screen(screen)
        await settle(pilot, lambda: app.screen is screen)
        await _gone(pilot, screen)
        assert box_text(app, "R") == "5,3"
        await burst(pilot, "enter")
        assert stored_text(app, "R") == "5,3"


async def test_enter_after_characters_still_on_the_list_when_the_focus_moved_stores_them(quiet):
    """The third lead, the text read before the keys reached the box: '5,3' read on the list
    of steps (in the form's queue: it has the keys while the group browses), the step's
    entry made current before the form handled them (as F3 or a landing makes it), then
    Enter: the characters are handled first, in the order read: '5,3' is stored."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await burst(pilot, "ctrl+l")
        lab = lab_screen(app)
        assert on_the_list(app)
        row = lab.pane.typing_row()
        assert row is not None and row.field.key == "R"
        _queued(app, lab.pane, "5,3")
        lab.pane.focus_row(row)  # no await between: the characters are still in the list's queue
        await burst(pilot, "enter")
        assert stored_text(app, "R") == "5,3"
