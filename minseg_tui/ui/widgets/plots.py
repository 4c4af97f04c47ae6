"""Terminal plots of traces handed in as arrays (textual-plotext); the widget only draws.

The legend is a line under the plot, never on the data: plotext puts its legend in the
plot's top-left corner, where a step response or a live stream has its points.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from collections.abc import Hashable, Sequence
from dataclasses import dataclass
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray
from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Vertical
from textual.content import Content
from textual.css.styles import RulesMap
from textual.geometry import Size
from textual.widgets import Static
from textual_plotext import PlotextPlot

from minseg_tui.quantities import axis_unit, format_ticks

Values = Sequence[float] | NDArray[np.float64]
"""The x or y values of a trace."""

GLYPHS: dict[str, str] = {
    "braille": "⠶⠶",
    "dot": "••",
    "+": "++",
    "-": "--",
    "|": "|",
    "┆": "┆",
    "level": "⠒⠒",
}
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
    next), drawn as a staircase, not as a line sloping between the samples; ``right``: on
    the plot's right axis, its own scale, labelled with the trace's label (one such trace
    a plot; a voltage beside a speed), its highest value on the row the other lines cover
    least (:func:`free_row`), so that a level line or the speed does not hide it."""

    x: Values
    y: Values
    label: str = ""
    marker: str = "braille"
    colour: int | None = None
    steps: bool = False
    right: bool = False
    short: str = ""
    """The label in a legend too narrow for the full ones ('': the label)."""


def drawn(tr: Trace) -> tuple[list[float], list[float]]:
    """The points plotext joins for ``tr`` (a staircase for a trace of ``steps``, as the
    report's figures draw it)."""
    x, y = list(tr.x), list(tr.y)
    if tr.steps and len(x) > 1:
        x = [a for a in x for _ in (0, 1)][1:]
        y = [b for b in y for _ in (0, 1)][:-1]
    return x, y


GUIDES = frozenset({"-", "|", "┆", "level"})
"""Markers of lines that guide the eye (a level, a time, a noise band): drawn under the data."""

LEVEL = "level"
"""The marker of a level drawn one braille dot high at its own height (:func:`draw_levels`),
not a text row: a dashed 63 % line filled a whole row (1.5 rad/s at 80x24), so the speed
'met' it 4 columns (10 ms) before it reached the level (walk 18, D3)."""

BRAILLE_BASE = 0x2800
"""The empty braille cell; its dots are bits of the code point."""

DOT_ROW_BITS = (0x01 | 0x08, 0x02 | 0x10, 0x04 | 0x20, 0x40 | 0x80)
"""The bits of both dots of each of a braille cell's four dot rows, from the top."""


def level_dot_row(value: float, lo: float, hi: float, rows: int) -> tuple[int, int] | None:
    """The (text row from the top, dot row from the top within it) where plotext puts a
    braille point of ``value`` on a y axis ``lo``..``hi`` of ``rows`` text rows (plotext:
    dot row floor(0.5 + (4 rows - 1) (value - lo) / (hi - lo)) from the bottom); None off
    the plot."""
    if not hi > lo or rows < 1 or not math.isfinite(value):
        return None
    dot = math.floor(round(0.5 + (4 * rows - 1) * (value - lo) / (hi - lo), 8))
    if not 0 <= dot < 4 * rows:
        return None
    return rows - 1 - dot // 4, 3 - dot % 4


