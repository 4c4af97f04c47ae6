"""The multimeter line: the virtual MinSeg's readings, or where to read the one on the bench."""

from __future__ import annotations

from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.lab.content.meter import DISPLAYS, shown, text
from minseg_tui.model.plant import MeterReading
from minseg_tui.ui.device import DeviceInfo

MODES: dict[str, str] = {unit: d.mode for unit, d in DISPLAYS.items()}
"""The multimeter's setting for an entry of each unit (:data:`~minseg_tui.lab.content.meter.DISPLAYS`)."""


class MeterPanel(Static):
    """Shows ``reading`` (u_A V, i A, R ohm) when the ``device`` is the virtual MinSeg, only
    the quantity ``unit`` ("Ω", "V", "mA": the step's entries) when given, as a meter set to
    it does (Task 4 shows no current: its step keeps the jumper in); on a real board, says to
    read the one on the bench."""

    reading: reactive[MeterReading | None] = reactive(None, layout=True)
    device: reactive[DeviceInfo | None] = reactive(None, layout=True)

    def __init__(self, unit: str = "") -> None:
        super().__init__("", classes="meter")
        self.unit = unit if unit in MODES else ""

    def render(self) -> str:
        if self.device is None or not self.device.virtual:
            return "multimeter: read the one on the bench (M1A-M1B)"
        m = self.reading
        head = "multimeter (virtual, M1A-M1B" + (f", {MODES[self.unit]}" if self.unit else "")
        if m is None:
            return f"{head}): reading…"
        if self.unit:
            return f"{head}) · {text(self.unit, shown(self.unit, m))}"
        return f"{head}): " + " · ".join(text(u, shown(u, m)) for u in ("V", "mA", "Ω"))
