"""Stop 38's "left": a notice at the bottom could reach a very tall rack. At 80x24 a notice
taller than the screen (made wide, 27 rows: an imported log's path of many long folder names
says that much) rose over the status line at the bottom, its title and first rows out of the
screen, and on top it ran under the footer. It stays between them now, its beginning shown."""

from __future__ import annotations

import pytest

from tests.ui.helpers import settle, start_with_a_run

FOLDERS = "/".join(f"a-folder-with-a-long-name-of-its-own-{k:02d}" for k in range(40))
SAID = f"imported /home/group/{FOLDERS}/step-log.csv as imported-1; the model check uses it"


@pytest.mark.parametrize(("step", "side"), [("task2", "bottom"), ("task12", "top")])
async def test_a_notice_taller_than_the_screen_stays_between_status_line_and_footer(
    quiet, step, side
):
    app = quiet()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start_with_a_run(pilot, step)
        app.notify(SAID, title="import", timeout=600)
        await settle(pilot, lambda: bool(app.screen.query("Toast")))
        await settle(pilot)
        assert app.screen.has_class("-notices-top") == (side == "top")
        (toast,) = app.screen.query("Toast")
        status = app.screen.query_one("DeviceStatus").region
        footer = app.screen.query_one("KeyFooter").region
        assert toast.region.y >= status.bottom, (toast.region, status)
        assert toast.region.bottom <= footer.y, (toast.region, footer)
        shown = app.screen.get_widget_at(toast.region.x + 2, toast.region.y)[0]
        assert shown is toast  # its first row, the title's, is on the screen and on top
        assert str(toast.render()).startswith("import")
