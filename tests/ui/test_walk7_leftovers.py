"""What walk 7 left on the screens, at 80x24 where it was seen (Pilot, real session folder):
Ctrl+O's whole "What to do" over a step whose own text is in view (D3)."""

from __future__ import annotations

from minseg_tui.lab.content.steps import step
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import goto, settle, start, typing_box


async def test_ctrl_o_never_shows_a_line_of_what_to_do_twice(quiet):
    """Task 5 at 80x24, Ctrl+O: the whole "What to do" lay over the step's own, one row
    short of it, so the own text's last line ('jumper back afterwards.') showed under the
    overlay, as if repeated. With the own text whole in view no overlay is drawn over it;
    once the step scrolls it away, Ctrl+O's whole text shows in the heading."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task5")
        pane = app.screen.pane
        heading = pane.query_one(".heading")
        own = pane.query_one(".todo")
        await pilot.press("ctrl+o")
        await settle(pilot)
        view = pane.scrollable_content_region
        assert view.y <= own.region.y and own.region.bottom <= view.bottom  # whole in view
        if heading.display:  # an overlay, if any, hides all of the own text, not all but a line
            assert own.region.bottom <= heading.region.bottom
        # the last entry, below the screen: the step scrolls its own text away
        last = pane.query_one("#" + field_id("i_ss@4.5"), FieldRow)
        for _ in range(3):  # i_ss at 2.5 V, 3.5 V, 4.5 V
            if typing_box(app) is last.input:
                break
            await pilot.press("tab")
            await settle(pilot)
        assert typing_box(app) is last.input
        assert own.region.bottom <= view.y or own.region.y < heading.region.bottom
        assert heading.display and heading.whole
        todo = heading.query_one(".heading-todo")
        shown = " ".join(str(todo.render()).split())
        assert (
            shown == " ".join(("What to do: " + step("task5").todo).split()) + " (Ctrl+O folds it)"
        )
        assert own.region.bottom <= heading.region.bottom  # no line of it under the heading
