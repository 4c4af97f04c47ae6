"""Walk 8, D4: a group whose only step run was cut short by a quit read "Nothing is missing."
on the class view and "Nothing stands out." in `minseg-tui class`; R typed "5.3" was shown
"5.300", T and T_63 in s while the lab gives ms, and at 80x24 the table's J was cut off.
Real session folders; the screen with Pilot at 80x24."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import DataTable, Static

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from minseg_tui.quantities import format_number
from tests.seeded import record_square_wave
from tests.ui.conftest import quiet_app
from tests.ui.helpers import class_view, settle

from .build import group

CUT = "run steps-2 interrupted (quit), 9.5 of 12 s: K, T and J rest on it"


def _quit_group(root: Path) -> Path:
    """Walk 8's group: R typed "5.3", the table, a complete step run and then one ended by
    a quit after three of its four periods (9.5 s with the lead-in at 0 V), chosen by the
    group for Tasks 11-15."""
    folder = group(root, ["Ida K", "Omar S"], seed=8, R="5.3", run=False, at="summary")
    with Session.open(folder) as s:
        record_square_wave(s, seed=8)  # steps-1, complete
        cut = record_square_wave(s, seed=9, periods=3, stopped_early=True, ended_by="quit")
        assert cut is not None and cut.interrupted and cut.ended_by == "quit"
        s.select_run(cut.name)
    return folder


def test_the_cli_says_the_run_in_use_was_interrupted(tmp_path, capsys):
    root = tmp_path / "sessions"
    _quit_group(root)
    assert main(["class", "--sessions", str(root)]) == 0
    out = capsys.readouterr().out
    assert f"- note: {CUT}" in out, out
    assert "Nothing stands out." not in out
    row = out.splitlines()[1]
    assert "Omar S  Summary and reflections  5.3  " in row, row  # R as typed, not 5.300
    assert "units: R Ω, " in out and "T_63 ms, T ms" in out


async def test_the_screen_says_it_and_fits_80_columns(tmp_path):
    root = tmp_path / "sessions"
    folder = _quit_group(root)
    with Session.open(folder, readonly=True) as s:
        st = s.results().identification.step  # type: ignore[union-attr]
        assert st is not None and st.J is not None
        T_ms, J = format_number(st.T * 1e3), format_number(st.J)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        table = screen.query_one(DataTable)
        cells = [str(c) for c in table.get_row_at(0)]
        assert cells[2] == "Summary, run cut" and cells[4] == "5.3"
        assert cells[7] == T_ms and cells[8] == J
        detail = str(screen.query_one("#class-group", Static).render())
        assert f"- note: {CUT}" in detail, detail
        assert "Nothing the numbers above need is missing." not in detail
        assert "Nothing else the numbers above need is missing." in detail
        assert "R 5.3 Ω" in detail and f"T {T_ms} ms" in detail
        await settle(pilot)
        # every column whole on screen: nothing to scroll sideways to
        assert table.virtual_size.width <= table.scrollable_content_region.width, (
            table.virtual_size,
            table.scrollable_content_region,
            [(c.label.plain, c.get_render_width(table)) for c in table.columns.values()],
        )
