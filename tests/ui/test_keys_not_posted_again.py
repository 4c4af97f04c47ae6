"""No key is posted a second time (issue 19, item 1): a key handed to a widget that no longer
has the focus (the step's form after Shift+Tab to the list of steps, the list after a
character moved the focus into an entry, the form under a palette that a key ahead of it
opened: now the palette opens before the app reads the keys after Ctrl+P) reaches the
widget focused now through Textual's own ways: it goes on up to the app, which runs that
widget's binding, or, a character or a key for the step's form, by a plain call. Before,
such a key was posted again as a new Key event (three places in ui/). Each test records
every Key event the app's widgets handle (``message_hook``) and asks that they are the very
events the burst sent, and that the keys did what the same keys typed one at a time do."""

from __future__ import annotations

from textual import events
from textual.command import CommandPalette
from textual.message import Message
from textual.widgets import Input

from minseg_tui.ui.screens.lab import LabScreen
from tests.ui.helpers import burst, goto, settle, shown, start, stored_text


class Keys:
    """The Key events the app's widgets handle while :attr:`on` is set, each kept (so that
    no two are ever the same object by chance)."""

    def __init__(self) -> None:
        self.on = False
        self.seen: list[events.Key] = []

    def hook(self, message: Message) -> None:
        if self.on and isinstance(message, events.Key):
            self.seen.append(message)

    def distinct(self) -> int:
        return len({id(k) for k in self.seen})


async def test_enter_after_characters_typed_on_the_list_is_not_posted_again(quiet):
    """Walk 8's D6 burst ('53' Enter with the focus on the list of steps): the list's '5'
    moves the focus into R; the Enter it was handed after it went to the form as a new event.
    Now the list hands it to the form by a plain call: three keys, three events."""
    keys = Keys()
    app = quiet()
    async with app.run_test(size=(80, 24), message_hook=keys.hook) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await burst(pilot, *"5,3", "enter")
        await burst(pilot, "shift+tab")
        await settle(pilot)
        keys.on = True
        await burst(pilot, "5", "3", "enter")
        await settle(pilot)
        assert stored_text(app, "R") == "53"
        assert keys.distinct() == 3


async def test_keys_after_shift_tab_out_of_the_step_are_not_posted_again(quiet):
    """Shift+Tab from the first entry to the list of steps, then ↓ and Enter, in one burst:
    the form was handed all three; ↓ and Enter, for the list now, went to it as new events.
    They now go on up to the app, which runs the list's bindings: the step after Task 2
    is shown, as with the keys typed one at a time."""
    keys = Keys()
    app = quiet()
    async with app.run_test(size=(80, 24), message_hook=keys.hook) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        keys.on = True
        await burst(pilot, "shift+tab", "down", "enter")
        await settle(pilot, lambda: shown(app, "task3"))
        assert keys.distinct() == 3


async def test_keys_after_ctrl_p_go_into_the_palette_without_being_posted_again(quiet):
    """'Ctrl+P task 6' in one burst: the characters the form was handed before the palette
    opened went to its search box as new events. Ctrl+P is now a priority binding whose
    action waits for the keys ahead of it and opens the palette before the app reads the keys
    after it, so they go to its search box as the app reads them, once each."""
    keys = Keys()
    app = quiet()
    async with app.run_test(size=(80, 24), message_hook=keys.hook) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        keys.on = True
        sent = ["ctrl+p", *"task 66", "backspace"]
        await burst(pilot, *sent)
        await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
        assert app.screen.query_one(Input).value == "task 6"
        assert keys.distinct() == len(sent)
        await pilot.press("escape")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
