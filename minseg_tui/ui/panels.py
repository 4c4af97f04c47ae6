"""The panel each kind of step shows above its entries: live plots, the table, the runs.

Panels pull arrays from the app's live buffer and results from the lab port, on a timer
or after an entry; every number comes from :mod:`minseg_tui.signals` or the lab layer.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.widget import Widget
from textual.widgets import DataTable, ProgressBar, Static

from minseg_tui import signals
from minseg_tui.errors import MinsegError
from minseg_tui.lab.steps import LEVELS, Step
from minseg_tui.ui.ports import TableView
from minseg_tui.ui.widgets.plots import Trace, TracePlot

if TYPE_CHECKING:
    from minseg_tui.ui.app import LabApp

PLOT_SPAN = 8.0
"""Seconds of the live stream on screen."""

FAST_WHY = (
    "Why fast sampling matters: the published MinSeg figures give T near 0.04 s, less than "
    "two 25 ms samples, and the manual's 20-tap average spans 0.5 s. Read at 25 ms with the "
    "average, the 63 % time mostly measures the filter. At 5 ms, timed by the board, the "
    "rise itself is visible."
)


class LivePanel(Vertical):
    """Angle and speed of the last seconds, the manual's speed beside the timestamp one."""

    def __init__(self, app: LabApp, step: Step) -> None:
        super().__init__(classes="panel live")
        self._lab_app = app
        self.step = step
        self.steady_text = ""
        self.levels = tuple(dict.fromkeys(f.level for f in step.fields if f.level is not None))
        if not self.levels and "capture_omega" in step.actions:
            self.levels = LEVELS
        self.level: float | None = None

    def compose(self) -> ComposeResult:
        with Horizontal(classes="plots"):
            yield TracePlot("angle", "t [s]", "theta [rad]", id="plot-angle")
            yield TracePlot("speed", "t [s]", "omega [rad/s]", id="plot-speed")
        yield Static("", id="steady")
        if "meter" in self.step.actions:
            yield MeterPanel(self._lab_app)

    def on_mount(self) -> None:
        self.redraw()
        if self._lab_app.config.refresh > 0:
            self.set_interval(self._lab_app.config.refresh, self.redraw)

    def _arrays(self) -> tuple[Any, Any, Any]:
        return self._lab_app.live.snapshot()

    def redraw(self) -> None:
        """Replot from the buffer and update the steady-state line (a few times a second)."""
        t, count, _u = self._arrays()
        lab = self._lab_app.lab
        if t.size:
            keep = t >= t[-1] - PLOT_SPAN
            tt, cc = t[keep], count[keep]
            theta = signals.angle(cc)
            w_lab = signals.lab_velocity(cc)
            w_ts = signals.timestamp_velocity(tt, cc)
            x = tt - tt[0]
            self.query_one("#plot-angle", TracePlot).show([Trace(x, theta, "theta")])
            self.query_one("#plot-speed", TracePlot).show(
                [Trace(x, w_ts, "board timestamps"), Trace(x, w_lab, "manual: Euler + 20-tap")]
            )
        if lab is not None and "capture_omega" in self.step.actions:
            s = lab.steady(t, count)
            state = "SETTLED" if s.settled else "not settled"
            self.steady_text = (f"steady state: {state} · mean {s.mean:.2f} rad/s ± {s.spread:.2f}"
                                f" over {s.window:.1f} s {s.note}").rstrip()
            level = "none (F3 sets 2.5 V)" if self.level is None else f"{self.level:g} V (F3 next)"
            self.query_one("#steady", Static).update(
                f"{self.steady_text}\nrequested: {level} · F4 captures omega_ss · F2 stops")
        elif t.size == 0:
            self.query_one("#steady", Static).update("waiting for samples...")

    def set_voltage(self) -> None:
        """F3: request this step's voltage on the board."""
        device = self._lab_app.device
        if device is None or not self.levels:
            self._lab_app.notify("no voltage to set on this step")
            return
        k = -1 if self.level is None else self.levels.index(self.level)
        self.level = self.levels[(k + 1) % len(self.levels)]
        device.set_voltage(self.level)
        self._lab_app.motor = f"{self.level:g} V"
        self._lab_app.refresh_status()
        self.redraw()

    def capture(self) -> None:
        """F4: take omega_ss from the settled window (refused while not settled)."""
        lab = self._lab_app.lab
        if lab is None or "capture_omega" not in self.step.actions:
            return
        if self.level is None:
            self._lab_app.notify("set a voltage first (F3)", severity="warning")
            return
        t, count, _u = self._arrays()
        result = lab.capture_live(self.level, t, count)
        self._lab_app.notify(result.message or f"omega_ss at {self.level:g} V captured",
                             severity="information" if result.ok else "warning")
        self._lab_app.refresh_fields()


