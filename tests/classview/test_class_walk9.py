"""Walk 9's class view defects (issue 20), Pilot at 80x24 on real session folders."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from rich.cells import cell_len
from textual.widgets import DataTable, Static

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
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
        assert cells[2] == "Task 10" and all(cells[4:]), cells  # its run: reached Task 10
        assert _cut(table, cells) == []
        await settle(pilot)
        assert _cut(table, cells) == []
        line = " ".join(str(c) for c in table.get_row_at(0))
        assert cells[4] in line and cells[8] in line
        assert table.columns["members"].width == MEMBERS_WIDTH  # type: ignore[index]


def _back_to_task4_after_the_summary(root: Path) -> Path:
    """Walk 9's group: every step through the summary, then back to Task 4 and quit there."""
    folder = group(root, ["Mia K", "Olle"], seed=1, at="summary")
    s = Session.open(folder)
    for key, answer in (("summary.1", "b"), ("summary.unclear", "why the two T differ")):
        s.enter(key, answer)
    s.go_to("task4")
    s.close()
    return folder


async def test_the_step_column_is_the_furthest_step_reached_not_the_one_left_on(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
):
    """D6: a group that reached the summary, went back to Task 4 and quit there was shown
    "Task 4" (the class view and `minseg-tui class`), read by an instructor as a group that
    stopped at Task 4. The step column is the furthest step reached; the detail says where
    the group is now."""
    root = tmp_path / "walk9-sessions"
    _back_to_task4_after_the_summary(root)
    assert main(["class", "--sessions", str(root), "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    rows = rows["groups"] if isinstance(rows, dict) else rows
    assert rows[0]["step"] == "Summary and reflections" and rows[0]["at"] == "Task 4"
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        screen = ClassScreen(root)
        await app.push_screen(screen)
        await settle(pilot, lambda: screen.done)
        cells = [str(c) for c in screen.query_one(DataTable).get_row_at(0)]
        assert cells[2] == "Summary", cells
        detail = " ".join(str(screen.query_one("#class-group", Static).render()).split())
        assert "reached Summary and reflections, now at Task 4" in detail, detail


def test_the_class_view_quotes_readings_with_the_digits_typed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
):
    """D9: walk 9's second group typed 296 for i_ss and 2.6 for u_ss at 2.5 V; `minseg-tui
    class` said "296.0 mA" and "2.600 V", digits the group never read off the meter (the
    report wrote them as typed)."""
    root = tmp_path / "walk9-sessions"
    group(root, ["Ada L", "Alan T"], seed=2, rows={2.5: ("2.6", "3.823", "296")})
    assert main(["class", "--sessions", str(root)]) == 0
    out = capsys.readouterr().out
    assert "i_ss at 2.5 V = 296 mA is above 100 mA" in out, out
    assert "u_ss at 2.5 V = 2.6 V is above the requested 2.5 V" in out, out
