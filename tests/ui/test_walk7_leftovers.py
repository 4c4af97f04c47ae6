"""What walk 7 left on the screens, at 80x24 where it was seen (Pilot, real session folder):
Ctrl+O's whole "What to do" over a step whose own text is in view (D3); a resumed Task 10's
plots (D11); the palette with no match (D17); the group's names corrected."""

from __future__ import annotations

import json
import threading
from pathlib import Path

from textual.command import CommandList, CommandPalette
from textual.widgets import Input, OptionList

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.lab.views import session as views
from minseg_tui.report.write import write_report
from minseg_tui.ui.screens.lab import NO_MATCH
from minseg_tui.ui.screens.names import NamesScreen
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.plots import TracePlot
from tests.ui.helpers import (
    GUARD,
    ROUNDS,
    goto,
    settle,
    shown,
    start,
    start_with_a_run,
    typing_box,
)


async def test_ctrl_o_never_shows_a_line_of_what_to_do_twice(quiet):
    """Task 5 at 80x24, Ctrl+O: the whole "What to do" lay over the step's own, one row
    short of it, so the own text's last line ('jumper back afterwards.') showed under the
    overlay, as if repeated. With the own text whole in view no overlay is drawn over it;
    once the step scrolls it away, Ctrl+O's whole text shows in the heading."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task5")
        pane = app.screen.pane
        heading = pane.query_one(".heading")
        own = pane.query_one(".todo")
        await pilot.press("ctrl+o")
        await settle(pilot)
        view = pane.scrollable_content_region
        assert view.y <= own.region.y and own.region.bottom <= view.bottom  # whole in view
        if heading.display:  # an overlay, if any, hides all of the own text, not all but a line
            assert own.region.bottom <= heading.region.bottom
        # the last entry, below the screen: the step scrolls its own text away
        last = pane.query_one("#" + field_id("i_ss@4.5"), FieldRow)
        for _ in range(3):  # i_ss at 2.5 V, 3.5 V, 4.5 V
            if typing_box(app) is last.input:
                break
            await pilot.press("tab")
            await settle(pilot)
        assert typing_box(app) is last.input
        assert own.region.bottom <= view.y or own.region.y < heading.region.bottom
        assert heading.display and heading.whole
        todo = heading.query_one(".heading-todo")
        shown = " ".join(str(todo.render()).split())
        assert (
            shown == " ".join(("What to do: " + step("task5").todo).split()) + " (Ctrl+O folds it)"
        )
        assert own.region.bottom <= heading.region.bottom  # no line of it under the heading


async def test_a_resumed_task_10_plots_the_run_in_use_before_its_fits_are_made(quiet, monkeypatch):
    """After a resume Task 10 showed both plots empty for about 4 s (walk 7, D11): its view
    waited for the three fits of each run. The fits are held here until the test lets them
    go: the 25 ms plot shows the run in use meanwhile, and the T readings follow."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task10")
        await settle(pilot)
    monkeypatch.setattr(views, "_run_views", {})  # a new process: no fit made yet
    monkeypatch.setattr(views, "_marked_views", {})
    let_go = threading.Event()
    fit = views.model_identify.fit_time_constant

    def held(*args, **kwargs):
        let_go.wait(GUARD)  # a guard against a hang, not a measure
        return fit(*args, **kwargs)

    monkeypatch.setattr(views.model_identify, "fit_time_constant", held)
    app2 = quiet()
    try:
        async with app2.run_test(size=(80, 24)) as pilot:
            await settle(pilot, lambda: bool(app2.screen.query("#sessions")))
            app2.screen.query_one("#sessions").focus()
            await pilot.press("enter")
            plot = None
            for _ in range(ROUNDS):  # rounds of message processing, not time
                await pilot.pause(0)
                if shown(app2, "task10"):
                    plot = app2.screen.query_one("#plot-slow", TracePlot)
                    if plot.traces:
                        break
            assert plot is not None and plot.traces, "the plot waited for the fits"
            assert not let_go.is_set()
            readings = str(app2.screen.query_one("#t-readings").render())
            assert "working out the T readings" in readings
            let_go.set()
            await settle(
                pilot,
                lambda: "working out" not in str(app2.screen.query_one("#t-readings").render()),
            )
            readings = str(app2.screen.query_one("#t-readings").render())
            assert "steps-1" in readings  # the runs, with what the step lets it show of T
    finally:
        let_go.set()


def _palette_lines(app) -> list[str]:
    """The palette's list, one line per option (its prompt, plain; none while the palette
    is not composed yet)."""
    found = app.screen.query(CommandList)
    if not found:
        return []
    options = found.first()
    return [
        " ".join(str(options.get_option_at_index(i).prompt).split())
        for i in range(options.option_count)
    ]


async def test_the_palette_says_when_no_command_matches(quiet):
    """Ctrl+P 'unplug' showed an empty list (walk 7, D17). The palette now says that no command
    matches the search, at once; a search that matches lists the commands without it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await pilot.press("ctrl+p")
        await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
        await pilot.press(*"unplug")
        await settle(pilot, lambda: bool(_palette_lines(app)))  # the search is a worker's
        lines = _palette_lines(app)
        assert lines and lines[0].startswith(f"{NO_MATCH} 'unplug'"), lines
        assert len(lines) == 1
        await pilot.press(*["backspace"] * 6, *"board")
        await settle(pilot, lambda: any("Board" in line for line in _palette_lines(app)))
        lines = _palette_lines(app)
        assert any("Board check" in line for line in lines), lines
        assert not any(NO_MATCH in line for line in lines), lines
        await pilot.press("escape")
        await settle(pilot)
        assert not isinstance(app.screen, CommandPalette)


async def test_the_palette_corrects_a_misspelt_name(quiet, tmp_path):
    """A name misspelt at the start (walk 7, D1: 'Omrr Haddad') could not be mended. The
    palette's "Correct the group's names" asks for them, the ones in use filled in; the
    session, its resume list and its report then give the new names, and the session keeps
    the old ones."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot, "Lena Berg, Omrr Haddad")
        await goto(pilot, "task2")
        await pilot.press("ctrl+p")
        await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
        await pilot.press(*"names")
        await settle(pilot, lambda: bool(_palette_lines(app)))  # the search is a worker's
        assert _palette_lines(app)[0].startswith("Correct the group's names")
        await pilot.press("enter")
        await settle(pilot, lambda: isinstance(app.screen, NamesScreen))
        box = app.screen.query_one("#names", Input)
        assert box.value == "Lena Berg, Omrr Haddad"
        await pilot.press("end", *["backspace"] * len("mrr Haddad"), *"mar Haddad", "enter")
        await settle(pilot, lambda: not isinstance(app.screen, NamesScreen))
        with app.session as s:
            assert s.members == ("Lena Berg", "Omar Haddad")
            assert s.former_members == ("Lena Berg, Omrr Haddad",)
            written = write_report(s)
        report = (Path(written.paths[0]).parent / "report.md").read_text(encoding="utf-8")
        assert "Group: Lena Berg, Omar Haddad" in report and "Omrr" not in report
    (saved,) = list_sessions(tmp_path / "sessions")
    assert saved.members == ("Lena Berg", "Omar Haddad")
    data = json.loads((saved.path / "session.json").read_text(encoding="utf-8"))
    assert data["former_members"] == ["Lena Berg, Omrr Haddad"]
    app2 = quiet()
    async with app2.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app2.screen.query("#sessions")))
        listed = app2.screen.query_one("#sessions", OptionList)
        label = str(listed.get_option_at_index(0).prompt)
        assert "Lena Berg, Omar Haddad" in label and "Omrr" not in label
