"""The model check: what the first-order model gets wrong in the run, and a log to load."""

from __future__ import annotations

from collections.abc import Callable, Mapping

from textual import on
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.widget import Widget
from textual.widgets import Collapsible, Input

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.session import CheckView
from minseg_tui.quantities import SPEED_AXIS, TIME_AXIS
from minseg_tui.ui.keys import PanelKeys, key_hint
from minseg_tui.ui.messages import LogImportRequested
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.widgets.fields import FOCUS_MARK
from minseg_tui.ui.widgets.plots import Trace, TracePlot
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox

DETAILS = "Details: what each figure means · Enter opens"
"""The fold's title while shut (the details follow the sentences a student reads first)."""

DETAILS_OPEN = "Details: what each figure means · Enter closes"
"""The fold's title while open (walk 16's D8: "Enter opens" on an open fold)."""

WHOLE_LOG = "measured vs models"
"""The check's plot's title when it shows the whole log (not the close-up where the cause
acts)."""

WHOLE_LOG_ONE, CLOSE_UP, CLOSE_UP_ONE = "measured vs model", "where the cause acts", "close-up"
"""The plot's titles when the check names no cause (only the first-order model is drawn:
walk 16's D8, a "+ ext." legend and "where the cause acts" with nothing extended), and the
close-up's when it names one."""

FOLD_SHUT, FOLD_OPEN = "+", "−"
"""Before a fold's title: shut (Enter opens it) and open. Not Textual's own "▶"/"▼": "▶" is
the mark of the entry the keys go to (:data:`~minseg_tui.ui.widgets.fields.FOCUS_MARK`),
and at 80x24 without colour two "▶" showed at once, the fold's and the path box's."""


