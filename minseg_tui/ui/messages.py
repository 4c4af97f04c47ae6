"""Messages workers post to the app: small, and coalesced where they come in floods."""

from __future__ import annotations

from textual.message import Message

from minseg_tui.ui.ports import Device, Event, LinkHealth


class SamplesArrived(Message):
    """New samples are in the live buffer (the buffer holds them; this only says "redraw soon").

    One pending message replaces another, so a fast stream never floods the queue.
    """

    def __init__(self, health: LinkHealth, total: int) -> None:
        super().__init__()
        self.health = health
        self.total = total

    def can_replace(self, message: Message) -> bool:
        return isinstance(message, SamplesArrived)


class LinkEvent(Message):
    """Something the board said or the link did (see :class:`~minseg_tui.ui.ports.Event`)."""

    def __init__(self, event: Event) -> None:
        super().__init__()
        self.event = event


class DeviceOpened(Message):
    """The device worker finished: the device, or None with the one-line ``error``."""

    def __init__(self, device: Device | None, error: str) -> None:
        super().__init__()
        self.device = device
        self.error = error
