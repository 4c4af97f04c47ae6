"""Snapshot tests of the screens at 80x24 and 120x40 (fixed date, no stream, no animations)."""

from __future__ import annotations

import pytest

from minseg_tui.ui.ports import Batch
from tests.ui.conftest import build_app
from tests.ui.fakes import FakeDevice

SIZES = [(80, 24), (120, 40)]


class QuietDevice(FakeDevice):
    """No samples: what is on screen does not depend on timing."""

    def read(self, timeout: float) -> Batch:
        import time

        time.sleep(timeout)
        return Batch((), (), ())


def _app(tmp_path):
    return build_app(tmp_path / "sessions", QuietDevice(seed=0))


def _to(step_id: str, entries: dict[str, str] | None = None):
    async def run_before(pilot) -> None:
        await pilot.press(*"Ada, Bo", "enter")
        await pilot.pause()
        for key, text in (entries or {}).items():
            pilot.app.lab.enter(key, text)
        pilot.app.go_to_step(step_id)
        await pilot.pause()
        await pilot.pause()
    return run_before


@pytest.mark.parametrize("size", SIZES)
def test_start_screen(snap_compare, tmp_path, size):
    assert snap_compare(_app(tmp_path), terminal_size=size)


@pytest.mark.parametrize("size", SIZES)
def test_resistance_step_with_a_refused_entry(snap_compare, tmp_path, size):
    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=_to("task2", {"R": "abc"}))


@pytest.mark.parametrize("size", SIZES)
def test_table_step(snap_compare, tmp_path, size):
    entries = {"R": "5.2", "u_ss@2.5": "2.05", "omega_ss@2.5": "3.1", "i_ss@2.5": "28 mA",
               "u_ss@3.5": "3.04", "omega_ss@3.5": "4.9", "i_ss@3.5": "32 mA",
               "u_ss@4.5": "4.02", "omega_ss@4.5": "6.7", "i_ss@4.5": "36 mA"}
    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=_to("table", entries))


@pytest.mark.parametrize("size", SIZES)
def test_summary_step(snap_compare, tmp_path, size):
    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=_to("summary", {"summary.1": "2"}))


@pytest.mark.parametrize("size", SIZES)
def test_help_screen(snap_compare, tmp_path, size):
    async def run_before(pilot) -> None:
        await _to("prep1")(pilot)
        await pilot.press("f1")
        await pilot.pause()
    assert snap_compare(_app(tmp_path), terminal_size=size, run_before=run_before)
