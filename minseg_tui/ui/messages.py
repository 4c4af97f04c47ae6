"""Messages workers post to the screens: small, and coalesced where they come in floods."""

from __future__ import annotations

from textual.message import Message

from minseg_tui.ui.ports import LinkHealth


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
    """Something the board said or the link did: ``kind`` such as STEP, STEPDONE, WDOG, LOST."""

    def __init__(self, kind: str, detail: str = "") -> None:
        super().__init__()
        self.kind = kind
        self.detail = detail
