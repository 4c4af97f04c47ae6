"""Snapshot tests of every screen at 80x24 and 120x40: a device double that streams nothing,
a frozen buffer for the live plots, a seeded recorded run, a fixed date, no animations."""

from __future__ import annotations

import pytest

from tests.ui.conftest import quiet_app
from tests.ui.fakes import METER, QuietDevice, frozen_stream, square_wave_stream
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    record_response_run,
    settle,
    start,
    start_run_on,
    taken,
)

SIZES = [(80, 24), (120, 40)]


def _to(
    step_id: str,
    entries: dict[str, str] | None = None,
    run: bool = False,
    live: bool = False,
    focus: str | None = "entry",
):
    async def run_before(pilot) -> None:
        app = pilot.app
        await start(pilot)
        enter_all(app, entries or {})
        if run:
            with app.session as s:
                record_response_run(s)
        if live:
            app.live.extend(frozen_stream())
        app.meter = METER
        await goto(pilot, step_id, focus)

    return run_before


def _app(tmp_path):
    return quiet_app(tmp_path / "sessions")


@pytest.mark.parametrize("size", SIZES)
def test_start_screen(snap_compare, tmp_path, size):
    async def run_before(pilot) -> None:
        await settle(pilot, lambda: pilot.app.device is not None)

    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=run_before)


@pytest.mark.parametrize("size", SIZES)
def test_prep_question_with_feedback(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("prep8", {"prep8.T": "b/a", "prep8.K": "c/b"}, focus=None),
    )


@pytest.mark.parametrize("size", SIZES)
def test_resistance_step_with_a_refused_entry(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("task2", {"R": "abc"}, focus=None)
    )


@pytest.mark.parametrize("size", SIZES)
def test_live_measurement_step(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("task4", {"u_ss@2.5": "2,05 V"}, live=True, focus=None),
    )


@pytest.mark.parametrize("size", SIZES)
def test_table_step(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("table", TABLE, focus=None)
    )


@pytest.mark.parametrize("size", SIZES)
def test_square_wave_run(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("task10", TABLE, run=True)
    )


@pytest.mark.parametrize("size", SIZES)
def test_square_wave_mid_run(snap_compare, tmp_path, size):
    """Task 10 while it records: 4 s of the 25 ms run plotted as it arrived."""
    dev = QuietDevice(seed=1)

    async def run_before(pilot) -> None:
        app = pilot.app
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "task10")
        seq = await start_run_on(pilot, dev)
        dev.feed(square_wave_stream(seq, (seq + 1) * 25_000, 4.0))
        await taken(pilot, seq + 160)

    assert snap_compare(
        quiet_app(tmp_path / "sessions", dev), terminal_size=size, run_before=run_before
    )


@pytest.mark.parametrize("size", SIZES)
def test_zoomed_rise_with_its_63_percent_marks(snap_compare, tmp_path, size):
    """Task 12 lands in the group's T, right under the zoom to the first rise: the 63 %
    level and the time the speed crosses it."""
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("task12", TABLE, run=True)
    )


@pytest.mark.parametrize("size", SIZES)
def test_model_check_close_up(snap_compare, tmp_path, size):
    """The model check lands on its text: the close-up where the cause acts, the residuals
    against the noise band, the lead figure first."""
    assert snap_compare(
        _app(tmp_path), terminal_size=size, run_before=_to("model_check", TABLE, run=True)
    )


@pytest.mark.parametrize("size", SIZES)
def test_summary_step(snap_compare, tmp_path, size):
    assert snap_compare(
        _app(tmp_path),
        terminal_size=size,
        run_before=_to("summary", {"summary.1": "b", "summary.5": "b, c"}),
    )


@pytest.mark.parametrize("size", SIZES)
def test_help_screen(snap_compare, tmp_path, size):
    async def run_before(pilot) -> None:
        await _to("prep1")(pilot)
        await pilot.press("f1")
        await settle(pilot, lambda: bool(pilot.app.screen.query("#help-keys")))

    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=run_before)
