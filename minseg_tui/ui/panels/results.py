"""Tasks 11-15: the run log, zoomed to one rise or whole, and the results beside the
group's own readings."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray
from textual import events
from textual.actions import SkipAction
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widget import Widget

from minseg_tui.lab.content.steps import Step
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.session import ResultsView
from minseg_tui.quantities import SPEED_AXIS, TIME_AXIS, axis_label, format_constant, format_value
from minseg_tui.ui.keys import PanelKeys, key_hint
from minseg_tui.ui.messages import RevealRequested
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.widgets.plots import LEVEL, Trace, TracePlot
from minseg_tui.ui.widgets.prose import Prose

CURSOR_JUMP = 5
"""Columns Shift+←/→ move the cursor at once."""

HELD_END = 1e-6
"""Task 11's zoom ends this long before the high level does (s): the sample at its end
already reports the low voltage."""


class ResponsePlot(TracePlot):
    """The run log, whole or zoomed to one rise. Focused, [ and ] pick the rise and z
    toggles; alt+left/right and F9 do the same from anywhere on the step (app keys). On a
    zoomed rise, ←/→ (Shift: five columns) move a cursor from column to column, and a click
    puts it on the column clicked (Home/End: on the first / last column with a sample); it
    reads t and omega off the plotted line there. Its keys are left out of the footer,
    which shows the app's (they pushed F8, F9, Alt+→ and Ctrl+R off its line at 80
    columns); the line under the plot and the F1 help list them."""

    BINDINGS = [
        Binding("left_square_bracket", "pick(-1)", "previous rise", show=False),
        Binding("right_square_bracket", "pick(1)", "next rise", show=False),
        Binding("z", "zoom", "zoom", show=False),
        Binding("left", "cursor(-1)", "cursor left", show=False),
        Binding("right", "cursor(1)", "cursor right", show=False),
        Binding("shift+left", f"cursor({-CURSOR_JUMP})", "cursor left", show=False),
        Binding("shift+right", f"cursor({CURSOR_JUMP})", "cursor right", show=False),
        Binding("home", "cursor_end(-1)", "cursor first", show=False),
        Binding("end", "cursor_end(1)", "cursor last", show=False),
    ]
    can_focus = True

    OWN_CHARACTERS: ClassVar[frozenset[str]] = frozenset("[]z")
    """The characters bound above, which the plot keeps while it holds the focus."""

    def check_consume_key(self, key: str, character: str | None) -> bool:
        """Textual's question to a focused widget, whether it takes ``key`` itself (Textual
        then leaves out the bindings the widgets around it have of that key,
        textual/screen.py:426-435): yes for the characters it binds, so that the step form
        around it does not take them for the first empty entry, and its binding runs as
        Textual runs it once the key has bubbled up to the app (z typed 'z' into the group's
        T)."""
        return character is not None and character in self.OWN_CHARACTERS

    def _panel(self) -> ResultsPanel | None:
        return next((p for p in self.ancestors if isinstance(p, ResultsPanel)), None)

    def action_cursor(self, columns: int) -> None:
        panel = self._panel()
        if panel is not None:
            panel.move_cursor(columns)

    def action_cursor_end(self, side: int) -> None:
        """Home (``side`` -1) / End (1): the cursor on the first / last column with a sample;
        off a zoomed rise the keys scroll the step as elsewhere."""
        panel = self._panel()
        if panel is None or not panel.cursor_to_end(side):
            raise SkipAction()

    def on_focus(self) -> None:
        panel = self._panel()
        if panel is not None:
            panel.move_cursor(0)

    def on_click(self, event: events.Click) -> None:
        """The cursor on the column clicked (a zoomed rise)."""
        panel = self._panel()
        if panel is not None and self.columns is not None:
            panel.put_cursor(event.screen_x - self.canvas_x - self.columns[0])

    def action_pick(self, delta: int) -> None:
        for p in self.ancestors:
            if isinstance(p, ResultsPanel):
                p.pick(delta)

    def action_zoom(self) -> None:
        for p in self.ancestors:
            if isinstance(p, ResultsPanel):
                p.toggle_zoom()


class ResultsPanel(ViewPanel[ResultsView], PanelKeys):
    """Tasks 11-15: the run log plotted, zoom to a rise, K, T (63 % and least squares with
    its interval), J, the model, omega at 5 V, and the group's readings beside them."""

    def __init__(self, step: Step) -> None:
        super().__init__("results")
        self.step = step
        self.zoom: int | None = 0 if step.id in ("task11", "task12") else None
        self._lines = Prose("computing…", id="results-lines")
        self._compare = Prose("", id="compare")
        self._details = Vertical(self._compare, self._lines, classes="details")
        self.cursor: int | None = None
        """The cursor's column in the zoomed rise's data area, from 0 at its left (None: no
        cursor yet; the plot's first focus puts it on the edge)."""
        self.reading: views.CursorReading | None = None
        """What the cursor reads now (None: no cursor shown)."""
        self._said: tuple[object, ...] | None = None
        """The results and comparisons last drawn (None: nothing drawn yet)."""
        self._reveal = False
        """The view just drawn shows results or comparisons it did not show before."""
        self._held: list[Callable[[], None]] = []
        """F9 and Alt+←/→ pressed before the plot was worked out: done once it is (walk 16's
        D4: 'Ctrl+P task 11 Enter F9' in one burst was refused, "the plot is still being
        worked out", 1 run in 3 at load 20)."""

    def compose(self) -> ComposeResult:
        yield ResponsePlot("run log", TIME_AXIS, SPEED_AXIS, id="plot-log")
        yield Prose("", id="cursor")
        yield Prose("", id="zoom-note", classes="hint")

    def after_rows(self) -> Widget:
        """The numbers, shown under the group's entries (the entry to type a reading into
        sits right under the plot it is read from): first the group's own values against
        the computed ones, right under the entries they typed them in, then the results."""
        return self._details

    def build(self, session: Session) -> ResultsView:
        return views.results(session, self.step.id)

    def show_view(self) -> None:
        view = self.view
        if view is None:
            return
        if self.zoom is not None and self.zoom >= len(view.rises):
            self.zoom = 0 if view.rises else None
        self._plot()
        said = (view.lines, view.compare, view.problems)
        self._reveal = self._said is not None and said != self._said
        self._said = said
        lines = list(view.lines) or [
            "no step result yet" + (f": {view.waiting}" if view.waiting else "")
        ]
        lines += [f"! {p}" for p in view.problems]
        self._lines.update("\n".join(lines))
        compared = "\n".join(f"{label}: yours {own} · {comp}" for label, own, comp in view.compare)
        self._compare.update(compared)
        self._compare.display = bool(compared)
        held, self._held = self._held, []
        for key in held:  # the keys that waited for the plot, in the order pressed
            key()

    def revealed(self) -> Widget | None:
        """The comparisons under the entries, when an answer (or a new run) changed what
        is shown: a group at 80x24 had them below the screen after answering."""
        return self._compare if self._reveal and self._compare.display else None

    def _plot(self) -> None:
        v = self.view
        if v is None:
            return
        plot = self.query_one(ResponsePlot)
        note = self.query_one("#zoom-note", Prose)
        self.reading = None
        self.query_one("#cursor", Prose).display = False
        if v.t.size == 0:
            plot.show([])
            note.update("no run recorded yet (Task 10)")
            return
        if self.zoom is None or not v.rises:
            plot.set_axes("run log", TIME_AXIS)
            plot.show(
                [
                    Trace(v.t, v.omega, "omega"),
                    Trace(v.t, v.u, v.u_label, "dot", steps=True, right=True),
                ]
            )
            if v.rises:
                said = f"{len(v.rises)} rises with results · {key_hint('zoom_next', 'rise 1')}"
            elif not v.lines:  # no results at all: what they wait for, or why (the lines)
                said = f"no results yet: {v.waiting}" if v.waiting else "no results (why: below)"
            else:
                said = "no rise long enough to read results from"
            note.update(f"run {v.run}: whole log, {said}")
            return
        w = v.rises[self.zoom]
        # Task 12 reads T: the close-up on the first few T, a few ms a column at 80 columns;
        # Task 11 reads the settled speed: the rise and its high level to its end (the zoom
        # to 5 T showed 0.2 s of it, too little to see where the speed settles)
        z0, z1 = (w.c0, w.c1) if self.step.id == "task12" and w.c1 > w.c0 else (w.z0, w.z1)
        if self.step.id == "task11":
            z1 = max(z1, w.t1 - HELD_END)
        keep = (v.t >= z0) & (v.t <= z1)
        x = v.t[keep] - w.t0  # time after the edge: the 63 % crossing is read off as T
        traces = [
            Trace(x, v.omega[keep], "omega"),
            Trace(x, v.u[keep], v.u_label, "dot", steps=True, right=True),
        ]
        lo, hi = z0 - w.t0, z1 - w.t0
        if x.size and self.step.id == "task11":
            hi = float(x[-1])  # to its last sample, not a column past it
        traces.append(Trace([lo, hi], [w.level, w.level], "63 %", LEVEL))
        read_T = "own.T" not in v.hidden  # the crossing is Task 12's answer
        if w.T_63 is not None and read_T:
            traces.append(Trace([w.T_63, w.T_63], [w.omega0, w.level], "crossing", "|"))
        self._cursor(plot, traces, x, v.omega[keep], (lo, hi))
        plot.set_axes(
            f"rise {self.zoom + 1}, after a voltage step up", axis_label("t after the edge", "s")
        )
        plot.show(traces, (lo, hi))
        crossing = (
            "the speed crosses it: read T there"
            if not read_T
            else f"the speed crosses it {format_constant(w.T_63, 's')} after the edge"
            + (f" ({views.REVEALED_ON_PLOT})" if "own.T" in v.revealed else "")
            if w.T_63 is not None
            else "the speed never crosses it"
        )
        change = (
            "the line is 63 % of the change"  # the steady speed is Task 11's answer
            if "own.omega_step" in v.hidden
            else f"from {format_value(w.omega0, 'rad/s', 3)} to "
            f"{format_value(w.omega_ss, 'rad/s', 3)}"
            + (f" ({views.REVEALED_ON_PLOT})" if "own.omega_step" in v.revealed else "")
            + f"; 63 % of the change is {format_value(w.level, 'rad/s', 3)}"
        )
        if self.step.id == "task11" and "own.omega_step" in v.revealed:
            # the reading revealed stands where the group is told to read it: at 80x24 the
            # caption then keeps to the lines it had with the reading, and the plot in view
            said = f" to the end of its high level: {change}"
        elif self.step.id == "task11":
            read = "" if "own.omega_step" in v.hidden else f"{change}; "
            said = f" to the end of its high level: {read}read omega_ss where it has settled"
        else:
            said = f": {change}, {crossing}"
        last = self.zoom + 1 >= len(v.rises)
        f9 = key_hint("zoom_next", "the whole log" if last else f"rise {self.zoom + 2}")
        note.update(
            f"run {v.run}, rise {self.zoom + 1} of {len(v.rises)}{said} · "
            f"shift+tab, ←/→ Cursor · {key_hint('pick_next')} · {f9}"
        )

    def _cursor(
        self,
        plot: ResponsePlot,
        traces: list[Trace],
        x: NDArray[np.float64],
        omega: NDArray[np.float64],
        xlim: tuple[float, float],
    ) -> None:
        """The cursor's line among ``traces`` and its reading under the plot: at the time of
        its column (plotext's columns span ``xlim`` evenly), the speed of the plotted line
        ``(x, omega)``."""
        line = self.query_one("#cursor", Prose)
        columns = plot.columns
        if self.cursor is None or columns is None:
            return
        line.display = True
        width = columns[1] - columns[0]
        lo, hi = xlim
        if x.size == 0 or not hi > lo or width <= 0:
            return
        # the columns with samples on both sides: at the frame's last column the cursor read
        # 'no sample there' and vanished (its time a hair past the last sample's)
        first = max(math.ceil((x[0] - lo) / (hi - lo) * width - 1e-6), 0)
        last = min(math.floor((x[-1] - lo) / (hi - lo) * width + 1e-6), width)
        self.cursor = max(first, min(self.cursor, last))
        # to the µs and within the samples: the edge's column read "t = -6.94e-15 ms"
        at = round(lo + (hi - lo) * self.cursor / width, 6)
        at = min(max(at, float(x[0])), float(x[-1]))
        self.reading = views.cursor_reading(x, omega, at)
        if self.reading is None:
            line.update("┆ cursor: no sample there · ←/→ move it")
            return
        traces.append(Trace([at, at], [float(np.min(omega)), float(np.max(omega))], "", "┆", 4))
        line.update(f"┆ cursor: {self.reading.text()} · ←/→ move it")

    def move_cursor(self, columns: int) -> None:
        """Move the cursor ``columns`` to the right (left if negative); 0 puts a first
        cursor on the edge. Only on a zoomed rise."""
        if self.zoom is None or self.view is None or not self.view.rises:
            return
        plot = self.query_one(ResponsePlot)
        if self.cursor is None:
            span = plot.columns
            lo, hi = plot.traces_xlim or (0.0, 0.0)
            if span is None or not hi > lo:
                return
            self.cursor = round((span[1] - span[0]) * -lo / (hi - lo))  # on the edge
        self.cursor += columns
        self._plot()

    def cursor_to_end(self, side: int) -> bool:
        """The cursor on the first (``side`` < 0) or the last column with a sample of the
        zoomed rise (:meth:`_cursor` keeps it within them); False: no zoomed rise."""
        if self.zoom is None or self.view is None or not self.view.rises:
            return False
        self.cursor = -(10**6) if side < 0 else 10**6
        self._plot()
        return True

    def put_cursor(self, column: int) -> None:
        """The cursor on ``column`` of the data area (a click)."""
        if self.zoom is None or self.view is None or not self.view.rises:
            return
        self.cursor = column
        self._plot()

    def action_reveal(self) -> None:
        """Ctrl+R (a lab assistant): show this step's computed values before the group answers."""
        self.post_message(RevealRequested(self.step.id))

    def _no_rise(self, key: Callable[[], None]) -> bool:
        """True, and said, when the plot has no rise to zoom to (walk 14, D9: F9 and Alt+→ on
        Task 11 before any run did nothing and said nothing, though the footer offers them);
        True, and ``key`` kept to be done once it is, while the plot is still being worked
        out."""
        v = self.view
        if v is not None and v.rises:
            return False
        if v is None:
            self._held.append(key)
            return True
        if not v.run:
            said = "no step run recorded yet (Task 10)"
        else:
            said = f"run {v.run} has no step up with results"
        self.notify(f"no rise to zoom to: {said}")
        return True

    def pick(self, delta: int) -> None:
        """Zoom to the previous/next rise."""
        if self._no_rise(lambda: self.pick(delta)) or self.view is None:
            return
        n = len(self.view.rises)
        self.zoom = (0 if self.zoom is None else self.zoom + delta) % n
        self._plot()
        self._plot_in_view()

    def _plot_in_view(self) -> None:
        """The plot a key just changed, scrolled into view if it is not (walk 17's D4: at
        80x24, once the answers are typed the plot lies above the view, and Alt+→ or F9
        changed it there: nothing seemed to happen). The least scroll: a plot in view stays
        where it is; the keys still go to the entry they went to."""
        plots = self.query(ResponsePlot)
        if plots and self.is_attached:
            self.screen.scroll_to_widget(plots.first(), animate=False, immediate=True)

    def action_pick_prev(self) -> None:
        """alt+left: the previous rise."""
        self.pick(-1)

    def action_pick_next(self) -> None:
        """alt+right: the next rise."""
        self.pick(1)

    def toggle_zoom(self) -> None:
        """One rise, or the whole log."""
        self.zoom = None if self.zoom is not None else 0
        self._plot()

    def key_actions(self) -> Mapping[str, Callable[[], object]]:
        return {
            "zoom_next": self.action_zoom_next,
            "pick_prev": self.action_pick_prev,
            "pick_next": self.action_pick_next,
            "reveal": self.action_reveal,
        }

    def action_zoom_next(self) -> None:
        """F9: the next rise, after the last the whole log, then the first rise again."""
        if self._no_rise(self.action_zoom_next) or self.view is None:
            return
        if self.zoom is None:
            self.zoom = 0
        elif self.zoom + 1 >= len(self.view.rises):
            self.zoom = None
        else:
            self.zoom += 1
        self._plot()
        self._plot_in_view()
