"""Walk 8, D7: a derived value that cannot be computed says which reading it waits for and
where to enter it ("needs R (Task 2)"), on the screen at 80x24 (Pilot, real session folder),
under F7, beside the group's own value, on Task 13 and in the report (real files)."""

from __future__ import annotations

from textual.widgets import DataTable

from minseg_tui.lab.content.needs import missing, needs, needs_short
from minseg_tui.lab.state.session import Session
from minseg_tui.report.write import write_report
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import TABLE, enter_all, goto, record_response_run, settle, start, type_in

WITHOUT_R = {k: v for k, v in TABLE.items() if k != "R"}
"""The walk's table: every row typed, Task 2's R left out."""


def test_every_derived_value_names_the_readings_it_waits_for():
    """The one table of inputs, followed down to the readings: J waits for the run, R and a
    row; the run's K for the u_ss it divides by, its T for nothing else;
    a row without i_ss waits for it alone once R and another row are there."""
    nothing = missing("J", lambda name: False)
    assert nothing[:3] == ("run", "R", "row")  # the row's u_ss: not one for T (walk 18, D4)
    assert missing("K", lambda name: False) == ("run", "u_ss@steps")  # not R: walk 10, D4
    assert missing("T", lambda name: False) == ("run",)  # the speed alone: walk 18, D4
    assert "i_ss" in missing("k_v@row", lambda name: name != "i_ss")
    assert missing("f@row", lambda name: name != "i_ss") == ("i_ss",)
    assert missing("k_v", lambda name: True) == ()
    assert needs(("R",)) == "needs R (Task 2)"
    assert needs(("R", "i_ss")) == "needs R (Task 2) and i_ss (Task 5)"
    assert needs_short(("R", "i_ss")) == "needs R…"
    assert needs_short(("omega_ss", "i_ss")) == "needs omega_ss"  # at most 14 characters


def _text(app, selector: str) -> str:
    return " ".join(str(app.screen.query_one(selector, Prose).render()).split())


async def test_the_table_without_R_says_R_is_what_is_missing(quiet):
    """Walk 8's screen: every k_v and f cell showed "—", F7 gave the bare formula and the
    comparison line "computed from your table —". Now the cells, F7, the line of final
    values under the table and the own value's line all say R (Task 2) is missing."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, WITHOUT_R)
        await goto(pilot, "table")
        await settle(pilot)
        table = app.screen.query_one("#table", DataTable)
        for r in range(3):
            assert str(table.get_cell_at((r, 4))) == "needs R"  # k_v
            assert str(table.get_cell_at((r, 5))) == "needs R"  # f
        assert table.region.bottom <= 24 and table.region.width <= 80
        assert "k_v, k_a and f (the medians): needs R (Task 2)" in _text(app, "#results")
        results = app.screen.query_one("#results", Prose)
        assert results.region.bottom <= 23  # above the footer, seen without scrolling
        table.focus()
        table.move_cursor(row=0, column=4)
        await pilot.press("f7")
        await settle(pilot)
        formula = _text(app, "#formula")
        assert formula.startswith("k_v here needs R (Task 2). k_v = (u_ss - R i_ss) / omega_ss")
        await type_in(pilot, "own.k_v", "0.5")
        await settle(pilot)
        assert "computed from your table: not yet, needs R (Task 2)" in _text(app, "#results")
        row = app.screen.query_one(f"#{field_id('own.k_v')}", FieldRow)
        said = " ".join(row.message.split())
        assert said == "○ stored, not judged yet: the value to compare with needs R (Task 2)"


async def test_a_row_without_its_current_says_i_ss_is_missing(quiet):
    """With R typed and the other rows complete, the row without i_ss names i_ss (Task 5)
    under F7 and in its cells."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, {k: v for k, v in TABLE.items() if k != "i_ss@4.5"})
        await goto(pilot, "table")
        await settle(pilot)
        table = app.screen.query_one("#table", DataTable)
        assert str(table.get_cell_at((2, 4))) == "needs i_ss"
        assert str(table.get_cell_at((2, 5))) == "needs i_ss"
        assert str(table.get_cell_at((0, 4))) not in ("—", "needs i_ss")
        table.focus()
        table.move_cursor(row=2, column=5)
        await pilot.press("f7")
        await settle(pilot)
        assert _text(app, "#formula").startswith("f here needs i_ss (Task 5). f = ")


