"""The model check: what the first-order model gets wrong in the run, and a log to load."""

from __future__ import annotations

from textual import on
from textual.app import ComposeResult
from textual.containers import Horizontal
from textual.widgets import Input

from minseg_tui.lab import views
from minseg_tui.lab.session import Session
from minseg_tui.lab.views import CheckView
from minseg_tui.ui.messages import LogImportRequested
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.widgets.plots import Trace, TracePlot
from minseg_tui.ui.widgets.prose import Prose


class ModelCheckPanel(ViewPanel[CheckView]):
    """Measured against the first-order model and the extended one, residuals, the named cause
    with its evidence, the gain; a log recorded elsewhere can be loaded (Enter in the path
    asks for it)."""

    def compose(self) -> ComposeResult:
        with Horizontal(classes="plots"):
            yield TracePlot("measured vs models", "t [s]", "omega [rad/s]", id="plot-check")
            yield TracePlot("residual (baseline)", "t [s]", "rad/s", id="plot-residual")
        yield Prose("computing…", id="check-lines")
        yield Input(placeholder="load a step log (CSV path), Enter", id="import-path")
        yield Prose("", id="import-msg", classes="hint")

    def build(self, session: Session) -> CheckView:
        return views.check(session)

    def show_view(self) -> None:
        v = self.view
        if v is None:
            return
        lines = self.query_one("#check-lines", Prose)
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
        path = event.value.strip()
        if not path:
            self.imported("type the path of a step log (t, u, omega columns) and press Enter")
            return
        self.post_message(LogImportRequested(path, self.imported))

    def imported(self, text: str) -> None:
        """Say what became of the log asked for (one line)."""
        self.query_one("#import-msg", Prose).update(text)
