"""The command palette: Enter runs the command picked for what was typed, then hands the
keys typed after it to the screen under the palette; closed once however many Enters it is
handed, and closed by Escape before the keys typed after it are read."""

from __future__ import annotations

import asyncio
from contextlib import suppress
from inspect import isawaitable
from typing import ClassVar

from textual import events, on
from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.command import Command, CommandInput, CommandList, CommandPalette
from textual.dom import DOMNode
from textual.widgets import Input, OptionList
from textual.worker import WorkerCancelled

from minseg_tui.ui.widgets.inturn import own_bindings


async def handled(node: DOMNode) -> None:
    """Return once ``node`` has handled every message queued on it now (its own queue: a
    callback queued behind them runs after them); at once when it is being removed."""
    done = asyncio.Event()
    if node.call_later(done.set):
        await done.wait()


_IN_TURN: frozenset[str] = frozenset(
    b.key
    for cls in (*CommandInput.__mro__, CommandPalette)
    for b in Binding.make_bindings(cls.__dict__.get("BINDINGS", []))
    if not b.priority
) - {"enter", "escape"}
"""The keys the search box and Textual's palette bind (editing keys, the arrows, Down to
the next command), bar Enter and Escape: :class:`SearchBox` runs their bindings in its own
key handler, in the order typed. Bound as Textual binds them, the box passed them up to the
app, which ran them behind the characters typed after them ('Tsk 5 Home Right a' in one
burst gave 'Tsk 5a') and behind Enter's command: Textual runs a widget's bindings only once
its key has bubbled up to the app's queue (textual/app.py:4341-4343), behind the keys read
meanwhile. Without it test_palette_enter's edited-in-the-burst and backspace-in-the-burst
cases and its test_enter_runs_the_command_the_group_moved_to (Down) fail."""


class SearchBox(CommandInput):
    """The palette's search box: Textual's own, which also runs the bindings of the keys it
    and the palette bind (:data:`_IN_TURN`) in its key handler, as it takes its characters
    in its own (textual/widgets/_input.py:743-754): each acts in the order typed, before the
    keys typed after it, in the box's one queue. :class:`Palette` composes it in place of
    Textual's."""

    async def on_key(self, event: events.Key) -> None:
        """``event.key``'s binding, as the app would run it: the first from the box up to
        the palette, then the app, whose action acts (the box's Down does not: it goes on to
        the palette's, the next command). A key none binds goes on as Textual sends it."""
        if event.key not in _IN_TURN:
            return
        palette = self.screen
        chain = [*_chain(self, palette), self.app]
        for above in chain:
            for binding in own_bindings(above, event.key):
                if await self.app.run_action(binding.action, above):
                    event.stop()
                    event.prevent_default()
                    return


def _chain(node: DOMNode, top: DOMNode) -> list[DOMNode]:
    """``node`` and its ancestors up to ``top``."""
    chain = []
    for above in node.ancestors_with_self:
        chain.append(above)
        if above is top:
            break
    return chain


