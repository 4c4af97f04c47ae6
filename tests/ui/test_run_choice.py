"""Issue 20, item 3: the run Tasks 11-15 and the report use. A choice stays until the group
changes it (saved in the session), without one the newest complete 25 ms run is used, an
interrupted run says what interrupted it, and old session files follow the same rule. Also
item 5: Ctrl+Q during a recording asks first."""

from __future__ import annotations

import json

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.state.session import Session
from minseg_tui.report.content import Table, build
from minseg_tui.ui.screens.quit import QuitScreen
from minseg_tui.ui.widgets.plots import TracePlot
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    record_response_run,
    resume,
    settle,
    start,
    start_run_on,
)


def _runs_table(session: Session) -> Table:
    (sec,) = [s for s in build(session).sections if s.title == "Recorded runs"]
    (table,) = [b for b in sec.blocks if isinstance(b, Table)]
    return table


async def test_the_chosen_run_survives_a_new_run_a_quit_and_a_resume(quiet):
    """'Use run steps-1', F5, Ctrl+Q during the recording: the resumed session still uses
    steps-1, and steps-2 is labelled as ended by a quit, not as recovered after a crash."""
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            chosen = record_response_run(s, seed=5)
            record_response_run(s, seed=6)
        app.screen.use_run(chosen)
        await goto(pilot, "task10")
        await start_run_on(pilot, dev)
        recording = app.recording.name
        await pilot.press("ctrl+q")  # asks first: a run is being recorded
        await settle(pilot)
        assert isinstance(app.screen, QuitScreen) and app.recording is not None
        await pilot.press("escape")  # keep recording
        await settle(pilot)
        assert not isinstance(app.screen, QuitScreen) and app.recording is not None
        await pilot.press("ctrl+q")
        await settle(pilot)
        await pilot.press("down", "enter")  # stop the run and quit
    again = quiet(QuietDevice(seed=1))
    async with again.run_test(size=(80, 24)) as pilot:
        await resume(pilot)
        with again.session as s:
            assert s.response_run().name == chosen
            ended = next(r for r in s.runs if r.name == recording)
            assert ended.interrupted and ended.interruption == "quit"
            assert s.recovered == []
            header = _runs_table(s).header
            (row,) = [r for r in _runs_table(s).rows if r[0] == recording]
        assert "interrupted by" in header and row[header.index("interrupted by")] == "quit"


def _stopped_run(session: Session) -> str:
    """A 25 ms step run stopped after 80 of its samples; its name."""
    plan = dict(step("task10").plans)["manual"]
    rec = session.start_run("steps", plan)
    for k in range(80):
        rec.append(k, k * 25_000, 3 * k, 4500 if k >= 20 else 0)
    info = session.finish_run(rec, stopped_early=True, ended_by="stopped")
    assert info is not None
    return info.name


def test_without_a_choice_the_newest_complete_25_ms_run_is_used(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        enter_all_session(s)
        complete = record_response_run(s)
        _stopped_run(s)  # newer, but interrupted
        fast = dict(step("task10").plans)["fast"]
        rec = s.start_run("fast", fast)
        for k in range(200):
            rec.append(k, k * 5_000, k, 4500)
        assert s.finish_run(rec) is not None  # newer, complete, but 5 ms
        assert s.response_run().name == complete
        assert build(s).sections  # the report is built from it


def enter_all_session(s: Session) -> None:
    for key, text in TABLE.items():
        s.enter(key, text)


def test_an_old_session_file_follows_the_same_rule(tmp_path):
    """A schema-1 file written before runs said what ended them (no 'ended_by', no
    'selected_run'): an interrupted newest run is not used, and says its cause is unknown."""
    with Session.create(tmp_path, ["A"]) as s:
        enter_all_session(s)
        complete = record_response_run(s)
        stopped = _stopped_run(s)
        folder = s.folder
    path = folder / "session.json"
    data = json.loads(path.read_text())
    assert data["schema"] == 1
    del data["selected_run"]
    for r in data["runs"]:
        r.pop("ended_by", None)
    path.write_text(json.dumps(data))
    with Session.open(folder) as old:
        assert old.response_run().name == complete
        (r,) = [r for r in old.runs if r.name == stopped]
        assert r.interrupted and r.interruption == "cause not recorded"
        header = _runs_table(old).header
        (row,) = [x for x in _runs_table(old).rows if x[0] == stopped]
        assert row[header.index("interrupted by")] == "cause not recorded"


async def test_task10_plots_the_run_in_use_and_names_it(quiet):
    """Issue 20, second walk: steps-2 was in use for Tasks 11-15 and Task 10's 25 ms plot
    showed the newest run, one stopped early, without saying so. It shows the run in use now,
    named in its title; with no run chosen, the newest complete one (the one in use)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s, seed=5)
            chosen = record_response_run(s, seed=6)
            stopped = _stopped_run(s)
            s.select_run(chosen)
            in_use = s.response_run()
            samples = in_use.samples
        await goto(pilot, "task10")
        plot = app.screen.query_one("#plot-slow", TracePlot)
        await settle(pilot, lambda: bool(plot.traces))
        assert plot._canvas.plot_title == f"25 ms run: {chosen}, in use"
        assert plot.traces[0].x.size == samples  # the run in use, not the stopped one
        app.screen.use_run(None)  # no choice: the newest complete run, not the stopped one
        await settle(pilot, lambda: stopped not in plot._canvas.plot_title)
        assert plot._canvas.plot_title == f"25 ms run: {chosen}, in use"
