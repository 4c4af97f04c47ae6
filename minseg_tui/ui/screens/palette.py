"""The command palette, closed once however many Enters it is handed, and closed by Escape
before the keys typed after it are read."""

from __future__ import annotations

from typing import ClassVar

from textual import on
from textual.binding import Binding, BindingType
from textual.command import CommandPalette
from textual.widgets import Input, OptionList


class Palette(CommandPalette):
    """Textual's palette, which closes itself on each Enter it is handed (the box's Enter, or
    the pick of a command in its list): two Enters in one burst ('Ctrl+P task 6 Enter ...
    Enter') closed the lab screen under it too and left an empty terminal. An Enter that
    reaches it once it has closed is not for it.

    Escape is bound with priority, so the app runs it the moment it reads the key: the keys
    typed after it go to the screen under the palette. Bound as Textual's palette binds it,
    the app handed Escape to the palette's search box, which passed it back up to the app's
    queue behind the keys typed after it; those went into the search box, and closed with
    it ('Ctrl+P xyzzy Esc 5,3 Enter' in one burst left R empty: walk 8)."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("escape", "escape", "Exit the command palette", show=False, priority=True)
    ]

    @on(Input.Submitted)
    @on(OptionList.OptionSelected)
    def _late_enter(self, event: Input.Submitted | OptionList.OptionSelected) -> None:
        if not self.is_current:
            event.stop()
            event.prevent_default()  # the palette's own handlers (a base class's) are not run

    @on(Input.Submitted)
    async def _enter_on_what_was_typed(self, event: Input.Submitted) -> None:
        """Enter in the search box: wait until the search of the text typed before it is done,
        so that Textual's own handler (run after this one) picks the best match of that text.

        The search runs in a worker the box's every change starts anew; an Enter that came
        with the query in one burst ('Ctrl+P names Enter') reached the palette while the
        list still held the entries of an empty search, and ran the first of them:
        Preparation 1, or the board check, which drives the motor (walk 10, D1). The box's
        change of text reaches the palette before its Enter does (both pass up the same
        queues), so the search started last is the search of what was typed.

        Each search is waited for on its own: the box's changes read in one go ('s', 'su',
        ..., 'summary') start one each, each cancelling the one before, and a wait for all
        of them together ended as soon as the first cancelled one did, with the last one
        still running (the board check ran from Task 12 in tmux)."""
        from contextlib import suppress

        from textual.worker import WorkerCancelled

        searches = [w for w in self.app.workers if w.node is self and not w.is_finished]
        for search in searches:
            with suppress(WorkerCancelled):  # a later change, or Escape, cancelled it
                await search.wait()
        if not self.is_current:  # closed meanwhile: nothing to run
            event.stop()
            event.prevent_default()
