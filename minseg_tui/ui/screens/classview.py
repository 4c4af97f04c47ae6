"""The class view in the lab assistant: every group of the sessions folder, one row each.

Opened from the start screen (F12). The groups are read in a worker thread, each session
opened read-only (:func:`minseg_tui.lab.views.classview.read_group`: no lock, nothing written),
and each row appears as soon as its session is read; once all are in, the class's median
decides which values are far from the class, one of the things marked "!"
(:data:`~minseg_tui.lab.views.classview.MARKED`). Under the table, the highlighted group in
full: every number with its unit, the model check's cause, the group's own values against
the computed ones, what is marked and what is missing. Enter opens the group's session read-only (as the start
screen opens a damaged one) over the class view, and Escape there comes back to it, the cursor
on that group; F8 writes the class's report (class.md, class.html, class.csv,
as ``minseg-tui class --out`` does) into the sessions folder; Escape goes back. Everything
works from the keyboard at 80x24.
"""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable, Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from rich.cells import cell_len
from rich.text import Text
from textual import events, on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.message import Message
from textual.screen import Screen
from textual.widgets import DataTable, Static

from minseg_tui.errors import InputError
from minseg_tui.lab.content.keys import KEY_NAMES
from minseg_tui.lab.saving.store import os_reason
from minseg_tui.lab.views import classread, classview
from minseg_tui.lab.views.classview import QUANTITIES, ClassView, Group
from minseg_tui.quantities import MISSING, format_difference
from minseg_tui.ui.widgets.fields import after_typed_keys
from minseg_tui.ui.widgets.footer import KeyFooter
from minseg_tui.ui.widgets.inturn import run_in_turn

GroupOpener = Callable[[Path], Awaitable[None]]
"""Opens the session in a folder read-only, over the class view, and returns once the lab
shows it (the app's)."""

ClassWriter = Callable[[ClassView, Path], Sequence[Path]]
"""Writes the class's report into a folder; the files written (the CLI hands in
:func:`minseg_tui.report.write.write_class`: the report layer sits beside the UI)."""

NO_WRITER = "this program was started without the report writer"
"""Said when a report is asked for of an app made without its writer (the lab's, the
class's)."""

COLUMNS: tuple[tuple[str, str], ...] = (
    ("#", "n"),
    ("group", "members"),
    ("step", "step"),
    ("!", "flags"),
    ("R", "R"),
    ("k_v", "k_v"),
    ("K", "K"),
    ("T", "T"),
    ("J", "J"),
)
"""The table's columns (header, what it holds), narrow enough for 80 columns: ``!`` counts
what the view marks (:data:`~minseg_tui.lab.views.classview.MARKED`); the numbers are in the units the
lab shows them in (T in ms; the group's detail below gives each unit), R with the digits typed."""


MEMBERS_WIDTH = 16
"""The group column's width (characters): longer names are cut in the table, so that J, the
last column, stays on an 80-column screen; the detail below gives them whole."""


TITLE = "Class view for instructors (read-only)"
"""How the screen names itself: the instructors' view of every group, which changes nothing."""


def _quantity(key: str) -> classview.Quantity:
    return next(q for q in QUANTITIES if q.key == key)


def _step(g: Group) -> str:
    """The furthest step the group reached, as the lab's list of steps names it ("Prep 7", "Summary"),
    with "run cut" when the run Tasks 11-15 use was interrupted (the detail below says how)."""
    step = g.step.replace("Preparation", "Prep").replace("Summary and reflections", "Summary")
    return (step or MISSING) + (", run cut" if g.notes else "")


def _members(g: Group) -> str:
    return ", ".join(g.members) or ("(cannot be read)" if not g.readable else g.id)


def row(k: int, g: Group) -> tuple[str, ...]:
    """The table's cells for group number ``k``."""
    return (
        str(k),
        _members(g),
        _step(g),
        str(len(g.flags)) if g.flags else ("?" if not g.readable else ""),
        *(g.text(key) for key in ("R", "k_v", "K", "T", "J")),
    )


