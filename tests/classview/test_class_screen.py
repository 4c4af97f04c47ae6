"""The class view in the lab assistant, with Pilot at 80x24: F12 on the start screen, the
rows, the highlighted group in full, Enter opening a group read-only, Escape back."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from textual.widgets import DataTable, Static

from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.lab.state.session import Session
from minseg_tui.ui.screens.classview import ClassScreen
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.start import StartScreen
from tests.ui.conftest import quiet_app
from tests.ui.helpers import class_view, goto, settle, start_with_a_run

from .build import group


def _class(root: Path) -> list[Path]:
    folders = [
        group(root, ["Ada [b]", "Bo"], seed=1),
        group(root, ["Cy", "Di"], seed=2, R="12 Ω"),
        group(root, ["Late"], seed=3, run=False, at="table"),
    ]
    (root / "zz-broken").mkdir()
    (root / "zz-broken" / "session.json").write_text("[]", encoding="utf-8")
    return folders


def _state(root: Path) -> dict[str, tuple[int, bytes]]:
    return {str(p): (p.stat().st_mtime_ns, p.read_bytes()) for p in root.rglob("*") if p.is_file()}


async def test_rows_detail_and_opening_a_group_read_only(tmp_path):
    root = tmp_path / "sessions"
    folders = _class(root)
    before = _state(root)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        table = screen.query_one(DataTable)
        assert table.row_count == 4
        cells = [str(c) for c in table.get_row_at(0)]
        assert cells[1] == "Ada [b], Bo" and cells[2] == "Task 12"  # names shown as typed
        detail = str(screen.query_one("#class-group", Static).render())
        assert "#1 Ada [b], Bo" in detail and "model check: dry friction" in detail
        await pilot.press("down")
        await settle(pilot)
        detail = str(screen.query_one("#class-group", Static).render())
        assert "#2 Cy, Di" in detail and "R = 12 Ω is outside the 3-6 Ω" in detail
        await pilot.press("down", "down")
        await settle(pilot)
        detail = str(screen.query_one("#class-group", Static).render())
        assert "lacks: cannot be read" in detail and "does not hold a JSON object" in detail
        await pilot.press("enter")  # an unreadable session stays where it is
        await settle(pilot)
        assert app.screen is screen
        await pilot.press("up", "up", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
        assert app.screen.readonly
        assert app.session is not None
        with app.session as s:
            assert s.folder == folders[1] and s.readonly
    assert _state(root) == before


async def test_escape_goes_back_and_a_missing_folder_is_said(tmp_path):
    app = quiet_app(tmp_path / "nothing-here")
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        await pilot.press("f12")
        await settle(pilot, lambda: isinstance(app.screen, ClassScreen))
        title = str(app.screen.query_one("#class-title", Static).render())
        assert "does not exist" in title
        await pilot.press("escape")
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))


def test_class_screen_snapshot(snap_compare, tmp_path, monkeypatch: pytest.MonkeyPatch):
    monkeypatch.chdir(tmp_path)
    _class(Path("sessions"))

    async def run_before(pilot) -> None:
        await class_view(pilot)
        await pilot.press("down")
        await settle(pilot)

    assert snap_compare(quiet_app(Path("sessions")), terminal_size=(80, 24), run_before=run_before)


async def test_the_lab_keeps_what_its_screens_computed_for_the_class_view(tmp_path):
    root = tmp_path / "sessions"
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")  # Tasks 11-15 computed for the step's view
        await goto(pilot, "model_check")  # and the model check, in the screens' workers
        assert "Likely cause:" in str(app.screen.query_one("#check-story").render())
    folder = list_sessions(root)[0].path
    kept = json.loads((Path(folder) / "session.json").read_text(encoding="utf-8"))["kept"]
    assert kept["check"]["cause"] and kept["step"]["K"] > 0
    with Session.open(Path(folder), readonly=True) as s:  # what the class view will take
        got = s.kept()
        res = s.results()
        assert got is not None and got.check is not None and got.step is not None
        assert res.step is not None and got.step.K == res.step.K
        assert got.check.cause == s.model_check().result.finding.cause
