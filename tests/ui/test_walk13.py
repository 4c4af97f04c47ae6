"""Walk 13's defects (issue 20), each as the walk met it, at 80x24 with Pilot on a real
session folder (/work/coord/WALK13.md)."""

from __future__ import annotations

import json

from textual.widgets import DataTable

from minseg_tui.lab.state import shown as lab_shown
from minseg_tui.quantities import format_constant
from minseg_tui.ui.panels.table import TablePanel
from minseg_tui.ui.screens.lab import StepPane
from minseg_tui.ui.widgets.fields import FOCUS_MARK, FieldRow, field_id
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox
from tests.ui.helpers import (
    TABLE,
    answering,
    burst,
    enter_all,
    goto,
    record_response_run,
    settle,
    start,
    start_with_a_run,
    stored_text,
    type_in,
    typing_box,
)


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


async def _on_summary_question(pilot, key: str) -> None:
    """The Summary step shown, the keys on question ``key``'s list of answers."""
    await start(pilot)
    await goto(pilot, "summary")
    app = pilot.app
    await settle(pilot, lambda: answering(app) is _row(app, "summary.1").answers)
    while answering(app) is not _row(app, key).answers:
        await burst(pilot, "tab")


async def test_enter_after_ticking_with_space_keeps_the_ticks_and_goes_on(quiet):
    """D1: Q5 (tick all that apply) 'Down Space Down Space Enter': Space ticked 'the input
    amplitude' and 'the static gain', then Enter unticked 'the static gain' (it acted as
    Space on the answer under the cursor) and the keys stayed on Q5; the group's right
    answer was stored 'partly'. Enter on an answer already ticked now leaves the ticks as
    they are and goes on to the next question, as Enter goes on from a text entry."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_summary_question(pilot, "summary.5")
        await burst(pilot, "down", "space", "down", "space", "enter")
        assert stored_text(app, "summary.5") == "b, c"
        assert _row(app, "summary.5").answers.chosen == (1, 2)
        assert answering(app) is _row(app, "summary.6").answers


async def test_enter_on_the_answer_picked_goes_on_to_the_next_question(quiet):
    """D1: Q1 'Space' (a model), 'Down Space' (a system), then 'Enter Space Enter Space Enter
    Space Enter' in one burst, meant for Q2-Q4: the keys never left Q1 (Enter on the answer
    picked did nothing, Space picked it again). Enter on the answer picked now goes on to
    the next question; Enter on another answer still picks it and stays (walk 6's bursts)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _on_summary_question(pilot, "summary.1")
        await burst(pilot, "space")
        await burst(pilot, "down", "space")
        assert stored_text(app, "summary.1") == "b"
        await burst(pilot, "enter", "space", "enter", "space", "enter", "space", "enter")
        for key in ("summary.1", "summary.2", "summary.3", "summary.4"):
            assert stored_text(app, key) == ("b" if key == "summary.1" else "a"), key
        assert answering(app) is _row(app, "summary.5").answers
        # the last question: Enter on its answer picked goes on to the text entry after it
        await burst(pilot, "tab", "space", "enter")
        assert stored_text(app, "summary.6") == "a"
        assert typing_box(app) is _row(app, "summary.unclear").input


def _shown_record(app) -> dict:
    with app.session as s:
        folder = s.folder
    return json.loads((folder / "session.json").read_text(encoding="utf-8")).get("shown", {})


async def test_j_typed_before_r_is_not_recorded_as_shown_until_a_j_is_computed(quiet):
    """D2: J typed on Task 13 before R (Task 2) and i_ss (Task 5): the screen said "not
    judged: J needs R ...", no computed J anywhere, yet the session recorded J as shown
    after the answer at that moment, and the report said so ("shown on Tasks 11-15" at a
    time no J existed). J is recorded as shown only once a computed J is on the screen."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, {k: v for k, v in TABLE.items() if k != "R" and not k.startswith("i_ss")})
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task13")
        await type_in(pilot, "own.J", "0.0018")
        await settle(pilot, lambda: "J needs R" in _row(app, "own.J").message)
        assert "own.J" not in _shown_record(app)
        # R and i_ss typed: J is computed, on the screen when Tasks 11-15 are drawn again
        enter_all(app, {k: v for k, v in TABLE.items() if k == "R" or k.startswith("i_ss")})
        await goto(pilot, "task12")
        await settle(pilot, lambda: "own.J" in _shown_record(app))
        got = _shown_record(app)["own.J"]
        assert (got["by"], got["answer"]) == (lab_shown.AFTER_ANSWER, "0.0018")


def _visible(pane: StepPane, widget) -> bool:
    """``widget`` lies whole in the part of the pane on screen (screen coordinates)."""
    return widget.region.height > 0 and pane.scrollable_content_region.contains_region(
        widget.region
    )


async def test_f7_from_an_entry_shows_a_formula_on_the_screen(quiet):
    """D3: Tasks 6-9 open with the keys in 'your k_v', the table scrolled above it at 80x24;
    F7 (the footer's 'f7 Formula') wrote the formula of the table's cell under its cursor
    below the table, off the screen: nothing on the screen changed. Now F7 from the step's
    entries takes the keys to the table (what stood in the entry stored, as leaving it
    stores it), with the formula line under it in view; ←/→ and Enter (or F7) then give
    the other cells'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "table")
        pane = app.screen.query(StepPane).last()
        assert typing_box(app) is _row(app, "own.k_v").input
        formula = app.screen.query_one("#formula", Prose)
        before = str(formula.render())
        await burst(pilot, *"0,5", "f7")
        await settle(pilot)
        table = app.screen.query_one("#table", DataTable)
        assert app.focused is table
        assert str(formula.render()) != before
        assert _visible(pane, formula), (pane.scroll_y, formula.region, pane.region)
        assert stored_text(app, "own.k_v") == "0,5"
        # (two bursts: 'Right ... F7' in one gives the old cell's formula, the arrows being
        # the form's priority keys handed on to the table after F7 ran: left to s34-focus)
        await burst(pilot, "right", "right", "right", "right")
        assert table.cursor_coordinate == (0, 4), table.cursor_coordinate
        await burst(pilot, "f7")
        assert "k_v" in str(formula.render())


async def test_the_run_log_box_is_marked_when_it_has_the_keys(quiet):
    """D4: on the model check, Shift+Tab put the keys in the box for a run log's path, with
    no "▶" before its label (every entry with the keys has one); the group typed its note
    there, and Enter tried to load a file named "friction". The box's label now carries the
    mark while the box has the keys, and loses it when they leave."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        box = app.screen.query_one("#import-path", TextBox)
        for _ in range(12):
            if app.focused is box:
                break
            await burst(pilot, "shift+tab")
        assert app.focused is box
        label = app.screen.query_one("#import-label", Prose)
        assert str(label.render()).startswith(FOCUS_MARK)
        await burst(pilot, "tab")
        assert app.focused is not box
        assert not str(label.render()).startswith(FOCUS_MARK)


async def test_a_fraction_typed_as_a_percentage_is_named(quiet):
    """D7: Prep 4 asks y(T) as a fraction of K c; '63' (the per cent, without '%') got "not
    right yet; check your working", while '63 %' is right. It now says what it read."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep4")
        row = await type_in(pilot, "prep4.fraction", "63")
        await settle(pilot, lambda: "check your working" not in row.message)
        assert "0.63" in row.message and "per cent" in row.message, row.message


async def test_a_value_ten_times_too_large_is_named_a_slipped_decimal_point(quiet):
    """D7: Task 15, '96,5' against 9.650 rad/s (5 V × the group's K = 1.93): "wrong: +900 %
    ... more than the 10 % off that reading or rounding explains", no word of the likely
    slip. A value a power of ten from the one computed the group's way now says so."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await type_in(pilot, "own.K", "1,93")
        await goto(pilot, "task15")
        row = await type_in(pilot, "own.omega_5", "96,5")
        await settle(pilot, lambda: "+900 %" in row.message)
        assert "10 times" in row.message and "decimal point" in row.message, row.message
        row = await type_in(pilot, "own.omega_5", "0,965")
        await settle(pilot, lambda: "-90 %" in row.message)
        assert "1/10 of" in row.message and "decimal point" in row.message, row.message


async def test_the_model_checks_own_t_is_set_beside_task_12s_on_screen(quiet):
    """D5: the model check's first sentences name "the first-order model the check fitted
    to this run (T = 40.53 ms, ...)", a T that appears nowhere in Tasks 11-15 (Task 12 says
    least squares 43.12 ms); why the two differ was only in Details, folded. The sentences
    on screen now give Task 12's least-squares T beside it and point to Details."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        story = app.screen.query_one("#check-story", Prose)
        await settle(pilot, lambda: "the check fitted to this run" in str(story.render()))
        with app.session as s:
            st = s.results().identification.step
        said = " ".join(str(story.render()).split())
        assert f"least-squares T of this run is {format_constant(st.T, 's')}" in said, said
        assert "Details" in said


async def test_j_computed_the_groups_way_names_the_constants_it_uses(quiet):
    """D8: J "computed your way 0.001816 kg m^2 (from your T = 57 ms)" used the table's k_v,
    k_a and f, not the k_v and k_a the group typed on Tasks 6-9 (0.495, 0.32 gave 0.001809),
    and did not say so. It now names them."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task13")
        enter_all(app, {"own.k_v": "0,495", "own.k_a": "0.32", "own.T": "57 ms"})
        row = await type_in(pilot, "own.J", "0.00181")
        compare = app.screen.query_one("#compare")
        await settle(pilot, lambda: "your J: yours" in str(compare.render()))
        said = " ".join(str(compare.render()).split())
        assert "from your T = 57 ms and the table's R, k_v, k_a and f" in said, said
        assert row.message


async def test_f7_before_the_tables_view_is_built_acts_once_it_is(quiet):
    """D3, second form: 'C-p task 6 Enter 0,49 F7' in one burst: F7 came before the step's
    table view was built and did nothing (a second F7 worked). The request now waits for
    the view: here the view is taken away before F7 and handed back after it, as the
    step's worker hands it over."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "table")
        panel = app.screen.query_one(TablePanel)
        built = panel.view
        assert built is not None
        panel.view = None  # not built yet
        await burst(pilot, "f7")
        assert app.focused is not app.screen.query_one("#table", DataTable)
        panel.receive(built)
        await settle(pilot)
        formula = app.screen.query_one("#formula", Prose)
        assert app.focused is app.screen.query_one("#table", DataTable)
        assert "F7 on a cell" not in str(formula.render())


async def test_a_reading_typed_with_a_trailing_zero_keeps_it_on_every_screen(quiet):
    """D6: Task 4, u_ss at 4.5 V typed '4,0': the echo said "read as 4 V", and the table of
    Tasks 6-9 and Task 11's "u_ss = 4 V" dropped the zero too: the group read 4.0 to 0.1 V
    and nobody could see it. A reading now keeps the digits it was typed with, through a
    unit change too ('0.0470 A' is 47.0 mA); computed values keep their own four digits."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        row = await type_in(pilot, "u_ss@4.5", "4,0")
        await settle(pilot, lambda: "read as" in row.message)
        assert "read as 4.0 V" in row.message.replace("\u00a0", " "), row.message
        enter_all(
            app,
            {
                **{k: v for k, v in TABLE.items() if k != "u_ss@4.5"},
                "i_ss@3.5": "0.0470 A",
                "i_ss@4.5": "47,0 mA",
            },
        )
        await goto(pilot, "table")
        table = app.screen.query_one("#table", DataTable)
        await settle(pilot, lambda: table.row_count == 3)
        rows = [[str(c) for c in table.get_row_at(k)] for k in range(3)]
        assert rows[2][:2] == ["4.5", "4.0"] and rows[2][3] == "47.0", rows
        assert rows[1][3] == "47.0" and rows[0][1:4] == ["2.05", "3.1", "28"], rows
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task11")
        lines = app.screen.query_one("#results-lines", Prose)
        await settle(pilot, lambda: "u_ss = " in lines.text)
        said = " ".join(lines.text.replace("\u00a0", " ").split())
        assert "u_ss = 4.0 V" in said, said