async def test_task_13_without_R_says_J_needs_R(quiet):
    """A run recorded, R left out: K and T come from the run alone, and J says it waits
    for R (Task 2)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, WITHOUT_R)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task13")
        await settle(pilot, lambda: "J:" in _text(app, "#results-lines"))
        assert "J: needs R (Task 2) (why: below)" in _text(app, "#results-lines")


def test_the_report_without_R_says_what_k_v_and_f_need(tmp_path):
    """report.md written from a real session folder: the rows' k_v and f said "not
    computed: the row is incomplete" though every row was complete; now they, and the line
    on the motor constants, say R (Task 2) is missing."""
    with Session.create(tmp_path, ["A"], date="2026-11-27") as s:
        for key, text in WITHOUT_R.items():
            s.enter(key, text)
        md = write_report(s).markdown.read_text(encoding="utf-8")
    assert "the row is incomplete" not in md
    assert md.count("not computed: needs R (Task 2)") == 6  # k_v and f of three rows
    assert "The motor constants k_v, k_a and f: not computed, needs R (Task 2)." in md


async def test_tasks_11_to_15_without_a_run_say_the_run_is_what_is_missing(quiet):
    """The table complete, no run yet: Task 11's results said only "no step result yet";
    they now say a step run (Task 10) is what they need."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "task11")
        await settle(pilot, lambda: "no step result" in _text(app, "#results-lines"))
        assert _text(app, "#results-lines").startswith(
            "no step result yet: needs a step run (Task 10)"
        )


def test_the_report_without_a_run_says_the_step_result_needs_one(tmp_path):
    """report.md with the table complete and no run: "No step result yet." now says what
    it needs and where."""
    with Session.create(tmp_path, ["A"], date="2026-11-27") as s:
        for key, text in TABLE.items():
            s.enter(key, text)
        md = write_report(s).markdown.read_text(encoding="utf-8")
    assert "No step result yet: needs a step run (Task 10)" in md


async def test_a_table_barely_begun_says_what_each_row_needs_and_fits_80_columns(quiet):
    """R and one u_ss typed: each row's k_v and f name the first reading they wait for, and
    the table stays within the pane at 80 columns (no scroll bar under it)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, {"R": "5.3", "u_ss@2.5": "2.05"})
        await goto(pilot, "table")
        await settle(pilot)
        table = app.screen.query_one("#table", DataTable)
        cells = [[str(table.get_cell_at((r, c))) for c in (4, 5)] for r in range(3)]
        assert cells == [
            ["needs omega_ss", "needs omega_ss"],
            ["needs u_ss…", "needs omega_ss"],
            ["needs u_ss…", "needs omega_ss"],
        ]
        assert table.virtual_size.width <= table.scrollable_content_region.width
        assert not table.show_horizontal_scrollbar


async def test_tasks_13_and_15_without_R_say_what_they_wait_for_from_the_table(quiet):
    """R left out, a run recorded (stop 30, issue 20's leftover): Task 13's own J said
    "J needs R, k_v and f from the table of Tasks 2-9", in words of its own; it now says
    what the one table of inputs gives, "needs R (Task 2)". Task 15 said "nothing computed
    to compare it with" though omega at 5 V needs only K, which the run gives: it is now
    judged against 5 V × the run's K."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, WITHOUT_R)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task13")
        row = await type_in(pilot, "own.J", "0.0018")
        await settle(pilot)
        said = " ".join(row.message.split())
        assert said == "○ not judged: J needs R (Task 2); the run alone gives omega_ss, K and T"
        assert row.region.bottom <= 23
        await goto(pilot, "task15")
        row = await type_in(pilot, "own.omega_5", "9.6")
        await settle(pilot)
        said = " ".join(row.message.split())
        assert said.startswith("✓ right: -1 % from 9.685 rad/s, computed your way"), said
        assert "your omega at 5 V: yours 9.6 rad/s · computed your way 9.685 rad/s" in _text(
            app, "#compare"
        )


def test_the_report_without_R_says_J_needs_R_and_the_group_s_way_what_it_waits_for(tmp_path):
    """report.md from a real session folder, R left out, a run recorded, the group's J and
    omega at 5 V typed but not their K: J's row and the line under the table said "J needs R,
    k_v and f from the table of Tasks 2-9" and "J waits for R, k_v and f ... (R is not
    entered yet (Task 2))", and omega at 5 V "needs the group's K"; all now come from the one
    table of inputs, with where to enter what is missing."""
    with Session.create(tmp_path, ["A"], date="2026-11-27") as s:
        for key, text in WITHOUT_R.items():
            s.enter(key, text)
        record_response_run(s)
        s.enter("own.J", "0.0018")
        s.enter("own.omega_5", "9.6")
        md = write_report(s).markdown.read_text(encoding="utf-8")
    (J,) = [line for line in md.splitlines() if line.startswith("| J (Task 13)")]
    assert "not computed: J needs R (Task 2); the run alone gives omega_ss, K and T" in J
    assert J.count("needs R (Task 2)") == 3  # the group's way, the verdict, the program's
    assert "J needs R, k_v and f" not in md and "J waits for" not in md
    assert "J needs R (Task 2); omega_ss in the steps, K and T need only the run" in md
    (w5,) = [line for line in md.splitlines() if line.startswith("| omega at u_A = 5 V")]
    assert "| needs the group's K (Task 11) |" in w5
