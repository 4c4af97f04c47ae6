"""Walk 18's defects (/work/coord/WALK18.md), at 80x24 with Pilot on real session folders.

D1: the report said nowhere near its top what a grader needs: which of the group's values of
Tasks 11-15 were changed after the program showed its own, which were shown before the group
answered (Ctrl+R), and which checked answers were first given wrong; the first two stood only in
the last column of one table, the third nowhere (only in session.json's history). D2: a
reading typed into the row of one voltage while the motor ran at another was stored without a
word. D5: a run stopped with F2 showed its bar at 0 %. D6: the start screen listed a session
in use by its folder's name (with the names as first misspelt), not by its names. Walk 17's
D2 left: a pick refused in a read-only session was said with ✗, the mark of a wrong answer."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from textual.widgets import DataTable, OptionList, ProgressBar

from minseg_tui.lab.state.session import Session
from minseg_tui.report import content, markdown
from minseg_tui.report.write import write_class, write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.widgets.fields import FieldRow
from tests.seeded import Clock
from tests.ui.conftest import DATE, quiet_app
from tests.ui.fakes import QuietDevice, square_wave_stream
from tests.ui.helpers import (
    TABLE,
    answering,
    burst,
    class_view,
    enter_all,
    goto,
    record_response_run,
    settle,
    shown,
    start,
    start_run_on,
    stored_text,
    taken,
    type_in,
)


def _report_app(root) -> LabApp:
    """The app on the device double, with the report's writer (F8)."""
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: dev, lambda session: write_report(session).paths)


def _first_section(md: str) -> tuple[str, str]:
    """The title and the text of the report's first section."""
    title, _, rest = md.split("\n## ", 1)[1].partition("\n")
    return title, rest.split("\n## ", 1)[0]


async def test_the_report_begins_with_what_a_grader_needs(tmp_path):
    """D1: Prep 4 '0,37' (✗) then '0,632'; Task 11 K '1.73' (7.8 rad/s over the requested
    4.5 V: ✗, the computed 1.940 shown under it) then '1,94'; Task 12 Ctrl+R, then T. F8: the
    report's first section, before the warnings, names all three."""
    app = _report_app(tmp_path)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep4")
        await type_in(pilot, "prep4.fraction", "0,37")
        await type_in(pilot, "prep4.fraction", "0,632")
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
        await goto(pilot, "task11")
        await type_in(pilot, "own.omega_step", "7,8")
        await type_in(pilot, "own.K", "1.73")
        await type_in(pilot, "own.K", "1,94")
        await goto(pilot, "task12")
        await pilot.press("ctrl+r")
        await settle(pilot)
        await type_in(pilot, "own.T", "57 ms")
        with app.session as s:
            folder = s.folder
        await pilot.press("f8")
        await settle(pilot, lambda: bool(app.exported))
    md = (folder / "report.md").read_text(encoding="utf-8")
    title, first = _first_section(md)
    assert title == "For the grader", title
    words = " ".join(first.split())
    assert "K (Task 11): '1.73' when the computed values were shown" in words, words
    assert "changed to '1,94'" in words, words
    assert "T (Task 12): revealed before answering" in words, words
    assert "Preparation 4, y(T) / (K c): '0,37'" in words and "now '0,632'" in words, words
    assert md.index("## For the grader") < md.index("## Warnings")


def _row(app: LabApp, key: str) -> FieldRow:
    return next(r for r in app.screen.query(FieldRow) if r.field.key == key)


