"""Walk 14's defects (issue 20), each as the walk met it, at 80x24 with Pilot on real session
folders (/work/coord/WALK14.md)."""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.widgets import Static

from minseg_tui.errors import InputError
from minseg_tui.lab.state.session import Session
from minseg_tui.ui.screens.lab import LabScreen
from tests.classview.build import group
from tests.ui.conftest import quiet_app
from tests.ui.fakes import QuietDevice, frozen_stream
from tests.ui.helpers import (
    burst,
    class_view,
    enter_all,
    goto,
    heard_notifications,
    settle,
    shown,
    start,
    start_with_a_run,
    type_in,
)


def _files(root: Path) -> dict[str, bytes]:
    """Every file under ``root`` with its bytes (a read-only session changes none)."""
    return {str(p): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


async def _open_from_the_class_view(pilot) -> None:
    """F12 on the start screen, Enter on the first group: its session opens read-only."""
    app = pilot.app
    await class_view(pilot)
    await pilot.press("enter")
    await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
    assert app.screen.readonly


async def test_ctrl_r_in_a_session_opened_from_the_class_view_shows_and_goes_on(tmp_path):
    """D1: the class view, Enter on a group (opened read-only), Task 14 (the group's model not
    typed yet), Ctrl+R: the program died with a traceback ("InputError: ... this session was
    opened read-only"), the reveal's save refused by the read-only session. Now the lab
    assistant sees the computed values, the notice says they are shown here and not
    recorded, the program goes on, and nothing under the sessions folder changes."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, at="task12")
    before = _files(root)
    app = quiet_app(root)
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await _open_from_the_class_view(pilot)
        await goto(pilot, "task14")
        await burst(pilot, "ctrl+r")
        await settle(pilot, lambda: any("not recorded" in m for m in said))
        assert app.is_running and isinstance(app.screen, LabScreen)
        with app.session as s:
            assert "own.model" in s.revealed()
        told = next(m for m in said if "not recorded" in m)
        assert "read-only" in told and "damaged" not in told
    assert _files(root) == before


async def test_f4_in_a_session_opened_from_the_class_view_says_so_and_goes_on(tmp_path):
    """D1: the class view, Enter, Task 4, F3, the speed settled, F4: the capture's save
    raised in the read-only session and the program died. Now F4 says the session is open
    read-only (opened to look, not damaged) and captures nothing; the program goes on.
    (Walk 15, D9: F3 there now refuses as well, the motor off.)"""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, at="task12")
    before = _files(root)
    app = quiet_app(root, QuietDevice(seed=2))
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await _open_from_the_class_view(pilot)
        await goto(pilot, "task4")
        with app.session as s:
            held = s.entry("omega_ss@2.5")
        await burst(pilot, "f3")
        assert app.requested is None  # walk 15, D9: F3 refuses there too (test_class_back)
        app.live.extend(frozen_stream(u=2.5))
        await burst(pilot, "f4")
        await settle(pilot, lambda: any("read-only" in m for m in said[1:]))
        assert app.is_running and isinstance(app.screen, LabScreen)
        told = [m for m in said[1:] if "read-only" in m]
        assert told and all("damaged" not in m for m in told)
        with app.session as s:
            assert s.entry("omega_ss@2.5") == held and s.capture_of(2.5) is None
    assert _files(root) == before


async def test_f5_in_a_session_opened_from_the_class_view_does_not_call_it_damaged(tmp_path):
    """D2: F5 on Task 10 of a sound session opened from the class view said "this session is
    open read-only (its file is damaged)". It says why it is read-only: opened to look."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, at="task12")
    app = quiet_app(root)
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await _open_from_the_class_view(pilot)
        await goto(pilot, "task10", focus=None)
        await burst(pilot, "f5")
        await settle(pilot, lambda: any("nothing can be recorded" in m for m in said))
        told = next(m for m in said if "nothing can be recorded" in m)
        assert "damaged" not in told and "to look" in told
        assert app.recording is None


def test_a_read_only_session_refuses_a_change_before_making_it(tmp_path):
    """D1's root: a read-only session changed itself in memory (and import_run copied the log
    into its runs/ folder) before its save refused. Each change is now refused first."""
    root = tmp_path / "sessions"
    folder = group(root, ["Ada", "Bo"], seed=1, at="task12")
    log = next((folder / "runs").glob("*.csv"))
    elsewhere = tmp_path / "log.csv"
    elsewhere.write_bytes(log.read_bytes())
    before = _files(root)
    with Session.open(folder, readonly=True) as s:
        R, runs = s.entry("R"), list(s.runs)
        for change in (
            lambda: s.enter("R", "9.9"),
            lambda: s.import_run(elsewhere),
            lambda: s.capture_omega(2.5, [0.0, 0.025, 0.05, 0.075], [3.8, 3.8, 3.8, 3.8]),
            lambda: s.select_run(runs[0].name),
        ):
            with pytest.raises(InputError, match="read-only"):
                change()
        assert s.entry("R") == R and s.runs == runs and s.capture_of(2.5) is None
    assert _files(root) == before


