"""The lab screen: the manual's parts on the left, the current step on the right."""

from __future__ import annotations

from textual import events, on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, VerticalScroll
from textual.screen import Screen
from textual.widget import Widget
from textual.widgets import Footer, Input, OptionList, Static
from textual.widgets.option_list import Option

from minseg_tui.lab.steps import Step
from minseg_tui.ui.ports import Lab
from minseg_tui.ui.widgets.fields import FieldRow
from minseg_tui.ui.widgets.status import DeviceStatus

_SHORT = {
    "Preparation": "Prep",
    "Summary and reflections (section 3.2)": "Summary",
    "Tasks 6-9": "Task 6-9",
    "Model check": "Check",
}

MARKS = {"done": "✓", "started": "…", "todo": " ", "info": " "}
"""The navigator's mark of a step's status (a character, not a colour)."""


def nav_label(step: Step, status: str = "todo") -> str:
    """Short name in the navigator: a status mark and the title up to its colon, abbreviated."""
    head = step.title.split(":")[0]
    for long, short in _SHORT.items():
        head = head.replace(long, short)
    return f"{MARKS.get(status, ' ')} {head}"


class StepPane(VerticalScroll):
    """Title, goal, what to do, the step's own panel (``extra``) and its entries."""

    def __init__(self, step: Step, lab: Lab, extra: Widget | None) -> None:
        super().__init__(classes="pane")
        self.step = step
        self._lab = lab
        self._extra = extra
        # With entries on the step, Tab goes straight to them (focusing one scrolls it
        # into view); a pane of text only stays focusable so the keys can scroll it.
        self.can_focus = not step.fields

    def compose(self) -> ComposeResult:
        yield Static(self.step.title, classes="title")
        yield Static("Goal: " + self.step.goal, classes="goal")
        yield Static("What to do: " + self.step.todo, classes="todo")
        if self._extra is not None:
            yield self._extra
            readout = getattr(self._extra, "readout", None)
            docked = readout() if callable(readout) else None
            if docked is not None:
                yield docked
        for f in self.step.fields:
            yield FieldRow(
                f, self._lab.text(f.key), self._lab.result(f.key), self._lab.chosen(f.key)
            )

    def on_mount(self) -> None:
        self.screen.refresh_bindings()  # the footer shows this step's panel keys

    @property
    def panel(self) -> Widget | None:
        """The step's own panel (live plots, table, runs, results...), or None."""
        return self._extra


