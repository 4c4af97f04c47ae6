"""Task 10: the step experiment on the board, 25 ms beside 5 ms, with the T readings."""

from __future__ import annotations

from collections.abc import Callable, Mapping

from textual.app import ComposeResult
from textual.containers import Horizontal
from textual.reactive import reactive
from textual.widgets import ProgressBar, Static

from minseg_tui.lab.content.keys import key_name
from minseg_tui.lab.content.steps import Step
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.state.task10 import RunProgress
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.session import RunView
from minseg_tui.quantities import SPEED_AXIS, TIME_AXIS, format_number, format_value
from minseg_tui.ui.keys import PanelKeys
from minseg_tui.ui.live import LiveBuffer
from minseg_tui.ui.messages import RunRequested
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.widgets.plots import Trace, TracePlot
from minseg_tui.ui.widgets.prose import Prose

FAST_WHY = (
    "Why 5 ms matters: the published MinSeg figures give T near 0.04 s, under two 25 ms "
    "samples, and the manual's 20-tap average spans 0.5 s. Read at 25 ms through the "
    "average, the 63 % time mostly measures the filter; at 5 ms, board-timed, the rise "
    "itself is visible. Compare the T readings side by side:"
)


PLOT_OF = {"steps": "plot-slow", "fast": "plot-fast"}
"""The plot (its id) each kind of run is drawn in."""

PLOT_TITLE = {"steps": "25 ms run", "fast": "5 ms run"}
"""Each plot's title before it shows a run; then the run's name (and whether it is the one
in use for Tasks 11-15) follows."""


