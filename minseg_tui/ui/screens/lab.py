"""The lab screen: the manual's parts on the left, the current step on the right.

The screen holds the session's entries: it writes what the group types, ticks or captures
(and the run Tasks 11-15 use, a log loaded from elsewhere), says so on the app's "lab
changed" signal, and on that signal brings the navigator's marks, the entries and the step's
panel up to date. It picks the panel of each step and hands it what it shows: the app's
state through bound reactive attributes, and views of the session built in a worker.
"""

from __future__ import annotations

import asyncio
import contextlib
import re
from collections.abc import Awaitable, Callable, Sequence
from dataclasses import replace
from functools import partial
from inspect import isawaitable
from pathlib import Path
from typing import Literal, TypeVar

from textual import events, on, work
from textual.actions import SkipAction
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.command import DiscoveryHit, Hit, Hits, Provider
from textual.containers import Horizontal, Vertical
from textual.css.query import NoMatches
from textual.css.scalar import Scalar
from textual.geometry import Region
from textual.reactive import reactive
from textual.screen import Screen
from textual.signal import Signal
from textual.widget import Widget
from textual.widgets import OptionList, Static
from textual.widgets.option_list import Option
from textual.worker import get_current_worker

from minseg_tui.errors import MinsegError
from minseg_tui.lab.content.keys import PALETTE, USE_RUN, key_name
from minseg_tui.lab.content.steps import STEPS, Step
from minseg_tui.lab.saving.runs import RunInfo
from minseg_tui.lab.state.session import ImportOrder, Session, copy_import
from minseg_tui.lab.state.task10 import RunProgress
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.session import EntryView
from minseg_tui.model.plant import MeterReading
from minseg_tui.ui.keys import PanelKeys, key_label, panel_keys
from minseg_tui.ui.live import LiveBuffer, at_level
from minseg_tui.ui.messages import (
    CaptureRequested,
    LogImportRequested,
    NoticesCrowd,
    RevealRequested,
    StepShown,
    VoltageRequested,
)
from minseg_tui.ui.panels.connect import ConnectPanel
from minseg_tui.ui.panels.live import LivePanel
from minseg_tui.ui.panels.model_check import ModelCheckPanel
from minseg_tui.ui.panels.report import ReportPanel
from minseg_tui.ui.panels.results import ResultsPanel
from minseg_tui.ui.panels.square_wave import SquareWavePanel
from minseg_tui.ui.panels.table import TablePanel
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.screens.status import StatusScreen
from minseg_tui.ui.shared import Shared
from minseg_tui.ui.widgets.fields import (
    FieldForm,
    FieldRow,
    Restoring,
    Store,
    after_typed_keys,
)
from minseg_tui.ui.widgets.footer import KeyFooter
from minseg_tui.ui.widgets.prose import Prose, wrap

V = TypeVar("V")

_SHORT = {
    "Preparation": "Prep",
    "Tasks 6-9": "Task 6-9",
    "Model check": "Check",
}

NOTES = ".notes"
"""The key ending of a step's own notes field."""

DONE = ".done"
"""The key ending of a step's done? field (ticked once the group did what it asks)."""

MARKS = views.MARK | {"todo": " ", "info": " "}
"""The navigator's mark of a step's status (:data:`~minseg_tui.lab.views.session.STATUS_MARKS`,
the same under an entry and in the report; blank: nothing to say)."""

marks_legend = views.marks_legend
"""What the marks mean, for F1: '✓ done, ✗ answered but wrong, ...'."""


STEP_IDS = tuple(s.id for s in STEPS)

PANEL_KEYS: tuple[tuple[str, str, str, str], ...] = panel_keys()
"""Keys that act on the shown step's panel: (keys, the panel's action, footer label, what it
is; no label: not in the footer). Each panel names its own, each with the method that does
it (:meth:`~minseg_tui.ui.keys.PanelKeys.key_actions`); the step's form binds them (it, or
a widget in it, holds the focus on the lab screen, so Textual finds them from the focus
up), and the screen calls that method (:meth:`LabScreen.run_panel_key`). The footer shows
a key on the steps whose panel offers it (:meth:`LabScreen.offers`), after the app's and
the screen's keys (:class:`~minseg_tui.ui.widgets.footer.KeyFooter`); elsewhere the app's
binding of the key says that it is not part of this step. None is printable, so no key is
taken from typing in an entry (Ctrl+arrows stay the entry's word moves). Reveal, a lab
assistant's key, is the last, the first the footer leaves out where a line cannot hold
them all."""

WORD_KEYS = ("ctrl+left", "ctrl+right")
"""Panel keys that are a text entry's word moves as well: in an entry they move by word."""

RUN_REFUSED = "nothing can be recorded in it; start a new session to record"
"""What F5 and F6 (and the app's start of a run) say in a read-only session, after why."""

READ_ONLY_REFUSED: dict[str, str] = {
    "set_voltage": "the motor is not driven from it; start a new session to drive it",
    "capture": "omega_ss is not captured into it",
    "run_square_wave": RUN_REFUSED,
    "run_fast": RUN_REFUSED,
}
"""The panel keys a read-only session refuses, with what the refusal says after why it is
read-only: F4 captures nothing into it, so F3 drives nothing either (walk 15, D9: F3 put
3.5 V on the motor in a session opened from the class view; and F4 with the motor off said
'set a voltage first (F3)', which F3 there would refuse). Neither the footer, the palette
nor a step's own lines offer them there (:meth:`LabScreen.offers`); pressed, they say
why."""


def nav_label(step: Step, status: str = "todo") -> str:
    """Short name in the navigator: a status mark and the step's ``nav`` name, else its title
    up to its colon, abbreviated."""
    head = step.nav or step.title.split(":")[0]
    for long, short in _SHORT.items():
        head = head.replace(long, short)
    return f"{MARKS.get(status, ' ')} {head}"


HEADING_ROWS = 2
"""The rows of a step's :class:`Heading` (lab.tcss), its whole "What to do" folded."""

WHOLE_TODO_KEY = key_name("whole_todo")
"""The key that shows the whole of a step's "What to do" in its heading (and folds it)."""

MORE = f"… {WHOLE_TODO_KEY} more"
"""The end of the heading's "What to do" line when the rest of it does not fit."""

FOLD = f" ({WHOLE_TODO_KEY} folds it)"
"""The end of the whole "What to do" in the heading."""


def todo_lines(todo: str, width: int, whole: bool) -> list[str]:
    """The heading's "What to do" at ``width`` columns: one line, cut with :data:`MORE` at
    its end when it is longer; or ``whole``, all of it wrapped, :data:`FOLD` at its end."""
    text = "What to do: " + todo
    if whole:
        return wrap(text + FOLD, width)
    if len(text) <= width:
        return [text]
    cut = text[: max(width - len(MORE) + 1, 0)]
    cut = cut[: cut.rindex(" ")] if " " in cut else cut[:-1]  # a word cut off goes whole
    return [cut.rstrip(" ,;:") + MORE]


class TodoLine(Static):
    """The heading's "What to do": its first line, saying when more follows and the key
    that shows it, or all of it (:func:`todo_lines`)."""

    def __init__(self, todo: str) -> None:
        super().__init__("", classes="heading-todo", markup=False)
        self.todo = todo
        self.whole = False

    def render(self) -> str:
        return "\n".join(todo_lines(self.todo, self.content_size.width, self.whole))

    def on_resize(self) -> None:
        self.refresh(layout=self.whole)


class Heading(Vertical):
    """The step's title and the start of what to do, on one line each, kept at the top of
    the step while its own title is scrolled away (a layer of its own over the step, so the
    step's text does not move when it shows). At 80x24 a step taller than the screen landed
    on its entry with its title and instructions above the screen: the group did not see
    what the step asks. :data:`WHOLE_TODO_KEY` shows all of what to do in it, over the step
    (it showed only its first line, and the rest was above the screen), and folds it."""

    def __init__(self, step: Step) -> None:
        self.todo = TodoLine(step.todo)
        self.title = Static(step.title, classes="heading-title", markup=False)
        super().__init__(self.title, self.todo, classes="heading")
        self.display = False

    def show_step(self, step: Step) -> None:
        """Hold ``step``'s title and what to do, folded, hidden (as made for it)."""
        self.title.update(step.title)
        self.todo.todo = step.todo
        if self.whole:
            self.show_whole(False)
        self.todo.refresh()
        self.display = False

    @property
    def whole(self) -> bool:
        """All of what to do shows."""
        return self.todo.whole

    def show_whole(self, whole: bool) -> None:
        self.todo.whole = whole
        self.set_class(whole, "-whole")
        self.todo.refresh(layout=True)

    def rows(self, width: int) -> int:
        """The rows it covers at ``width`` columns."""
        return 1 + len(todo_lines(self.todo.todo, width, self.whole))


