"""The help screen: every key of the app, from the bindings themselves."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Static

INTRO = (
    "minseg-tui guides a group through the DC-motor lab. The left column lists the "
    "manual's parts in order; the right shows what the step is for, what to do and what "
    "to type. Everything typed is saved at once. Ctrl+P opens the command palette."
)


class HelpScreen(ModalScreen[None]):
    """Lists the keys; Escape, F1 or q closes it."""

    BINDINGS = [Binding("escape,f1,q", "dismiss", "Close")]

    def __init__(self, keys: list[tuple[str, str]]) -> None:
        super().__init__()
        self._keys = keys

    def compose(self) -> ComposeResult:
        lines = [f"  {k:<12} {d}" for k, d in self._keys]
        with VerticalScroll(id="help"):
            yield Static("Keys", classes="title")
            yield Static(INTRO, classes="para")
            yield Static("\n".join(lines), id="help-keys")
            yield Static("Esc closes this help.", classes="hint")
