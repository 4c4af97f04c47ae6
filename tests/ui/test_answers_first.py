"""Issue 20, items 1-2 in the TUI: the group's own value before the computed one on Tasks
11-15, Ctrl+R for a lab assistant, and comparisons made the group's way (Pilot, real session
folder, the seeded plant's step run)."""

from __future__ import annotations

import json

from minseg_tui.model.motor import inertia_from_time_constant
from minseg_tui.ui.app import KEYS
from tests.ui.helpers import goto, settle, start_with_a_run, type_in


def _text(app, selector: str) -> str:
    return str(app.screen.query_one(selector).render())


async def test_task11_shows_K_only_once_the_group_has_typed_its_own(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        with app.session as s:
            K = s.results().identification.step.K
        lines = _text(app, "#results-lines")
        assert f"K = {K:.4g}" not in lines and "K: shown once you enter yours" in lines
        assert "T (63 %)" not in lines and "J = " not in lines
        assert "your K: yours — · computed: shown once you enter yours" in _text(app, "#compare")
        await type_in(pilot, "own.K", "1.9")
        lines = _text(app, "#results-lines")
        assert f"K = {K:.4g}" in lines and "T (63 %)" not in lines  # T waits for Task 12
        assert "your K: yours 1.9 rad/s/V · computed your way" in _text(app, "#compare")


async def test_ctrl_r_reveals_the_step_and_the_session_keeps_it(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        assert app.screen.pane.check_action("panel_key", ("reveal",))
        assert app.screen.active_bindings["ctrl+r"].binding.description == "Reveal"
        assert any(k == "Ctrl+R" for k, _ in KEYS)  # in F1's list
        assert "T (63 %)" not in _text(app, "#results-lines")
        await pilot.press("ctrl+r")  # from within the entry of T
        await settle(pilot)
        assert "T (63 %)" in _text(app, "#results-lines")
        assert "revealed before answering" in _text(app, "#compare")
        with app.session as s:
            folder = s.folder
            assert s.revealed() == {"own.T"}
        data = json.loads((folder / "session.json").read_text(encoding="utf-8"))
        assert data["revealed"] == ["own.T"]
        await goto(pilot, "task10", focus=None)
        assert not app.screen.pane.check_action("panel_key", ("reveal",))  # Tasks 11-15 only


async def test_J_from_the_groups_63_percent_T_is_not_shown_as_39_percent_off(quiet):
    app = quiet()
    async with app.run_test(size=(120, 40)) as pilot:
        await start_with_a_run(pilot, "task12")
        with app.session as s:
            ident = s.results().identification
        st = ident.step
        T_ms = round(st.T_63 * 1e3, 1)  # read at 63 %, as the manual says
        await type_in(pilot, "own.T", f"{T_ms} ms")
        await goto(pilot, "task13")
        J = inertia_from_time_constant(T_ms / 1e3, ident.R, ident.f, ident.k_v, ident.k_a)
        await type_in(pilot, "own.J", f"{J * 1.002:.5g}")
        compare = _text(app, "#compare")
        assert f"from your T = {T_ms:g}" in compare and "+0.2 %" in compare, compare
        assert "least squares" in compare and "J grows in proportion to T" in compare
        assert "+3" not in compare.splitlines()[0]  # not the least-squares J's +30-odd %


async def test_task10_keeps_its_T_readings_until_the_group_has_its_own_T(quiet):
    app = quiet()
    async with app.run_test(size=(120, 40)) as pilot:
        await start_with_a_run(pilot, "task10")
        with app.session as s:
            T_63 = s.results().identification.step.T_63
        readings = _text(app, "#t-readings")
        assert "steps-1" in readings and "shown once you enter your own T" in readings
        assert f"{T_63:.3g}" not in readings
        await goto(pilot, "task12")
        await type_in(pilot, "own.T", "50 ms")
        await goto(pilot, "task10", focus=None)
        readings = _text(app, "#t-readings")
        assert "shown once" not in readings and "steps-1" in readings
