"""Terminal plots of traces handed in as arrays (textual-plotext); the widget only draws.

The legend is a line under the plot, never on the data: plotext puts its legend in the
plot's top-left corner, where a step response or a live stream has its points.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from textual.app import ComposeResult
from textual.containers import Vertical
from textual.content import Content
from textual.widgets import Static
from textual_plotext import PlotextPlot

Values = Sequence[float] | NDArray[np.float64]
"""The x or y values of a trace."""

GLYPHS: dict[str, str] = {"braille": "⠶⠶", "dot": "••", "+": "++", "-": "--", "|": "|"}
"""How the legend shows each marker (what the trace looks like on the plot)."""

COLOURS: tuple[tuple[str, str], ...] = (
    ("cyan+", "ansi_bright_cyan"),
    ("orange+", "ansi_bright_yellow"),
    ("red+", "ansi_bright_red"),
    ("green+", "ansi_bright_green"),
    ("magenta+", "ansi_bright_magenta"),
)
"""The traces' colours in order, as plotext and as the legend name them (the same terminal
colours); the markers tell the traces apart without them."""


@dataclass(frozen=True)
class Trace:
    """One line: x and y values, its legend label and its marker (braille, dot, +, -, |);
    ``colour``: an index into :data:`COLOURS` (None: the trace's own place in the plot), so
    two lines of one thing (a band's edges) share a colour and one legend entry; ``steps``:
    each value holds until the next x (a voltage the board applies from one sample to the
    next), drawn as a staircase, not as a line sloping between the samples."""

    x: Values
    y: Values
    label: str = ""
    marker: str = "braille"
    colour: int | None = None
    steps: bool = False


def drawn(tr: Trace) -> tuple[list[float], list[float]]:
    """The points plotext joins for ``tr`` (a staircase for a trace of ``steps``, as the
    report's figures draw it)."""
    x, y = list(tr.x), list(tr.y)
    if tr.steps and len(x) > 1:
        x = [a for a in x for _ in (0, 1)][1:]
        y = [b for b in y for _ in (0, 1)][:-1]
    return x, y


def _colour(k: int, tr: Trace) -> tuple[str, str]:
    return COLOURS[(k if tr.colour is None else tr.colour) % len(COLOURS)]


def legend(traces: Sequence[Trace]) -> Content:
    """The legend line: each labelled trace's marker, in its colour, and label."""
    parts: list[str | tuple[str, str]] = []
    for k, tr in enumerate(traces):
        if not tr.label:
            continue
        if parts:
            parts.append("  ")
        parts += [(GLYPHS.get(tr.marker, tr.marker * 2), _colour(k, tr)[1]), " "]
        parts.append(tr.label)
    return Content.assemble(*parts)


class Canvas(PlotextPlot):
    """The plot itself (no legend)."""

    def __init__(self, title: str, xlabel: str, ylabel: str) -> None:
        super().__init__(classes="canvas")
        self._title = title
        self._xlabel = xlabel
        self._ylabel = ylabel
        self.traces: tuple[Trace, ...] = ()
        self.xlim: tuple[float, float] | None = None

    def on_mount(self) -> None:
        super().on_mount()
        self.draw()

    @property
    def plot_title(self) -> str:
        """The title drawn above the plot."""
        return self._title

    def set_axes(self, title: str, xlabel: str) -> None:
        self._title = title
        self._xlabel = xlabel

    def draw(self) -> None:
        plt = self.plt
        plt.clear_data()
        plt.clear_figure()
        plt.title(self._title)
        plt.xlabel(self._xlabel)
        plt.ylabel(self._ylabel)
        for k, tr in enumerate(self.traces):
            if len(tr.x):
                plt.plot(*drawn(tr), marker=tr.marker, color=_colour(k, tr)[0])
        if self.xlim is not None:
            plt.xlim(*self.xlim)
        self.refresh()


class TracePlot(Vertical):
    """A plot with a title and axis labels, and its legend on a line below it; :meth:`show`
    replaces what it draws.

    Traces differ by marker as well as colour, so they stay apart under NO_COLOR."""

    DEFAULT_CSS = """
    TracePlot { width: 1fr; height: 1fr; }
    TracePlot > .canvas { height: 1fr; }
    TracePlot > .legend { height: auto; color: $text-muted; padding: 0 0 0 1; }
    """

    def __init__(self, title: str, xlabel: str, ylabel: str, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self._canvas = Canvas(title, xlabel, ylabel)
        self._legend = Static("", classes="legend")

    def compose(self) -> ComposeResult:
        yield self._canvas
        yield self._legend

    @property
    def traces(self) -> tuple[Trace, ...]:
        """What the plot draws now."""
        return self._canvas.traces

    @property
    def legend(self) -> str:
        """The legend line as shown (plain text)."""
        return str(self._legend.render())

    def set_axes(self, title: str, xlabel: str) -> None:
        """Change the title and the x axis' label (drawn with the next :meth:`show`)."""
        self._canvas.set_axes(title, xlabel)

    def show(self, traces: Sequence[Trace], xlim: tuple[float, float] | None = None) -> None:
        """Draw ``traces`` (and nothing else) at the next refresh, over ``xlim`` (s) if given."""
        self._canvas.traces = tuple(traces)
        self._canvas.xlim = xlim
        self._legend.update(legend(traces))
        if self._canvas.is_mounted:
            self._canvas.draw()
