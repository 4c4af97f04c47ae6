"""Ten kilobytes pasted into Preparation 11's formula in the real TUI (Pilot, 80x24): the
app stays up, the entry says in one short line what was refused, and the formula typed
before stays in effect (s39 attack: '1+1+...' of 10 kB raised a RecursionError out of the
entry's reading, in the screen's thread)."""

from __future__ import annotations

from minseg_tui.lab.state.entries import MAX_TYPED
from tests.ui.conftest import quiet_app
from tests.ui.helpers import goto, paste_in, start, stored_text

KEPT = "(u_ss - R i_ss) / omega_ss"


async def test_a_ten_kilobyte_paste_into_a_formula_is_refused_and_kept(tmp_path):
    app = quiet_app(tmp_path / "sessions")
    pasted = "1+" * 5000 + "1"
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep11")
        await paste_in(pilot, "prep11.k_v", KEPT)
        await paste_in(pilot, "prep11.k_v", pasted)
        assert app.is_running
        with app.session as s:
            e = s.entry("prep11.k_v")
        assert e is not None and e.ok and e.text == KEPT
        assert e.refused is not None and e.refused[0] == pasted
        assert f"(at most {MAX_TYPED})" in e.refused[1]
        assert stored_text(app, "prep11.k_v") == pasted  # the box shows what was pasted
