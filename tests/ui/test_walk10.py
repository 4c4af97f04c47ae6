"""Walk 10's defects (issue 20), each as the walk met it, at 80x24 with Pilot on a real
session folder."""

from __future__ import annotations

import asyncio

import pytest
from textual.command import CommandInput, CommandPalette, Hits, Provider
from textual.widgets import Input

from minseg_tui.ui.app import TRANSIENT_SHOWN
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.names import NamesScreen
from minseg_tui.ui.widgets.footer import KeyFooter, KeyLabel
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    burst,
    goto,
    heard_notifications,
    record_response_run,
    settle,
    start,
    start_with_a_run,
)
from tests.ui.test_link_words import _event, _on_a_standing_wheel, _status, _stream


class SlowSearch(Provider):
    """A search that finds nothing and answers late (after many turns of the event loop, as
    on a loaded machine): the keys of a burst are all read before it is done, whatever
    the machine."""

    TURNS = 500

    async def search(self, query: str) -> Hits:
        for _ in range(self.TURNS):
            await asyncio.sleep(0)
        for hit in ():
            yield hit


def _step(app) -> str:
    with app.session as s:
        return s.current_step


@pytest.mark.parametrize(
    ("at", "query", "lands", "slow"),
    [
        ("task11", "task 12", "task12", True),
        ("task11", "task 14", "task14", True),
        ("task10", "summary", "summary", True),
        ("task2", "task 12", "task12", True),
        ("task2", "task 12", "task12", False),
    ],
    ids=["task11-to-12", "task11-to-14", "task10-to-summary", "task2-to-12", "task2-to-12-as-is"],
)
async def test_palette_query_and_enter_in_one_burst_go_where_the_query_says(
    quiet, monkeypatch, at, query, lands, slow
):
    """D1: 'Ctrl+P task 12 Enter' sent at once from Task 11's answer ran the board check
    (the palette's first entry before the search was done), and from Task 10 every query
    went to Preparation 1. Enter now goes where the typed text says; the motor is not
    driven. With a slow search, the burst is read long before the search is done."""
    if slow:
        monkeypatch.setattr(LabScreen, "COMMANDS", LabScreen.COMMANDS | {SlowSearch})
    device = QuietDevice(seed=1)
    app = quiet(device)
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, at)
        said = heard_notifications(app)
        before = list(device.commands)
        await burst(pilot, "ctrl+p", *query, "enter")
        await settle(pilot)
        assert isinstance(app.screen, LabScreen)
        assert _step(app) == lands
        assert not [s for s in said if s.startswith("board check")]
        assert device.commands == before  # the motor was not driven


async def test_palette_names_and_enter_in_one_burst_opens_the_names_dialog(quiet):
    """D1 at Task 2 (the board unpowered there): 'Ctrl+P names Enter' at once opened the
    board check's result; now the names dialog opens and the motor stays off."""
    device = QuietDevice(seed=1)
    app = quiet(device)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        said = heard_notifications(app)
        await burst(pilot, "ctrl+p", *"names", "enter")
        await settle(pilot)
        assert isinstance(app.screen, NamesScreen)
        assert not [s for s in said if s.startswith("board check")]
        assert device.commands == []
        assert _step(app) == "task2"


def _text(app, selector: str) -> str:
    return " ".join(str(app.screen.query_one(selector).render()).split())


async def _task11_with_a_run_alone(pilot) -> None:
    """A new session, a step run recorded and nothing typed (no u_ss), on Task 11."""
    await start(pilot)
    with pilot.app.session as s:
        record_response_run(s)
    await goto(pilot, "task11")


async def test_task11_with_a_run_and_no_u_ss_asks_for_the_u_ss_alone(quiet):
    """D4 (walk 3 of walk 10): after F5 with the table empty, Task 11's plot said its results
    'need the table of Tasks 4-9 filled' and the lines under it named R (Task 2) and a
    complete row; the run's results need only a u_ss to divide by. Once u_ss at 4.5 V is
    typed (R and i_ss still empty) they come."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _task11_with_a_run_alone(pilot)
        note, lines = _text(app, "#zoom-note"), _text(app, "#results-lines")
        # the rises and the speed's readings need no u_ss (walk 18, D4); K alone waits for it
        assert "rise 1 of 4" in note, note
        assert (
            "K, J, the model and omega at 5 V: not yet, needs u_ss at the steps' voltage (Task 4)"
            in lines
            and "R (Task 2)" not in lines
        ), lines
        with app.session as s:
            s.enter("u_ss@4.5", "4,05")
        await goto(pilot, "task12")
        await goto(pilot, "task11")
        assert "shown once you enter yours" in _text(app, "#results-lines")
        assert "no results yet" not in _text(app, "#zoom-note")


async def test_ctrl_r_with_nothing_computed_records_nothing_and_says_so(quiet):
    """D5 (walk 10, walk 3): Ctrl+R on Task 11 with a run but no u_ss showed dashes, said
    'computed values shown', and the session recorded both values as shown then; the report
    later said they were revealed at that time. Now only what is computed is shown and
    recorded: omega_ss in the steps, from the speed alone (walk 18, D4); K once u_ss is in,
    when Ctrl+R shows and records it (and the comparisons say so, with no notice)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _task11_with_a_run_alone(pilot)
        said = heard_notifications(app)
        await pilot.press("ctrl+r")
        await settle(pilot)
        # omega_ss in the steps needs only the speed (walk 18, D4): it is shown and recorded;
        # K, which divides by u_ss, is neither
        assert said == [], said
        assert "K = " not in _text(app, "#results-lines")
        with app.session as s:
            assert s.revealed() == {"own.omega_step"}
            assert {k: v.by for k, v in s.shown().items()} == {"own.omega_step": "reveal"}
            s.enter("u_ss@4.5", "4,05")
        await goto(pilot, "task12")
        await goto(pilot, "task11")
        await pilot.press("ctrl+r")
        await settle(pilot)
        # said in the step's comparisons, not in a notice over the step (issue 20)
        assert "revealed before answering (Ctrl+R): the report says so" in _text(app, "#compare")
        assert said == [], said
        assert "K = " in _text(app, "#results-lines")
        with app.session as s:
            assert s.revealed() == {"own.omega_step", "own.K"}
            assert {k: v.by for k, v in s.shown().items()} == {
                "own.omega_step": "reveal",
                "own.K": "reveal",
            }


