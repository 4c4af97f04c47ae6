"""Walk 16's defects (issue 20), each as the walk met it, at 80x24 with Pilot on real session
folders (/work/coord/WALK16.md)."""

from __future__ import annotations

import json
import shutil

import pytest
from textual.widgets import OptionList

from minseg_tui.lab.content.keys import PALETTE
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views.classview import read_group
from minseg_tui.report.write import write_report
from minseg_tui.ui.panels.results import ResultsPanel
from minseg_tui.ui.screens.classview import detail
from minseg_tui.ui.screens.lab import LabScreen, StepCommands
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox
from tests.classview.build import group
from tests.shared_data import SHARED_DATA
from tests.ui.conftest import quiet_app
from tests.ui.helpers import (
    burst,
    goto,
    heard_notifications,
    import_a_copy,
    lab_screen,
    settle,
    shown,
    start,
    start_with_a_run,
    stored_text,
    type_in,
)


async def test_a_letter_on_the_tick_goes_after_the_notes_not_over_them(tmp_path):
    """D2: Prep 1, 'read ch 2.1 Enter' (the notes stored, the focus on to "done?"), then a
    stray 'k': the notes' box showed "k" alone, and PgDn stored "k" over "read ch 2.1". A
    character typed outside the entries goes into the step's entry, replacing what it holds:
    right for a reading typed off a plot, wrong for free text. Now it goes on after the
    notes."""
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep1")
        await type_in(pilot, "prep1.notes", "read ch 2.1")
        # the focus went on to "done?" (a list of answers); a letter typed there
        await burst(pilot, "k")
        box = app.screen.query_one(f"#{field_id('prep1.notes')}", FieldRow).input
        assert box.value == "read ch 2.1k"
        await burst(pilot, "pagedown")
        await settle(pilot, lambda: stored_text(app, "prep1.notes") != "read ch 2.1")
        assert stored_text(app, "prep1.notes") == "read ch 2.1k"


async def test_a_short_text_typed_over_a_long_one_shows(tmp_path):
    """D2's second half: the model check's notes held a 56-character path, scrolled to its
    end in the box; the notes focused (all selected) and 'X' typed over it: the box looked
    empty, its view still scrolled one column into the new text (Home showed the "X"). A
    text that fits the box now shows from its first column."""
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep1")
        long = "/work/shared/data/real-motors/ev3-large-duty100/step.csv"
        await type_in(pilot, "prep1.notes", long)
        row = app.screen.query_one(f"#{field_id('prep1.notes')}", FieldRow)
        row.input.focus()  # the row's text all selected, as Tab or Shift+Tab leaves it
        await settle(pilot, lambda: row.input.selection == (0, len(long)))
        await burst(pilot, "X")
        assert row.input.value == "X"
        assert row.input.render_line(0).text.strip() == "X"


async def test_a_copied_session_folder_is_told_apart_on_the_resume_list(tmp_path):
    """D1: a group copied its session's folder to sessions/tina-backup; the resume list then
    showed two rows "2026-11-28  Tina K, Omar B  at Summary …" alike, and Enter on the
    first opened the copy (the newer), where the next day's work went; once one of them is
    used the two differ by their step only, which does not say which is which either. Rows
    of one group and date now say their folder."""
    root = tmp_path / "sessions"
    Session.create(root, ["Tina K", "Omar B"], date="2026-11-28").close()
    Session.create(root, ["Lea P", "Tom R"], date="2026-11-28").close()
    (original,) = (p for p in root.iterdir() if p.name.startswith("2026-11-28-tina"))
    shutil.copytree(original, root / "tina-backup")
    copied = root / "tina-backup" / "session.json"
    data = json.loads(copied.read_text(encoding="utf-8"))
    copied.write_text(json.dumps({**data, "current_step": "task10"}), encoding="utf-8")
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        listed = app.screen.query_one("#sessions", OptionList)
        labels = {
            str(listed.get_option_at_index(i).id): str(listed.get_option_at_index(i).prompt)
            for i in range(listed.option_count)
        }
        tina = {k: v for k, v in labels.items() if "Tina K" in v}
        assert len(tina) == 2
        assert len(set(tina.values())) == 2, tina
        assert "tina-backup" in tina[str(root / "tina-backup")]
        assert original.name in tina[str(original)]
        lea = next(v for v in labels.values() if "Lea P" in v)
        assert "2026-11-28-lea" not in lea  # a row unlike the others stays as it was


