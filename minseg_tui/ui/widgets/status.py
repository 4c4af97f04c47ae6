"""The status line: which device, its firmware, link health, lost and refused lines, motor."""

from __future__ import annotations

from textual.content import Content
from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.lab.content.keys import in_palette
from minseg_tui.ui.device import DeviceInfo, LinkState


def status_text(info: DeviceInfo | None, link: LinkState, motor: str, width: int = 80) -> str:
    """One line for the top of the screen, at most ``width`` characters (plain text: the
    state is in words, never in colour alone). A link event replaces the health counters;
    what does not fit goes, least important first (firmware, the port, then words of the name)."""
    if info is None:
        return f"{link.event or 'no device'} · motor {motor}"[:width]
    if info.virtual:
        who = "VIRTUAL MinSeg (no board found)" if info.fallback else "VIRTUAL MinSeg"
        short = "VIRTUAL (no board)" if info.fallback else "VIRTUAL"
        port = ""
    else:
        who = short = f"board {info.name}"
        port = info.port
    said = link.event or f"link {link.state} · lost {link.dropped} · bad {link.corrupt}"
    tail = f"motor {motor}"
    for parts in (
        (who, port, info.firmware, said, tail),
        (who, port, said, tail),
        (who, said, tail),
        (short, said, tail),
    ):
        text = " · ".join(p for p in parts if p)
        if len(text) <= width:
            return text
    return f"{who} · {said}"[: width - len(tail) - 3] + " · " + tail


class DeviceStatus(Static):
    """Always-visible device line: shows ``device``, ``link`` and ``motor`` (bound to the
    app's state by the screen); below it, while the session cannot be saved, ``saving``
    (what is wrong and where it will save)."""

    device: reactive[DeviceInfo | None] = reactive(None)
    link: reactive[LinkState] = reactive(LinkState())
    motor: reactive[str] = reactive("off")
    saving: reactive[str] = reactive("", layout=True)

    def render(self) -> Content:
        """The line (and the save problem), as plain text: a port's or a folder's name with
        brackets in it is shown as it is, never read as markup."""
        width = self.size.width or 78
        line = status_text(self.device, self.link, self.motor, width)
        if self.saving:
            return Content(f"{line}\n! {self.saving} ({in_palette('save_elsewhere')})")
        return Content(line)