async def test_square_wave_done_gives_way_to_the_link_counters(quiet):
    """D2 (walk 10, walk 3): after a run the top line said 'square wave done' for the rest of
    the session, through later runs, and the link's counters never came back. It is news
    now: shown for a few seconds of board time, then 'link ok · lost 0 · bad 0' again."""
    async with _on_a_standing_wheel(quiet) as (pilot, dev, heard, seq):
        app = pilot.app
        seq = await _event(pilot, dev, heard, seq, "square_wave_done", "square wave done")
        assert "square wave done" in _status(app)
        seq = await _stream(pilot, dev, seq, TRANSIENT_SHOWN)
        assert "square wave done" not in _status(app)
        assert "link ok · lost 0 · bad 0" in _status(app)


async def test_a_new_run_takes_square_wave_done_off_the_top_line_at_once(quiet):
    """D2's rest: F5 within the few seconds 'square wave done' of the last run is shown put
    it beside 'motor steps' of the new run. The new run's square wave ends the news."""
    async with _on_a_standing_wheel(quiet) as (pilot, dev, heard, seq):
        app = pilot.app
        await goto(pilot, "task10")
        seq = await _event(pilot, dev, heard, seq, "square_wave_done", "square wave done")
        said_at = seq
        assert "square wave done" in _status(app)
        await pilot.press("f5")
        await settle(pilot)
        while not (dev.commands and dev.commands[-1].startswith("STEP")):
            seq = await _stream(pilot, dev, seq, 0.1)
            assert (seq - said_at) * 0.025 < TRANSIENT_SHOWN, "the news ran out first"
        await settle(pilot, lambda: app.task10 is not None and app.task10.phase == "square_wave")
        assert (seq - said_at) * 0.025 < TRANSIENT_SHOWN
        assert "square wave done" not in _status(app)
        assert "link ok · lost 0 · bad 0" in _status(app)


def _footer(app) -> list[str]:
    footer = app.screen.query_one(KeyFooter)
    return [f"{k.key_display} {k.description}".strip() for k in footer.query(KeyLabel) if k.display]


async def test_task1_s_footer_shows_f10_which_works_on_every_step(quiet):
    """D6: Task 1 asks for F10, but its footer showed 'pgdn Next step f1 Help f2 STOP f8
    Export'; every other step shows its F-keys. F10 is in Task 1's footer now, and only
    there, and it still runs the board check on any step (the app's priority key)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task1")
        await settle(pilot)
        assert "f10 Board check" in _footer(app), _footer(app)
        await goto(pilot, "task2")
        await settle(pilot)
        assert not [k for k in _footer(app) if k.startswith("f10")], _footer(app)
        for step_id in ("task1", "task2"):
            await goto(pilot, step_id)
            said = heard_notifications(app)
            app.action_board_check = lambda said=said: said.append("F10")  # the check itself
            await pilot.press("f10")
            await settle(pilot)
            assert said == ["F10"], (step_id, said)
            del app.action_board_check


async def test_enter_queued_behind_many_changes_of_the_box_waits_for_the_last_search(quiet):
    """D1 as the terminal gave it: the palette read the box's changes for 's', 'su', ...,
    'summary' and the Enter one after the other, each change starting a search and
    cancelling the one before; Enter came before any of those searches had run. Waiting
    for them together ended at the first cancelled one, and Enter ran the list of the empty
    search (the board check, from Task 12). Posted to the palette in one go, as they
    reach it from the box."""
    device = QuietDevice(seed=1)
    app = quiet(device)
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        said = heard_notifications(app)
        await pilot.press("ctrl+p")
        await settle(pilot, lambda: isinstance(app.screen, CommandPalette))
        palette = app.screen
        box = palette.query_one(CommandInput)
        with box.prevent(Input.Changed):
            box.value = "summary"
        for n in range(1, len("summary") + 1):
            palette.post_message(Input.Changed(box, "summary"[:n]))
        palette.post_message(Input.Submitted(box, "summary"))
        await settle(pilot)
        assert isinstance(app.screen, LabScreen)
        assert _step(app) == "summary"
        assert not [s for s in said if s.startswith("board check")]
        assert device.commands == []
