"""A session folder whose session.json is gone but whose runs/ is left (s36 attack, left:
the class view listed it, the start screen did not): the start screen lists it with what it
lacks and which run logs can be recovered, and Enter on it says so where the start screen
says things, staying there (nothing to open)."""

from __future__ import annotations

from textual.widgets import OptionList, Static

from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.ui.screens.start import StartScreen
from tests.classview.build import group
from tests.ui.conftest import quiet_app
from tests.ui.helpers import settle

LOST = (
    "no session.json (deleted?): names and entries are lost; 1 run log left in it "
    "(runs/steps-1.csv): start a new session and load each with Ctrl+P → Import a run log"
)


def test_the_picker_lists_a_folder_whose_session_file_is_gone(tmp_path):
    root = tmp_path / "sessions"
    kept = group(root, ["Ada", "Bo"], seed=3)
    lost = group(root, ["Cy", "Di"], seed=4)
    (lost / "session.json").unlink()
    (root / "photos").mkdir()  # a folder of something else: still not listed
    infos = {i.path: i for i in list_sessions(root)}
    assert set(infos) == {kept, lost}
    assert infos[lost].damaged == LOST
    assert infos[lost].runs_left == ("runs/steps-1.csv",)
    assert infos[kept].damaged is None and infos[kept].runs_left is None


async def test_the_start_screen_shows_it_and_enter_says_what_can_be_recovered(tmp_path):
    root = tmp_path / "sessions"
    lost = group(root, ["Cy", "Di"], seed=4)
    (lost / "session.json").unlink()
    async with quiet_app(root).run_test(size=(200, 30), notifications=True) as pilot:
        await settle(pilot, lambda: bool(pilot.app.screen.query("#sessions")))
        sessions = pilot.app.screen.query_one("#sessions", OptionList)
        assert sessions.option_count == 1
        label = str(sessions.get_option_at_index(0).prompt)
        assert label == f"{lost}: damaged — {LOST}"
        sessions.focus()
        await pilot.press("enter")
        await settle(pilot)
        assert isinstance(pilot.app.screen, StartScreen)
        said = str(pilot.app.screen.query_one("#start-msg", Static).render())
        assert said == f"{lost}: {LOST}"