def detail(k: int, g: Group) -> Text:
    """Everything of group number ``k``, as lines of text (no markup: names are the
    students' own)."""
    out = Text()
    out.append(f"#{k} {_members(g)}", style="bold")
    where = f"reached {g.step or '?'}" + (f", now at {g.at}" if g.at and g.at != g.step else "")
    out.append(f"  {g.date or 'no date'} · {where} · {g.id}\n")
    nums = [f"{q.key} {'–' if g.value(q.key) is None else g.with_unit(q.key)}" for q in QUANTITIES]
    out.append(" · ".join(nums) + "\n")
    on = f" (on {g.check_on})" if g.check_on else ""
    out.append(f"model check: {g.cause or 'not run'}{on}\n")
    for o in g.own:
        if o.rel_diff is not None:
            out.append(
                f"{o.label}: {format_difference(o.own, o.computed)} from the value computed the group's way"
                + (f", {o.mark} {'right' if o.right else 'wrong'}" if o.mark else "")
                + "\n"
            )
    for f in g.flags:
        out.append(f"! {f}\n", style="bold")
    for x in g.lacks:
        out.append(f"- lacks: {x}\n")
    for x in g.notes:
        out.append(f"- note: {x}\n")
    if not g.flags:
        out.append(f"Nothing marked '!' ({classview.MARKED}).\n")
    if not g.lacks:  # what the numbers above need (walk 14, D3: "Nothing is missing." stood
        # under a group with one row of three and no Summary)
        other = "else " if g.notes else ""
        out.append(f"Nothing {other}the numbers above need is missing.\n")
    if g.unanswered:
        out.append(f"Not answered yet: {g.unanswered}.\n")
    out.append(classview.NOT_MARKED + "\n")
    return out


def read_class(root: Path) -> ClassView:
    """Every session under ``root`` read now (read-only) and the class judged; InputError:
    ``root`` is not a sessions folder."""
    return classview.judge([classread.read(folder) for folder in classview.session_folders(root)])


class ClassTable(DataTable[Text]):
    """The class's table, one row a group: its arrows (Home, End, PgUp, PgDn) move the
    cursor as each key is read, so an Enter typed right after them opens the group they moved
    to (:mod:`minseg_tui.ui.widgets.inturn`; walk 15's D1)."""

    async def on_key(self, event: events.Key) -> None:
        await run_in_turn(self, event)


