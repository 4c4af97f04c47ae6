"""Walk 9's class view defects (issue 20), Pilot at 80x24 on real session folders."""

from __future__ import annotations

from pathlib import Path

from rich.cells import cell_len
from textual.widgets import DataTable

from minseg_tui.lab.views import classread
from minseg_tui.ui.screens.classview import COLUMNS, MEMBERS_WIDTH, ClassScreen, row
from minseg_tui.ui.screens.start import StartScreen
from tests.ui.conftest import quiet_app
from tests.ui.helpers import settle

from .build import group


def _cut(table: DataTable[object], cells: tuple[str, ...]) -> list[str]:
    """The cells of ``cells`` wider than their column as the table would draw it now (the
    group's names are cut on purpose)."""
    out = []
    for (_, key), cell in zip(COLUMNS, cells, strict=True):
        column = table.columns[key]  # type: ignore[index]
        width = column.get_render_width(table) - 2 * table.cell_padding
        if key != "members" and cell_len(cell) > width:
            out.append(f"{key} {cell!r} in {width}")
    return out


async def test_the_columns_hold_the_values_as_soon_as_the_row_is_in(tmp_path: Path):
    """D5: at the first F12 of walk 9 (one group, a loaded PC) the row read R "5", k_v "0.4",
    K "1", T "4", J "0", step "Task": every column as wide as its header, sized before the
    row's values arrived and not again after. Here the row of a real session is handed to
    the screen as its reader hands it, and the table is looked at before it has had a turn
    of its own (the window a busy PC leaves open): every value fits its column."""
    folder = group(tmp_path / "class", ["Mia K", "Olle"], seed=1, at="task4")
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        screen = ClassScreen(tmp_path / "empty")
        (tmp_path / "empty").mkdir()
        await app.push_screen(screen)
        await settle(pilot)  # its reader found no group (an empty folder)
        g = classread.read(folder)
        screen._group_read(ClassScreen.GroupRead(1, g))
        table = screen.query_one(DataTable)
        cells = row(1, g)
        assert cells[2] == "Task 4" and all(cells[4:]), cells
        assert _cut(table, cells) == []
        await settle(pilot)
        assert _cut(table, cells) == []
        line = " ".join(str(c) for c in table.get_row_at(0))
        assert cells[4] in line and cells[8] in line
        assert table.columns["members"].width == MEMBERS_WIDTH  # type: ignore[index]