async def test_the_report_of_a_copied_session_names_its_own_folder(tmp_path):
    """D1's second half: F8 in the copy (sessions/tina-backup) wrote a report whose head
    said "session 2026-11-28-tina-k-omar-b", the id its copied file still holds: two
    reports named one session. The report names the folder it is written from, as the class
    view names a copy (tests/classview/test_class_cli.py)."""
    root = tmp_path / "sessions"
    Session.create(root, ["Tina K", "Omar B"], date="2026-11-28").close()
    (original,) = root.iterdir()
    copy = root / "tina-backup"
    shutil.copytree(original, copy)
    app = quiet_app(root)
    app._writer = lambda session: write_report(session).paths  # the CLI's writer
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        listed = app.screen.query_one("#sessions", OptionList)
        listed.focus()
        keys = [str(listed.get_option_at_index(i).id) for i in range(listed.option_count)]
        listed.highlighted = keys.index(str(copy))
        await settle(pilot, lambda: app.focused is listed)
        await burst(pilot, "enter")
        await settle(pilot, lambda: shown(app))
        await burst(pilot, "f8")
        await settle(pilot, lambda: (copy / "report.md").exists())
    byline = (copy / "report.md").read_text(encoding="utf-8").splitlines()[2]
    assert "session tina-backup ·" in byline, byline
    assert original.name not in byline


async def test_enter_on_a_session_in_use_says_why_nothing_opens(tmp_path):
    """D5: a second window's start screen listed only the first window's session, "…: in
    use by another minseg-tui (pid 7723)"; Tab Tab Enter did nothing and said nothing. Now
    the line under the names says where the session is open and what to do."""
    root = tmp_path / "sessions"
    held = Session.create(root, ["Tina K", "Omar B"], date="2026-11-28")  # the other window
    try:
        app = quiet_app(root)
        async with app.run_test(size=(80, 24)) as pilot:
            await settle(pilot, lambda: isinstance(app.screen, StartScreen))
            await burst(pilot, "tab", "tab", "enter")
            said = str(app.screen.query_one("#start-msg").render())
            assert isinstance(app.screen, StartScreen)
            assert f"{held.folder.name} is open in another minseg-tui" in said
            assert "quit it there first" in said
    finally:
        held.close()


