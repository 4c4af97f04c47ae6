"""Reading a long step without a mouse: the arrow keys scroll the step (PgUp/PgDn move
between steps), as many lines as were pressed, and a step scrolled by the group stays where
they put it."""

from __future__ import annotations

from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.screens.lab import StepPane
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    burst,
    enter_all,
    goto,
    record_response_run,
    resume,
    settle,
    start,
    typing_box,
)


async def _lab_with_a_run(app, pilot) -> None:
    await start(pilot)
    enter_all(app, TABLE)
    with app.session as s:
        record_response_run(s)


async def test_a_burst_of_arrow_keys_scrolls_as_many_lines(quiet):
    """Seen in tmux (walk 4): twenty Down keys sent at once on the model check scrolled it
    one line (a held arrow key on a busy machine is such a burst): each key asked Textual to
    scroll one line below the same target, deferred to the next refresh."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _lab_with_a_run(app, pilot)
        await goto(pilot, "model_check")
        pane = app.screen.query(StepPane).last()
        assert app.focused is pane and pane.max_scroll_y > 12
        await burst(pilot, *["down"] * 12)
        assert pane.scroll_y == 12
        await burst(pilot, *["up"] * 5)
        assert pane.scroll_y == 7
        await goto(pilot, "task12")  # in an entry: the arrows scroll the step too
        pane = app.screen.query(StepPane).last()
        landed = pane.scroll_y
        assert landed >= 4
        await burst(pilot, *["up"] * 4)
        assert pane.scroll_y == landed - 4


async def test_a_step_scrolled_with_the_keys_stays_when_its_view_is_drawn_again(quiet):
    """Task 12: the group lands in its T, scrolls up with the arrows to read the zoom, and the
    lab changes (another run picked from the palette): the view is drawn again and the step
    stays where the group put it instead of jumping back to the entry."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _lab_with_a_run(app, pilot)
        await goto(pilot, "task12")
        pane = app.screen.query(StepPane).last()
        await burst(pilot, "up", "up", "up")
        read = pane.scroll_y
        app.screen.use_run(None)
        await settle(pilot)
        assert pane.scroll_y == read


async def test_the_focused_entry_stays_in_view_when_the_panel_above_it_grows(tmp_path):
    """Seen in tmux (walk 4): on the summary at 80x24, 'why does f fall with speed' typed
    into the last entry, then F8: the list of files written appeared above and pushed the
    entry (and its text) out of sight under the footer."""
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=tmp_path, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: dev, lambda session: write_report(session).paths)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "summary")  # lands on the first question; typing goes below
        await burst(pilot, *"why does f fall with speed")
        box = typing_box(app)
        assert box is app.screen.query_one(f"#{field_id('summary.unclear')} EntryBox")
        assert app.screen.can_view_entire(box)
        await burst(pilot, "f8")
        await settle(pilot, lambda: bool(app.exported))
        assert app.screen.can_view_entire(box)
        assert box.value == "why does f fall with speed"


async def test_a_resumed_step_shows_the_entry_it_lands_in(quiet):
    """Seen in tmux (walk 4): a session left on Task 12 (its T typed) resumed at 80x24 with
    the top of the step in view and the focused T under the footer."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _lab_with_a_run(app, pilot)
        await goto(pilot, "task12")
        await burst(pilot, *"57 ms", "enter")
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        await settle(pilot)
        box = app.screen.query_one(f"#{field_id('own.T')} EntryBox")
        assert typing_box(app) is box
        assert app.screen.can_view_entire(box)


async def test_an_entry_brought_into_view_after_its_step_has_gone_does_nothing(quiet):
    """make test under load: the lab opened landed in Preparation 1's notes and asked to bring
    them into view after the next refresh; 'PgDn' typed with the names had removed that step
    by then, and the deferred call crashed the app (NoScreen)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        row = app.screen.query_one(f"#{field_id('prep1.notes')}", FieldRow)
        await burst(pilot, "pagedown")
        assert not row.is_attached
        row.bring_into_view(True)  # what the deferred call does
        await settle(pilot)
        assert app.screen.query(StepPane).last().step.id == "prep2"
