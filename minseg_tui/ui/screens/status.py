"""The screens' common ground: the device status line on top, bound to the app's state."""

from __future__ import annotations

from textual.reactive import reactive
from textual.screen import Screen

from minseg_tui.ui.device import DeviceInfo, LinkState
from minseg_tui.ui.widgets.status import DeviceStatus


class StatusScreen(Screen[None]):
    """A screen that shows the app's ``device``, ``link`` and ``motor`` in its status line,
    and ``saving`` (why the session is not on disk) under it (the app binds these when it
    makes the screen)."""

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