class StepPane(FieldForm):
    """The step on the right: title, goal, what to do, the step's own panel (and the readout
    it keeps in sight at the bottom) and its entry rows, in the one form that owns the rows'
    keys (:class:`~minseg_tui.ui.widgets.fields.FieldForm`); the :class:`Heading` over its
    top while it is scrolled down. It outlives the step:
    :meth:`show` puts the next step's widgets in it, so that the keys typed after PgDn, still
    on their way to it, land in the new step. :meth:`focus_on` lands in the step."""

    BINDINGS = [
        # with priority, as the app reads them, once the keys ahead of them are handled
        # (after_typed_keys: F4 has captured and moved on before the reading typed after it
        # arrives)
        *[
            Binding(key, f"panel_key('{action}', True)", show=False, priority=True)
            if key in WORD_KEYS
            else Binding(key, f"panel_key('{action}')", label, show=bool(label), priority=True)
            for keys, action, label, _ in PANEL_KEYS
            for key in keys.split(",")
        ],
        # a panel key a read-only session refuses: not in its footer (the binding above is
        # not live there), still saying why when pressed
        *[
            Binding(key, f"refused_key('{action}')", show=False, priority=True)
            for keys, action, _, _ in PANEL_KEYS
            if action in READ_ONLY_REFUSED
            for key in keys.split(",")
        ],
        # a class's bindings of a key replace its base's: the form's word moves, after the
        # panel's (which skip in a text entry)
        *(Binding(key, f"row_key('{key}')", show=False, priority=True) for key in WORD_KEYS),
    ]

    browsing: reactive[bool] = reactive(False, init=False)
    """The group browses the list of steps: the form's keys drive it (:meth:`browse`)."""

    def __init__(
        self,
        store: Store,
        restore: Callable[[FieldRow, Restoring], None],
        choose: Callable[[FieldRow, tuple[int, ...]], None],
        readonly: bool = False,
    ) -> None:
        super().__init__(store, restore, choose, readonly, classes="pane")
        self.step: Step | None = None
        """The step shown (None before the first)."""
        self.panel: Widget | None = None
        self._heading: Heading | None = None
        self._text: tuple[Heading, Prose, Prose, Prose] | None = None
        """The step's heading, title, goal and what to do: mounted with the first step, then
        given each next step's words (:meth:`show`)."""
        self._keep: FieldRow | Literal["focused", "scrolled"] = "focused"
        """What stays in view when the step grows or shrinks above its entries: the entry the
        step landed in, while it has the focus (placed again from the top of the step: the
        panel's view comes from a worker, before or after the landing, and moves the entry
        down); the focused entry; or nothing once the group scrolled (arrows, mouse) since
        the focus last moved in the step: it stays where they put it.

        A flag of ours, as Textual offers nothing for it: it scrolls a widget into view when
        the widget takes the focus, once, not when the content above it changes height later
        (``Widget.anchor`` keeps a scrollable's end in view, for logs), and it has no event
        that tells the group's scrolling from the program's (the form learns it from the
        mouse wheel and its own arrow-key actions)."""
        self._landed_at: tuple[object, ...] | None = None
        """The layout the landed entry was last placed on (:meth:`laid_out`)."""
        self._moved: tuple[FieldRow, int] | None = None
        """The entry the keys last moved to within the step (not a landing: Enter, Tab, a
        character typed off the rows) and the step's scroll when they did."""
        self._moved_at: tuple[object, ...] | None = None
        """The layout that entry was last placed on (:meth:`laid_out`)."""
        self._left_at: int | None = None
        """The scroll the form's last placing left the step at (None: none since the keys
        moved)."""
        self._revealing = False
        """Ctrl+R asked for the step's computed values: the next view drawn shows them."""

    def on_mount(self) -> None:
        self.screen.screen_layout_refresh_signal.subscribe(self, self.laid_out, immediate=True)

    def laid_out(self, _: Screen[object]) -> None:
        """The screen was laid out (called at once, the regions fresh): the entry the step
        landed in, while it has the keys and the group has not scrolled, is placed again
        from the top when this layout moved it, changed its height or changed the room
        around it. The placings deferred to after a refresh ran on whichever layout was the
        last when the screen came to them, and a layout often follows another (the step's
        scrollbar comes with the one after the layout that made the step taller than its
        view; the panel's view, a hint moving under its box): where the entry landed
        depended on the timing (Task 5 by 0 or 3 rows, Tasks 4 and 11-15 by up to 3). An
        entry the keys moved to since is placed again the same way, from the scroll the step
        had when they moved (:meth:`_place_moved_again`)."""
        landed = self._keep
        if self.is_placing:
            return
        if isinstance(landed, FieldRow) and landed is self.keyed:
            where = landed.layout_key()
            if where != self._landed_at:
                self._landed_at = where
                landed.place_now(landing=True)
            return
        self._place_moved_again()

    def _place_moved_again(self) -> None:
        """The entry the keys moved to (Enter, Tab), placed again from the scroll the step had
        when they moved, after a layout that moved it, while the step is where the last
        placing left it (nothing else scrolled it since: the group, a notice making room).
        A placing deferred to after a refresh may run before a layout still to come: '30,1
        Enter' typed on Task 5 in one burst placed the 3.5 V entry where it lay before the
        2.5 V row's hint went, and scrolled the step by 4 rows where 2 show it whole."""
        moved = self._moved
        row = self.keyed
        if moved is None or row is not moved[0] or self._keep == "scrolled":
            return
        where = row.layout_key()
        if where == self._moved_at:
            return
        self._moved_at = where
        if self._left_at != round(self.scroll_y):
            return
        with self.placing():
            self.scroll_to(y=moved[1], animate=False, immediate=True)
            row.place_now()

    def focus_row(self, row: FieldRow, landing: bool = False) -> None:
        if landing:
            self._moved = None
        elif self._moved is None or self._moved[0] is not row:
            self._moved, self._moved_at = (row, round(self.scroll_y)), None
            self._left_at = None
        super().focus_row(row, landing)

    async def show(self, step: Step, panel: Widget | None, rows: Sequence[FieldRow]) -> None:
        """Put ``step``'s widgets in the form in place of the last step's; return once they
        are mounted."""
        # no row is current, without the watcher: it would restyle the leaving row as not
        # current (its label, its box), about a sixth of a step change's CPU, just before
        # the row is removed
        self.set_reactive(FieldForm.current, None)
        self._keep, self._moved = "focused", None
        widgets: list[Widget] = []
        text = self._text
        if text is None:
            self._heading = Heading(step)
            text = self._text = (
                self._heading,
                Prose(step.title, classes="title"),
                Prose("Goal: " + step.goal, classes="goal"),
                Prose("What to do: " + step.todo, classes="todo"),
            )
            widgets += text
        else:  # the step's text stays mounted, the next step's in it: fewer widgets to style
            await self.remove_children([w for w in self.children if w not in text])
            heading, title, goal, todo = text
            heading.show_step(step)
            title.update(step.title)
            goal.update("Goal: " + step.goal)
            todo.update("What to do: " + step.todo)
        if panel is not None:
            widgets.append(panel)
            if isinstance(panel, LivePanel):
                readout = panel.readout()
                if readout is not None:
                    widgets.append(readout)
        widgets += rows
        after = panel.after_rows() if isinstance(panel, ViewPanel) else None
        if after is not None and not self.readonly:  # (a log is not loaded into it)
            widgets.append(after)
        self.scroll_to(y=0, animate=False, immediate=True)
        await self.mount_all(widgets)
        self.step, self.panel = step, panel
        self.screen.refresh_bindings()  # the footer shows this step's panel keys

    def revealing(self) -> None:
        """Ctrl+R: the view drawn next shows the step's computed values (:meth:`_drawn`)."""
        self._revealing = True

    @on(ViewPanel.Drawn)
    def _drawn(self, event: ViewPanel.Drawn) -> None:
        """The panel drew its view; what it newly shows (an answer's comparison) is brought
        into view with the entry the group is in, else the entry alone.

        Not when Ctrl+R showed the computed values while the plot is zoomed to a rise (Tasks
        11-12, or F9): the group reads its answer off that plot, and at 80x24 bringing the
        comparisons under the entry into view scrolled the plot off the screen (Task 12: by
        14 rows, the plot's frame gone). The step stays where it is, the entry kept in
        view; the values revealed show on the plot's own lines (Task 12: "the speed crosses
        it 56.88 ms after the edge" and the crossing's mark; Task 11: the rise's ends and its
        63 %), and the comparisons are brought into view once the group answers."""
        revealing, self._revealing = self._revealing, False
        panel = self.panel
        reading = isinstance(panel, ResultsPanel) and panel.zoom is not None
        if self._keep_after_rows_in_view():
            return
        if event.reveal is None or (revealing and reading):
            self._keep_entry_in_view()
        elif not self._reveal_with_entry(event.reveal):
            self._keep_entry_in_view()

    def _reveal_with_entry(self, widget: Widget) -> bool:
        """Scroll so that the focused entry and ``widget`` are both in view, the entry first
        when both do not fit (False: no entry of this step has the focus, or the group
        scrolled away)."""
        row = self.typing
        if row is None or self._keep == "scrolled":
            return False
        self._keep = "focused"  # the group answered: the landing is over
        seen = [self.scroll_y, 3]  # the scroll the layout was measured at; tries left

        def place(again: bool) -> None:
            if not (row.is_attached and widget.is_attached):
                return
            if self.scroll_y != seen[0] and seen[1] > 0:
                # another placing (the entry's own, after the view drew) scrolled the step
                # since the last layout: the regions below are from before that scroll, and
                # measured now they put the entry a few rows above the view (the row at
                # scroll 22 read as at 5: scrolled to 25, the entry's top off the screen).
                # Once the screen has laid the new scroll out.
                seen[:] = [self.scroll_y, seen[1] - 1]
                self.screen.refresh(layout=True)
                self.call_after_refresh(place, again)
                return
            view = self.scrollable_content_region
            top = row.region.y - view.y + self.scroll_y
            bottom = row.region.bottom - view.y + self.scroll_y
            end = widget.region.bottom - view.y + self.scroll_y
            # the entry's top below the heading, which covers the step's top once it scrolls
            y = min(max(self.scroll_y, end - view.height, bottom - view.height), top)
            if y > 0:
                y = min(y, max(top - HEADING_ROWS, 0))
            # the regions stay those of the scroll measured at until the screen draws the
            # new one: the next placing waits for that draw, as for another placing's scroll
            # (measured at once, the second placing read the entry at scroll 20 where the
            # screen had drawn it at 11, and put it 9 rows above the view: 1 run in 6)
            seen[0] = self.scroll_y
            self.scroll_to(y=y, animate=False, immediate=True)
            if again:  # once more when the layout has settled
                self.call_after_refresh(place, False)

        self.call_after_refresh(place, True)
        return True

    def _keep_after_rows_in_view(self) -> bool:
        """The widget the panel sets under the entries (the model check's box to load a log,
        :meth:`~minseg_tui.ui.panels.view_panel.ViewPanel.after_rows`), while it has the keys
        and the group has not scrolled away: brought into view whole, the line that answers
        under it too, once the screen is laid out (False: it has not the keys). Ctrl+P
        "Import a run log" lands in it at once, before the check's view is drawn above it:
        at 80x24 the box then sat 30 rows below the screen with the keys in it."""
        panel = self.panel
        after = panel.after_rows() if isinstance(panel, ViewPanel) else None
        if after is None or not after.is_attached or not after.has_focus_within:
            return False
        if self._keep != "scrolled":
            after.call_after_refresh(self.scroll_to_widget, after, animate=False, immediate=True)
        return True

    @on(FieldRow.Reflowed)
    def _keep_entry_in_view(self) -> None:
        """The step grew or shrank above its entries (the panel drew its view, or the
        report's files after F8; an entry's hint moved under its box or back). The entry
        the step landed in is placed again from the top of the step; an entry the group
        moved to since stays in view. Either only while the group has not scrolled away. A
        list of answers as well as a text entry (walk 12's D4: after F8 on Summary, Q4's
        answers went below the screen)."""
        landed = self._keep
        if isinstance(landed, FieldRow):
            if landed.is_attached and landed is self.keyed:
                landed.call_after_refresh(landed.bring_into_view, True)
                return
            self._keep = "focused"
        row = self.keyed
        if self._keep != "scrolled" and row is not None:
            row.call_after_refresh(row.bring_into_view)

    def make_room(self, notice: Region, kept: Sequence[Region], top: bool) -> bool:
        """Scroll the step so that the rows ``kept`` (screen regions: the entry with the keys,
        the row judged last) come out from under ``notice``, a notice at the screen's ``top``
        (else at its bottom): by as many rows as it covers of them, when the step scrolls
        that far and the rows stay between its heading and the lines docked at its bottom.
        False when it cannot (nothing scrolled): the notice is taller than the room."""
        if not kept:
            return False
        view = self.scrollable_content_region
        readouts = self.query_children(".readout")
        docked = readouts.first().outer_size.height if readouts and readouts.first().display else 0
        first, last = min(r.y for r in kept), max(r.bottom for r in kept)
        if top:
            by = notice.bottom - first  # the rows go down by this many
            y = self.scroll_y - by
            fits = y >= 0 and last + by <= view.bottom - docked
        else:
            by = last - notice.y  # the rows go up by this many
            y = self.scroll_y + by
            heading = self._heading.rows(view.width) if self._heading is not None else 0
            fits = y <= self.max_scroll_y and first - by >= view.y + heading
        if by <= 0 or not fits:
            return False
        self.scroll_to(y=y, animate=False, immediate=True)
        return True

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """A panel key is live (and in the footer) only on the steps whose panel has it, and
        not in a read-only session that refuses it (:data:`READ_ONLY_REFUSED`): there its
        hidden binding says why. Escape is the entries' only where it does not go back to
        the class view (the screen's priority binding runs first there, and the footer
        shows the first live binding of a key from the focus up: the entries' hid the way
        back)."""
        screen = self.screen
        if not isinstance(screen, LabScreen):
            return action not in ("panel_key", "refused_key")
        if action == "panel_key":
            return screen.offers(str(parameters[0]))
        if action == "refused_key":
            return screen.refuses(str(parameters[0]))
        if action == "bring_back" and parameters == ("held",):
            return screen.back is None
        return True

    async def action_refused_key(self, action: str) -> None:
        """A panel key a read-only session refuses: the line that says why."""
        screen = self.screen
        if isinstance(screen, LabScreen):
            await screen.run_panel_key(action)

    async def action_panel_key(self, action: str, word_key: bool = False) -> None:
        """A panel key (:data:`PANEL_KEYS`): the step's panel does it, after the keys typed
        before it (what stands in the entries stored first). ``word_key``: the key is a
        text entry's word move too (Ctrl+arrows), and does that in an entry (skipped here:
        the form's next binding of it runs)."""
        shown = self.screen
        if not isinstance(shown, LabScreen):
            return
        screen: LabScreen = shown  # (narrowed for the closure below)

        async def run() -> bool:
            if self.app.screen is not screen:
                return True
            if word_key and self.typing is not None:
                return False
            screen.store_typed()
            await screen.run_panel_key(action)
            return True

        if await after_typed_keys(self.app, run) is False:
            raise SkipAction()

    def on_descendant_focus(self, event: events.DescendantFocus) -> None:
        self.browsing = False
        if self._keep == "scrolled":
            self._keep = "focused"
        self.call_after_refresh(self._clear_heading, event.widget)

    def watch_scroll_y(self, old: float, new: float) -> None:
        """The heading shows while the step's own title is scrolled away, or while it shows
        all of what to do. Not on each scroll of an entry's placing (the step's top, then the
        entry): each change of its display costs a layout of the screen, so it is set once
        where the placing left the step (:meth:`placed`)."""
        super().watch_scroll_y(old, new)
        if self._heading is not None and not self.is_placing:
            self._heading.display = self._heading_wanted()

    def placed(self) -> None:
        self._left_at = round(self.scroll_y)
        if self._heading is not None:
            self._heading.display = self._heading_wanted()

    def _heading_wanted(self) -> bool:
        """The heading shows while the step's own title is scrolled away, or with all of what
        to do (:data:`WHOLE_TODO_KEY`), except while the step's own "What to do" is whole in
        view below where it would end: over Task 5's own text at 80x24 it covered all but that
        text's last line, which showed under it as a repeated line (walk 7, D3)."""
        heading = self._heading
        if heading is None:
            return False
        if heading.whole and self._own_todo_below(heading):
            return False
        return round(self.scroll_y) > 0 or heading.whole

    def _own_todo_below(self, heading: Heading) -> bool:
        """The step's own "What to do" stands whole in the step's view and reaches below the
        rows the whole heading would cover: the heading over it would leave its end showing
        under the heading (over it whole, it hides it and keeps the step's title in sight)."""
        todo = next(iter(self.query_children(".todo")), None)
        if todo is None or not todo.is_attached:
            return False
        view = self.scrollable_content_region
        region = todo.virtual_region
        top = region.y - round(self.scroll_y)
        bottom = top + region.height
        return top >= 0 and bottom <= view.height and bottom > heading.rows(view.width)

    def covered_rows(self, y: int) -> int:
        """Rows the heading covers at the step's top while it is scrolled to ``y`` (it shows
        once the step's title is scrolled away)."""
        heading = self._heading
        if heading is None or not (y > 0 or heading.whole):
            return 0
        return heading.rows(self.scrollable_content_region.width)

    @property
    def title_bottom(self) -> int:
        """The screen row under the step's title as shown (the heading's while the step is
        scrolled down, else the step's own; 0 when neither is on screen): no notice is
        drawn above it (walk 16's D7)."""
        heading, text = self._heading, self._text
        shown = heading.title if heading is not None and heading.display else None
        if shown is None and text is not None:
            shown = text[1]
        if shown is None or not shown.region:
            return 0
        return max(shown.region.bottom, 0)

    @property
    def heading_rows(self) -> int:
        """Rows the heading covers at the top of the step (0 while it is hidden)."""
        heading = self._heading
        if heading is None or not heading.display:
            return 0
        return heading.rows(self.scrollable_content_region.width)

    def toggle_whole_todo(self) -> None:
        """:data:`WHOLE_TODO_KEY`: all of the step's "What to do" over its top, or folded
        again to its first line; the entry the group is in stays in sight under it."""
        heading = self._heading
        if heading is None:
            return
        heading.show_whole(not heading.whole)
        heading.display = self._heading_wanted()
        box = self.keys_box
        focused = box if box is not None else self.screen.focused
        if focused is not None and focused is not self and self in focused.ancestors:
            self.call_after_refresh(self._clear_heading, focused)

    def _clear_heading(self, widget: Widget) -> None:
        """A focused ``widget`` under the heading (Textual scrolls a widget above the view to
        the top edge, where the heading lies) is scrolled down from under it."""
        focused = widget.has_focus or widget is self.keys_box  # the keys go to it
        if not (widget.is_attached and self.is_attached and focused and widget.region):
            return  # an empty region: not on the screen at all (below it, say), not under it
        over = self.scrollable_content_region.y + self.heading_rows - widget.region.y
        if over > 0:
            self.scroll_to(y=max(self.scroll_y - over, 0), animate=False, immediate=True)

    def watch_current(self, old: FieldRow | None, new: FieldRow | None) -> None:
        super().watch_current(old, new)
        if new is not None:
            self.browsing = False
        if new is not None and self._keep == "scrolled":
            self._keep = "focused"
        box = new.box if new is not None and new.is_attached else None
        if box is not None:
            self.call_after_refresh(self._clear_heading, box)

    def on_mouse_scroll_down(self, _: events.MouseScrollDown) -> None:
        self._group_scrolled()

    def on_mouse_scroll_up(self, _: events.MouseScrollUp) -> None:
        self._group_scrolled()

    @property
    def follows_keys(self) -> bool:
        return self._keep != "scrolled"

    def _group_scrolled(self) -> None:
        """The group scrolls: the step stays where they put it."""
        self._keep = "scrolled"

    def _scroll_lines(self, lines: int) -> None:
        """The arrow keys (on the step or in one of its entries): ``lines`` down (up if
        negative) from where the last key put the step, at once, so a burst of keys (or a
        held key on a busy machine) scrolls as many lines as were pressed; Textual's own
        defers each to the next refresh, all from the same place. The step then stays where
        the group put it."""
        if not self.allow_vertical_scroll:
            raise SkipAction()
        self._group_scrolled()
        self.scroll_to(y=self.scroll_target_y + lines, animate=False, immediate=True)

    def action_scroll_down(self) -> None:
        self._scroll_lines(1)

    def action_scroll_up(self) -> None:
        self._scroll_lines(-1)

    def _nav(self) -> StepList | None:
        navs = self.screen.query("#nav")
        nav = navs.first() if navs else None
        return nav if isinstance(nav, StepList) else None

    def browse(self) -> None:
        """The group browses the list of steps (Ctrl+L, Shift+Tab out of the step): the form
        keeps the focus with no current row (what stands in the row left is stored), and
        ↑/↓, Home/End and Enter drive the list (:meth:`off_rows_key`); a character goes
        into the step's first empty entry, as anywhere outside the rows."""
        self.store_pending()
        self.current = None
        self.browsing = True
        if self.screen.focused is not self:
            self.screen.set_focus(self, scroll_visible=False)

    def watch_browsing(self, browsing: bool) -> None:
        nav = self._nav()
        if nav is not None:
            nav.set_class(browsing, "-browsing")

    def off_rows_key(self, key: str) -> bool:
        """While browsing: ↑/↓ the step before or after (shown, the form staying on the
        list), Home/End the first or last, Enter into the step's entry."""
        nav = self._nav()
        if not self.browsing or nav is None:
            return False
        if key == "down":
            nav.action_cursor_down()
        elif key == "up":
            nav.action_cursor_up()
        elif key == "home":
            nav.action_first()
        elif key == "end":
            nav.action_last()
        elif key == "enter":
            self.focus_on("entry")
        else:
            return False
        return True

    def leave(self, delta: int) -> bool:
        """Tab or Shift+Tab out of the step: to the list of steps, while it shows."""
        nav = self._nav()
        if nav is None or not nav.display:
            return False
        self.browse()
        return True

    def landing_row(self) -> FieldRow | None:
        """The entry the step lands in: the first one with nothing in it, else the first;
        on a step with a panel, its notes and its done? do not count (the step lands at the
        top, on what the panel shows). None: no such entry."""
        rows = [
            r for r in self.rows() if self.panel is None or not r.field.key.endswith((NOTES, DONE))
        ]
        return next((r for r in rows if r.is_empty), rows[0] if rows else None)

    def focus_on(self, what: str) -> None:
        """Focus the step's landing entry (``entry``: scrolled into view, its text selected
        so that typing replaces it; the step itself, at its top, where it has none, so the
        arrow keys scroll it) or the widget the selector ``what`` finds (scrolled into
        view). At once, not after the messages already queued: keys of the same burst go
        here."""
        if what == "entry":
            row = self.landing_row()
            if row is not None:
                self.focus_row(row, landing=True)
                self._keep, self._landed_at = row, None
            else:
                self.current = None
                self.browsing = False
                self.screen.set_focus(self)
            return
        for w in self.query(what):
            self.screen.set_focus(w)
        self._keep_after_rows_in_view()  # (a widget just mounted is not laid out yet)