class LabScreen(Screen[None]):
    """Navigator + step pane. PgUp/PgDn or the list move between steps; every entry autosaves."""

    BINDINGS = [
        Binding("pagedown,ctrl+n", "next_step", "Next step", priority=True),
        Binding("pageup,ctrl+b", "prev_step", "Prev step", show=False, priority=True),
        Binding("ctrl+l", "focus_nav", "Steps", show=False),
        Binding("ctrl+t", "toggle_nav", "Hide steps", show=False),
    ]

    def __init__(self, lab: Lab) -> None:
        super().__init__()
        self.lab = lab
        self._shown: str | None = None
        """The step whose pane was last mounted (the DOM may not hold it yet)."""

    def compose(self) -> ComposeResult:
        yield DeviceStatus()
        with Horizontal(id="body"):
            yield OptionList(
                *[Option(nav_label(s, self.lab.status(s.id)), id=s.id) for s in self.lab.steps],
                id="nav",
            )
            yield Static("", classes="pane")
        yield Footer()

    def on_mount(self) -> None:
        nav = self.query_one("#nav", OptionList)
        ids = [s.id for s in self.lab.steps]
        start = self.lab.current if self.lab.current in ids else ids[0]
        nav.highlighted = ids.index(start)
        self.show_step(start)

    @property
    def step(self) -> Step:
        """The step on screen."""
        return self.query(StepPane).last().step

    @property
    def panel(self) -> Widget | None:
        """The panel of the step on screen (the last pane mounted; the one before may still be
        leaving), or None."""
        panes = self.query(StepPane)
        return panes.last().panel if panes else None

    def show_step(self, step_id: str) -> None:
        """Put ``step_id`` on the right and remember it in the session."""
        step = next(s for s in self.lab.steps if s.id == step_id)
        if self._shown == step_id:  # not the DOM: a pane mounted with the screen is not in it yet
            return
        self._shown = step_id
        self.lab.go(step_id)
        extra = self.app.step_panel(step)  # type: ignore[attr-defined]
        nav_has_focus = self.focused is self.query_one("#nav")
        self.query(".pane").remove()
        self.query_one("#body").mount(StepPane(step, self.lab, extra))
        if not nav_has_focus:  # moved with PgDn/PgUp or the palette: land in the first entry
            self.call_after_refresh(self._focus_first_input)

    @on(OptionList.OptionHighlighted, "#nav")
    def _highlighted(self, event: OptionList.OptionHighlighted) -> None:
        if event.option_index != event.option_list.highlighted:
            return  # stale: the list's first highlight on mount, after a resume moved it on
        if event.option.id:
            self.show_step(event.option.id)

    @on(OptionList.OptionSelected, "#nav")
    def _selected(self, event: OptionList.OptionSelected) -> None:
        self.call_after_refresh(self._focus_first_input)

    def _focus_first_input(self) -> None:
        panes = self.query(StepPane)
        rows = panes.last().query(FieldRow) if panes else None
        if rows:
            rows.first().focus_input()

    def on_key(self, event: events.Key) -> None:
        """Typing on the list of steps goes into the step's first entry, not nowhere."""
        if (
            self.focused is not self.query_one("#nav")
            or not event.is_printable
            or not event.character
        ):
            return
        inputs = self.query(StepPane).last().query(Input)
        if inputs:
            event.stop()
            event.prevent_default()
            inputs.first().focus()
            inputs.first().insert_text_at_cursor(event.character)

    @on(FieldRow.Typed)
    def _typed(self, event: FieldRow.Typed) -> None:
        result = self.lab.enter(event.key, event.text)
        event.row.show_result(result)
        self.app.entry_stored(event.key)  # type: ignore[attr-defined]
        if result.ok and event.submitted:  # Enter on an accepted entry moves on to the next one
            self.focus_after(event.key)

    def focus_after(self, key: str) -> None:
        """Focus the entry after field ``key`` (stays put on the last one)."""
        rows = list(self.query(FieldRow))
        keys = [r.field.key for r in rows]
        if key in keys and keys.index(key) + 1 < len(rows):
            rows[keys.index(key) + 1].focus_input()

    @on(FieldRow.Chosen)
    def _chosen(self, event: FieldRow.Chosen) -> None:
        event.row.show_result(self.lab.choose(event.key, event.indices))
        self.app.entry_stored(event.key)  # type: ignore[attr-defined]

    def _move(self, delta: int) -> None:
        nav = self.query_one("#nav", OptionList)
        n = len(self.lab.steps)
        nav.highlighted = max(0, min(n - 1, (nav.highlighted or 0) + delta))

    def action_next_step(self) -> None:
        self._move(1)

    def action_prev_step(self) -> None:
        self._move(-1)

    def action_focus_nav(self) -> None:
        nav = self.query_one("#nav")
        nav.display = True
        nav.focus()

    def action_toggle_nav(self) -> None:
        """Hide or show the list of steps (more room for the step at 80 columns)."""
        nav = self.query_one("#nav")
        nav.display = not nav.display

    def refresh_marks(self) -> None:
        """Update the status marks in the navigator after an entry or a run."""
        nav = self.query_one("#nav", OptionList)
        for k, s in enumerate(self.lab.steps):
            label = nav_label(s, self.lab.status(s.id))
            if str(nav.get_option_at_index(k).prompt) != label:
                nav.replace_option_prompt_at_index(k, label)

    def go_to(self, step_id: str) -> None:
        """Move the navigator (and the pane) to ``step_id``."""
        ids = [s.id for s in self.lab.steps]
        self.show_step(step_id)  # mount the pane now; the highlight below then changes nothing
        self.query_one("#nav", OptionList).highlighted = ids.index(step_id)
        self.call_after_refresh(self._focus_first_input)
