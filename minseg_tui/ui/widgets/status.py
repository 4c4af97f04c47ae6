"""The status line: which device, its firmware, link health, lost and refused lines, motor."""

from __future__ import annotations

from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.ui.ports import DeviceInfo, LinkHealth


def status_text(
    info: DeviceInfo | None, health: LinkHealth | None, motor: str, event: str = "", width: int = 80
) -> str:
    """One line for the top of the screen, at most ``width`` characters (plain text: the
    state is in words, never in colour alone). A link event replaces the health counters;
    what does not fit goes, least important first (firmware, the port, then words of the name)."""
    if info is None:
        return f"{event or 'no device'} · motor {motor}"[:width]
    if info.virtual:
        who = "VIRTUAL MinSeg (no board found)" if info.fallback else "VIRTUAL MinSeg"
        short = "VIRTUAL (no board)" if info.fallback else "VIRTUAL"
        port = ""
    else:
        who = short = f"board {info.name}"
        port = info.port
    h = health or LinkHealth("ok")
    link = event or f"link {h.state} · lost {h.dropped} · bad {h.corrupt}"
    tail = f"motor {motor}"
    for parts in (
        (who, port, info.firmware, link, tail),
        (who, port, link, tail),
        (who, link, tail),
        (short, link, tail),
    ):
        text = " · ".join(p for p in parts if p)
        if len(text) <= width:
            return text
    return f"{who} · {link}"[: width - len(tail) - 3] + " · " + tail


class DeviceStatus(Static):
    """Always-visible device line; set ``info``, ``health``, ``motor`` and ``event``."""

    info: reactive[DeviceInfo | None] = reactive(None)
    health: reactive[LinkHealth | None] = reactive(None)
    motor: reactive[str] = reactive("off")
    event: reactive[str] = reactive("")

    def render(self) -> str:
        width = self.size.width or 78
        return status_text(self.info, self.health, self.motor, self.event, width)