def draw_levels(text: Text, levels: Sequence[tuple[float, str]], ylim: tuple[float, float]) -> None:
    """Draw each level (value, colour) of ``levels`` into the plot ``text`` plotext built, in
    place: one row of braille dots at the value's own height across the data area, in the
    level's colour, in the empty cells only: a cell a line passes through stays that line's,
    so a curve crossing the level is seen whole, rising to the level's height where it
    meets it (merged into the level's cells, the speed's dots a row under the level read as
    touching it 3 columns early; a braille trace drawn by plotext over the curve hid it)."""
    plain = text.plain
    lines = plain.split("\n")
    top = next((k for k, ln in enumerate(lines) if "┌" in ln and "┐" in ln), None)
    bottom = next((k for k, ln in enumerate(lines) if "└" in ln and "┘" in ln), None)
    if top is None or bottom is None or bottom - top < 2:
        return
    first, last = lines[top].index("┌") + 1, lines[top].rindex("┐") - 1
    starts = [0]
    for ln in lines[:-1]:
        starts.append(starts[-1] + len(ln) + 1)
    chars = list(plain)
    paint: list[tuple[int, str]] = []
    for value, colour in levels:
        at = level_dot_row(value, ylim[0], ylim[1], bottom - top - 1)
        if at is None:
            continue
        row, dots = top + 1 + at[0], DOT_ROW_BITS[at[1]]
        for col in range(first, last + 1):
            k = starts[row] + col
            ch = chars[k]
            if ch == " ":
                chars[k] = chr(BRAILLE_BASE | dots)
                paint.append((k, colour))
    text.plain = "".join(chars)
    for k, colour in paint:
        text.stylize(colour, k, k + 1)


MOST_TICKS = 4
"""Most intervals between the labelled ticks of an axis (so at most five labels)."""

ROUND = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0)
"""Round steps, times a power of ten, between the rows of a plot."""


def ticks(lo: float, hi: float, most: int = MOST_TICKS) -> tuple[float, float, list[float]]:
    """The limits of an axis over the values ``lo``..``hi`` and its ticks: round numbers (1,
    2, 2.5 or 5 times a power of ten) inside the limits, at most ``most`` intervals apart
    (for the x axis, whose columns are fine enough to put a tick where its value is). A
    flat range gets a unit either side."""
    if not hi > lo:
        lo, hi = lo - 1.0, hi + 1.0
    raw = (hi - lo) / most
    power = 10.0 ** math.floor(math.log10(raw))
    step = next(m * power for m in (1, 2, 2.5, 5, 10) if m * power >= raw * (1 - 1e-9))
    first = math.ceil(lo / step - 1e-9)
    last = math.floor(hi / step + 1e-9)
    return lo, hi, [_round(k * step) for k in range(first, last + 1)]


def row_ticks(
    lo: float, hi: float, rows: int, most: int = MOST_TICKS
) -> tuple[float, float, list[float]]:
    """The limits of a y axis of ``rows`` rows over the values ``lo``..``hi``, chosen so that
    every row stands for a round value (a round step from row to row, 0 on a row when it is
    in range), and the ticks: some of those rows, at most ``most`` intervals apart, 0 among
    them when it is in range. A label is then exactly the value of its row; plotext's own
    labels are the limits split evenly and rounded, so a wheel standing still drew its zero
    line on the row labelled 0.33 and a residual's zero row read '-0.00'. A flat range gets a
    unit either side."""
    if not hi > lo:
        lo, hi = lo - 1.0, hi + 1.0
    gaps = max(rows - 1, 1)
    raw = (hi - lo) / gaps
    power = 10.0 ** math.floor(math.log10(raw))
    for step in (m * p for p in (power, power * 10) for m in ROUND):
        bottom = math.floor(lo / step + 1e-9)
        if (bottom + gaps) * step >= hi * (1 - 1e-9) - 1e-12:
            break
    every = math.ceil(gaps / most)
    zero = (-bottom) % every  # label the rows whose index is congruent to 0's row
    at = [_round((bottom + k) * step) for k in range(gaps + 1) if k % every == zero]
    return _round(bottom * step), _round((bottom + gaps) * step), at


def _round(value: float) -> float:
    """A multiple of a round step without the float noise of the product (0.30000000000000004
    is 0.3), never -0."""
    return round(value, 10) + 0.0


