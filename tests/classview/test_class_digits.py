"""Issue 20, left by stop 34: the class view showed R from the number ("5,30" typed was
5.3 Ω) while the lab, the report and Task 11 give a reading with the digits typed
(quantities.format_reading, walk 13's D6). Now the screen's table and detail, the CLI's
table and the class report give "5.30". Real session folders; the screen with Pilot at
80x24."""

from __future__ import annotations

from textual.widgets import DataTable, Static

from minseg_tui.cli import main
from tests.ui.conftest import quiet_app
from tests.ui.helpers import class_view

from .build import group


def _two_groups(root) -> None:
    group(root, ["Ida K", "Omar S"], seed=8, R="5,30", run=False)
    group(root, ["Li W", "Noor B"], seed=9, R="5.3 ohm", run=False)


async def test_the_screen_shows_r_with_the_digits_typed(tmp_path):
    root = tmp_path / "sessions"
    _two_groups(root)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        table = screen.query_one(DataTable)
        cells = {str(table.get_row_at(k)[1]): str(table.get_row_at(k)[4]) for k in range(2)}
        assert cells == {"Ida K, Omar S": "5.30", "Li W, Noor B": "5.3"}
        detail = str(screen.query_one("#class-group", Static).render())
        assert "R 5.30 Ω" in detail, detail


def test_the_cli_and_the_class_report_show_r_with_the_digits_typed(tmp_path, capsys):
    root = tmp_path / "sessions"
    _two_groups(root)
    out_dir = tmp_path / "out"
    assert main(["class", "--sessions", str(root), "--out", str(out_dir)]) == 0
    rows = capsys.readouterr().out.splitlines()
    ida = next(r for r in rows if "Omar S" in r)
    li = next(r for r in rows if "Noor B" in r)
    assert " 5.30 " in ida and " 5.3 " in li, (ida, li)
    md = (out_dir / "class.md").read_text(encoding="utf-8")
    assert "| 5.30 |" in md, md