async def test_a_reading_typed_into_the_row_of_another_voltage_is_said_so(quiet):
    """D2: Task 4 left the motor at 4.5 V; on Task 5 the keys land in 'i_ss at 2.5 V' and the
    meter reads the 4.5 V current: '37,2 Enter' was stored there with nothing said. Now a line
    under the entry says the motor runs at 4.5 V, not 2.5 V; F3 to 2.5 V and the reading
    typed there stands without it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await burst(pilot, "f3", "f3", "f3")  # 2.5, 3.5, 4.5 V
        assert app.requested == 4.5
        await goto(pilot, "task5")
        await burst(pilot, *"37,2", "enter")
        row = _row(app, "i_ss@2.5")
        said = " ".join(row.message.split())
        assert "! typed while the motor runs at 4.5 V, not 2.5 V" in said, said
        await burst(pilot, "f3")  # 2.5 V: the keys on its row, its text ready to replace
        assert app.requested == 2.5
        await burst(pilot, *"29,8", "enter")
        said = " ".join(row.message.split())
        assert stored_text(app, "i_ss@2.5") == "29,8"
        assert "motor runs at" not in said, said


async def test_a_run_stopped_with_f2_keeps_its_bar_where_it_stopped(tmp_path):
    """D5: Task 10, F5, 2 s of the 12 s run recorded ('18 %'), F2: the bar fell to 0 % while
    the line under it said the run's samples were kept. It stays at the share recorded."""
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=tmp_path, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task10", focus=None)
        seq = await start_run_on(pilot, dev)
        dev.feed(square_wave_stream(seq, (seq + 1) * 25_000, 2.0))
        await taken(pilot, seq + 80)
        bar = app.screen.query_one("#run-progress", ProgressBar)
        recorded = bar.percentage
        assert recorded is not None and 0.1 < recorded < 0.3, recorded
        await pilot.press("f2")
        await settle(pilot, lambda: app.run_progress is not None and not app.run_progress.recording)
        await settle(pilot)
        assert "samples kept" in app.run_progress.text, app.run_progress.text
        assert bar.percentage == pytest.approx(recorded, abs=0.02), bar.percentage


async def test_a_session_in_use_is_listed_by_its_names_not_its_folder(tmp_path):
    """D6: a group's names mended (Ctrl+P "Correct the group's names": "Osar B" to "Oskar B"),
    its session open in one window; the start screen of another listed it as
    "sessions/2026-11-28-maja-k-osar-b-leila-n: in use by another minseg-tui (pid …)": the
    folder, with the old spelling, where every other row shows date, names and step."""
    s = Session.create(tmp_path, ["Maja K", "Osar B", "Leila N"], date="2026-11-28", clock=Clock())
    s.set_members(["Maja K", "Oskar B", "Leila N"])
    try:
        app = quiet_app(tmp_path)
        async with app.run_test(size=(80, 24)) as pilot:
            await settle(pilot, lambda: bool(app.screen.query("#sessions")))
            listed = app.screen.query_one("#sessions", OptionList)
            row = " ".join(str(listed.get_option_at_index(0).prompt).split())
    finally:
        s.close()
    assert "2026-11-28 Maja K, Oskar B, Leila N at Preparation 1" in row, row
    assert "in use by another minseg-tui" in row and "osar" not in row, row


async def test_a_pick_refused_in_a_read_only_session_is_not_marked_wrong(tmp_path):
    """Walk 17's D2, what was left (re-checked in walk 18): in a session opened read-only from
    the class view, a pick on the Summary is refused and the group's answer shown again, but
    the refusal began '✗ this session is open read-only', ✗ being the mark of a wrong
    answer, under an answer that is right."""
    root = tmp_path / "sessions"
    s = Session.create(root, ["Mira K", "Jonas P"], date="2026-11-28", clock=Clock())
    s.choose("summary.1", [1])  # "a system": right
    s.go_to("summary")
    s.close()
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: dev, None, write_class)
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        await settle(pilot, lambda: app.focused is screen.query_one(DataTable))
        await burst(pilot, "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        await goto(pilot, "summary")
        row = _row(app, "summary.1")
        await burst(pilot, "shift+tab")
        await settle(pilot, lambda: answering(app) is row.answers)
        await burst(pilot, "up", "enter")
        await settle(pilot)
        said = row.message.strip()
        assert "read-only" in said and "not stored" in said, said
        assert not said.startswith("✗"), said
        assert row.answers is not None and row.answers.chosen == (1,)


def test_the_graders_lists_of_what_was_shown_say_not_known_for_an_older_session(tmp_path):
    """D1, the other side: a session begun with an older program, which did not record what
    the group was shown, is not said to have had 'none' shown before answering or changed
    after; the first section says since when the record runs."""
    folder = tmp_path / "schema1"
    shutil.copytree(Path(__file__).parents[1] / "lab" / "old_sessions" / "schema1", folder)
    with Session.open(folder) as s:
        assert s.shown_since is not None and s.shown_since > s.created
        md = markdown.render(content.build(s))
    title, first = _first_section(md)
    words = " ".join(first.split())
    assert title == "For the grader"
    assert "answered (Tasks 11-15): none" not in words, words
    assert "values (Tasks 11-15): none" not in words, words
    assert words.count("the session was begun with an older program") == 2, words
