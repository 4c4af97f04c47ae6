"""Issue 18 in the TUI, through Pilot: a step identify cannot use says what is missing (and
the session resumes); names and notes with Rich markup in them shown as typed; a session
file with a long integer listed as damaged beside the sound ones; Task 10 after a run is
saved late."""

from __future__ import annotations

import json

import pytest
from textual.widgets import OptionList

from minseg_tui.device.protocol import Ident
from minseg_tui.lab.saving.store import SessionNotWritable
from minseg_tui.lab.state.session import Session
from minseg_tui.ui.panels.connect import ConnectPanel
from minseg_tui.ui.panels.report import ReportPanel, written_in
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.status import DeviceStatus
from tests.lab.test_identify_guards import CASES, ENTRIES, _log
from tests.ui.conftest import quiet_app
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import class_view, goto, resume, settle, start, type_in


def _results(app) -> str:
    return app.screen.query_one("#results-lines", Prose).text


async def test_a_step_without_k_says_what_is_missing_on_every_resume(quiet, tmp_path):
    """A run whose rising steps end below the driver's drop: a ZeroDivisionError traceback
    on showing Task 11, again on every resume."""
    words, high, how = CASES["below the drop"]
    _log(tmp_path / "log.csv", high, how)
    with Session.create(tmp_path / "sessions", ["Ada"], date="2024-04-16") as s:
        for key, text in ENTRIES.items():
            s.enter(key, text)
        # chosen for Tasks 11-15 (an import alone feeds the model check: walk 16, D3)
        s.select_run(s.import_run(tmp_path / "log.csv").name)
    for _ in range(2):  # and again after a resume
        async with quiet().run_test(size=(100, 40)) as pilot:
            await resume(pilot)
            await goto(pilot, "task11", focus=None)
            await settle(pilot, lambda: "computing" not in _results(pilot.app))
            text = _results(pilot.app)
            assert words in text and "gives no step result" in text


def _toasts(app) -> str:
    """The notifications shown (Textual's Toast widgets, found by their type name: the
    class itself is not exported)."""
    return " ".join(str(t.render()) for t in app.screen.query("Toast"))


async def test_names_with_markup_are_shown_as_typed_and_keep_the_folder_open(tmp_path):
    """'Cy [/], Di' as a group's names: every later start was a MarkupError; 'Ada [absent]'
    was shown as 'Ada '."""
    root = tmp_path / "sessions"
    Session.create(root, ["Ada [absent]"], date="2024-04-15").close()
    app = quiet_app(root)
    async with app.run_test(size=(100, 40)) as pilot:
        await start(pilot, "Cy [/], Di")
    async with quiet_app(root).run_test(size=(100, 40)) as pilot:  # the next start
        await settle(pilot, lambda: bool(pilot.app.screen.query("#sessions")))
        sessions = pilot.app.screen.query_one("#sessions", OptionList)
        labels = [str(sessions.get_option_at_index(k).prompt) for k in range(2)]
        assert any("Cy [/], Di" in label for label in labels)
        assert any("Ada [absent]" in label for label in labels)
        await resume(pilot)
        assert isinstance(pilot.app.screen, LabScreen)


async def test_typed_and_refused_text_and_file_names_are_shown_as_they_are(tmp_path):
    root = tmp_path / "sessions [bold]"
    async with quiet_app(root).run_test(size=(100, 40), notifications=True) as pilot:
        app = pilot.app
        await start(pilot)
        await goto(pilot, "task2")
        row = await type_in(pilot, "R", "5 [red]x")  # refused: the message quotes it
        assert "'5 [red]x'" in str(row.query(Prose).last().text)
        await goto(pilot, "prep1", focus=None)
        row = await type_in(pilot, "prep1.notes", "wheel [b]loose[/b]")
        assert row.input.value == "wheel [b]loose[/b]"
        root.rename(tmp_path / "gone")  # a save fails: the status names the folder
        await type_in(pilot, "prep1.notes", "wheel [b]loose[/b] again")
        status = str(app.screen.query_one(DeviceStatus).render())
        assert "sessions [bold]" in status
        # a notification that names a file with brackets in it
        app.notify(f"cannot read {root}/[/]x.csv")
        await settle(pilot)
        assert "sessions [bold]/[/]x.csv" in _toasts(app)


async def test_a_damaged_session_in_a_folder_with_brackets_is_named_as_it_is(tmp_path):
    root = tmp_path / "sessions"
    s = Session.create(root, ["Ada"], session_id="g [red]x", date="2024-04-16")
    s.enter("R", "5.2")
    s.close()
    data = json.loads((s.folder / "session.json").read_text())
    data["entries"]["R"]["history"] = 5
    (s.folder / "session.json").write_text(json.dumps(data))
    async with quiet_app(root).run_test(size=(120, 40), notifications=True) as pilot:
        await settle(pilot, lambda: bool(pilot.app.screen.query("#sessions")))
        label = str(
            pilot.app.screen.query_one("#sessions", OptionList).get_option_at_index(0).prompt
        )
        assert "g [red]x" in label
        await resume(pilot)
        assert "g [red]x" in _toasts(pilot.app)