POINTS_PER_COLUMN = 4
"""Most points a trace hands plotext per terminal column (a braille cell is two dots wide):
plotext joins every pair of points, and the 2419 samples of a 5 ms run took it about 0.1 s
a plot on every redraw."""


def thin(x: Sequence[float], y: Sequence[float], most: int) -> tuple[list[float], list[float]]:
    """At most about ``most`` of the points (x, y), in order, that draw the same picture at
    the plot's resolution: the first and the last, and in each of ``most // 2`` runs of
    consecutive points its lowest and its highest (so no peak, spike or step is lost)."""
    n = len(x)
    if n <= most:
        return list(x), list(y)
    ys = np.asarray(y, dtype=float)
    keep = {0, n - 1}
    edges = np.linspace(0, n, max(most // 2, 1) + 1).astype(int)
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        seg = ys[a:b]
        if seg.size and not np.isnan(seg).all():
            keep.update((a + int(np.nanargmin(seg)), a + int(np.nanargmax(seg))))
    at = sorted(keep)
    return [x[k] for k in at], [y[k] for k in at]


def _layer(tr: Trace) -> int:
    """Where a trace is drawn, bottom up: 0 the input's staircase, 1 a guide, 2 the data."""
    return 0 if tr.steps else 1 if tr.marker in GUIDES else 2


def drawing_order(traces: Sequence[Trace]) -> list[int]:
    """The indices of ``traces`` in the order plotext draws them (each over the ones before):
    the input's staircase, the guides, then the data, each kind in list order."""
    return sorted(range(len(traces)), key=lambda k: _layer(traces[k]))


def _colour(k: int, tr: Trace) -> tuple[str, str]:
    return COLOURS[(k if tr.colour is None else tr.colour) % len(COLOURS)]


def legend(traces: Sequence[Trace], width: int | None = None) -> Content:
    """The legend line: each labelled trace's marker, in its colour, and label (a trace on
    the right axis says so). Within ``width`` columns if it can be (None: no limit): else
    tighter (one marker glyph, one space between entries), then with the traces' short
    labels. Wrapped, its second line fell under the screen's edge beside another plot's
    first, and the two read as one legend (the model check at 80x24)."""
    forms = ((False, 2, "  "), (False, 1, " "), (True, 1, " "))
    line = Content("")
    for short, glyphs, gap in forms:
        parts: list[str | tuple[str, str]] = []
        for k, tr in enumerate(traces):
            if not tr.label:
                continue
            if parts:
                parts.append(gap)
            glyph = GLYPHS.get(tr.marker, tr.marker * 2)
            parts += [(glyph[:glyphs], _colour(k, tr)[1]), " "]
            label = (tr.short or tr.label) if short else tr.label
            parts.append(label + (", right axis" if tr.right else ""))
        line = Content.assemble(*parts)
        if width is None or line.cell_length <= width:
            break
    return line


def _cells(
    x: Sequence[float],
    y: Sequence[float],
    braille: bool,
    box: tuple[float, float, float, float],
    cols: int,
    rows: int,
) -> set[tuple[int, int]]:
    """The (column, row) cells a line through the points (x, y) covers in a plot of ``cols``
    by ``rows`` cells spanning ``box`` = (x lo, x hi, y lo, y hi); row 0 at the bottom. A
    braille line has four dots a cell in height (plotext puts a value on its dot row)."""
    x_lo, x_hi, y_lo, y_hi = box
    sub = 4 if braille else 1

    def at(px: float, py: float) -> tuple[int, int]:
        c = round((px - x_lo) / (x_hi - x_lo) * (cols - 1))
        r = (
            round((py - y_lo) / (y_hi - y_lo) * (rows * sub - 1)) // sub
            if braille
            else round((py - y_lo) / (y_hi - y_lo) * (rows - 1))
        )
        return c, r

    pts = [at(a, b) for a, b in zip(x, y, strict=True) if math.isfinite(a) and math.isfinite(b)]
    cells = set(pts[:1])
    for (c0, r0), (c1, r1) in zip(pts, pts[1:], strict=False):
        n = max(abs(c1 - c0), abs(r1 - r0), 1)
        cells.update(
            (c0 + round((c1 - c0) * j / n), r0 + round((r1 - r0) * j / n)) for j in range(n + 1)
        )
    return cells


def free_row(covered: set[tuple[int, int]], columns: set[int], rows: int) -> int:
    """The row, in the upper half of ``rows`` rows (row 0 at the bottom), that the cells
    ``covered`` by other lines leave freest over ``columns``; the highest of equals."""
    candidates = range(rows - 1, max((rows - 1) // 2, 1) - 1, -1)
    return min(candidates, key=lambda r: sum((c, r) in covered for c in columns))


BUILDS_KEPT = 32
"""How many plots built by plotext are kept (:class:`Canvas`)."""

_built: OrderedDict[Hashable, Text] = OrderedDict()
"""Plots built by plotext, by what they draw (the newest last): a plot drawn again as it
was (the same step's view on a return to it, Tasks 11 and 12 zoomed on the same rise, a
redraw of the screen around it) is not built again (10-40 ms each)."""


def _signature(traces: Sequence[Trace]) -> tuple[object, ...]:
    """What ``traces`` draw, hashable (their values as bytes)."""
    return tuple(
        (
            np.asarray(tr.x, dtype=float).tobytes(),
            np.asarray(tr.y, dtype=float).tobytes(),
            tr.label,
            tr.marker,
            tr.colour,
            tr.steps,
            tr.right,
        )
        for tr in traces
    )


class Canvas(PlotextPlot):
    """The plot itself (no legend). The text plotext builds is kept by what it draws
    (:data:`_built`)."""

    def __init__(self, title: str, xlabel: str, ylabel: str) -> None:
        super().__init__(classes="canvas")
        self._title = title
        self._xlabel = xlabel
        self._ylabel = ylabel
        self.traces: tuple[Trace, ...] = ()
        self.xlim: tuple[float, float] | None = None
        self._drawn: Hashable = None
        """What :meth:`draw` last handed plotext (the key of its build in :data:`_built`)."""
        self._levels: list[tuple[float, str]] = []
        """The levels (value, colour) of the traces of marker :data:`LEVEL`, drawn over
        plotext's build (:func:`draw_levels`)."""
        self._ylim: tuple[float, float] | None = None
        """The y axis' limits handed plotext last (None: not laid out)."""

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

    def _ylabel_fitting(self) -> str:
        """The y label, or its unit alone ("omega [rad/s]" -> "rad/s") where plotext's line
        of labels cannot hold it left of the x label, which it centres: on the model check's
        narrow close-up, "omega [rad/s]" took the place of "t [s]", and the ticks, seconds
        into the run, read as speeds (walk 9, D3). The unit is read back with
        :func:`~minseg_tui.quantities.axis_unit`, from the label :func:`~minseg_tui.quantities.
        axis_label` made."""
        label, width = self._ylabel, self.size.width
        unit = axis_unit(label)
        if width and unit and len(label) + 1 > (width - len(self._xlabel)) // 2:
            return unit
        return label

    def draw(self) -> None:
        """Hand plotext what :attr:`traces` draw, at the widget's size, and refresh; nothing
        when that is what it was last handed (a view delivered again after each entry typed,
        a redraw of a stream that brought nothing new): no repaint for the same picture."""
        if self._hand():
            self.refresh()

    def _hand(self) -> bool:
        """Hand plotext what :attr:`traces` draw at the widget's size now (False: it has
        that already)."""
        key = (
            self._title,
            self._xlabel,
            self._ylabel,
            self.xlim,
            self.size,
            _signature(self.traces),
        )
        if key == self._drawn:
            return False
        self._drawn = key
        plt = self.plt
        plt.clear_data()
        plt.clear_figure()
        plt.title(self._title)
        plt.xlabel(self._xlabel)
        plt.ylabel(self._ylabel_fitting())
        xs: list[float] = []
        ys: list[float] = []
        lines: list[tuple[Trace, list[float], list[float]]] = []
        # plotext draws over what it drew before: the input's staircase first, then the guides
        # (a level, a marker line: '-' and '|'), then the data, which must show where it
        # crosses them (a dashed 63 % line hid the speed at its crossing); each trace keeps
        # its place in the list for its colour
        self._levels, self._ylim = [], None
        for k in drawing_order(self.traces):
            tr = self.traces[k]
            if len(tr.x) and tr.marker == LEVEL:  # drawn by our own code (_build)
                ys += [v for v in tr.y if math.isfinite(v)]
                self._levels.append((float(tr.y[0]), _colour(k, tr)[1].removeprefix("ansi_")))
            elif len(tr.x):
                x, y = drawn(tr)
                if self.size.width:
                    x, y = thin(x, y, POINTS_PER_COLUMN * self.size.width)
                side = "right" if tr.right else "left"
                plt.plot(x, y, marker=tr.marker, color=_colour(k, tr)[0], yside=side)
                xs += [v for v in x if math.isfinite(v)]
                if not tr.right:
                    ys += [v for v in y if math.isfinite(v)]
                lines.append((tr, x, y))
        if self.xlim is not None:
            xs = list(self.xlim)
        if xs:
            lo, hi, at = ticks(min(xs), max(xs))
            plt.xlim(lo, hi)
            plt.xticks(at, format_ticks(at))
        rows = self.size.height - 3 - bool(self._title) - bool(self._xlabel or self._ylabel)
        if ys and rows >= 2:  # laid out: the rows are known (drawn again on a resize)
            lo, hi, at = row_ticks(min(ys), max(ys), rows)
            self._ylim = (lo, hi)
            plt.ylim(lo, hi)
            plt.yticks(at, format_ticks(at))
            if xs:
                self._right_axis(lines, (min(xs), max(xs), lo, hi), rows)
        return True

    def _right_axis(
        self,
        lines: list[tuple[Trace, list[float], list[float]]],
        box: tuple[float, float, float, float],
        rows: int,
    ) -> None:
        """The scale of the trace on the right axis (if any): its lowest value on the bottom
        row, its highest on the row the others leave freest where it is at its highest,
        ticks at both, its label under the axis."""
        right = [(tr, x, y) for tr, x, y in lines if tr.right]
        if not right:
            return
        tr, x, y = right[0]
        values = [v for v in y if math.isfinite(v)]
        if not values:
            return
        u_lo, u_hi = min(values), max(values)
        if not u_hi > u_lo:
            u_hi = u_lo + 1.0
        x_lo, x_hi = box[0], box[1]
        if self.xlim is not None:
            x_lo, x_hi = self.xlim
        if not x_hi > x_lo:
            return
        cols = max(self.size.width - 12, 8)  # about the plot's columns (the axes' ticks aside)
        covered: set[tuple[int, int]] = set()
        for other, ox, oy in lines:
            if not other.right:
                covered |= _cells(
                    ox, oy, other.marker == "braille", (x_lo, x_hi, box[2], box[3]), cols, rows
                )
        high = {c for c, r in _cells(x, y, False, (x_lo, x_hi, u_lo, u_hi), cols, 2) if r == 1}
        row = free_row(covered, high, rows)
        # textual-plotext's stub types yside as a number and leaves it out of ylabel;
        # plotext takes "right" in all three
        side: Any = "right"
        self.plt.ylim(u_lo, u_lo + (u_hi - u_lo) * (rows - 1) / row, yside=side)
        self.plt.yticks([u_lo, u_hi], format_ticks([u_lo, u_hi]), yside=side)
        self.plt.ylabel(tr.label, yside=side)  # type: ignore[call-arg]

    def on_resize(self) -> None:
        self.draw()  # the y ticks sit on rows

    def _build(self) -> Text:
        """plotext's build of what :meth:`draw` handed it, at the widget's size (kept). Handed
        again first when the size changed since: the layout gives the canvas its new size
        before its Resize event runs :meth:`draw`, and a frame painted between the two drew
        the old size's y ticks on the new rows (the model check's close-up read 8, 4, 0
        where its rows give 9, 6, 3)."""
        if self.size.area:
            self._hand()
        key = (self._drawn, self.size, self.app.theme, self.theme)
        text = _built.get(key)
        if text is None:
            built = super().render()
            assert isinstance(built, Text)
            if self._levels and self._ylim is not None:
                draw_levels(built, self._levels, self._ylim)
            _built[key] = text = built
            while len(_built) > BUILDS_KEPT:
                _built.popitem(last=False)
        else:
            _built.move_to_end(key)
        return text

    def render(self) -> Text:
        return self._build().copy()

    @property
    def columns(self) -> tuple[int, int] | None:
        """The first and the last column of the plot's data area in the widget, as drawn
        now (None: not laid out yet); plotext puts x on column first + round((last - first)
        (x - lo) / (hi - lo)). Read off the build the screen shows (:data:`_built`), not
        left behind by the last paint: a paint may come later, or, headless, never."""
        if self._drawn is None or not self.size.area:
            return None
        return data_columns(self._build().plain)


def data_columns(plain: str) -> tuple[int, int] | None:
    """The first and the last column of the data area of a plot drawn as ``plain`` text
    (inside the corners of its frame), or None without a frame."""
    for line in plain.split("\n"):
        if "┌" in line and "┐" in line:
            first, last = line.index("┌") + 1, line.rindex("┐") - 1
            return (first, last) if last > first else None
    return None


class Legend(Static):
    """A plot's legend, drawn for its width (:func:`legend`)."""

    def __init__(self) -> None:
        super().__init__("", classes="legend")
        self.traces: tuple[Trace, ...] = ()

    def show(self, traces: Sequence[Trace]) -> None:
        """Say ``traces``; a layout of the screen only when its entries changed."""
        old = [(t.label, t.short, t.marker, t.colour, t.right) for t in self.traces]
        self.traces = tuple(traces)
        if old != [(t.label, t.short, t.marker, t.colour, t.right) for t in self.traces]:
            self.refresh(layout=True)

    def render(self) -> Content:
        width = self.content_size.width
        return legend(self.traces, width or None)

    def get_content_height(self, container: Size, viewport: Size, width: int) -> int:
        """The rows of the legend made for ``width``, the width the layout asks about. Textual
        measures the render of the width the legend had before and keeps that height by the
        width asked: a legend first measured before it was laid out (its full labels, two
        rows at 80x24) stayed two rows high once it read one, its second row empty."""
        rules = cast(RulesMap, self.styles)  # Textual's own call passes the styles as its rules
        return legend(self.traces, width or None).get_height(rules, width) if width else 0

    def on_resize(self) -> None:
        self.refresh(layout=True)


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
        self._legend = Legend()

    def compose(self) -> ComposeResult:
        yield self._canvas
        yield self._legend

    @property
    def traces(self) -> tuple[Trace, ...]:
        """What the plot draws now."""
        return self._canvas.traces

    @property
    def plot_title(self) -> str:
        """The title drawn above the plot."""
        return self._canvas.plot_title

    @property
    def columns(self) -> tuple[int, int] | None:
        """The first and the last column of the data area, in the plot (None: not drawn)."""
        return self._canvas.columns

    @property
    def traces_xlim(self) -> tuple[float, float] | None:
        """The x range the plot was last shown over (None: its data's own)."""
        return self._canvas.xlim

    @property
    def canvas_x(self) -> int:
        """The screen column of the plot's left edge."""
        return self._canvas.region.x

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
        self._legend.show(traces)
        if self._canvas.is_mounted:
            self._canvas.draw()
