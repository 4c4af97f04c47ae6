"""The panel each kind of step shows above its entries: live plots, the meter, the table, the
runs, the results, the model check, the report.

Panels pull arrays from the app's live buffer (on a timer, a few times a second, never per
sample) and views from the lab port (slow ones in a worker); every number comes from
:mod:`minseg_tui.signals` or the lab layer through :mod:`minseg_tui.ui.backend`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from textual import on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.widget import Widget
from textual.widgets import DataTable, Input, ProgressBar, Static

from minseg_tui import signals
from minseg_tui.errors import MinsegError
from minseg_tui.lab.steps import LEVELS, Step
from minseg_tui.ui.ports import CheckView, ResultsView, RunView, TableView
from minseg_tui.ui.widgets.fields import LabInput
from minseg_tui.ui.widgets.plots import Trace, TracePlot

if TYPE_CHECKING:
    from minseg_tui.ui.app import LabApp

PLOT_SPAN = 8.0
"""Seconds of the live stream on screen."""

ZOOM_BEFORE = 0.2
"""Seconds shown before a rising step when zoomed to it."""

FAST_WHY = (
    "Why 5 ms matters: the published MinSeg figures give T near 0.04 s, under two 25 ms "
    "samples, and the manual's 20-tap average spans 0.5 s. Read at 25 ms through the "
    "average, the 63 % time mostly measures the filter; at 5 ms, board-timed, the rise "
    "itself is visible. Compare the T readings side by side:"
)


def _s(v: float | None) -> str:
    return "—" if v is None else f"{v:.3f} s"


class LivePanel(Vertical):
    """Angle and speed of the last seconds, the manual's speed beside the timestamp one; the
    steady-state indicator (Task 4); F3 sets the next voltage; the virtual multimeter."""

    def __init__(self, app: LabApp, step: Step) -> None:
        super().__init__(classes="panel live")
        self._lab_app = app
        self.step = step
        self.levels = tuple(dict.fromkeys(f.level for f in step.fields if f.level is not None))
        if not self.levels and {"capture_omega", "live_velocity"} & set(step.actions):
            self.levels = LEVELS  # Task 3 says "set a voltage": F3 steps through the lab's
        self.plots = bool({"live_velocity", "capture_omega"} & set(step.actions))

    @property
    def level(self) -> float | None:
        """The voltage requested with F3 (V), kept by the app: it outlives the step on screen."""
        return self._lab_app.requested

    @level.setter
    def level(self, value: float | None) -> None:
        self._lab_app.requested = value

    def compose(self) -> ComposeResult:
        if self.plots:
            with Horizontal(classes="plots"):
                yield TracePlot("angle", "t [s]", "theta [rad]", id="plot-angle")
                yield TracePlot("speed", "t [s]", "omega [rad/s]", id="plot-speed")

    def readout(self) -> Widget | None:
        """The lines to keep in sight while typing (the steady-state indicator, the requested
        voltage and keys, the multimeter): the step pane docks them at its bottom."""
        parts: list[Widget] = []
        if self.levels or "capture_omega" in self.step.actions:
            parts.append(Static("", id="steady"))
        if "meter" in self.step.actions:
            parts.append(MeterPanel(self._lab_app))
        return Vertical(*parts, classes="readout") if parts else None

    def on_mount(self) -> None:
        self.redraw()
        if self._lab_app.config.refresh > 0:
            self.set_interval(self._lab_app.config.refresh, self.redraw)

    def redraw(self) -> None:
        """Replot from the buffer and update the indicator (a few times a second)."""
        t, count, _u = self._lab_app.live.snapshot()
        if self.plots and t.size > 1:
            keep = t >= t[-1] - PLOT_SPAN
            tt, cc = t[keep], count[keep]
            x = tt - tt[0]
            self.query_one("#plot-angle", TracePlot).show([Trace(x, signals.angle(cc), "theta")])
            self.query_one("#plot-speed", TracePlot).show(
                [
                    Trace(x, signals.timestamp_velocity(tt, cc), "board time"),
                    Trace(x, signals.lab_velocity(cc), "manual", "dot"),
                ]
            )
        steady = self.screen.query("#steady")
        if not steady:
            return
        level = "0 V (motor off)" if self.level is None else f"{self.level:g} V"
        keys = "F3 next voltage · F2 stop"
        if "capture_omega" in self.step.actions and self._lab_app.lab is not None:
            s = self._lab_app.lab.steady(t, count)
            state = "SETTLED" if s.settled else "not settled"
            mean = "—" if s.mean != s.mean else f"{s.mean:.2f} ± {s.spread:.2f} rad/s"
            text = (
                f"steady: {state} · {mean} over {s.window:g} s {s.note}".rstrip()
                + f"\nrequested {level} · {keys} · F4 capture"
            )
        else:
            text = f"requested {level} · {keys}"
        if t.size == 0:
            text = "waiting for samples…\n" + text
        steady.first(Static).update(text)

    def offers(self, action: str) -> bool:
        """Whether the panel's key ``action`` does something on this step (F3 where there are
        voltages to set, F4 on Task 4)."""
        return {
            "set_voltage": bool(self.levels),
            "capture": "capture_omega" in self.step.actions,
        }.get(action, True)

    def set_voltage(self) -> None:
        """F3: request the next of this step's voltages on the board."""
        device = self._lab_app.device
        if device is None or not self.levels:
            self._lab_app.notify("no voltage to set on this step (Tasks 4-5)")
            return
        k = -1 if self.level not in self.levels else self.levels.index(self.level)
        level = self.levels[(k + 1) % len(self.levels)]
        try:
            device.set_voltage(level)
        except MinsegError as exc:
            self._lab_app.notify(str(exc), severity="error")
            return
        self.level = level
        self._lab_app.motor = f"{level:g} V"
        self._lab_app.refresh_status()
        self.redraw()

    def capture(self) -> None:
        """F4: take omega_ss from the settled window (refused while not settled)."""
        lab = self._lab_app.lab
        if lab is None or "capture_omega" not in self.step.actions:
            self._lab_app.notify("capturing omega_ss is part of Task 4")
            return
        if self.level is None:
            self._lab_app.notify("set a voltage first (F3)", severity="warning")
            return
        t, count, _u = self._lab_app.live.snapshot()
        result = lab.capture_live(self.level, t, count)
        if not result.ok:  # a success shows in the field itself; a toast would hide the meter
            self._lab_app.notify(result.message, severity="warning")
        self._lab_app.refresh_fields()
        if result.ok:  # next comes the multimeter reading at the same voltage
            self._lab_app.focus_after(f"omega_ss@{self.level:g}")