async def test_a_long_integer_in_one_session_file_hides_no_other(tmp_path):
    """A 401-digit whole number (OverflowError) or a 5000-digit one (ValueError) in one
    session.json kept the TUI from starting at all."""
    root = tmp_path / "sessions"
    Session.create(root, ["Bo"], date="2024-04-14").close()
    for digits, sid in ((401, "long-401"), (5000, "long-5000")):
        s = Session.create(root, ["Ada"], session_id=sid, date="2024-04-16")
        s.enter("R", "5.2")
        s.close()
        path = s.folder / "session.json"
        text = path.read_text(encoding="utf-8").replace('"value": 5.2', '"value": ' + "9" * digits)
        path.write_text(text, encoding="utf-8")
    async with quiet_app(root).run_test(size=(160, 40)) as pilot:
        await settle(pilot, lambda: bool(pilot.app.screen.query("#sessions")))
        sessions = pilot.app.screen.query_one("#sessions", OptionList)
        labels = [str(sessions.get_option_at_index(k).prompt) for k in range(3)]
        assert sum("damaged" in label for label in labels) == 2
        assert any("Bo" in label and "damaged" not in label for label in labels)


async def test_task10_shows_a_run_saved_late_at_once(quiet, tmp_path):
    """A run that finished while nothing could be written (a full disk, a stick pulled out)
    is kept in memory and saved once the disk is back: Task 10 said 'no runs recorded yet'
    until the group paged away and back."""
    root = tmp_path / "sessions"
    async with quiet().run_test(size=(100, 40)) as pilot:
        app = pilot.app
        await start(pilot)
        await goto(pilot, "task10", focus=None)
        status = app.screen.query_one("#run-status", Prose)
        assert status.text == "no runs recorded yet"
        with app.session as s:
            rec = s.start_run("steps", ts=0.025)
            for k in range(40):
                rec.append(k, 25_000 * k, 3 * k, 2500 if k >= 4 else 0)
            root.rename(tmp_path / "gone")  # the disk goes before the run is kept
            with pytest.raises(SessionNotWritable):
                s.finish_run(rec)
        app.lab_changed.publish(None)  # as the app does once a run ends
        await settle(pilot)
        assert status.text == "no runs recorded yet"  # true: not kept yet
        (tmp_path / "gone").rename(root)
        app.retry_save()
        await settle(pilot, lambda: status.text != "no runs recorded yet")
        assert status.text.startswith("▸ steps-1 (40 samples")  # the run in use, marked


async def test_a_board_and_report_files_with_brackets_are_named_as_they_are(tmp_path):
    """What a board says of itself (its name, firmware) and its port, and the report's file
    names, hold text nobody here chose: shown as is, never as markup."""
    dev = QuietDevice(seed=1)
    dev.ident = Ident("fw [/] 1.0.0", 1, "Mega [red]", 720, 25000, 9000, "BRAKE")
    dev.port = "/dev/tty[/]0"
    dev.board = None  # a real board, as far as the app can tell
    async with quiet_app(tmp_path / "sessions", dev).run_test(size=(120, 40)) as pilot:
        app = pilot.app
        await settle(pilot, lambda: app.device is not None)
        await start(pilot)
        await goto(pilot, "task1", focus=None)
        said = str(app.screen.query_one(ConnectPanel).render())
        assert "Mega [red] on /dev/tty[/]0, firmware fw [/] 1.0.0" in said
        assert "/dev/tty[/]0" in str(app.screen.query_one(DeviceStatus).render())
        await goto(pilot, "summary", focus=None)
        app.screen.written = written_in((f"{tmp_path}/[/]report.md",), app.config.sessions)
        await settle(pilot)
        assert f"{tmp_path}/[/]report.md" in str(app.screen.query_one(ReportPanel).render())


async def test_the_class_view_of_a_folder_with_brackets_names_it_as_it_is(tmp_path):
    """The class view's title names the sessions folder: '[/]' in its path was a MarkupError
    as the view opened (issue 18, item 3)."""
    root = tmp_path / "class [/] 2026"
    Session.create(root, ["Ada"], date="2024-04-16").close()
    async with quiet_app(root).run_test(size=(120, 40)) as pilot:
        app = pilot.app
        await class_view(pilot)
        title = str(app.screen.query_one("#class-title").render())
        assert "class [/] 2026" in title
