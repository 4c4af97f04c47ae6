"""The status line: which device, its firmware, link health, lost and refused lines, motor."""

from __future__ import annotations

from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.ui.ports import DeviceInfo, LinkHealth


def status_text(info: DeviceInfo | None, health: LinkHealth | None, motor: str) -> str:
    """One line for the top of the screen (plain text; the widget adds no colour of meaning)."""
    if info is None:
        return "no device"
    who = "virtual MinSeg — no board found" if info.virtual and info.port == "auto" else (
        "virtual MinSeg" if info.virtual else f"board {info.name} on {info.port}")
    h = health or LinkHealth("ok")
    return (f"{who} · {info.firmware} · link {h.state} · lost {h.dropped}"
            f" · bad {h.corrupt} · motor {motor}")


class DeviceStatus(Static):
    """Always-visible device line; set ``info``, ``health`` and ``motor`` to update it."""

    info: reactive[DeviceInfo | None] = reactive(None)
    health: reactive[LinkHealth | None] = reactive(None)
    motor: reactive[str] = reactive("off")

    def render(self) -> str:
        return status_text(self.info, self.health, self.motor)
