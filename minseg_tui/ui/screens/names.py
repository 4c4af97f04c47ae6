"""The palette's "Correct the group's names": a misspelt name typed at the start mended."""

from __future__ import annotations

from collections.abc import Callable

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import Input

from minseg_tui.lab.content.keys import PALETTE
from minseg_tui.ui.screens.dialog import close_dialog
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox


class NamesScreen(ModalScreen[None]):
    """Asks for the group's names, the ones in use filled in, and hands them to ``rename``
    (it returns the one line to show; a line starting with '✗' keeps the dialog open).
    Escape closes without a change, before the app reads the next key."""

    BINDINGS = [Binding("escape", "close", "Close", priority=True)]
    AUTO_FOCUS = "#names"

    def __init__(self, names: str, rename: Callable[[str], str]) -> None:
        super().__init__()
        self._names = names
        self._rename = rename

    def compose(self) -> ComposeResult:
        with Vertical(id="ask", classes="dialog"):
            yield Prose(PALETTE["correct_names"], classes="title")
            yield Prose(
                "Mend the names, commas between them, and press Enter (Esc: no change). The "
                "report, the resume list and the class view then show them; the session keeps "
                "the names it had before.",
                classes="para",
            )
            yield TextBox(value=self._names, id="names")
            yield Prose("", id="renamed")

    @on(Input.Submitted, "#names")
    def _submitted(self, event: Input.Submitted) -> None:
        event.stop()
        if not self.is_current:  # closed by an Enter before this one
            return
        said = self._rename(event.value)
        if said.startswith("✗"):
            self.query_one("#renamed", Prose).update(said)
            return
        self.app.notify(said, title="session", timeout=8)
        self.dismiss(None)

    async def action_close(self) -> None:
        await close_dialog(self, None)
