"""The help screen: every key of the app, from the bindings themselves."""

from __future__ import annotations

from rich.table import Table
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Static

from minseg_tui.lab.content.keys import KEY_NAMES
from minseg_tui.ui.keys import QUIT_SAVED
from minseg_tui.ui.screens.dialog import close_dialog
from minseg_tui.ui.screens.lab import marks_legend

INTRO = (
    f"The left column lists the lab's steps in order ({marks_legend()}); "
    "the right shows the goal, what to do and what to type. Everything typed is saved at once."
)
"""What the lab screen shows (F1 there): said only there, where that column is."""

START_NOW = (
    "Now: type the group's names and press Enter to start the lab; or Tab to the saved "
    f"sessions and Enter on one to resume it. {KEY_NAMES['class_view']} opens the class view "
    "(instructors)."
)
"""F1 on the start screen: what to do there (walk 17's D7: it said "The left column lists
the lab's steps", and there is none there)."""

CLASS_NOW = (
    "Now: the class view, one row a group: the arrows pick a group, Enter opens its session "
    f"read-only, {KEY_NAMES['export']} writes the class's report, Escape goes back."
)
"""F1 on the class view: what to do there."""


def lab_now(title: str) -> str:
    """F1 on a step of the lab: the step, and where its "What to do" is."""
    return (
        f"Now: {title}. What to do stands at the top of the step ({KEY_NAMES['whole_todo']}: "
        "all of it); type into the entries under it, Enter stores each. The footer shows "
        "the keys of this step; PgDn goes on to the next one."
    )


QUIT = "quit"
"""Ctrl+Q's line in F1 outside the lab (no session open there to be saved)."""


KEY_WIDTH = 10
"""The keys' column of F1's list (its widest key, 'Ctrl+← →' and the like, fits)."""


def key_table(keys: list[tuple[str, str]]) -> Table:
    """F1's list in two columns: a description too long for its line wraps under itself,
    never under the keys (walk 11, D7: 'log (check)' stood under 'F9')."""
    table = Table.grid(padding=(0, 1))
    table.add_column(width=KEY_WIDTH, no_wrap=True)
    table.add_column(ratio=1)
    for key, what in keys:
        table.add_row(key, what)
    return table


class KeyList(Static):
    """F1's list of keys, drawn as :func:`key_table`; ``text``: the same as plain text, one
    key a line."""

    def __init__(self, keys: list[tuple[str, str]], id: str | None = None) -> None:
        super().__init__(key_table(keys), id=id)
        self.text = "\n".join(f"{k:<{KEY_WIDTH}} {d}" for k, d in keys)


class HelpScreen(ModalScreen[None]):
    """Lists the keys; Escape, F1 or q closes it, before the app reads the next key
    (:func:`~minseg_tui.ui.screens.dialog.close_dialog`)."""

    BINDINGS = [Binding("escape,f1,q", "close", "Close", priority=True)]

    def __init__(self, keys: list[tuple[str, str]], now: str = "", lab: bool = True) -> None:
        """``now``: what to do on the screen F1 was pressed on (first); ``lab``: that screen
        is a step of the lab (the steps' column and the saved session exist there)."""
        super().__init__()
        self._now = now
        self._lab = lab
        self._keys = keys if lab else [(k, QUIT if d == QUIT_SAVED else d) for k, d in keys]

    def compose(self) -> ComposeResult:
        with VerticalScroll(id="help"):
            yield Static("Keys — Esc closes", classes="title")
            if self._now:
                yield Static(self._now, classes="para", id="help-now")
            if self._lab:
                yield Static(INTRO, classes="para")
            yield KeyList(self._keys, id="help-keys")

    async def action_close(self) -> None:
        await close_dialog(self, None)
