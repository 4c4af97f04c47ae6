"""Task 10: the step experiment on the board, 25 ms beside 5 ms, with the T readings."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.containers import Horizontal
from textual.reactive import reactive
from textual.widgets import ProgressBar, Static

from minseg_tui.lab import views
from minseg_tui.lab.session import Session
from minseg_tui.lab.steps import Step
from minseg_tui.lab.views import RunView
from minseg_tui.ui.messages import RunRequested
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.recording import RunProgress
from minseg_tui.ui.widgets.plots import Trace, TracePlot

FAST_WHY = (
    "Why 5 ms matters: the published MinSeg figures give T near 0.04 s, under two 25 ms "
    "samples, and the manual's 20-tap average spans 0.5 s. Read at 25 ms through the "
    "average, the 63 % time mostly measures the filter; at 5 ms, board-timed, the rise "
    "itself is visible. Compare the T readings side by side:"
)


def _s(v: float | None) -> str:
    return "—" if v is None else f"{v:.3f} s"


class StepRunPanel(ViewPanel[tuple[RunView, ...]]):
    """F5/F6 ask for the board's step sequence; shows the app's ``run_progress`` while it
    records (F2 stops it at once), then the latest 25 ms run beside the 5 ms one with both T
    readings next to each other."""

    run_progress: reactive[RunProgress | None] = reactive(None)

    def __init__(self, step: Step) -> None:
        super().__init__()
        self.step = step

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

    def build(self, session: Session) -> tuple[RunView, ...]:
        return views.runs(session)

    @property
    def recording(self) -> bool:
        """Whether a run is being recorded now."""
        return self.run_progress is not None and self.run_progress.recording

    def watch_run_progress(self, old: RunProgress | None, new: RunProgress | None) -> None:
        """Move the bar and say where the run is: while it records and when it ends (a run
        that ended before the panel was shown leaves the bar alone)."""
        if new is None or not (new.recording or (old is not None and old.recording)):
            return
        self.call_later(self._progress, new)

    def _progress(self, p: RunProgress) -> None:
        self.query_one(ProgressBar).update(progress=100 * p.fraction)
        self.query_one("#run-status", Static).update(p.text)

    def show_view(self) -> None:
        runs = self.view
        if runs is None:
            return
        for v in runs:
            plot = self.query_one("#plot-slow" if v.kind == "steps" else "#plot-fast", TracePlot)
            traces = [Trace(v.t, v.omega, "board time")]
            if v.kind == "steps":
                traces.append(Trace(v.t, v.omega_lab, "manual", "dot"))
            plot.show(traces)
        rows = [f"{'run':<9}{'T 63% manual':>13}{'T 63%':>9}{'T fit (95% CI)':>24}"]
        for v in runs:
            ci = f" ({v.T_ci[0]:.3f}..{v.T_ci[1]:.3f})" if v.T_ci else ""
            rows.append(
                f"{v.name:<9}{_s(v.T_63_lab) if v.kind == 'steps' else '—':>13}{_s(v.T_63):>9}"
                f"{_s(v.T_ls) + ci:>24}"
            )
        if not runs:
            rows.append("no run yet: F5 (25 ms), then F6 (5 ms)")
        self.query_one("#t-readings", Static).update("\n".join(rows))
        if not self.recording:
            said = ", ".join(
                f"{v.name} ({v.samples} samples{', interrupted' if v.interrupted else ''})"
                for v in runs
            )
            self.query_one("#run-status", Static).update(said or "no runs recorded yet")

    def run_steps(self) -> None:
        """F5: the manual's plan at 25 ms."""
        self.post_message(RunRequested("manual"))

    def run_fast(self) -> None:
        """F6: the same at 5 ms."""
        self.post_message(RunRequested("fast"))
