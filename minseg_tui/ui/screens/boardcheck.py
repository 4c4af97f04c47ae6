"""The board check on screen: the question it may ask (did the wheel turn?), its answer, and
the hand check (turn the wheel once, then Enter)."""

from __future__ import annotations

import threading
from collections.abc import Callable

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import OptionList
from textual.widgets.option_list import Option

from minseg_tui.lab.content.keys import PALETTE, key_name
from minseg_tui.ui.screens.dialog import (
    answer_bindings,
    close_dialog,
    close_with_highlighted,
    move_highlight,
)
from minseg_tui.ui.widgets.prose import Prose

TURN_ANSWERS: tuple[tuple[str, str], ...] = (
    ("yes", "It turned"),
    ("no", "It did not turn"),
    ("unsure", "I did not see"),
)
"""The answers to "did the wheel turn?": (answer, words)."""


class WheelQuestionScreen(ModalScreen[str]):
    """Asks whether the wheel turned while the board check drove it; dismissed with ``yes``,
    ``no`` or ``unsure`` (Escape). Enter and Escape close it before the app reads the next
    key (:mod:`~minseg_tui.ui.screens.dialog`)."""

    BINDINGS = [
        Binding("escape", "unsure", "I did not see", priority=True),
        Binding("enter", "answer", show=False, priority=True),
        *answer_bindings(),
    ]
    AUTO_FOCUS = "#answers"

    def compose(self) -> ComposeResult:
        with Vertical(id="ask", classes="dialog"):
            yield Prose(f"{PALETTE['board_check']}: no counts", classes="title")
            yield Prose(
                "The board drove the motor for half a second and the encoder counted "
                "nothing. Did the wheel turn?",
                classes="para",
            )
            yield OptionList(*[Option(text, id=key) for key, text in TURN_ANSWERS], id="answers")

    @on(OptionList.OptionSelected, "#answers")
    def _answer(self, event: OptionList.OptionSelected) -> None:
        if self.is_current:  # not an answer handed on after the first one closed it
            self.dismiss(event.option.id or "unsure")

    def action_move(self, action: str) -> None:
        move_highlight(self.query_one("#answers", OptionList), action)

    async def action_answer(self) -> None:
        await close_with_highlighted(self, self.query_one("#answers", OptionList), "unsure")

    async def action_unsure(self) -> None:
        await close_dialog(self, "unsure")


class BoardCheckScreen(ModalScreen[None]):
    """What the board check found (``ok`` or not, and its ``text``); Enter or Escape closes
    it, before the app reads the next key (:func:`~minseg_tui.ui.screens.dialog.close_dialog`)."""

    BINDINGS = [
        Binding("escape", "close", "Close", priority=True),
        Binding("enter", "close", "Close", priority=True),
    ]

    def __init__(
        self,
        ok: bool,
        text: str,
        what: str = PALETTE["board_check"],
        again: str = f"{key_name('board_check')} checks again",
    ) -> None:
        super().__init__()
        self.ok = ok
        self.text = text
        self.what = what
        self.again = again
        """How to make the check once more (the hand check is not F10's)."""

    def compose(self) -> ComposeResult:
        title = f"{self.what}: " + ("all well" if self.ok else "something is wrong")
        with Vertical(id="board-check", classes="dialog"):
            yield Prose(title, classes="title")
            yield Prose(self.text, id="check-text", classes="para")
            yield Prose(f"Enter or Escape closes; {self.again}.", classes="para")

    async def action_close(self) -> None:
        await close_dialog(self, None)


REVOLUTION = "Counts per revolution"
"""The hand check's title: on its question and on its answer."""


class RevolutionScreen(ModalScreen[None]):
    """The hand check: turn the wheel once by hand, then Enter (sets ``done``); Escape sets
    ``cancelled`` and ``done`` and closes. On the virtual MinSeg, whose wheel nobody can
    turn, ``turn`` is its simulated hand: Enter has it turn the wheel once, a little over
    or under, then counts."""

    BINDINGS = [
        Binding("enter", "turned", "Turned once"),
        Binding("escape", "cancel", "Cancel", priority=True),
    ]

    def __init__(
        self,
        done: threading.Event,
        cancelled: threading.Event,
        turn: Callable[[], object] | None = None,
    ) -> None:
        super().__init__()
        self.done = done
        self.cancelled = cancelled
        self.turn = turn

    def compose(self) -> ComposeResult:
        with Vertical(id="revolution", classes="dialog"):
            yield Prose(REVOLUTION, classes="title")
            yield Prose(
                "Mark the wheel (a piece of tape), turn it exactly once by hand, either way, "
                "then press Enter. The motor is off. 720 counts are expected."
                if self.turn is None
                else "The virtual MinSeg has no wheel to turn by hand: press Enter and a "
                "simulated hand turns it once, a little over or under, as a hand does. On the "
                "real board you turn it yourself. 720 counts are expected.",
                id="revolution-text",
                classes="para",
            )

    def action_turned(self) -> None:
        if self.done.is_set():
            return
        if self.turn is not None:
            self.turn()
        self.query_one("#revolution-text", Prose).update("Counting the last samples…")
        self.done.set()

    async def action_cancel(self) -> None:
        self.cancelled.set()
        self.done.set()
        await close_dialog(self, None)