class MeterPanel(Static):
    """The virtual MinSeg's multimeter (on a real board: read the one on the bench)."""

    def __init__(self, app: LabApp) -> None:
        super().__init__("", classes="meter")
        self._lab_app = app

    def on_mount(self) -> None:
        self._lab_app.meter_wanted += 1
        self.redraw()
        if self._lab_app.config.refresh > 0:
            self.set_interval(self._lab_app.config.refresh, self.redraw)

    def on_unmount(self) -> None:
        self._lab_app.meter_wanted -= 1

    def redraw(self) -> None:
        device = self._lab_app.device
        if device is None or not device.info.virtual:
            self.update("multimeter: read the one on the bench (M1A-M1B)")
            return
        m = self._lab_app.meter_reading
        self.update(
            "multimeter (virtual, M1A-M1B): reading…"
            if m is None
            else f"multimeter (virtual, M1A-M1B): {m.u_A:.2f} V · {m.i * 1000:.1f} mA · {m.R:.1f} Ω"
        )


class Recomputing:
    """Mixin of the panels built from what the lab holds: marked ``panel recompute`` (the app
    calls :meth:`recompute` after every entry and run) and built once when mounted. Put it
    before the Textual base: ``class XPanel(Recomputing, Vertical)``."""

    def __init__(self, app: LabApp, classes: str = "") -> None:
        super().__init__(classes=f"panel recompute {classes}".rstrip())  # type: ignore[call-arg]
        self._lab_app = app

    def on_mount(self) -> None:
        self.recompute()

    def recompute(self) -> None:
        """Rebuild from the lab's current entries and runs."""
        raise NotImplementedError


class ConnectPanel(Recomputing, Static):
    """Task 1: who the program talks to, and how to change it."""

    def recompute(self) -> None:
        d = self._lab_app.device
        if d is None:
            text = "No device yet. Ctrl+P → Switch to virtual board to practise."
        elif d.info.virtual:
            text = (
                f"Connected to the VIRTUAL MinSeg ({d.info.firmware})"
                + (": no board was found." if d.info.fallback else ".")
                + " Plug a board in and restart with --port, or keep practising."
            )
        else:
            text = f"Connected to {d.info.name} on {d.info.port}, firmware {d.info.firmware}."
        self.update(text)


