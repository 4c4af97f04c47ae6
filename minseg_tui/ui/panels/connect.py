"""Task 1: who the program talks to, and how to change it."""

from __future__ import annotations

from textual.content import Content
from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.lab.content.keys import in_palette, key_name
from minseg_tui.ui.device import DeviceInfo


class ConnectPanel(Static):
    """Says which ``device`` the app is connected to (None: none yet)."""

    device: reactive[DeviceInfo | None] = reactive(None, layout=True)

    def __init__(self) -> None:
        super().__init__("", classes="panel")

    def render(self) -> Content:
        """Plain text: a file's or a port's name with brackets in it is shown as it is."""
        return Content(self._text())

    def _text(self) -> str:
        d = self.device
        if d is None:
            return f"No device yet. {in_palette('switch_to_virtual')} to practise."
        check = f"\n{key_name('board_check')}: board check (does the wheel turn when asked, and the count follow?)."
        if d.virtual:
            return (
                f"Connected to the VIRTUAL MinSeg ({d.firmware})"
                + (": no board was found." if d.fallback else ".")
                + " Plug a board in and restart with --port, or keep practising."
                + check
            )
        return f"Connected to {d.name} on {d.port}, firmware {d.firmware}." + check
