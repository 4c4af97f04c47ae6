"""The multimeter line: the virtual MinSeg's readings, or where to read the one on the bench."""

from __future__ import annotations

from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.model.plant import MeterReading
from minseg_tui.quantities import format_fixed
from minseg_tui.ui.device import DeviceInfo


class MeterPanel(Static):
    """Shows ``reading`` (u_A V, i A, R ohm) when the ``device`` is the virtual MinSeg; on a
    real board, says to read the one on the bench."""

    reading: reactive[MeterReading | None] = reactive(None, layout=True)
    device: reactive[DeviceInfo | None] = reactive(None, layout=True)

    def __init__(self) -> None:
        super().__init__("", classes="meter")

    def render(self) -> str:
        if self.device is None or not self.device.virtual:
            return "multimeter: read the one on the bench (M1A-M1B)"
        m = self.reading
        if m is None:
            return "multimeter (virtual, M1A-M1B): reading…"
        shown = (
            format_fixed(m.u_A, 2, "V"),
            format_fixed(m.i * 1000, 1, "mA"),
            format_fixed(m.R, 1, "Ω"),
        )
        return "multimeter (virtual, M1A-M1B): " + " · ".join(shown)