class TablePanel(Recomputing, Vertical):
    """Tasks 6-9 filling itself; F7 (or Enter on a cell) shows the formula behind the cell."""

    def __init__(self, app: LabApp) -> None:
        super().__init__(app)
        self.view: TableView | None = None

    def compose(self) -> ComposeResult:
        yield DataTable(id="table", cursor_type="cell", zebra_stripes=False, header_height=2)
        yield Static("F7 on a cell: the formula behind it.", id="formula", classes="hint")
        yield Static("", id="results")
        yield Static("", id="warnings")

    def recompute(self) -> None:
        """Rebuild from the lab's current entries (in a worker: it computes the results, the
        step fit on the chosen run included)."""
        if self._lab_app.lab is not None:
            self._load()

    @work(thread=True, exclusive=True, group="table")
    def _load(self) -> None:
        lab = self._lab_app.lab
        assert lab is not None
        view = lab.table()
        self.app.call_from_thread(self._show, view)

    def _show(self, view: TableView) -> None:
        if not self.is_attached:
            return  # the step changed while the worker ran
        self.view = view
        table = self.query_one(DataTable)
        cursor = table.cursor_coordinate
        table.clear(columns=True)
        table.add_columns(*view.columns)
        for row in view.rows:
            table.add_row(*[c.text for c in row])
        table.move_cursor(row=cursor.row, column=cursor.column, animate=False)
        lines = ["  ".join(f"{name} = {cell.text}" for name, cell in view.results)]
        lines += [
            f"{label}: yours {own} · computed {comp}"
            for label, own, comp in view.compare
            if own != "—"
        ]
        self.query_one("#results", Static).update("\n".join(lines))
        self.query_one("#warnings", Static).update("\n".join(f"! {w}" for w in view.warnings))

    def formula(self) -> None:
        """Show the formula of the cell under the cursor."""
        if self.view is None or not self.view.rows:
            return
        table = self.query_one(DataTable)
        r, c = table.cursor_coordinate
        cell = self.view.rows[r][c]
        self.query_one("#formula", Static).update(
            cell.formula or f"{cell.text}: measured, no formula"
        )

    def on_data_table_cell_selected(self, _event: DataTable.CellSelected) -> None:
        self.formula()


class StepRunPanel(Recomputing, Vertical):
    """Task 10: run the board's step sequence with progress (F2 stops it at once); the
    25 ms run beside the 5 ms one, with both T readings next to each other."""

    def __init__(self, app: LabApp, step: Step) -> None:
        super().__init__(app)
        self.step = step
        self.views: tuple[RunView, ...] = ()

    def compose(self) -> ComposeResult:
        plans = dict(self.step.plans)
        m = plans["manual"]
        yield Static(
            f"F5: {m.periods} steps 0 → {m.high:g} V, {m.half_period:g} s each, at "
            f"{m.ts * 1000:g} ms. F6: the same at {plans['fast'].ts * 1000:g} ms. F2 stops.",
            classes="hint",
        )
        yield ProgressBar(total=100, show_eta=False, id="run-progress")
        yield Static("", id="run-status")
        with Horizontal(classes="plots"):
            yield TracePlot("25 ms run", "t [s]", "omega [rad/s]", id="plot-slow")
            yield TracePlot("5 ms run", "t [s]", "omega [rad/s]", id="plot-fast")
        yield Static(FAST_WHY, classes="para")
        yield Static("", id="t-readings")

    def recompute(self) -> None:
        """Show the runs already recorded (after a resume, too); computed in a worker."""
        if self._lab_app.lab is None or self._lab_app.recording is not None:
            return
        self._load()

    @work(thread=True, exclusive=True, group="runs")
    def _load(self) -> None:
        lab = self._lab_app.lab
        assert lab is not None
        views = lab.run_views()
        self.app.call_from_thread(self._show, views)

    def _show(self, views: tuple[RunView, ...]) -> None:
        if not self.is_attached:
            return  # the step changed while the worker ran
        if not self.query("#t-readings"):
            self.call_after_refresh(self._show, views)
            return
        self.views = views
        for v in views:
            plot = self.query_one("#plot-slow" if v.kind == "steps" else "#plot-fast", TracePlot)
            traces = [Trace(v.t, v.omega, "board time")]
            if v.kind == "steps":
                traces.append(Trace(v.t, v.omega_lab, "manual", "dot"))
            plot.show(traces)
        rows = [f"{'run':<9}{'T 63% manual':>13}{'T 63%':>9}{'T fit (95% CI)':>24}"]
        for v in views:
            ci = f" ({v.T_ci[0]:.3f}..{v.T_ci[1]:.3f})" if v.T_ci else ""
            rows.append(
                f"{v.name:<9}{_s(v.T_63_lab) if v.kind == 'steps' else '—':>13}{_s(v.T_63):>9}"
                f"{_s(v.T_ls) + ci:>24}"
            )
        if not views:
            rows.append("no run yet: F5 (25 ms), then F6 (5 ms)")
        self.query_one("#t-readings", Static).update("\n".join(rows))
        if self._lab_app.recording is None:
            runs = ", ".join(
                f"{v.name} ({v.samples} samples{', interrupted' if v.interrupted else ''})"
                for v in views
            )
            self.query_one("#run-status", Static).update(runs or "no runs recorded yet")

    def run_steps(self) -> None:
        self._lab_app.start_run("manual")

    def run_fast(self) -> None:
        self._lab_app.start_run("fast")

    def progress(self, fraction: float, text: str) -> None:
        """Move the bar (0-1) and say where the run is."""
        self.query_one(ProgressBar).update(progress=100 * fraction)
        self.query_one("#run-status", Static).update(text)