class Palette(CommandPalette):
    """Textual's palette, which closes itself on each Enter it is handed (the box's Enter, or
    the pick of a command in its list): two Enters in one burst ('Ctrl+P task 6 Enter ...
    Enter') closed the lab screen under it too and left an empty terminal. An Enter that
    reaches it once it has closed is not for it.

    Escape and Enter are bound with priority, so the app runs them the moment it reads the
    key, before it reads the keys typed after them: those go to the screen under the
    palette. Bound as Textual's palette binds them, the app handed the key to the palette's
    search box, which passed it back up to the app's queue behind the keys typed after it;
    those went into the search box, and closed with it ('Ctrl+P xyzzy Esc 5,3 Enter' in one
    burst left R empty: walk 8). Enter also ran whatever the list showed when it came, the
    hits of an earlier part of the search ('Ctrl+P Task 5 Enter 5,3 Enter' in one burst went
    to Preparation 1, the first command listed for an empty search): it now waits for the
    search of everything typed before it (:meth:`action_run`). Its search box is our
    :class:`SearchBox`, which runs its editing keys in the order typed."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("escape", "escape", "Exit the command palette", show=False, priority=True),
        Binding("enter", "run", "Run the command", show=False, priority=True),
    ]

    ROUNDS: ClassVar[int] = 12
    """Most rounds :meth:`_searched` waits for the box's keys to settle (a burst's keys
    settle in three: typed, their change of the text passed up, its search done)."""

    async def _searched(self) -> None:
        """Wait until the list shows the hits of everything typed before now: the box has
        handled the keys typed before (characters and its editing keys it takes itself,
        :class:`SearchBox`), its changes of text have reached the palette, which starts a search
        for each (a worker of the palette's; each cancels the one before), and the search of
        the last is done. Round by round along the box and its ancestors up to the palette
        until a round finds no search running and the box and the list as they were."""
        box = self.query_one(CommandInput)
        listing = self.query_one(CommandList)
        chain = _chain(box, self)
        before: tuple[object, ...] | None = None
        for _ in range(self.ROUNDS):
            for node in chain:
                await handled(node)
            searches = [w for w in self.app.workers if w.node is self and not w.is_finished]
            if searches:
                with suppress(WorkerCancelled):
                    await self.app.workers.wait_for_complete(searches)
            now = (box.value, listing.option_count, listing.highlighted)
            if not searches and now == before:
                return
            before = now

    def compose(self) -> ComposeResult:
        """Textual's palette, with :class:`SearchBox` in place of its search box (as
        placeholder and selection on focus)."""
        for widget in super().compose():
            if type(widget) is CommandInput:
                yield SearchBox(
                    placeholder=widget.placeholder, select_on_focus=widget.select_on_focus
                )
            else:
                yield widget

    def _picked(self) -> Command | None:
        """The command Enter runs: the one highlighted in the list (the best match of the
        search unless the group moved to another), or the first there is; None: none."""
        listing = self.query_one(CommandList)
        index = listing.highlighted if listing.highlighted is not None else 0
        if not 0 <= index < listing.option_count:
            return None
        option = listing.get_option_at_index(index)
        return option if isinstance(option, Command) and not option.disabled else None

    async def action_run(self) -> None:
        """Enter: the command picked for everything typed before it, run once the palette has
        closed; the app reads the keys typed after Enter only when this returns, so they go
        where the command leaves the group (the first entry of the step it went to)."""
        if not self.is_current:
            return
        await self._searched()
        picked = self._picked()
        if picked is None or not self.is_current:
            return  # nothing to run: the palette stays, as Textual's does
        self.app.post_message(CommandPalette.Closed(option_selected=True))
        await self.dismiss()
        ran = picked.hit.command()
        if isawaitable(ran):
            await ran
        await handled(self.app.screen)  # what the command asked of the screen (a step shown)

    @on(Input.Submitted)
    def _submitted(self, event: Input.Submitted) -> None:
        """The box's Enter, posted to the palette by other than a key (a key's Enter is the
        priority binding's, :meth:`action_run`): run as that Enter runs, on the app's queue
        (a screen cannot wait for its own dismissal in its own handler), never by Textual's
        own handler, which runs whatever the list shows when it comes: 'summary' posted
        change by change and then its Enter ran the board check from Task 12 (walk 10, D1)."""
        event.stop()
        event.prevent_default()  # the palette's own handler (a base class's) is not run
        if self.is_current:
            self.app.call_next(self.action_run)

    @on(OptionList.OptionSelected)
    def _late_pick(self, event: OptionList.OptionSelected) -> None:
        """A pick that reaches the palette once it has closed is not for it."""
        if not self.is_current:
            event.stop()
            event.prevent_default()  # the palette's own handlers (a base class's) are not run
