"""The second walk of issue 20 at 80x24 on the virtual MinSeg, graded in the TUI: Task 13's
J typed with f in mN m s/rad (as the Tasks 6-9 table shows it) gets ✗ in the list of steps,
with the slip named, not ✓; a unitless 57 for T is refused, not stored as 57 s; '5,3 ohm'
says what was stored (Pilot, real session folder, the seeded plant's step run)."""

from __future__ import annotations

from tests.ui.helpers import goto, nav_mark, settle, start, start_with_a_run, type_in


async def test_a_J_with_f_in_mN_m_s_per_rad_gets_a_cross_and_the_unit_named(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        await type_in(pilot, "own.T", "57 ms")
        await goto(pilot, "task13")
        with app.session as s:
            i = s.results().identification
        # J = T (R f + k_v k_a) / R with the table's numbers, f as the table shows it (mN m s/rad)
        typed = f"0.057*({i.R:.3g}*{i.f * 1e3:.4g}+{i.k_v:.3g}*{i.k_a:.3g})/{i.R:.3g}"
        await type_in(pilot, "own.J", typed)
        await settle(pilot)
        compare = " ".join(str(app.screen.query_one("#compare").render()).split())
        assert (
            "+" in compare
            and "wrong: off by more than the 10 %" in compare
            and "f goes into this formula in N m s/rad" in compare
        )
        assert nav_mark(app, "task13") == "✗"


async def test_a_unitless_0_057_for_T_is_refused_and_an_unjudged_T_not_ticked(quiet):
    """T's entry is in ms (a bare 57 is 57 ms): a bare 0.057, seconds typed without the
    unit, is refused as ambiguous with both readings offered."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task12")
        row = await type_in(pilot, "own.T", "0.057")
        await settle(pilot)
        said = " ".join(row.message.split())
        assert "'0.057' is ambiguous" in said and "'57 ms'" in said and "'0.057 s'" in said
        assert nav_mark(app, "task12") == "?"
        await pilot.press("ctrl+u", *"57", "enter")
        await settle(pilot)
        assert "not judged yet" in " ".join(row.message.split())
        assert nav_mark(app, "task12") == "○"  # stored, nothing to judge it by: its own mark


async def test_5_comma_3_ohm_says_what_was_stored(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        row = await type_in(pilot, "R", "5,3 ohm")
        await settle(pilot)
        assert "read as 5.3 Ω" in " ".join(row.message.replace("\u00a0", " ").split())
