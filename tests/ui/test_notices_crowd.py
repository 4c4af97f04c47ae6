"""Two notices at once at 80x24 (issue 20, walk 12's D5: "two F8 in a row stack two notices
over eleven lines"). Textual stacks every notice on screen, each half the screen wide, on its
right, where the entries' boxes and verdicts are: together they covered the entry being typed
in or the reading just judged whichever side they went to.

What a student needs: the newest word on each thing, and the entry they type in and the
verdict they just got in sight. So a notice replaces the one on screen with the same title
(a second F8's replaces the first's), F8 says the files written and what is unanswered in one
notice, notices have no blank rows above and below their words, and when the notices on
screen would still cover the entry typed in or the row judged last on the side with more
room, the oldest go first; the newest always shows."""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import pytest
from textual.geometry import Region

import minseg_tui.ui.app as app_module
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import burst, goto, lab_screen, settle, start


def _row(app, key: str) -> FieldRow:
    return app.screen.query_one(f"#{field_id(key)}", FieldRow)


def _toasts(app) -> list[tuple[str, Region]]:
    """The notices on screen, oldest first: the text each shows (title and message) and where."""
    return [(str(t.render()), t.region) for t in app.screen.query("Toast")]


def _writing_app(root) -> LabApp:
    """The app on the device double, with the report writer the CLI gives it."""
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: QuietDevice(seed=1), lambda s: write_report(s).paths)


async def _task5_judged(pilot) -> tuple[FieldRow, FieldRow]:
    """Task 5: '30,1 Enter' typed in one burst in the 2.5 V row (judged), the keys on to the
    3.5 V row; the step scrolled by 2 rows, as it is every time (test_landing_timing): the
    judged reading on rows 9-12, the 3.5 V entry on rows 13-18, nine rows above them (the
    status line's included) and five below (the footer's included)."""
    app = pilot.app
    await start(pilot)
    await goto(pilot, "task5")
    await burst(pilot, *"30,1", "enter")
    judged, keyed = _row(app, "i_ss@2.5"), _row(app, "i_ss@3.5")
    assert judged.message == "read as 30.1 mA"
    pane = lab_screen(app).pane
    assert pane.current is keyed
    assert (pane.scroll_y, judged.region.y, judged.region.bottom, keyed.region.bottom) == (
        2,
        9,
        13,
        19,
    )
    return judged, keyed


def _clear_of(app, rows: list[FieldRow]) -> None:
    toasts = _toasts(app)
    assert toasts
    for text, region in toasts:
        for row in rows:
            assert region.height > 0 and row.region.height > 0
            assert not region.overlaps(row.region), (text, region, row.field.key, row.region)


async def test_two_f8_in_a_row_show_one_report_notice_off_the_entries(
    monkeypatch: pytest.MonkeyPatch,
):
    """Walk 12's D5: F8 twice on Task 5 at 80x24 stacked four notices (two each: the files
    written, what is unanswered) from row 2 to below the screen. Now F8 says both in one
    notice, the second F8's replaces the first's, and it covers neither the 3.5 V entry the
    keys are in nor the 2.5 V reading just judged."""
    monkeypatch.setattr(app_module, "NOTICE_S", 600.0)  # held long enough to be looked at
    # a sessions folder whose path is as long as a group's ('/home/ada/minseg/sessions/'),
    # not pytest's 70 characters: the notice says it whole
    root = Path(tempfile.mkdtemp(prefix="ms")) / "sessions"
    try:
        await _two_f8(_writing_app(root))
    finally:
        shutil.rmtree(root.parent)


async def _two_f8(app: LabApp) -> None:
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        judged, keyed = await _task5_judged(pilot)
        for _ in range(2):
            app.exported = ()
            await burst(pilot, "f8")
            await settle(pilot, lambda: bool(app.exported) and bool(_toasts(app)))
        await settle(pilot)
        texts = [text for text, _ in _toasts(app)]
        assert len(texts) == 1, texts  # the files written and what is unanswered, in one
        assert texts[0].startswith("report\nwritten: report.md, report.html"), texts
        assert "\nunanswered, marked in the report: " in texts[0], texts
        assert lab_screen(app).pane.current is keyed
        _clear_of(app, [judged, keyed])


async def test_two_notices_of_different_kinds_leave_the_entries_in_sight(quiet):
    """Two long notices of different kinds at once on Task 5 (the keys on the 3.5 V row, the
    2.5 V reading just judged): together they would cover one of the rows whichever side
    they went to; the older goes, the newer shows, off both rows."""
    app = quiet()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        judged, keyed = await _task5_judged(pilot)
        long = "a notice long enough to wrap over several lines of a half screen: " * 2
        app.notify("first: " + long, title="one kind", timeout=600)
        app.notify("second: " + long, title="another kind", timeout=600)
        await settle(pilot)
        texts = [text for text, _ in _toasts(app)]
        assert any(t.startswith("another kind\nsecond: ") for t in texts), texts
        _clear_of(app, [judged, keyed])