class StepPlot(TracePlot):
    """The step log, whole or zoomed to one rising step. Focused, [ and ] pick the step and z
    toggles; alt+left/right and F9 do the same from anywhere on the step (app keys)."""

    BINDINGS = [
        Binding("left_square_bracket", "pick(-1)", "prev step"),
        Binding("right_square_bracket", "pick(1)", "next step"),
        Binding("z", "zoom", "zoom"),
    ]
    can_focus = True

    def action_pick(self, delta: int) -> None:
        for p in self.ancestors:
            if isinstance(p, ResultsPanel):
                p.pick(delta)

    def action_zoom(self) -> None:
        for p in self.ancestors:
            if isinstance(p, ResultsPanel):
                p.toggle_zoom()


class ResultsPanel(Recomputing, Vertical):
    """Tasks 11-15: the step log plotted, zoom to a step, K, T (63 % and least squares with
    its interval), J, the model, omega at 5 V, and the group's readings beside them."""

    def __init__(self, app: LabApp, step: Step) -> None:
        super().__init__(app, "results")
        self.step = step
        self.view: ResultsView | None = None
        self.zoom: int | None = 0 if step.id in ("task11", "task12") else None

    def compose(self) -> ComposeResult:
        yield StepPlot("step log", "t [s]", "omega [rad/s]", id="plot-log")
        yield Static("", id="zoom-note", classes="hint")
        yield Static("computing…", id="results-lines")
        yield Static("", id="compare")

    def recompute(self) -> None:
        if self._lab_app.lab is not None:
            self._load()

    @work(thread=True, exclusive=True, group="results")
    def _load(self) -> None:
        lab = self._lab_app.lab
        assert lab is not None
        view = lab.results_view(self.step.id)
        self.app.call_from_thread(self._show, view)

    def _show(self, view: ResultsView) -> None:
        if not self.is_attached:
            return  # the step changed while the worker ran
        if not self.query("#compare"):
            self.call_after_refresh(self._show, view)
            return
        self.view = view
        if self.zoom is not None and self.zoom >= len(view.steps):
            self.zoom = 0 if view.steps else None
        self._plot()
        lines = list(view.lines) or ["no step result yet"]
        lines += [f"! {p}" for p in view.problems]
        self.query_one("#results-lines", Static).update("\n".join(lines))
        self.query_one("#compare", Static).update(
            "\n".join(
                f"{label}: yours {own} · computed {comp}" for label, own, comp in view.compare
            )
        )

    def _plot(self) -> None:
        v = self.view
        if v is None:
            return
        plot = self.query_one(StepPlot)
        note = self.query_one("#zoom-note", Static)
        if v.t.size == 0:
            plot.show([])
            note.update("no step run yet (Task 10)")
            return
        keep = np.ones(v.t.size, dtype=bool)
        if self.zoom is not None and v.steps:
            w = v.steps[self.zoom]
            keep = (v.t >= w.t0 - ZOOM_BEFORE) & (v.t <= w.t1)
            note.update(
                f"run {v.run}: step {self.zoom + 1} of {len(v.steps)}, 63 % at {_s(w.T_63)}"
                " · alt+←/→ step · F9 next"
            )
        else:
            note.update(f"run {v.run}: whole log, {len(v.steps)} rising steps · F9 zooms")
        plot.show(
            [Trace(v.t[keep], v.omega[keep], "omega"), Trace(v.t[keep], v.u[keep], "u_A", "dot")]
        )

    def pick(self, delta: int) -> None:
        """Zoom to the previous/next rising step."""
        if self.view is None or not self.view.steps:
            return
        n = len(self.view.steps)
        self.zoom = (0 if self.zoom is None else self.zoom + delta) % n
        self._plot()

    def pick_prev(self) -> None:
        """alt+left: the previous rising step."""
        self.pick(-1)

    def pick_next(self) -> None:
        """alt+right: the next rising step."""
        self.pick(1)

    def toggle_zoom(self) -> None:
        """One step, or the whole log."""
        self.zoom = None if self.zoom is not None else 0
        self._plot()

    def zoom_next(self) -> None:
        """F9: the next step, then the whole log, then the first step again."""
        if self.view is None or not self.view.steps:
            return
        if self.zoom is None:
            self.zoom = 0
        elif self.zoom + 1 >= len(self.view.steps):
            self.zoom = None
        else:
            self.zoom += 1
        self._plot()