async def test_f12_enter_in_one_burst_opens_the_group(tmp_path):
    """D4: 'F12 Enter' in one burst on the start screen left the class view up, the Enter
    lost (2 of 2 at load 18): the start screen's Enter, a priority binding, ran before F12's
    binding, on the start screen ("Type the group members' names first."). F12 now acts as
    it is read, so the Enter after it is the class view's: it opens the group read-only."""
    root = tmp_path / "sessions"
    folder = group(root, ["Ada", "Bo"], seed=1, run=False)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        await burst(pilot, "f12", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
        assert app.session is not None
        with app.session as s:
            assert s.folder == folder and s.readonly


TASKS_11_TO_14 = ("own.omega_step", "own.K", "own.T", "own.J", "own.model")
EV3 = SHARED_DATA / "real-motors" / "ev3-large-duty100" / "step.csv"


def _verdicts(app) -> dict[str, bool | None]:
    with app.session as s:
        return {c.key: c.right for c in s.comparisons() if c.key in TASKS_11_TO_14}


@pytest.mark.shared_data
async def test_an_import_at_the_model_check_leaves_tasks_11_to_15_their_run(tmp_path):
    """D3: a group done with Tasks 11-15 imported an EV3 motor's log at the model check, and
    it took Tasks 11-15 with it: Tasks 11-12 turned ✗, 13-14 !, judged against a motor the
    group never touched. An import now feeds the model check only; the line says Tasks 11-15
    keep their run, and how to judge them on the import; the report and the class view say
    which run the model check used."""
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        with app.session as s:
            given_on = s.response_run().name
            folder = s.folder
            for key in TASKS_11_TO_14:  # each the program's own value: ✓ (J from our T)
                (c,) = (c for c in s.comparisons() if c.key == key)
                if isinstance(c.computed, str):
                    s.enter(key, c.computed)
                elif key == "own.T":
                    s.enter(key, f"{c.computed * 1e3:.4g} ms")
                else:
                    s.enter(key, f"{c.computed:.5g}")
        before = _verdicts(app)
        assert before == dict.fromkeys(TASKS_11_TO_14, True), before
        app.import_log()  # the palette's "Import a run log": the model check, its box
        await settle(pilot, lambda: shown(app, "model_check"))
        box = app.screen.query_one("#import-path", TextBox)
        await settle(pilot, lambda: app.focused is box)
        box.value = str(EV3)
        await pilot.press("enter")
        msg = app.screen.query_one("#import-msg", Prose)
        await settle(pilot, lambda: bool(msg.text))
        assert _verdicts(app) == before  # Tasks 11-14 unchanged
        said = " ".join(msg.text.split())
        assert said.startswith(f"imported {EV3} as imported-1 ("), said
        assert (
            f"the model check uses it; Tasks 11-15 keep run {given_on} "
            "(Ctrl+P 'Use run imported-1' judges them on it)" in said
        ), said
        with app.session as s:
            assert s.response_run().name == given_on and s.check_run().name == "imported-1"
        story = app.screen.query_one("#check-story", Prose)
        await settle(pilot, lambda: story.text.startswith("run imported-1"))
        assert story.text.startswith(f"run imported-1 (Tasks 11-15 use run {given_on}),")
        with app.session as s:
            write_report(s)
        report = (folder / "report.md").read_text(encoding="utf-8")
        flat = " ".join(report.split())
        assert (
            f"Tasks 11-15 use run {given_on}, the newest complete 25 ms run (the group chose "
            "none); the model check uses run imported-1, a log imported at the model check."
        ) in flat
        assert (
            f"Run imported-1 (a log imported at the model check; Tasks 11-15 use run {given_on})"
            in flat
        )
        g = read_group(folder)
        assert g.check_on == (
            f"run imported-1, a log imported at the model check; Tasks 11-15 use run {given_on}"
        )
        assert f"(on {g.check_on})" in detail(1, g).plain.split("model check: ", 1)[1]
        # the group can still judge Tasks 11-15 on the import, and go back
        lab_screen(app).use_run("imported-1")
        with app.session as s:
            assert s.response_run().name == "imported-1" == s.check_run().name
        assert _verdicts(app) != before
        lab_screen(app).use_run(given_on)
        with app.session as s:
            assert s.response_run().name == given_on == s.check_run().name
        assert _verdicts(app) == before


async def test_the_palettes_import_says_tasks_11_to_15_keep_their_run(tmp_path):
    """D3's words: the palette's "Import a run log" said "Tasks 11-15 and the model check
    then use it"; now the import is the model check's only, and "Use run imported-1" says
    it judges Tasks 11-15 on the log."""
    app = quiet_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        (entry,) = (
            c for c in app.get_system_commands(app.screen) if c.title == PALETTE["import_log"]
        )
        assert entry.help == (
            "Load a log recorded elsewhere into the model check (Tasks 11-15 keep their run)"
        )
        await import_a_copy(pilot, tmp_path)
        helps = {t: h for t, _, h in StepCommands(app.screen).entries()}
        assert helps["Use run imported-1 for Tasks 11-15"] == (
            "an imported log: Tasks 11-15 are then judged on it, as the model check is"
        )


async def test_f9_before_the_plot_is_worked_out_waits_for_it(tmp_path):
    """D4: 'Ctrl+P task 11 Enter F9' in one burst (load 20): 1 run in 3 the F9 came before
    Task 11's plot was worked out and was refused, "no rise to zoom to: the plot is still
    being worked out". The key now waits for the plot and is done once it is drawn: rise 2."""
    app = quiet_app(tmp_path / "sessions")
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        panel = app.screen.query_one(ResultsPanel)
        await settle(pilot, lambda: panel.view is not None and panel.zoom == 0)
        view = panel.view
        panel.view = None  # as it is while the step's view is being worked out
        panel.action_zoom_next()
        panel.pick(1)
        await settle(pilot)
        assert not any("no rise to zoom to" in m for m in said), said
        assert panel.zoom == 0  # nothing done yet
        panel.view = view
        panel.show_view()  # the plot worked out: F9 (rise 2), then Alt+→ (rise 3)
        assert panel.zoom == 2
