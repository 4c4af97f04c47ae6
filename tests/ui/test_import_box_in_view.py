"""Stop 37 left (s37-real): after Ctrl+P "Import a run log" at 80x24 the path box had the
keys but sat below the screen (rows 53-55 of a 22-row view) until Enter or Shift+Tab: the
group typed a path it could not see. The box, its label and the line that answers under it
are brought into view when the palette lands there, and stay there while the check's view
is drawn (it comes from a worker, after the landing, and pushes the box down), and after
Enter, when the answer comes."""

from __future__ import annotations

from minseg_tui.ui.panels.model_check import ImportBox
from minseg_tui.ui.screens.lab import StepPane
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox
from tests.ui.helpers import in_step_view, settle, shown, start_with_a_run


async def _palette_import(pilot) -> None:
    await pilot.press("ctrl+p")
    await settle(pilot)
    for c in "import a run":
        await pilot.press(c)
    await settle(pilot)
    await pilot.press("enter")


async def test_the_palettes_import_box_is_in_view_at_80x24(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "prep1")
        await _palette_import(pilot)
        await settle(pilot, lambda: shown(app, "model_check"))
        story = app.screen.query_one("#check-story", Prose)
        await settle(pilot, lambda: story.text.startswith("run steps-1"))  # the view drawn
        await settle(pilot)
        pane = app.screen.query_one(StepPane)
        box = app.screen.query_one("#import-path", TextBox)
        assert app.focused is box
        assert in_step_view(pane, box), (pane.scroll_y, box.region, pane.scrollable_content_region)
        assert in_step_view(pane, app.screen.query_one(ImportBox))  # its label over it too
        # the path typed and Enter: the answer under the box is seen with it
        log = tmp_path / "elsewhere.csv"
        with app.session as s:
            log.write_bytes(s.run_path(s.response_run().name).read_bytes())
        for c in str(log):
            await pilot.press(c)
        await pilot.press("enter")
        msg = app.screen.query_one("#import-msg", Prose)
        await settle(pilot, lambda: msg.text.startswith("imported"))
        await settle(pilot, lambda: story.text.startswith("run imported-1"))
        await settle(pilot)
        assert in_step_view(pane, box) and in_step_view(pane, msg), (pane.scroll_y, msg.region)
