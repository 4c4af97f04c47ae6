"""Walk 17's defects (/work/coord/WALK17.md), at 80x24 with Pilot on real session folders.

D1: the class view's F8 wrote class.md/html/csv from the rows read when the view opened, so a
group's work done since (in another window) was missing from the files. D2: in a session
opened read-only from the class view, Enter on an answer moved the pick on screen to it,
though the pick was refused and not stored. D4: on Tasks 11-15 at 80x24, once the answers are
typed the plot is above the view, and Alt+→ or F9 changed it there with nothing seen."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import DataTable

from minseg_tui.lab.state.session import Session
from minseg_tui.report.write import write_class
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.widgets.fields import FieldRow
from tests.seeded import Clock
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import answering, burst, class_view, goto, settle, shown


def _class_app(root: Path) -> LabApp:
    """The app on the device double, with the class report's writer (F8 in the class view)."""
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: dev, None, write_class)


def _summary_group(root: Path) -> Path:
    """A group that answered the Summary's first question "a system" (option 1)."""
    s = Session.create(root, ["Mira K", "Jonas P"], date="2026-11-28", clock=Clock())
    s.choose("summary.1", [1])
    s.go_to("summary")
    s.close()
    return s.folder


def _row(app: LabApp, key: str) -> FieldRow:
    return next(r for r in app.screen.query(FieldRow) if r.field.key == key)


async def test_a_pick_refused_in_a_read_only_session_leaves_the_groups_answer_shown(tmp_path):
    """D2: F12, Enter on the group, its Summary, 'Up Enter' on Q1: the list showed 'a model'
    picked (● moved off 'a system') under "✗ this session is open read-only …: not stored".
    The pick is refused and the list shows the group's answer again; Space does the same;
    nothing is written."""
    root = tmp_path / "sessions"
    folder = _summary_group(root)
    before = (folder / "session.json").read_bytes()
    app = _class_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        await settle(pilot, lambda: app.focused is screen.query_one(DataTable))
        await burst(pilot, "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        await goto(pilot, "summary")  # the keys on Q2, the first question not answered
        row = _row(app, "summary.1")
        assert row.answers is not None and row.answers.chosen == (1,)
        await burst(pilot, "shift+tab")
        await settle(pilot, lambda: answering(app) is row.answers)
        await burst(pilot, "up", "enter")
        await settle(pilot)
        assert "read-only" in row.message
        assert row.answers.chosen == (1,), "the refused pick is shown as the group's answer"
        await burst(pilot, "up", "up", "space")  # on "a model"
        await settle(pilot)
        assert row.answers.chosen == (1,)
    assert (folder / "session.json").read_bytes() == before
