"""The screens' common ground: the device status line on top, bound to the app's state."""

from __future__ import annotations

import asyncio

from textual.binding import Binding
from textual.reactive import reactive
from textual.screen import Screen
from textual.widget import Widget

from minseg_tui.ui.device import DeviceInfo, LinkState
from minseg_tui.ui.widgets.status import DeviceStatus


class StatusScreen(Screen[None]):
    """A screen that shows the app's ``device``, ``link`` and ``motor`` in its status line,
    and ``saving`` (why the session is not on disk) under it (the app binds these when it
    makes the screen); and the means for a key of a burst to wait for the keys before it.

    Tab and Shift+Tab are the screen's before any widget's (priority): the focus moves when
    the key arrives, once the keys typed before it are in their box, so the keys typed after
    it in the same burst go into the next box (as a widget's key, Tab reached the app only
    after those keys had been handed to the box it was leaving)."""

    BINDINGS = [
        Binding("tab", "app.focus_next", show=False, priority=True),
        Binding("shift+tab", "app.focus_previous", show=False, priority=True),
    ]

    device: reactive[DeviceInfo | None] = reactive(None)
    link: reactive[LinkState] = reactive(LinkState())
    motor: reactive[str] = reactive("off")
    saving: reactive[str] = reactive("")

    def status_line(self) -> DeviceStatus:
        """The status line, bound to this screen's device, link, motor and save state (call
        in compose)."""
        return DeviceStatus().data_bind(
            StatusScreen.device, StatusScreen.link, StatusScreen.motor, StatusScreen.saving
        )

    async def settle_typing(self) -> None:
        """Wait until the keys already handed to the focused widget (and to the screen) are
        in it: typed in the same burst as the key being handled, they belong before it.
        Call before a key acts on what was typed (PgDn, Enter, F-keys)."""
        here = asyncio.current_task()
        for target in (self.focused, self):
            if target is None or getattr(target, "_task", None) is here:
                continue  # called from that widget's own handler: its queue waits for us
            done = asyncio.Event()
            if target.call_later(done.set):
                await done.wait()

    async def settle_from(self, widget: Widget) -> None:
        """Wait until the messages ``widget`` has posted are handled up to this screen (each
        bubbles from a widget's queue to its parent's: draining them in that order sees it
        through)."""
        here = asyncio.current_task()
        for node in widget.ancestors_with_self:
            if getattr(node, "_task", None) is not here:
                done = asyncio.Event()
                if node.call_later(done.set):
                    await done.wait()
            if node is self:
                return