class ModelCheckPanel(ViewPanel[CheckView], PanelKeys):
    """What the first-order model gets wrong in the run: first the close-up where the cause
    acts (measured, both models, and their residuals against the noise floor), F9 switches
    to the whole log and back; under it two or three sentences a student reads first (what
    the simple model gets wrong at the close-up's step, the likely cause in everyday words,
    how much better the extended model does), then a fold with the details, each figure
    with what it measures and why it matters: the simple model, the figure that leads,
    why the cause, the extended model, the other figures, the noise and what the run cannot
    show. A log recorded elsewhere can be loaded (Enter in the path
    asks for it): its box stands under the step's notes (:meth:`after_rows`), so that Tab
    reaches the notes first and notes are never typed into it."""

    def __init__(self) -> None:
        super().__init__()
        self.close_up = True
        """The close-up where the cause acts (False: the whole log)."""
        self._import = ImportBox()

    def compose(self) -> ComposeResult:
        plots = Horizontal(classes="plots check-plots")
        plots.display = False  # no empty frames while the check works: shown with its view
        with plots:
            yield TracePlot(WHOLE_LOG, TIME_AXIS, SPEED_AXIS, id="plot-check")
            yield TracePlot("residual", TIME_AXIS, "rad/s", id="plot-residual")
        yield Prose("computing…", id="check-story")
        with Collapsible(
            title=DETAILS,
            id="check-details",
            collapsed=True,
            collapsed_symbol=FOLD_SHUT,
            expanded_symbol=FOLD_OPEN,
        ):
            yield Prose("", id="check-lines")

    @on(Collapsible.Expanded, "#check-details")
    @on(Collapsible.Collapsed, "#check-details")
    def _fold_title(self, event: Collapsible.Expanded | Collapsible.Collapsed) -> None:
        """The fold's title says what Enter does now: opens it, or closes it."""
        fold = event.collapsible
        fold.title = DETAILS if fold.collapsed else DETAILS_OPEN

    def after_rows(self) -> Widget:
        """The box to load a log recorded elsewhere, under the step's notes."""
        return self._import

    def build(self, session: Session) -> CheckView:
        return views.check(session)

    def show_view(self) -> None:
        v = self.view
        if v is None:
            return
        story = self.query_one("#check-story", Prose)
        lines = self.query_one("#check-lines", Prose)
        plots = self.query_one(".check-plots")
        run = f"run {v.run or '—'}" + (f" ({v.elsewhere})" if v.elsewhere else "")
        if v.problem:
            plots.display = False
            story.update(f"{run}: {v.problem}")
            lines.update("")
            return
        self._plot()
        plots.display = True
        where = (
            f"{run}, {v.close_title} · {key_hint('zoom_next', 'the whole log')}"
            if self.close_up and v.close_t.size
            else f"{run}, the whole log · "
            f"{key_hint('zoom_next', 'the close-up the words speak of')}"
        )
        story.update("\n".join([where, " ".join([*v.story, v.other_T]).rstrip()]))
        # a blank line between the parts: at 80x24 the paragraphs ran together
        text = [f"cause: {v.cause_words or v.cause}", *v.details]
        lines.update("\n\n".join(text))

    def _plot(self) -> None:
        v = self.view
        if v is None:
            return
        check = self.query_one("#plot-check", TracePlot)
        residual = self.query_one("#plot-residual", TracePlot)
        named = v.cause != "none"  # no cause: no extended model to draw
        if self.close_up and v.close_t.size:
            t, om, ba, ex = v.close_t, v.close_omega, v.close_baseline, v.close_extended
            check.set_axes(CLOSE_UP if named else CLOSE_UP_ONE, TIME_AXIS)
            residual.set_axes("measured - model", TIME_AXIS)
        else:
            t, om, ba, ex = v.t, v.omega, v.baseline, v.extended
            check.set_axes(WHOLE_LOG if named else WHOLE_LOG_ONE, TIME_AXIS)
            residual.set_axes("measured - model, whole log", TIME_AXIS)
        span = (float(t[0]), float(t[-1])) if t.size > 1 else None
        # drawn in this order: the measured speed (and the first order's miss) on top
        check.show(
            [
                *([Trace(t, ex, "extended", "+", colour=2, short="ext.")] if named else []),
                Trace(t, ba, "first order", "braille", colour=1, short="1st order"),
                Trace(t, om, "measured", "dot", colour=0, short="meas."),
            ],
            span,
        )
        # the residuals carry their model's marker and colour (the title says measured -)
        traces = []
        if v.noise is not None and span is not None:
            lo, hi = span
            traces += [
                Trace([lo, hi], [v.noise, v.noise], "noise ±", "-", colour=3),
                Trace([lo, hi], [-v.noise, -v.noise], "", "-", colour=3),
            ]
        if named:
            traces.append(Trace(t, om - ex, "extended", "+", colour=2, short="ext."))
        traces.append(Trace(t, om - ba, "first order", "braille", colour=1, short="1st order"))
        residual.show(traces, span)

    def key_actions(self) -> Mapping[str, Callable[[], object]]:
        return {"zoom_next": self.action_zoom_next}

    def action_zoom_next(self) -> None:
        """F9: the close-up, or the whole log."""
        self.close_up = not self.close_up
        self.show_view()

    def imported(self, text: str) -> None:
        """Say what became of the log asked for (one line)."""
        self._import.imported(text)


class ImportBox(Vertical):
    """A run log recorded elsewhere: its path, Enter asks for it (the lab screen loads it
    and answers in one line under the box). While the box has the keys its label has the
    mark an entry's label has then (:data:`~minseg_tui.ui.widgets.fields.FOCUS_MARK`; walk
    13: unmarked, it took a note meant for the box above it)."""

    LABEL = "A run log recorded elsewhere (CSV): its path, then Enter"

    def __init__(self) -> None:
        super().__init__(classes="import")

    def compose(self) -> ComposeResult:
        yield Prose(self.LABEL, id="import-label", classes="hint")
        yield TextBox(placeholder="load a run log (CSV path), Enter", id="import-path")
        yield Prose("", id="import-msg", classes="hint")

    def on_descendant_focus(self) -> None:
        self.query_one("#import-label", Prose).update(FOCUS_MARK + self.LABEL)

    def on_descendant_blur(self) -> None:
        self.query_one("#import-label", Prose).update(self.LABEL)

    @on(Input.Submitted, "#import-path")
    def _import(self, event: Input.Submitted) -> None:
        event.stop()
        path = event.value.strip()
        if not path:
            self.imported("type the path of a run log (t, u, omega columns) and press Enter")
            return
        self.post_message(LogImportRequested(path, self.imported))

    def imported(self, text: str) -> None:
        """Say what became of the log asked for (one line); nothing once the box is gone
        (the lab screen's notice says it then)."""
        if self.is_attached:
            self.query_one("#import-msg", Prose).update(text)