class MeterPanel(Static):
    """The virtual MinSeg's multimeter (blank on a real board: read your own meter)."""

    def __init__(self, app: LabApp) -> None:
        super().__init__("", classes="panel")
        self._lab_app = app

    def on_mount(self) -> None:
        self.redraw()
        if self._lab_app.config.refresh > 0:
            self.set_interval(self._lab_app.config.refresh, self.redraw)

    def redraw(self) -> None:
        device = self._lab_app.device
        if device is None or not device.info.virtual:
            self.update("Read the multimeter on the bench.")
            return
        m = device.meter()
        self.update("multimeter (virtual): —" if m is None else
                    f"multimeter (virtual) on M1A/M1B: {m.u_A:.2f} V · {m.i * 1000:.1f} mA · R {m.R:.2f} Ω")


class TablePanel(Vertical):
    """Tasks 6-9 filling itself; F7 (or Enter on a cell) shows the formula behind the cell."""

    def __init__(self, app: LabApp) -> None:
        super().__init__(classes="panel recompute")
        self._lab_app = app
        self.view: TableView | None = None

    def compose(self) -> ComposeResult:
        yield DataTable(id="table", cursor_type="cell", zebra_stripes=False)
        yield Static("", id="results")
        yield Static("", id="warnings")
        yield Static("F7 on a cell: the formula behind it.", id="formula", classes="hint")

    def on_mount(self) -> None:
        self.recompute()

    def recompute(self) -> None:
        """Rebuild from the lab's current entries."""
        lab = self._lab_app.lab
        if lab is None:
            return
        self.view = lab.table()
        table = self.query_one(DataTable)
        table.clear(columns=True)
        table.add_columns(*self.view.columns)
        for row in self.view.rows:
            table.add_row(*[c.text for c in row])
        self.query_one("#results", Static).update(
            "  ".join(f"{name} = {cell.text}" for name, cell in self.view.results))
        self.query_one("#warnings", Static).update("\n".join(f"! {w}" for w in self.view.warnings))

    def formula(self) -> None:
        """Show the formula of the cell under the cursor."""
        if self.view is None or not self.view.rows:
            return
        table = self.query_one(DataTable)
        r, c = table.cursor_coordinate
        cell = self.view.rows[r][c]
        self.query_one("#formula", Static).update(cell.formula or f"{cell.text}: measured, no formula")

    def on_data_table_cell_selected(self, _event: DataTable.CellSelected) -> None:
        self.formula()


class StepRunPanel(Vertical):
    """Task 10: run the board's step sequence with progress; F2 stops it at once."""

    def __init__(self, app: LabApp, step: Step) -> None:
        super().__init__(classes="panel recompute")
        self._lab_app = app
        self.step = step

    def compose(self) -> ComposeResult:
        yield Static("F5 runs 4 steps 0 → 4.5 V (1 s each) at 25 ms; F6 the same at 5 ms. "
                     "F2 stops the motor at any time.", classes="hint")
        yield ProgressBar(total=100, show_eta=False, id="run-progress")
        yield Static("", id="run-status")
        yield Static(FAST_WHY, classes="para")
        with Horizontal(classes="plots"):
            yield TracePlot("25 ms, manual filter", "t [s]", "omega [rad/s]", id="plot-slow")
            yield TracePlot("5 ms, board-timed", "t [s]", "omega [rad/s]", id="plot-fast")

    def on_mount(self) -> None:
        self.recompute()

    def recompute(self) -> None:
        """Show the runs already recorded (after a resume, too)."""
        lab = self._lab_app.lab
        if lab is None:
            return
        for name, plot_id in (("manual", "#plot-slow"), ("fast", "#plot-fast")):
            run = lab.run(name)
            if run is not None:
                t, omega = run
                self.query_one(plot_id, TracePlot).show([Trace(t, omega, name)])
        self.query_one("#run-status", Static).update(lab.run_status())

    def run_steps(self) -> None:
        self._lab_app.start_run("manual", 0.025)

    def run_fast(self) -> None:
        self._lab_app.start_run("fast", 0.005)

    def progress(self, fraction: float, text: str) -> None:
        """Move the bar (0-1) and say where the run is."""
        self.query_one(ProgressBar).update(progress=100 * fraction)
        self.query_one("#run-status", Static).update(text)


class TextPanel(Static):
    """Results as text lines from the lab (model check, Tasks 11-15)."""

    def __init__(self, app: LabApp, what: str) -> None:
        super().__init__("", classes="panel recompute")
        self._lab_app = app
        self._what = what

    def on_mount(self) -> None:
        self.recompute()

    def recompute(self) -> None:
        lab = self._lab_app.lab
        if lab is None:
            return
        try:
            text = getattr(lab, self._what)()
        except MinsegError as exc:
            text = str(exc)
        self.update(text)


def panel_for(app: LabApp, step: Step) -> Widget | None:
    """The panel of ``step``'s kind, or None."""
    acts = set(step.actions)
    if acts & {"live_velocity", "capture_omega"}:
        return LivePanel(app, step)
    if step.id == "table":
        return TablePanel(app)
    if "run_steps" in acts:
        return StepRunPanel(app, step)
    if "results" in acts:
        return TextPanel(app, "results_text")
    if "model_check" in acts:
        return TextPanel(app, "model_check_text")
    if "meter" in acts:
        return MeterPanel(app)
    return None

