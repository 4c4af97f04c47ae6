"""Tasks 6-9: the table filling itself, the formula behind every cell."""

from __future__ import annotations

from collections.abc import Callable, Mapping

from textual.app import ComposeResult
from textual.binding import Binding
from textual.widget import Widget
from textual.widgets import DataTable

from minseg_tui.lab.content.keys import key_name
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.lab.views.session import TableView
from minseg_tui.quantities import MISSING
from minseg_tui.ui.keys import PanelKeys
from minseg_tui.ui.panels.view_panel import ViewPanel
from minseg_tui.ui.widgets.fields import FieldForm
from minseg_tui.ui.widgets.prose import Prose


class CellTable(DataTable[str]):
    """The table of Tasks 6-9, whose cursor keys act in the order typed with the keys
    around them. The arrows are the step form's priority keys too (they edit an entry);
    with the table focused the form's skip them, and Textual tried the table's own binding
    only once the key had bubbled back up to the app, behind the keys the app had read
    meanwhile: "Right Right F7" in one burst showed the formula of the cell the cursor left
    (walk 13). Bound with priority here, the table's binding runs next in the app's own
    pass over the priority bindings, before the app reads the next key."""

    BINDINGS = [
        Binding(key, f"cursor_{key}", show=False, priority=True)
        for key in ("up", "down", "left", "right")
    ]


class TablePanel(ViewPanel[TableView], PanelKeys):
    """The table of Tasks 6-9 with the final values and warnings; F7 (or Enter on a cell)
    shows the formula behind the cell. The warnings come under the group's entries (a step
    lands on its first entry: at 80x24 the warnings above it pushed the table and the step's
    title off the screen)."""

    def __init__(self) -> None:
        super().__init__()
        self._warnings = Prose("", id="warnings", classes="para")
        self._formula_asked = False
        self._showing: tuple[object, ...] | None = None
        """While F7 from elsewhere on the step has given the table the keys: the layout the
        table and the formula's line were last brought into view on (() before the first),
        else None (:meth:`_laid_out`)."""

    def compose(self) -> ComposeResult:
        yield CellTable(id="table", cursor_type="cell", zebra_stripes=False, header_height=2)
        yield Prose(
            f"{key_name('formula')} on a cell: the formula behind it.", id="formula", classes="hint"
        )
        yield Prose("", id="results")

    def on_mount(self) -> None:
        self.screen.screen_layout_refresh_signal.subscribe(self, self._laid_out, immediate=True)

    def _laid_out(self, _: object) -> None:
        """The screen was laid out (the regions fresh): after F7 from the step's entries, the
        table, its cursor's cell and the formula's line under it are brought into view below
        the step's heading, on each layout that moves them while the table has the keys. A
        scroll made after a refresh read the layout from before the formula's new text, and
        another scroll of the step came after it: at 80x24, with the group's k_v, k_a and f
        judged under the table, the formula's line ended under the heading and the table
        with its cursor above the screen (walk 14's D3)."""
        if self._showing is None:
            return
        table = self.query_one(DataTable)
        form = self.parent
        if not (self.screen.focused is table and isinstance(form, FieldForm)):
            self._showing = None
            return
        line = self.query_one("#formula", Prose)
        where = (table.region, line.region, form.scrollable_content_region)
        if where != self._showing:
            self._showing = where
            form.show_whole(table, line)

    def after_rows(self) -> Widget:
        """The warnings, shown under the group's entries."""
        return self._warnings

    def build(self, session: Session) -> TableView:
        return views.table(session)

    def show_view(self) -> None:
        view = self.view
        if view is None:
            return
        table = self.query_one(DataTable)
        cursor = table.cursor_coordinate
        table.clear(columns=True)
        table.add_columns(*view.columns)
        for row in view.rows:
            table.add_row(*[c.text for c in row])
        table.move_cursor(row=cursor.row, column=cursor.column, animate=False)
        lines = ["  ".join(f"{name} = {cell.text}" for name, cell in view.results) or view.waiting]
        lines += [
            f"{label}: yours {own} · {comp}" for label, own, comp in view.compare if own != MISSING
        ]
        self.query_one("#results", Prose).update("\n".join(lines))
        self._warnings.update("\n".join(f"! {w}" for w in view.warnings))
        self._warnings.display = bool(view.warnings)
        if self._formula_asked:
            self._formula_asked = False
            self.action_formula()

    def key_actions(self) -> Mapping[str, Callable[[], object]]:
        return {"formula": self.action_formula}

    def action_formula(self) -> None:
        """Show the formula of the cell under the cursor. From elsewhere on the step (its
        entries, below the table: at 80x24 the table and the formula's line were off the
        screen, walk 13) the keys go to the table first, its formula's line in view. Asked
        before the step's view is built (F7 in the burst that opened the step), it is done
        once the view is drawn."""
        if self.view is None:
            self._formula_asked = True
            return
        if not self.view.rows:
            return
        table = self.query_one(DataTable)
        self._say(*table.cursor_coordinate)
        if self.screen.focused is not table:
            # at once (Widget.focus waits for the app's next turn, and a layout between took
            # the table for not focused)
            self.screen.set_focus(table, scroll_visible=False)
            self._showing = ()
            self.screen.refresh(layout=True)  # brought into view on the next layout

    def _say(self, r: int, c: int) -> None:
        """The formula's line: that of the cell at row ``r``, column ``c``."""
        if self.view is None or not 0 <= r < len(self.view.rows):
            return
        row = self.view.rows[r]
        if 0 <= c < len(row):
            cell = row[c]
            line = self.query_one("#formula", Prose)
            line.update(cell.formula or f"{cell.text}: measured, no formula")

    def on_data_table_cell_selected(self, _event: DataTable.CellSelected) -> None:
        self.action_formula()

    def on_data_table_cell_highlighted(self, event: DataTable.CellHighlighted) -> None:
        """The cursor moved on the table while it has the keys (after F7): the formula's
        line follows it (walk 17's D8: it stayed on the cell F7 was pressed on, 'u = 2.5 V'
        under the highlighted f)."""
        if self.screen.focused is self.query_one(DataTable):
            self._say(event.coordinate.row, event.coordinate.column)
