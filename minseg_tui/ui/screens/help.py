"""The help screen: every key of the app, from the bindings themselves."""

from __future__ import annotations

from rich.table import Table
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Static

from minseg_tui.ui.screens.dialog import close_dialog
from minseg_tui.ui.screens.lab import marks_legend

INTRO = (
    f"The left column lists the lab's steps in order ({marks_legend()}); "
    "the right shows the goal, what to do and what to type. Everything typed is saved at once."
)


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

    def __init__(self, keys: list[tuple[str, str]]) -> None:
        super().__init__()
        self._keys = keys

    def compose(self) -> ComposeResult:
        with VerticalScroll(id="help"):
            yield Static("Keys — Esc closes", classes="title")
            yield Static(INTRO, classes="para")
            yield KeyList(self._keys, id="help-keys")

    async def action_close(self) -> None:
        await close_dialog(self, None)