class ClassScreen(Screen[None]):
    """The class view of ``root`` (a sessions folder)."""

    BINDINGS = [
        Binding("escape", "back", "Back"),
        Binding("enter", "open_group", "Open read-only", priority=True),
        Binding("f8", "export_class", "Export class"),
    ]
    AUTO_FOCUS = "#class-table"

    @dataclass
    class GroupRead(Message):
        """A group's row is ready (its number in the table from 1)."""

        number: int
        group: Group

    @dataclass
    class ClassWritten(Message):
        """The class's report is written to ``paths`` (or ``error``: why not)."""

        paths: tuple[Path, ...]
        error: str = ""

    @dataclass
    class ClassRead(Message):
        """Every group is read and judged against the class (or ``error``: why not)."""

        view: ClassView | None
        error: str = ""

    def __init__(
        self,
        root: Path,
        writer: ClassWriter | None = None,
        open_group: GroupOpener | None = None,
    ) -> None:
        super().__init__()
        self.root = Path(root)
        self.writer = writer
        """Writes the class's report (F8); None: this program was started without it."""
        self.open_group = open_group
        """Opens a group's session read-only over this screen (Enter); None: nowhere to."""
        self.groups: list[Group] = []
        self.view: ClassView | None = None
        """The class judged, once every group is read (what F8 writes)."""
        self._arrived = asyncio.Event()
        """Set when a group's row comes in or the reading ends (Enter waits for its row)."""
        self._ended = False
        """The reading has ended (every group in, or an error said in the title)."""
        self._left = False
        """Another screen (a group opened read-only) was shown over this one since it was
        read: shown again, it reads the sessions again."""

    @property
    def done(self) -> bool:
        """Every group is read and the class judged: :attr:`view` is set."""
        return self.view is not None

    def compose(self) -> ComposeResult:
        yield Static(Text(f"{TITLE} of {self.root} — reading the sessions…"), id="class-title")
        table = ClassTable(id="class-table", cursor_type="row", zebra_stripes=True)
        yield table
        with VerticalScroll(id="class-detail"):
            yield Static("", id="class-group")
        yield KeyFooter()

    def on_mount(self) -> None:
        self._fill()
        self._read()

    def _fill(self) -> None:
        """(Re)build the table from :attr:`groups`, each column as wide as its widest cell
        (the group's names: :data:`MEMBERS_WIDTH`), the cursor kept on its row. The widths
        are set here, with the values, not measured by the table once it is idle: on a
        loaded PC the columns once kept their headers' widths and cut every number to it,
        R "5", K "1", J "0" (walk 9, D5)."""
        table = self.query_one(DataTable)
        cursor = table.cursor_row
        rows = [row(k, g) for k, g in enumerate(self.groups, 1)]
        table.clear(columns=True)
        for n, (header, key) in enumerate(COLUMNS):
            width = max([cell_len(header), *(cell_len(r[n]) for r in rows)])
            table.add_column(header, key=key, width=MEMBERS_WIDTH if key == "members" else width)
        for k, cells in enumerate(rows, 1):
            table.add_row(*map(Text, cells), key=str(k))
        if rows:
            table.move_cursor(row=min(max(cursor, 0), len(rows) - 1))

    def _append(self, k: int, g: Group) -> None:
        """Add group ``k``'s row under the others. The table is built again (:meth:`_fill`)
        only when a cell is wider than its column: building it again for every group that
        came in took the screen's thread 45 of the 47 s that 300 cached groups take to
        read, up to 1 s at a time, and keys waited behind it (s39 attack)."""
        table = self.query_one(DataTable)
        cells = row(k, g)
        columns = table.ordered_columns
        if len(columns) != len(COLUMNS) or any(
            key != "members" and cell_len(cell) > column.width
            for (_, key), cell, column in zip(COLUMNS, cells, columns, strict=True)
        ):
            self._fill()
            return
        table.add_row(*map(Text, cells), key=str(k))

    @work(thread=True, exclusive=True, group="class", name="read the class")
    def _read(self) -> None:
        """Worker: read each session (read-only), post its row, then judge the class."""
        try:
            folders = classview.session_folders(self.root)
        except InputError as exc:
            self.post_message(self.ClassRead(None, str(exc)))
            return
        groups = []
        for k, folder in enumerate(folders, 1):
            if not self.is_attached:
                return  # the screen was left: the rest is not wanted
            g = classread.read(folder)
            groups.append(g)
            self.post_message(self.GroupRead(k, g))
        view = classview.judge(groups)
        self.post_message(self.ClassRead(view))

    def on_screen_suspend(self) -> None:
        self._left = True

    def on_screen_resume(self) -> None:
        if self._left and self.done:
            # back from a group opened read-only: the groups may have worked on meanwhile in
            # another program (walk 17's D1), so the rows are read again
            self._left = False
            self._read_again()

    @work(thread=True, exclusive=True, group="class", name="read the class again")
    def _read_again(self) -> None:
        """Worker: read every session again and judge the class (the rows replaced at once
        when it is done; the table as it was until then)."""
        try:
            view = read_class(self.root)
        except InputError as exc:
            self.post_message(self.ClassRead(None, str(exc)))
            return
        if self.is_attached:
            self.post_message(self.ClassRead(view))

    @on(GroupRead)
    def _group_read(self, event: GroupRead) -> None:
        self.groups.append(event.group)
        self._append(len(self.groups), event.group)
        if event.number == 1:
            self._show(0)
        self._arrived.set()

    @on(ClassRead)
    def _class_read(self, event: ClassRead) -> None:
        self._ended = True
        self._arrived.set()
        title = self.query_one("#class-title", Static)
        if event.view is None:
            title.update(Text(f"{TITLE}: {event.error}"))
            return
        self.view = event.view
        self.groups = list(event.view.groups)
        self._fill()
        table = self.query_one(DataTable)
        title.update(Text(f"{TITLE} of {self.root}: {classview.marked_summary(event.view)}"))
        self._show(table.cursor_row)

    def _show(self, index: int) -> None:
        if 0 <= index < len(self.groups):
            self.query_one("#class-group", Static).update(detail(index + 1, self.groups[index]))

    @on(DataTable.RowHighlighted)
    def _highlighted(self, event: DataTable.RowHighlighted) -> None:
        self._show(event.cursor_row)

    @on(DataTable.RowSelected)
    async def _selected(self, event: DataTable.RowSelected) -> None:
        await self.action_open_group()

    async def action_open_group(self) -> None:
        """Open the highlighted group's session read-only in the lab, over the class view (the
        app's :attr:`open_group`), once the table has taken the keys typed before Enter
        ('Down Enter' in one burst opens the row Down went to); the keys typed after Enter
        wait until the lab shows its step, and land there."""
        await after_typed_keys(self.app, self._open_group)

    async def _open_group(self) -> None:
        if self.app.screen is not self:
            return  # a second Enter while the first opens the group
        table = self.query_one(DataTable)
        # an Enter typed with F12 ('F12 Enter' in one burst) comes before the first row is
        # read: it waits for the row the cursor is on (walk 16's D4), the keys after it too
        while table.cursor_row >= len(self.groups) and not self._ended:
            self._arrived.clear()
            await self._arrived.wait()
        index = table.cursor_row
        if not 0 <= index < len(self.groups) or not self.groups[index].readable:
            self.notify("this session cannot be read; see what it lacks below", timeout=5)
            return
        if self.open_group is None:
            self.notify("this program was started without the lab to open a session in")
            return
        await self.open_group(self.groups[index].folder)

    def action_export_class(self) -> None:
        """F8: the class's report into the sessions folder, once every group is read: the
        sessions are read again for it, so that it holds what they hold now (walk 17's D1:
        a group still at work in another window had moved on since the view was opened), and
        the table shows the same rows."""
        if self.writer is None:
            self.notify(NO_WRITER, severity="error")
            return
        if self.view is None:
            self.notify(
                f"the class is still being read: {KEY_NAMES['export']} writes its report once "
                "every group is in",
                severity="warning",
            )
            return
        self._write(self.writer)

    @work(thread=True, exclusive=True, group="class-report", name="class report")
    def _write(self, writer: ClassWriter) -> None:
        """Worker: read the sessions again, show the rows read and write the class's report
        from them (the report's modules are slow to load)."""
        try:
            view = read_class(self.root)
        except InputError as exc:
            self.post_message(self.ClassWritten((), str(exc)))
            return
        self.post_message(self.ClassRead(view))
        try:
            paths = tuple(writer(view, self.root))
        except OSError as exc:
            self.post_message(self.ClassWritten((), os_reason(exc)))
            return
        self.post_message(self.ClassWritten(paths))

    @on(ClassWritten)
    def _written(self, event: ClassWritten) -> None:
        if event.error:
            self.notify(
                f"cannot write the class report in {self.root} ({event.error})",
                severity="error",
            )
            return
        names = ", ".join(p.name for p in event.paths)
        self.notify(f"written: {names}, in {self.root}", title="class report")

    async def action_back(self) -> None:
        """Back to the start screen."""
        await self.app.pop_screen()