class SquareWavePanel(ViewPanel[tuple[RunView, ...]], PanelKeys):
    """F5/F6 ask for the board's square wave; shows the app's ``run_progress`` while it
    waits for the wheel and while it records (F2 stops it at once), the run plotted as it
    arrives from the ``live`` buffer (redrawn every ``refresh`` s; at each progress when 0),
    then the latest 25 ms run beside the 5 ms one with both T readings next to each other."""

    run_progress: reactive[RunProgress | None] = reactive(None)

    def __init__(
        self, step: Step, live: LiveBuffer, refresh: float = 0.25, readonly: bool = False
    ) -> None:
        super().__init__()
        self.step = step
        self.readonly = readonly
        """A read-only session: F5 and F6 refuse there, so its lines do not offer them."""
        self._live = live
        self._refresh = refresh

    def on_mount(self) -> None:
        if self._refresh > 0:
            self.set_interval(self._refresh, self.draw_live)

    def compose(self) -> ComposeResult:
        plans = dict(self.step.plans)
        m = plans["manual"]
        steps = f"{m.periods} steps 0 → {m.high:g} V, {m.half_period:g} s each"
        fast = f"{plans['fast'].ts * 1000:g} ms"
        yield Prose(
            f"The runs: {steps}, at {m.ts * 1000:g} ms, or the same at {fast}; none is "
            "recorded in a read-only session."
            if self.readonly
            else f"{key_name('run_square_wave')}: {steps}, at {m.ts * 1000:g} ms. "
            f"{key_name('run_fast')}: the same at {fast}. {key_name('stop_motor')} stops.",
            classes="hint",
        )
        # no bar until a run waits or records here: a bar at 0 % beside the run in use read
        # as 'nothing recorded' on a resumed session (walk 15, D7)
        bar = ProgressBar(total=100, show_eta=False, id="run-progress")
        bar.display = False
        yield bar
        yield Prose("", id="run-status")
        with Horizontal(classes="plots"):
            for kind, plot in PLOT_OF.items():
                yield TracePlot(PLOT_TITLE[kind], TIME_AXIS, SPEED_AXIS, id=plot)
        yield Prose(FAST_WHY, classes="para")
        yield Static("", id="t-readings", markup=False)

    def build(self, session: Session) -> tuple[RunView, ...]:
        return views.runs(session)

    def sketch(self, session: Session) -> tuple[RunView, ...] | None:
        """The runs' speeds without their T readings when a run's fits are not made yet (a
        resumed session): the plots show the run in use at once."""
        quick = views.runs(session, fits=False)
        return quick if any(not v.fitted for v in quick) else None

    @property
    def recording(self) -> bool:
        """Whether a run is being recorded (or waits for the wheel to stand) now."""
        p = self.run_progress
        return p is not None and (p.recording or p.waiting)

    def watch_run_progress(self, old: RunProgress | None, new: RunProgress | None) -> None:
        """Move the bar and say where the run is: while it waits and records, and when it
        ends (a run that ended before the panel was shown leaves the bar alone)."""
        busy = old is not None and (old.recording or old.waiting)
        if new is None or not (new.recording or new.waiting or busy):
            return
        self.call_later(self._progress, new)

    def _progress(self, p: RunProgress) -> None:
        bar = self.query_one(ProgressBar)
        bar.display = True
        bar.update(progress=100 * p.fraction)
        self.query_one("#run-status", Prose).update(p.text)
        if self._refresh <= 0:
            self.draw_live()

    def draw_live(self) -> None:
        """While a run records: plot what has arrived of it, from the live buffer."""
        p = self.run_progress
        if p is None or not p.recording or p.t0 is None or p.kind not in PLOT_OF:
            return
        t, count, _u = self._live.snapshot()
        v = views.recording(t, count, p.t0)
        if v.x.size == 0:
            return
        traces = [Trace(v.x, v.omega, "board time")]
        if p.kind == "steps":
            traces.append(Trace(v.x, v.omega_lab, "manual", "dot"))
        plot = self.query_one(f"#{PLOT_OF[p.kind]}", TracePlot)
        plot.set_axes(f"{PLOT_TITLE[p.kind]}: recording", TIME_AXIS)
        plot.show(traces, (0.0, max(p.duration, 1e-3)))

    def show_view(self) -> None:
        runs = self.view
        if runs is None:
            return
        live = self.run_progress.kind if self.recording and self.run_progress else ""
        for v in runs:
            if v.kind == live or not v.plotted:
                continue  # being recorded again: the plot shows the new run as it arrives
            plot = self.query_one(f"#{PLOT_OF.get(v.kind, 'plot-fast')}", TracePlot)
            if v.kind in PLOT_TITLE:  # which run it shows, and whether it is the one in use
                name = f"{v.name}, in use" if v.in_use else v.name
                plot.set_axes(f"{PLOT_TITLE[v.kind]}: {name}", TIME_AXIS)
            traces = [Trace(v.t, v.omega, "board time")]
            if v.kind == "steps":
                traces.append(Trace(v.t, v.omega_lab, "manual", "dot"))
            plot.show(traces)
        rows = [f"{'run':<11}{'T 63% manual':>13}{'T 63%':>10}{'T fit (95% CI)':>27}"]
        for v in runs:
            ci = (
                f" ({format_number(v.T_ci[0], 3)}..{format_number(v.T_ci[1], 3)})" if v.T_ci else ""
            )
            name = ("▸ " if v.in_use else "  ") + v.name
            rows.append(
                f"{name:<11}{format_value(v.T_63_lab, 's', 3) if v.kind == 'steps' else '—':>13}{format_value(v.T_63, 's', 3):>10}"
                f"{format_value(v.T_ls, 's', 3) + ci:>27}"
            )
        if not runs:
            rows.append(
                f"no run yet: {key_name('run_square_wave')} (25 ms), then "
                f"{key_name('run_fast')} (5 ms)"
            )
        elif any(not v.fitted for v in runs):
            rows = rows[:1] + ["working out the T readings…"]
        elif any(v.T_hidden for v in runs):
            rows.append("T: shown once you enter your own T (Task 12)")
        self.query_one("#t-readings", Static).update("\n".join(rows))
        if not self.recording:
            said = ", ".join(
                f"{'▸ ' if v.in_use else ''}{v.name} ({v.samples} samples"
                f"{f', interrupted: {v.interruption}' if v.interrupted else ''}"
                f"{', in use for Tasks 11-15' if v.in_use else ''})"
                for v in runs
            )
            self.query_one("#run-status", Prose).update(said or "no runs recorded yet")

    def key_actions(self) -> Mapping[str, Callable[[], object]]:
        return {"run_square_wave": self.action_run_square_wave, "run_fast": self.action_run_fast}

    def action_run_square_wave(self) -> None:
        """F5: the manual's plan at 25 ms."""
        self.post_message(RunRequested("manual"))

    def action_run_fast(self) -> None:
        """F6: the same at 5 ms."""
        self.post_message(RunRequested("fast"))