class ModelCheckPanel(Recomputing, Vertical):
    """Measured against the first-order model and the extended one, residuals, the named cause
    with its evidence, the gain; a log recorded elsewhere can be loaded."""

    def __init__(self, app: LabApp) -> None:
        super().__init__(app)
        self.view: CheckView | None = None

    def compose(self) -> ComposeResult:
        with Horizontal(classes="plots"):
            yield TracePlot("measured vs models", "t [s]", "omega [rad/s]", id="plot-check")
            yield TracePlot("residual (baseline)", "t [s]", "rad/s", id="plot-residual")
        yield Static("computing…", id="check-lines")
        yield LabInput(placeholder="load a step log (CSV path), Enter", id="import-path")
        yield Static("", id="import-msg", classes="hint")

    def recompute(self) -> None:
        if self._lab_app.lab is not None:
            self._load()

    @work(thread=True, exclusive=True, group="check")
    def _load(self) -> None:
        lab = self._lab_app.lab
        assert lab is not None
        view = lab.check_view()
        self.app.call_from_thread(self._show, view)

    def _show(self, v: CheckView) -> None:
        if not self.is_attached:
            return  # the step changed while the worker ran
        if not self.query("#check-lines"):
            self.call_after_refresh(self._show, v)
            return
        self.view = v
        lines = self.query_one("#check-lines", Static)
        if v.problem:
            lines.update(f"run {v.run or '—'}: {v.problem}")
            return
        self.query_one("#plot-check", TracePlot).show(
            [
                Trace(v.t, v.omega, "measured"),
                Trace(v.t, v.baseline, "first order", "dot"),
                Trace(v.t, v.extended, "extended", "+"),
            ]
        )
        self.query_one("#plot-residual", TracePlot).show(
            [Trace(v.t, v.residual, "measured - model")]
        )
        lines.update(
            "\n".join(
                [
                    f"run {v.run} · cause: {v.cause}",
                    f"evidence: {v.evidence}",
                    f"extended model: {v.extended_model}",
                    f"gain: {v.gain}",
                ]
            )
        )

    @on(Input.Submitted, "#import-path")
    def _import(self, event: Input.Submitted) -> None:
        event.stop()
        lab = self._lab_app.lab
        path = event.value.strip()
        msg = self.query_one("#import-msg", Static)
        if lab is None or not path:
            msg.update("type the path of a step log (t, u, omega columns) and press Enter")
            return
        try:
            text = lab.import_run(path)
        except MinsegError as exc:
            msg.update(f"✗ {exc}")
            return
        msg.update(text)
        self._lab_app.entry_stored("import")


class ReportPanel(Recomputing, Static):
    """The summary step: F8 writes the report; the files written."""

    def recompute(self) -> None:
        paths = self._lab_app.exported
        self.update(
            "F8 (or Ctrl+P → Export report) writes report.md, report.html and the runs' CSV."
            + ("\nwritten:\n" + "\n".join(f"  {p}" for p in paths) if paths else "")
        )


def panel_for(app: LabApp, step: Step) -> Widget | None:
    """The panel of ``step``'s kind, or None."""
    acts = set(step.actions)
    if acts & {"live_velocity", "capture_omega", "meter"}:
        return LivePanel(app, step)
    if "connect" in acts:
        return ConnectPanel(app)
    if step.id == "table":
        return TablePanel(app)
    if "run_steps" in acts:
        return StepRunPanel(app, step)
    if "results" in acts:
        return ResultsPanel(app, step)
    if "model_check" in acts:
        return ModelCheckPanel(app)
    if step.id == "summary":
        return ReportPanel(app)
    return None
