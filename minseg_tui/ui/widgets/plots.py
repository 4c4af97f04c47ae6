"""Terminal plots of traces handed in as arrays (textual-plotext); the widget only draws."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from textual_plotext import PlotextPlot

Values = Sequence[float] | NDArray[np.float64]
"""The x or y values of a trace."""


@dataclass(frozen=True)
class Trace:
    """One line: x and y values and its legend label."""

    x: Values
    y: Values
    label: str = ""
    marker: str = "braille"


class TracePlot(PlotextPlot):
    """A plot with a title and axis labels; :meth:`show` replaces what it draws.

    Traces differ by marker as well as colour, so they stay apart under NO_COLOR."""

    def __init__(self, title: str, xlabel: str, ylabel: str, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self._title = title
        self._xlabel = xlabel
        self._ylabel = ylabel
        self.traces: tuple[Trace, ...] = ()

    def on_mount(self) -> None:
        super().on_mount()
        self._draw()

    def show(self, traces: Sequence[Trace]) -> None:
        """Draw ``traces`` (and nothing else) at the next refresh."""
        self.traces = tuple(traces)
        self._draw()
        self.refresh()

    def _draw(self) -> None:
        plt = self.plt
        plt.clear_data()
        plt.clear_figure()
        plt.title(self._title)
        plt.xlabel(self._xlabel)
        plt.ylabel(self._ylabel)
        for tr in self.traces:
            if len(tr.x):
                plt.plot(list(tr.x), list(tr.y), label=tr.label or None, marker=tr.marker)
