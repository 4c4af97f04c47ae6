"""Issue 20, second walk: the start screen offered every student "f12 Class view" as one of
its keys, with nothing to say that it is the instructors' view of every group. The key now
names it so (a student may still open it: it is read-only, and the view says so)."""

from __future__ import annotations

from textual.widgets import Static

from minseg_tui.ui.screens.classview import ClassScreen
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.footer import KeyFooter, KeyLabel
from tests.ui.helpers import settle


async def test_the_start_screen_names_the_class_view_as_the_instructors(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        footer = app.screen.query_one(KeyFooter)
        keys = {k.key_display: k for k in footer.query(KeyLabel) if k.display}
        f12 = keys["f12"]
        assert f12.description == "Class view (instructors)"
        assert f12.region.right <= app.screen.size.width  # shown whole at 80 columns
        await pilot.press("f12")
        await settle(pilot, lambda: isinstance(app.screen, ClassScreen))
        title = str(app.screen.query_one("#class-title", Static).render())
        assert title.startswith("Class view for instructors (read-only)")
