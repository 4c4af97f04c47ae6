"""The screens' common ground: the device status line on top, bound to the app's state."""

from __future__ import annotations

from textual import events
from textual.message import Message
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

    _shown_once = False
    """The screen has been shown (its first ScreenResume posted)."""

    def post_message(self, message: Message) -> bool:
        """As Textual's, except that the screen's first ScreenResume (it is shown for the first
        time) does not restyle the whole screen: each widget was styled as it was mounted,
        and a change of focus or of classes since restyled what it changed
        (tests/ui/test_restyles.py checks that such a restyle changes nothing). It was some
        16 % of the Python calls of a start from the app to the lab's first step."""
        if isinstance(message, events.ScreenResume) and not self._shown_once:
            self._shown_once = True
            message = events.ScreenResume(refresh_styles=False)
        return super().post_message(message)

    def status_line(self) -> DeviceStatus:
        """The status line, bound to this screen's device, link, motor and save state (call
        in compose)."""
        return DeviceStatus().data_bind(
            StatusScreen.device, StatusScreen.link, StatusScreen.motor, StatusScreen.saving
        )
