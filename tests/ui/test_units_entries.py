"""Issue 20, item 5 (units and entries): one unit per quantity, the units the program shows
accepted, Backspace after a refusal, the mark of a wrong answer, refusals in view, notices
that expire, the 63 % marker on its value, a question before quitting mid-recording, and
step names in the resume list. Each through the real TUI (Pilot)."""

from __future__ import annotations

from textual.widgets import OptionList

from minseg_tui.quantities import parse_quantity
from minseg_tui.ui.app import PANEL_KEYS
from minseg_tui.ui.widgets.fields import field_id
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    nav_mark,
    record_response_run,
    settle,
    start,
    start_with_a_run,
    type_in,
)


def test_every_unit_of_the_table_is_accepted_in_its_field():
    assert parse_quantity("1,855 mN m s/rad", "mN m s/rad").value == 1.855e-3
    assert parse_quantity("0.001855 N m s/rad", "mN m s/rad").value == 0.001855
    assert parse_quantity("1,855", "mN m s/rad").value == 1.855e-3


async def test_f_is_asked_for_in_the_unit_the_table_shows_it_in(quiet):
    """The table shows f in mN m s/rad; "1,855" typed from it was stored as 1.855 N m s/rad
    (+99909 %), and "1,855 mN m s/rad" was refused."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "table")
        with app.session as s:
            f = s.results().identification.f
        assert "mN m s/rad" in app.screen.query_one("#results", Prose).text
        for typed in (f"{f * 1e3:.3f}".replace(".", ","), f"{f * 1e3:.3f} mN m s/rad"):
            row = await type_in(pilot, "own.f", typed)
            assert not row.has_class("refused"), row.message
            with app.session as s:
                (c,) = [c for c in s.comparisons("table") if c.key == "own.f"]
            assert c.rel_diff is not None and abs(c.rel_diff) < 0.01
        assert "[mN m s/rad]" in str(row.query_one(".field-label").render())


async def test_backspace_after_a_refusal_deletes_one_character(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        row = await type_in(pilot, "R", "5.3 V")
        assert row.has_class("refused")
        await pilot.press("backspace")
        await settle(pilot)
        assert row.input.value == "5.3 "


async def test_a_wrong_answer_gets_its_own_mark_in_the_list_of_steps(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep5")
        await type_in(pilot, "prep5.percent", "50")
        await settle(pilot)
        assert nav_mark(app, "prep5") == "✗"
        await type_in(pilot, "prep5.percent", "63,2")
        await settle(pilot)
        assert nav_mark(app, "prep5") == "✓"


async def test_the_resume_list_names_the_step_as_the_lab_does(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task13")
    again = quiet()
    async with again.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(again.screen.query("#sessions")))
        listed = str(again.screen.query_one("#sessions", OptionList).get_option_at_index(0).prompt)
        assert listed.endswith("at Task 13") and "task13" not in listed


async def test_every_entry_label_shows_its_unit(quiet):
    """'u_ss at 2.5 V [V]' lost its '[V]': the label read it as a style."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        label = app.screen.query_one("#" + field_id("u_ss@2.5")).query_one(".field-label")
        assert str(label.render()) == "u_ss at 2.5 V [V]"


async def test_the_zoom_note_names_f9_as_the_footer_does(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await pilot.press("f9")
        await settle(pilot)
        note = str(app.screen.query_one("#zoom-note").render())
        (footer,) = [label for keys, _, label, _ in PANEL_KEYS if keys == "f9"]
        assert f"f9 {footer}" in note and "F9" not in note


async def test_a_run_before_the_table_is_filled_says_why_there_are_no_results(quiet):
    """It said '0 rising steps': it meant steps with results, which need a u_ss (walk 10,
    D4: not the whole table of Tasks 4-9, as it then said). The rises and T need only the
    speed (walk 18, D4): K says it waits for u_ss."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task11")
        await settle(pilot)
        note = str(app.screen.query_one("#zoom-note").render())
        assert "0 rises" not in note and "rise 1 of 4" in note, note  # T needs no u_ss
        lines = str(app.screen.query_one("#results-lines").render())
        assert (
            "K, J, the model and omega at 5 V: not yet, needs u_ss at the steps' voltage (Task 4)"
            in lines
        )
        enter_all(app, TABLE)
        await goto(pilot, "table")
        await goto(pilot, "task11")
        await settle(pilot)
        note = str(app.screen.query_one("#zoom-note").render())
        assert "rise 1 of 4" in note  # the table filled: the rises have results


async def test_a_refusal_is_brought_into_view_whole(quiet):
    """The last entry of Preparation 7 at 80x24: the refusal's last lines sat below the
    visible area."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep7")
        row = await type_in(pilot, "prep7.K", "4.7 zz")
        await settle(pilot)
        msg = row.query_one(".field-msg", Prose)
        assert row.has_class("refused") and msg.size.height >= 2
        assert app.screen.can_view_entire(msg)