async def test_the_class_view_does_not_say_nothing_is_missing_of_an_unfinished_group(tmp_path):
    """D3: a group with one row of three (4.5 V), no board checks, none of its own values of
    Tasks 11-15 and no Summary: the class view's detail said "Nothing is missing." It says
    that what the numbers above need is there, and names what the group has not answered
    yet, as F8's notice does."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, at="task12", rows={2.5: ("", "", ""), 3.5: ("", "", "")})
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await class_view(pilot)
        detail = str(app.screen.query_one("#class-group", Static).render())
        assert "Nothing is missing" not in detail
        assert "Nothing the numbers above need is missing." in detail
        assert "Not answered yet: Task 1, 3, 4, 5, " in detail, detail


async def test_a_formula_with_several_unknown_names_is_refused_once_naming_them_all(quiet):
    """D6: Preparation 12, 'ka*iss/wss Enter': refused for 'wss' alone (no hint), then, 'wss'
    mended, for 'ka', then for 'iss': three refusals for one formula, the last name first.
    One refusal now names each unknown name in the order typed, each with its hint ('w' is
    how the lab writes omega by hand)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep12")
        row = await type_in(pilot, "prep12.f", "ka*iss/wss")
        assert (
            "unknown names 'ka' (did you mean k_a?), 'iss' (did you mean i_ss?), "
            "'wss' (did you mean omega_ss?)"
        ) in row.message, row.message


async def test_r_ten_times_the_meter_asks_about_the_decimal_comma_first(quiet):
    """D7: Task 2 '53 Enter' with the multimeter showing 5.3 Ω: "above 20 Ω: a loose motor
    cable or the current jumper missing", not a word of the likeliest slip, a decimal comma
    lost; the class view names it (an R a power of ten off). The warning asks it first."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        row = await type_in(pilot, "R", "53")
        assert "above 20 Ω: a decimal comma lost (53 for 5,3)?" in row.message, row.message


async def test_a_wrong_value_says_by_how_much_reading_explains_in_plain_words(quiet):
    """D11: Task 15 '95' against 9.500 rad/s: "wrong: +900 % ..., more than the 10 % off
    that reading or rounding explains". It reads "off by more than the 10 % that reading or
    rounding explains"."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await type_in(pilot, "own.omega_step", "7,7")
        await type_in(pilot, "own.K", "1,9")
        await goto(pilot, "task15")
        row = await type_in(pilot, "own.omega_5", "95")
        assert "off by more than the 10 % that reading or rounding explains" in row.message, (
            row.message
        )


async def test_f9_and_alt_right_without_a_run_say_there_is_no_rise(quiet):
    """D9: Task 11 before any run, F9 (the footer's "f9 Zoom"): nothing changed and nothing
    was said, while Ctrl+R on the same screen explains itself. F9 and Alt+→ now say that
    there is no rise to zoom to and why."""
    app = quiet()
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task11")
        await burst(pilot, "f9")
        await settle(pilot, lambda: any("no rise to zoom to" in m for m in said))
        assert "no rise to zoom to: no step run recorded yet (Task 10)" in said
        said.clear()
        await burst(pilot, "alt+right")
        await settle(pilot, lambda: any("no rise to zoom to" in m for m in said))


async def test_f3_after_a_resume_on_task_4_goes_to_the_first_voltage_not_done(quiet):
    """D8: Task 4 with the 2.5 and 3.5 V rows done, the program quit and the session resumed
    (the motor off), F3: 2.5 V again (and F4 there captured the 2.5 V row again); the
    group needed F3 three times for 4.5 V. With the motor off, F3 now sets the first voltage
    whose entries are all empty; from a voltage it goes on to the next, as before."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(
            app,
            {
                "omega_ss@2.5": "3.825",
                "u_ss@2.5": "2,05",
                "omega_ss@3.5": "5.808",
                "u_ss@3.5": "3,05",
            },
        )
        await goto(pilot, "task4")
        assert app.requested is None
        await burst(pilot, "f3")
        assert app.requested == 4.5
        await burst(pilot, "f3")
        assert app.requested == 2.5
