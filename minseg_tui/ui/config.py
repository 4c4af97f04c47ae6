"""How the app is started: which device, where sessions live, and test switches."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class UiConfig:
    """Start-up settings shared by the CLI and the tests.

    device: ``"auto"`` (board if found, else the virtual MinSeg), ``"sim"`` or a port name /
    pyserial URL; sessions: folder of the sessions; today: the date put into a new session
    (ISO, None for the real date); animations: False turns Textual's animations off;
    refresh: plot redraw period in s (0: drawn once, when shown); seed: the virtual
    MinSeg's seed.
    """

    device: str = "auto"
    sessions: Path = Path("sessions")
    today: str | None = None
    animations: bool = True
    refresh: float = 0.25
    seed: int = 0