class StepList(OptionList, can_focus=False):
    """The list of steps. It never takes the focus: the step's form holds it, and while the
    group browses the steps (Ctrl+L, Shift+Tab out of the step) the form's keys drive the
    list (:meth:`StepPane.browse`), shown as focused meanwhile (``-browsing``). So every key
    typed on the lab screen is in the form's one queue: a character typed while browsing
    goes into the step's first empty entry, and the keys after it follow it there, with no
    key ever waiting in the list's queue for the form."""

    DEFAULT_CSS = """
    StepList.-browsing {
        background-tint: $foreground 5%;
        & > .option-list--option-highlighted {
            color: $block-cursor-foreground;
            background: $block-cursor-background;
            text-style: $block-cursor-text-style;
        }
    }
    """

    def action_cursor_down(self) -> None:
        """↓: the next step, none after the last. Textual's list goes round to its first
        entry: from the model check, ↓ ↓ then PgUp showed Preparation 1 (issue 20, walk 5),
        PgUp seemingly jumping to the list's end."""
        if self.highlighted is None or self.highlighted < self.option_count - 1:
            super().action_cursor_down()

    def action_cursor_up(self) -> None:
        """↑: the step before, none before the first."""
        if self.highlighted is None or self.highlighted > 0:
            super().action_cursor_up()

    def focus(self, scroll_visible: bool = True) -> StepList:
        """Focusing the list: the group browses the steps (:meth:`StepPane.browse`)."""
        screen = self.screen
        if isinstance(screen, LabScreen):
            screen.pane.browse()
        return self


