"""The command palette, closed once however many Enters it is handed."""

from __future__ import annotations

from textual import on
from textual.command import CommandPalette
from textual.widgets import Input, OptionList


class Palette(CommandPalette):
    """Textual's palette, which closes itself on each Enter it is handed (the box's Enter, or
    the pick of a command in its list): two Enters in one burst ('Ctrl+P task 6 Enter ...
    Enter') closed the lab screen under it too and left an empty terminal. An Enter that
    reaches it once it has closed is not for it."""

    @on(Input.Submitted)
    @on(OptionList.OptionSelected)
    def _late_enter(self, event: Input.Submitted | OptionList.OptionSelected) -> None:
        if not self.is_current:
            event.stop()
            event.prevent_default()  # the palette's own handlers (a base class's) are not run
