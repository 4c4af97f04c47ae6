"""The multimeter line: the virtual MinSeg's readings, or where to read the one on the bench."""

from __future__ import annotations

from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.model.plant import MeterReading
from minseg_tui.quantities import format_fixed
from minseg_tui.ui.device import DeviceInfo

MODES: dict[str, str] = {"Ω": "on Ω", "V": "on V=", "mA": "on mA, jumper out"}
"""The multimeter's setting for an entry of each unit (Tasks 2, 4 and 5, as their steps say):
a meter shows the one quantity it is set to measure, the current only where the jumper is out."""


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
        shown = {
            "V": format_fixed(m.u_A, 2, "V"),
            "mA": format_fixed(m.i * 1000, 1, "mA"),
            "Ω": format_fixed(m.R, 1, "Ω"),
        }
        if self.unit:
            return f"{head}) · {shown[self.unit]}"
        return f"{head}): " + " · ".join(shown.values())