class StepCommands(Provider):
    """The lab screen's palette: one entry per step ("Go to: Task 10: the step experiment")
    and per recorded run ("Use run steps-1 for Tasks 11-15")."""

    def entries(self) -> Sequence[tuple[str, Callable[[], object], str]]:
        """(text, what it does, help) of every entry."""
        screen = self.screen
        if not isinstance(screen, LabScreen):
            return []
        with screen.session as s:
            runs = list(s.runs)  # frozen records: read outside the session's lock
        go, use = screen.go_to, screen.use_run
        steps = [
            (f"{PALETTE['go_to']} {s.title}", partial(go, s.id), "move to this step") for s in STEPS
        ]
        if screen.readonly:  # the run in use is not changed in it (Session.select_run)
            return steps
        return (
            steps
            + [
                (
                    f"{USE_RUN} {r.name}{_interrupted(r)} for Tasks 11-15",
                    partial(use, r.name),
                    "an imported log: Tasks 11-15 are then judged on it, as the model check is"
                    if r.kind == "imported"
                    else "the run the results and the model check use",
                )
                for r in runs
            ]
            + [
                (
                    PALETTE["use_newest_run"],
                    partial(use, None),
                    "the default: no interrupted run, no imported log",
                )
            ]
        )

    async def discover(self) -> Hits:
        for text, action, help_text in self.entries():
            yield DiscoveryHit(text, action, help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for text, action, help_text in self.entries():
            score = max(matcher.match(name) for name in searched_as(text))
            if text.startswith(USE_RUN):
                score *= RUN_TIE
            if score > 0:
                yield Hit(score, matcher.highlight(text), action, text=text, help=help_text)


RUN_TIE = 0.99
"""A run's palette entry's score, as a share of the matcher's: it changes the run Tasks 11-15
are judged on, so on a tie it ranks under the other command. "import" scored 21.0 for both
"Import a run log" and "Use run imported-1 for Tasks 11-15"; the palette sorts by score
alone, and hits of its two providers (Textual's system commands, :class:`StepCommands`)
arrive in an order that changes from process to process: Enter ran one or the other. Only
scores within 1 % of each other change places."""


def _interrupted(r: RunInfo) -> str:
    """What cut a run short, in brackets after its name ('' for a complete run)."""
    return f" ({r.interruption or 'interrupted'})" if r.interrupted else ""


def searched_as(text: str) -> list[str]:
    """What a palette entry is found by: its text, and for a step of several tasks ('Go to:
    Tasks 6-9: k_v, k_a and f') the text with each task's own number ('… Task 8: …'): the
    manual names Task 7, 8 and 9, and 'task 8' matched nothing."""
    many = re.search(r"\bTasks (\d+)-(\d+)", text)
    if many is None:
        return [text]
    first, last = int(many[1]), int(many[2])
    return [text] + [
        text[: many.start()] + f"Task {n}" + text[many.end() :] for n in range(first, last + 1)
    ]


NO_MATCH = "no command matches"
"""The start of the palette's one line when nothing matches what was typed."""


class NoMatch(Provider):
    """The palette's line when no command matches the search: 'no command matches 'unplug''
    with the kinds of commands there are, in place of an empty box (walk 7, D17: Textual's
    own 'No matches found' came half a second late, after the group had looked). Matched as
    Textual's system commands and :class:`StepCommands` match, on their titles."""

    def titles(self) -> list[str]:
        screen = self.screen
        titles = [c.title for c in self.app.get_system_commands(screen)]
        if isinstance(screen, LabScreen):
            titles += [text for text, _, _ in StepCommands(screen).entries()]
        return titles

    async def search(self, query: str) -> Hits:
        if not query.strip():
            return
        matcher = self.matcher(query)
        if any(matcher.match(name) > 0 for title in self.titles() for name in searched_as(title)):
            return
        text = f"{NO_MATCH} '{query.strip()}'"
        yield Hit(
            1.0,
            text,
            lambda: None,
            text=text,
            help="try a step ('Task 5'), 'run', 'board', 'motor' or 'report'; Esc closes",
        )


def _not_taken(order: ImportOrder, got: RunInfo | OSError | MinsegError) -> None:
    """The copy made for ``order`` that no session took (its screen or the app gone): removed
    from runs/, and its log no longer held."""
    if not isinstance(got, RunInfo):
        return
    if order.logs is not None:
        order.logs.drop(order.folder / got.file)
    with contextlib.suppress(OSError):
        (order.folder / got.file).unlink()


class LabScreen(StatusScreen):
    """Navigator + step pane. PgUp/PgDn or the list move between steps; every entry autosaves.

    ``session`` is the open session, ``live`` the buffer the device worker fills,
    ``lab_changed`` the app's signal that the session changed (published here too),
    ``set_voltage`` the app's way to put a voltage (V) on the motor (F3's request, handled
    here), ``refresh`` the live plots' redraw period (s), and ``back`` the app's way back to
    the class view under this screen, for a session opened from it (None: opened from the
    start screen; Escape then is the entries'). The app binds the reactive attributes."""

    BINDINGS = [
        # the screen's before any widget's (priority: a list or a table has its own PgDn),
        # run once the keys typed before them are handled (after_typed_keys)
        Binding("pagedown,ctrl+n", "next_step", key_label("PgDn/PgUp"), priority=True),
        Binding("pageup,ctrl+b", "prev_step", "Prev step", show=False, priority=True),
        Binding("tab", "into_step(1)", show=False),
        Binding("shift+tab", "into_step(-1)", show=False),
        Binding("ctrl+l", "focus_nav", "Steps", show=False),
        Binding("ctrl+t", "toggle_nav", "Hide steps", show=False),
        Binding("ctrl+o", "whole_todo", "What to do", show=False),
        # a session opened from the class view: Escape closes it (over the entries' Escape:
        # nothing typed in it is stored), there only (check_action)
        Binding("escape", "back_to_class", "Class view", priority=True),
    ]
    COMMANDS = StatusScreen.COMMANDS | {StepCommands, NoMatch}
    AUTO_FOCUS = ".pane"
    """The step's form (the lab opens landed in its step, its entry in view, as PgDn lands)."""

    requested: reactive[float | None] = reactive(None)
    meter: reactive[MeterReading | None] = reactive(None)
    run_progress: reactive[RunProgress | None] = reactive(None)
    written: reactive[tuple[str, tuple[str, ...]]] = reactive(("", ()))

    def __init__(
        self,
        session: Shared[Session],
        live: LiveBuffer,
        lab_changed: Signal[None],
        set_voltage: Callable[[float], None],
        refresh: float = 0.25,
        back: Callable[[], Awaitable[None]] | None = None,
    ) -> None:
        super().__init__()
        self.session = session
        self._set_voltage = set_voltage
        self.back = back
        """Closes this session and shows the class view again (None: no class view under it)."""
        with session as s:
            self.readonly = s.readonly
            """A damaged session opened to be read only: nothing typed is stored."""
        self._live = live
        self._lab_changed = lab_changed
        self._refresh = refresh
        self._shown: str | None = None
        """The step last asked for (its widgets may not be in the form yet)."""
        self._views_asked = 0
        self._importing: str | None = None  # the log a worker reads and copies (as typed)
        """How many panel views were asked for (:meth:`_load`): only the last is shown."""
        self._judged: FieldRow | None = None
        """The entry the lab judged last (its verdict under its box), while it is on the
        step shown: notices are kept off it (:meth:`place_notices`)."""
        self._crowded: int | None = None
        """How many notices were on screen when the oldest was asked to go (None: none asked
        for): asked once per count, not again at each layout before it has gone."""
        self._undone: dict[str, list[str]] = {}
        """By field key, the answers Ctrl+Z took back, newest last: what Ctrl+Y brings
        forward again (until another answer is stored in the field)."""
        self._elsewhere: dict[str, tuple[str, str]] = {}
        """Readings typed into one voltage's row while the motor ran at another: the text
        typed and the line said under it (:func:`views.typed_at_another_level`), said as long
        as that text stands there (not stored: the session does not know the motor's voltage
        when a value was typed)."""
        self.shown = asyncio.Event()
        """Set once the first step is on screen and focused (the app waits for it before it
        hands on the keys typed after the Enter that opened the lab)."""

    def compose(self) -> ComposeResult:
        yield self.status_line()
        with self.session as s:
            labels = [nav_label(st, s.step_status(st.id)) for st in STEPS]
        with Horizontal(id="body"):
            yield StepList(
                *[Option(label, id=st.id) for label, st in zip(labels, STEPS, strict=True)],
                id="nav",
            )
            yield StepPane(self._store, self._restore, self._choose, self.readonly)
        yield KeyFooter()

    async def on_mount(self) -> None:
        self._lab_changed.subscribe(self, self._on_lab_changed)
        self.screen_layout_refresh_signal.subscribe(self, self._laid_out)
        with self.session as s:
            current = s.current_step
        start = current if current in STEP_IDS else STEP_IDS[0]
        self._highlight(STEP_IDS.index(start))
        await self.show_step(start, "entry")
        self.shown.set()

    # -- the step on screen --------------------------------------------------------------
    @property
    def pane(self) -> StepPane:
        """The form that shows the step."""
        return self.query_one(StepPane)

    @property
    def step(self) -> Step:
        """The step on screen."""
        step = self.pane.step
        assert step is not None
        return step

    @property
    def panel(self) -> Widget | None:
        """The panel of the step on screen (the last pane mounted; the one before may still be
        leaving), or None. Read from the body's children, not by a walk of the whole screen:
        the footer asks for the panel keys (:meth:`panel_keys`) whenever the keys change."""
        try:
            panes = self.get_child_by_id("body").query_children(StepPane)
        except NoMatches:  # not composed yet
            return None
        return panes.first().panel if panes else None

    @property
    def step_id_shown(self) -> str | None:
        """The id of the step on screen, read as :attr:`panel` is (the footer asks for it
        too); None before the screen is composed or while it has no step."""
        try:
            panes = self.get_child_by_id("body").query_children(StepPane)
        except NoMatches:  # not composed yet
            return None
        step = panes.first().step if panes else None
        return step.id if step is not None else None

    def place_notices(self) -> None:
        """Notices (Textual's toasts, as wide as half the screen, on its right, where the
        entries' boxes and verdicts are) show on the side of the screen with more room
        away from the entry the group types in (or the widget focused in the step) and the
        entry the lab judged last, its verdict under it: at the bottom, where Textual puts
        them, or at the top. F8's list of files sat over the summary's last field, being
        typed in (issue 20, walk 5); on Task 5 a notice sat over the reading just judged,
        above the entry the keys had moved on to (walk 12's D5). When the notices on that
        side still cover either entry, the app is asked to take the oldest away
        (:class:`NoticesCrowd`; the newest always stays): two F8 in a row stacked notices over
        eleven rows (walk 12). Called again whenever the screen is laid out while notices
        show, where their heights are known."""
        focused = self.focused
        pane = self.pane if self.query(StepPane) else None
        keyed = pane.current if pane is not None and pane.keys_box is not None else None
        widget = keyed if keyed is not None else focused  # the entry: its box and verdict
        kept = [w.region for w in (widget, self._judged) if w is not None and w is not pane]
        kept = [r for r in kept if r]  # on screen (a row scrolled away has none)
        low = False
        if kept:
            above = min(r.y for r in kept)  # rows over them, the status line's included
            below = self.size.height - max(r.bottom for r in kept)
            low = above > below
        # on top, the notices start under the step's title, which they hid at 80x24 (walk
        # 16's D7: "Task 4: u_ss and omega_▌ set a voltage first (F3)"): its first row is
        # the status line's, kept by the notice's own margin
        rack = (
            self.query_children("ToastRack").first() if self.query_children("ToastRack") else None
        )
        if rack is not None and low and pane is not None:
            margin = max(pane.title_bottom - 1, 0)
            if rack.styles.margin.top != margin:
                rack.styles.margin = (margin, 0, 0, 0)
        elif rack is not None and rack.styles.inline.has_rule("margin"):
            rack.styles.clear_rule("margin")  # at the bottom: Textual's, which keeps the footer
        if low != self.has_class("-notices-top"):
            self.set_class(low, "-notices-top")
            return  # the notices move: looked at again once laid out there
        # a notice never taller than the rows between the status line (or, on top, the
        # step's title) and the footer: one of 27 rows at 80x24 rose over the status line
        # at the bottom, its title and first rows out of the screen, and on top it ran
        # under the footer; cut, it shows its beginning, the title with it
        top = rack.styles.margin.top if rack is not None and low else 0
        room = max(self.size.height - 2 - top, 3)
        for toast in self._toasts():
            if toast.styles.max_height != Scalar.from_number(room):
                toast.styles.max_height = room
        toasts = [t.region for t in self._toasts()]
        if len(toasts) == self._crowded:
            return  # the oldest is on its way out
        self._crowded = None
        if len(toasts) > 1 and any(t.overlaps(r) for t in toasts for r in kept):
            # too many at once for the room on that side: the oldest goes (the app holds them)
            self._crowded = len(toasts)
            self.post_message(NoticesCrowd())
        elif pane is not None and toasts and any(toasts[0].overlaps(r) for r in kept):
            # one notice taller than the room on its side: the step makes room under it, or
            # the notice is made wider (so fewer rows) and looked at again once laid out
            if not pane.make_room(toasts[0], kept, low) and not self.has_class("-notices-wide"):
                self.add_class("-notices-wide")
        elif not toasts and self.has_class("-notices-wide"):
            self.remove_class("-notices-wide")

    def _laid_out(self, _: Screen[object]) -> None:
        """The screen was laid out: notices that came or went, or rows that moved, are placed
        anew (:meth:`place_notices`) once their regions are known."""
        if self.is_current and self._toasts():
            self.place_notices()
        elif self.has_class("-notices-wide"):  # the notices have gone: the next starts narrow
            self.remove_class("-notices-wide")

    def _toasts(self) -> list[Widget]:
        """The notices on the screen, oldest first (Textual's toasts, in its rack of them, a
        child of the screen: not a walk of the whole screen at each layout)."""
        racks = self.query_children("ToastRack")
        return list(racks.first().query("Toast")) if racks and racks.first().display else []

    def offers(self, action: str) -> bool:
        """Whether panel key ``action`` (:data:`PANEL_KEYS`) acts on the step shown: its panel
        has the key (its ``KEYS``), it does something here (its ``check_action``), and the
        session takes what it does (a read-only one refuses :data:`READ_ONLY_REFUSED`)."""
        return self._has_key(action) and not (self.readonly and action in READ_ONLY_REFUSED)

    def refuses(self, action: str) -> bool:
        """Whether panel key ``action`` would act on the step shown but this read-only session
        refuses it (pressed, it says why; offered nowhere)."""
        return self.readonly and action in READ_ONLY_REFUSED and self._has_key(action)

    def _has_key(self, action: str) -> bool:
        panel = self.panel
        if not isinstance(panel, PanelKeys) or action not in panel.key_actions():
            return False
        return panel.check_action(action, ()) is not False

    async def run_panel_key(self, action: str) -> None:
        """Panel key ``action``: the step's panel does it, by a plain call of the method it
        names for it (:meth:`~minseg_tui.ui.keys.PanelKeys.key_actions`; nothing on a step
        whose panel does not have it), and this returns once it is done (F4's capture: the
        keys typed after it act on the result)."""
        panel = self.panel
        if self.readonly and action in READ_ONLY_REFUSED:
            with self.session as s:
                said = f"{views.read_only(s)}: {READ_ONLY_REFUSED[action]}"
            self.notify(said, severity="warning")
            return
        if isinstance(panel, PanelKeys) and self.offers(action):
            # A call from the form's binding (StepPane.action_panel_key): Textual looks for a
            # key's bindings from the focused widget up (textual/screen.py:408-424), and the
            # panel is never focused; the form around it is.
            done = panel.key_actions()[action]()
            if isawaitable(done):
                await done

    def _panel_for(self, step: Step) -> Widget | None:
        """The panel of ``step``'s kind (None for steps that only take entries), bound to the
        state it shows."""
        acts = set(step.actions)
        if acts & {"live_velocity", "capture_omega", "meter"}:
            return LivePanel(step, self._live, self._refresh, self.readonly).data_bind(
                LabScreen.requested, LabScreen.meter, LabScreen.device
            )
        if "connect" in acts:
            return ConnectPanel().data_bind(LabScreen.device)
        if step.id == "table":
            return TablePanel()
        if "run_square_wave" in acts:
            return SquareWavePanel(step, self._live, self._refresh, self.readonly).data_bind(
                LabScreen.run_progress
            )
        if "results" in acts:
            return ResultsPanel(step)
        if "model_check" in acts:
            return ModelCheckPanel()
        if step.id == "summary":
            return ReportPanel(self.readonly).data_bind(LabScreen.written)
        return None

    def _rows(self, step: Step) -> list[FieldRow]:
        with self.session as s:
            return [
                FieldRow(
                    f,
                    views.typed(s, f.key),
                    views.entry(s, f.key),
                    views.chosen(s, f.key),
                    readonly=self.readonly,
                    held=views.held(s, f.key),
                )
                for f in step.fields
            ]

    async def show_step(self, step_id: str, focus: str | None) -> None:
        """Put ``step_id`` on the right and remember it in the session; return once its pane
        is mounted and ``focus`` focused (see :meth:`StepPane.focus_on`; None: the focus stays
        where it is), so that a key handled after this one acts on the new step."""
        if self._shown == step_id:  # not the DOM: a pane mounted with the screen is not in it yet
            return
        self.store_typed()  # what stands in the entries of the step being left
        self._shown = step_id
        step = STEPS[STEP_IDS.index(step_id)]
        if not self.readonly:
            with self.session as s:
                s.go_to(step_id)
        panel = self._panel_for(step)
        pane = self.pane
        self.post_message(StepShown(step))
        await pane.show(step, panel, self._rows(step))
        if isinstance(panel, ViewPanel):
            self._load(panel)
        if focus is not None and self._shown == step_id:
            pane.focus_on(focus)

    def _load(self, panel: ViewPanel[V]) -> None:
        """Build ``panel``'s view in a worker, from a frozen snapshot of the session as it
        stands now (the worker never reads the live session)."""
        with self.session as s:
            snapshot = s.snapshot()
        self._views_asked += 1
        self._build(panel, snapshot, self._views_asked)

    @work(thread=True, exclusive=True, group="view", name="panel view")
    def _build(self, panel: ViewPanel[V], session: Session, asked: int) -> None:
        """Worker: build ``panel``'s view from ``session`` (a snapshot) and hand it over, as
        the ``asked``-th view asked for."""
        worker = get_current_worker()
        quick = panel.sketch(session) if panel.view is None else None
        if quick is not None and not worker.is_cancelled:  # shown first, while it builds
            self.app.call_from_thread(self._deliver, panel, quick, asked)
        view = panel.build(session)
        if not worker.is_cancelled:
            self.app.call_from_thread(self._deliver, panel, view, asked)

    def _deliver(self, panel: ViewPanel[V], view: V, asked: int) -> None:
        if asked != self._views_asked:
            # a view of an older snapshot: the worker passed its check for cancellation just
            # before a newer view was asked for, and its hand-over may come after the newer
            # one's, which it would replace until the session changed again
            return
        if panel.is_attached:  # else the step changed while the worker ran
            panel.receive(view)
            if not self.readonly:  # the report says when the group first saw each value
                with self.session as s:
                    views.note_drawn(s, view)

    def _on_lab_changed(self, _: None) -> None:
        """The session changed: the navigator's marks, the entries the lab changed (a
        capture) or warns about anew, and the panel's view."""
        self.refresh_marks()
        pane = self.pane
        with self.session as s:
            for row in pane.rows():
                text = views.typed(s, row.field.key)
                row.held = views.held(s, row.field.key)
                key = row.field.key
                if row.sent is not None and text != row.sent:
                    result = views.entry(s, key)
                    row.lab_changed(
                        text, self._said_elsewhere(key, text, result) if result else None
                    )
                elif (result := views.entry(s, key)) is not None:
                    # a warning another row raised or cleared
                    row.update_result(self._said_elsewhere(key, text, result))
        panel = pane.panel
        if isinstance(panel, ViewPanel):
            self._load(panel)

    def _changed(self) -> None:
        self._lab_changed.publish(None)

    # -- moving ------------------------------------------------------------------------
    @on(OptionList.OptionHighlighted, "#nav")
    async def _highlighted(self, event: OptionList.OptionHighlighted) -> None:
        """The group browses the list of steps: each step shows, the form stays on the list
        (:attr:`StepPane.browsing`; moved by the mouse: the step's entry)."""
        if event.option_index != event.option_list.highlighted:
            return  # stale: the list's first highlight on mount, after a resume moved it on
        if event.option.id:
            focus = None if self.pane.browsing else "entry"
            await self.show_step(event.option.id, focus)

    def _highlight(self, index: int) -> None:
        """Highlight step ``index`` in the list of steps without the message that the group
        browsed there (the caller shows the step, with the focus it wants)."""
        nav = self.query_one("#nav", OptionList)
        with nav.prevent(OptionList.OptionHighlighted):
            nav.highlighted = index

    @on(OptionList.OptionSelected, "#nav")
    def _selected(self, event: OptionList.OptionSelected) -> None:
        self.call_after_refresh(self.pane.focus_on, "entry")

    def go_to(self, step_id: str, focus: str | None = "entry") -> None:
        """Move the navigator (and so the pane) to ``step_id``; then focus its first entry
        (``focus="entry"``), the widget the selector ``focus`` finds, or leave the focus
        where it is (None)."""
        index = STEP_IDS.index(step_id)
        nav = self.query_one("#nav", OptionList)
        if nav.highlighted == index and self._shown == step_id:
            if focus is not None:
                self.pane.focus_on(focus)
            return
        self._highlight(index)
        self.call_later(self.show_step, step_id, focus)

    async def _move(self, delta: int) -> None:
        """PgDn/PgUp: the next or previous step, shown with its entry focused after the keys
        typed before the key (they land in the step being left) and before those typed after
        it are handed on (they land in the new step)."""
        nav = self.query_one("#nav", OptionList)
        index = max(0, min(len(STEPS) - 1, (nav.highlighted or 0) + delta))
        if index == nav.highlighted:
            return
        self._highlight(index)
        shown = asyncio.Event()

        async def show() -> None:  # on the screen's own queue (its panels bind to it)
            try:
                await self.show_step(STEP_IDS[index], "entry")
            finally:
                shown.set()

        if self.call_later(show):
            await shown.wait()

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """Escape goes back to the class view (and the footer says so) only in a session
        opened from it."""
        if action == "back_to_class":
            return self.back is not None
        return super().check_action(action, parameters)

    async def action_back_to_class(self) -> None:
        """Escape: this read-only session closed and the class view shown again, after the
        keys typed before it (those typed after it go to the class view)."""
        await after_typed_keys(self.app, self._back_to_class)

    async def _back_to_class(self) -> None:
        if self.back is not None and self.app.screen is self:
            await self.back()

    async def action_next_step(self) -> None:
        await after_typed_keys(self.app, partial(self._move, 1))

    async def action_prev_step(self) -> None:
        await after_typed_keys(self.app, partial(self._move, -1))

    def action_into_step(self, delta: int) -> None:
        """Tab (Shift+Tab) outside the step: into its first (last) field or widget."""
        self.pane.enter(delta)

    def action_focus_nav(self) -> None:
        nav = self.query_one("#nav")
        nav.display = True
        self.pane.browse()

    def action_whole_todo(self) -> None:
        """Ctrl+O: the whole of the step's "What to do" (again: folded)."""
        self.pane.toggle_whole_todo()

    def action_toggle_nav(self) -> None:
        """Hide or show the list of steps (more room for the step at 80 columns)."""
        nav = self.query_one("#nav")
        nav.display = not nav.display
        if not nav.display:
            self.pane.browsing = False

    def refresh_marks(self) -> None:
        """Update the status marks in the navigator after an entry or a run."""
        nav = self.query_one("#nav", OptionList)
        with self.session as s:
            labels = [nav_label(st, s.step_status(st.id)) for st in STEPS]
        for k, label in enumerate(labels):
            if str(nav.get_option_at_index(k).prompt) != label:
                nav.replace_option_prompt_at_index(k, label)

    # -- what the group enters -----------------------------------------------------------
    def store_typed(self) -> None:
        """Store what stands in the shown step's entries and was not stored yet (any key that
        leaves an entry, or the step, calls this): accepted or refused, as Enter does."""
        for row in self.pane.rows():
            text = row.pending()
            if text is not None:
                self._store(row, text, submitted=False)

    def _store(self, row: FieldRow, text: str, submitted: bool, undoing: bool = False) -> EntryView:
        """Store ``text`` for ``row`` (``submitted``: with Enter) and show the verdict. An
        answer stored by any means but Ctrl+Z or Ctrl+Y (``undoing``) ends what Ctrl+Y
        could bring forward in that field."""
        if not undoing:
            self._undone.pop(row.field.key, None)
        if self.readonly:
            with self.session as s:
                result = EntryView(False, f"{views.read_only(s)}: not stored")
            row.show_result(result)
            return result
        key = row.field.key
        with self.session as s:
            old = s.entry(key)
            before = old.text if old is not None and old.ok else ""
            s.enter(key, text)
            result = views.entry(s, key) or EntryView(True)
            row.held = views.held(s, key)
        elsewhere = views.typed_at_another_level(key, self.requested) if text.strip() else ""
        if elsewhere:
            self._elsewhere[key] = (text, elsewhere)
        else:
            self._elsewhere.pop(key, None)
        row.show_result(self._said_elsewhere(key, text, result))
        self._judged_now(row)
        if not submitted and before.strip() and row.held != before:
            # an answer replaced by leaving the field, not by Enter (a stray key, say): said,
            # and Ctrl+Z in the field brings the old one back
            self.notify(
                f"{row.field.label}: {text.strip()!r} stored in place of {before.strip()!r} "
                f"(not confirmed with Enter); {key_name('undo')} in the field brings the old answer "
                "back",
                title="answer replaced",
            )
        self._changed()
        return result

    def _said_elsewhere(self, key: str, text: str, result: EntryView) -> EntryView:
        """``result`` with the line of :attr:`_elsewhere` added while ``text``, the text that
        stands in ``key``, is the reading it was said of (and accepted)."""
        typed, line = self._elsewhere.get(key, ("", ""))
        if not line or not result.ok or typed != text or line in result.warnings:
            return result
        return replace(result, warnings=(*result.warnings, line))

    def _restore(self, row: FieldRow, how: Restoring) -> None:
        """Escape in an entry: a refused text the lab keeps there is dropped with its refusal
        (the answer in effect stands alone again, and its mark in the list of steps comes
        back). Ctrl+Z: the answer stored before the one in effect (one further back each
        time), entered again; Ctrl+Y: the answer the last Ctrl+Z took back. Either says what
        it brought back, in place of what, and how it is judged."""
        if how == "held":
            self._withdraw(row)
            return
        key, label = row.field.key, row.field.label
        undone = self._undone.setdefault(key, [])
        with self.session as s:
            current = views.held(s, key)
            if how == "undo":
                target = views.previous_answer(s, key, skip=undone)
            else:
                target = undone[-1] if undone else None
        if target is None:
            self.notify(
                f"{label}: no earlier answer to bring back"
                if how == "undo"
                else f"{label}: nothing to bring forward ({key_name('redo')} undoes a {key_name('undo')})",
                title="undo" if how == "undo" else "redo",
            )
            return
        row.refresh_from_lab(target, None)
        row.input.cursor_position = len(target)
        result = self._store(row, target, submitted=True, undoing=True)
        if how == "undo":
            undone.append(current)
        else:
            undone.pop()
        with self.session as s:
            verdict = views.judged(s, key) if result.ok else ""
            further = views.previous_answer(s, key, skip=undone) is not None
        said = f"{label}: back to {target.strip()!r}"
        if current.strip():
            said += f" in place of {current.strip()!r}"
        if verdict:
            said += f"; {verdict}"
        keys = [f"{key_name('undo')} goes further back"] if further else []
        if undone:
            keys.append(f"{key_name('redo')} brings {undone[-1].strip()!r} back")
        self.notify(said + (f" ({', '.join(keys)})" if keys else ""), title="answer brought back")

    def _withdraw(self, row: FieldRow) -> None:
        """Escape in ``row``: the refused text the lab keeps for it dropped (nothing else
        stored), and the row shows what is in effect, without the refusal."""
        if self.readonly:
            return
        key = row.field.key
        with self.session as s:
            if not s.withdraw_refused(key):
                return
            held = views.held(s, key)
            result = views.entry(s, key) or EntryView(True)
            row.held = held
        row.refresh_from_lab(held, result)
        row.input.cursor_position = len(held)
        self._changed()

    def _choose(self, row: FieldRow, indices: tuple[int, ...]) -> None:
        """The group ticked options ``indices`` (0-based) of ``row``'s list: stored, and the
        verdict shown."""
        if self.readonly:
            with self.session as s:
                stored = views.chosen(s, row.field.key)
                # said without ✗, the mark of a wrong answer: the group's answer under it is
                # not judged by this (walk 18, walk 17's D2 left)
                row.show_result(EntryView(True, f"{views.read_only(s)}: not stored"))
            # the list shows what the group answered, not the pick just refused (walk 17's
            # D2: the lab assistant saw 'a signal' picked where the group had 'a system')
            row.show_chosen(stored)
            return
        key = row.field.key
        with self.session as s:
            s.choose(key, list(indices))
            result = views.entry(s, key) or EntryView(True)
        row.show_result(result)
        self._judged_now(row)
        self._changed()

    def _judged_now(self, row: FieldRow) -> None:
        """The lab judged ``row``: the notices on screen move off it and off the entry the
        keys go to, if they lie over either (:meth:`place_notices`)."""
        self._judged = row
        if self.query("Toast"):
            self.call_after_refresh(self.place_notices)  # once the keys have moved on

    def focus_after(self, key: str) -> None:
        """Focus the entry after field ``key`` (stays put on the last one)."""
        self.pane.focus_after(key)

    def watch_requested(self, level: float | None) -> None:
        """F3 set the motor to ``level`` (V) while the group types in a row of another voltage
        (Tasks 4-5): typing goes on in the first empty row of the new voltage (else its
        first), its text selected so that the next reading replaces it and lands in the row
        of the voltage on the motor. When the keys are already in a row of that voltage, that
        row is made ready the same way (walk 12's D1: '37,1' stood with the cursor at its
        end, and 'F3 37 Enter' stored '37,137'). What stood typed in a row was stored before
        (the panel key stores it, as leaving an entry does)."""
        if level is None or not self.is_attached:
            return
        panes = self.query(StepPane)
        pane = panes.first() if panes else None
        if pane is None or pane.current is None or pane.current.field.level is None:
            return
        if pane.current.field.level == level:
            pane.focus_row(pane.current)
            return
        rows = [r for r in pane.rows() if not r.field.options and r.field.level == level]
        if rows:
            pane.focus_row(next((r for r in rows if r.is_empty), rows[0]))

    @on(CaptureRequested)
    def _capture(self, event: CaptureRequested) -> None:
        """F4: omega_ss from the settled window of the live stream."""
        event.stop()
        try:
            self._capture_now(event.level)
        finally:
            event.done.set()

    def _capture_now(self, level: float) -> None:
        if self.readonly:  # walk 14, D1: the capture's save raised, and the program died
            with self.session as s:
                said = f"{views.read_only(s)}: omega_ss is not captured into it"
            self.notify(said, severity="warning")
            return
        t, count = at_level(*self._live.snapshot(), level)
        with self.session as s:
            result = views.capture_live(s, level, t, count)
        if not result.ok:  # a success shows in the field itself; a toast would hide the meter
            self.notify(result.message, severity="warning")
        self._changed()
        if result.ok:  # next comes the multimeter reading at the same voltage
            self.focus_after(f"omega_ss@{level:g}")

    @on(VoltageRequested)
    def _voltage(self, event: VoltageRequested) -> None:
        """F3: the app puts the voltage on the motor, now (a plain call: the app reads the
        keys typed after F3 once this is done)."""
        event.stop()
        try:
            self._set_voltage(event.level)
        finally:
            event.done.set()

    @on(RevealRequested)
    def _reveal(self, event: RevealRequested) -> None:
        """Ctrl+R: the step's computed values shown before the group answered (the report says so)."""
        event.stop()
        with self.session as s:
            keys = s.reveal(event.step_id)
            waiting = "" if keys else views.reveal_waits(s, event.step_id)
            read_only = views.read_only(s) if s.readonly else ""
        if not keys:
            self.notify(waiting or "nothing hidden on this step", severity="information")
            return
        if read_only:  # walk 14, D1: the reveal's save raised, and the program died
            self.notify(f"computed values shown here, not recorded: {read_only}")
        if event.step_id == self.step_id_shown:
            self.pane.revealing()
        # else no notice: the step's comparisons say it beside each value shown ("revealed
        # before answering (Ctrl+R): the report says so"); a notice over the step's top
        # covered Task 12's title and three rows of the plot being read for 5 s at 80x24
        self._changed()

    @on(LogImportRequested)
    def _import(self, event: LogImportRequested) -> None:
        """A run log recorded elsewhere: the model check uses it; Tasks 11-15 keep their run
        unless the group chooses the import (walk 16's D3: an EV3 motor's log imported at
        the model check took Tasks 11-15 with it, and Tasks 11-12 turned ✗, 13-14 !). It is
        read, checked and copied in a worker (s38 attack: a 227 MB log froze the screen for
        97 s); meanwhile the reply says it is being read, and a second log waits its turn."""
        event.stop()
        if self._importing is not None:
            event.reply(f"still reading {self._importing}: load {event.path} once it is in")
            return
        try:
            with self.session as s:
                order = s.import_order(Path(event.path).expanduser())
        except MinsegError as exc:
            event.reply(f"✗ {exc}")
            return
        self._importing = event.path
        event.reply(f"reading {event.path} ...")
        self._copy(self.app, order, event.path, event.reply, self._shown)

    @work(thread=True, group="import", name="import a run log")
    def _copy(
        self,
        app: App[object],
        order: ImportOrder,
        path: str,
        reply: Callable[[str], None],
        shown: str | None,
    ) -> None:
        """Worker: read, check and copy the log of ``order`` (no session touched), then hand
        what became of it to :meth:`_imported`, on the UI thread, where the screen is known
        to be there or not: a copy that arrives after the lab screen closed (the app running
        on) or the app stopped is a run of no session, and is removed, nothing said. ``app``:
        the app, as the UI thread had it (a screen closed meanwhile no longer finds it)."""
        got: RunInfo | OSError | MinsegError
        try:
            got = copy_import(order)
        except MinsegError as exc:
            got = exc
        settled = False

        def deliver() -> None:
            nonlocal settled
            settled = True
            if self.is_attached:
                self._imported(order, got, path, reply, shown)
            else:  # the screen closed while the log was read: not said on another screen
                _not_taken(order, got)

        try:
            app.call_from_thread(deliver)
        except RuntimeError:  # the app gone meanwhile
            if settled:
                raise
        if not settled:
            _not_taken(order, got)

    def _imported(
        self,
        order: ImportOrder,
        got: RunInfo | OSError | MinsegError,
        path: str,
        reply: Callable[[str], None],
        shown: str | None,
    ) -> None:
        """The copy of the log asked for at step ``shown`` is made (or refused): the session
        takes it, and ``reply`` says so (a notice too when the step shown changed)."""
        self._importing = None
        info: RunInfo | None
        try:
            if isinstance(got, MinsegError):
                raise got
            with self.session as s:
                info = s.add_import(order, got)
                said = views.imported(s, path, info)
        except MinsegError as exc:
            said, info = f"✗ {exc}", None
        reply(said)
        if shown != self._shown:  # the box that asked is not in view
            self.notify(said, title="import", severity="information" if info else "error")
        if info is not None:
            self._changed()

    def use_run(self, name: str | None) -> None:
        """Tasks 11-15 and the model check use run ``name`` (None: the newest complete step
        run); an imported log the model check used gives way to it."""
        try:
            with self.session as s:
                s.select_run(name)
                said = views.run_in_use(s)
        except MinsegError as exc:
            self.notify(str(exc), severity="error")
            return
        self.notify(said, title="runs")
        self._changed()
