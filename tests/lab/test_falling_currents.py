"""Task 5's warning when a current reading falls as the voltage rises (walk 4: readings
typed one row off went unnoticed): it fires on a mix-up, names both rows, reaches the report,
and stays quiet on the virtual board's own meter over a normal filling, seed after seed."""

from __future__ import annotations

from pathlib import Path

import pytest

from minseg_tui.device.virtual import VirtualBoard, settings_from
from minseg_tui.lab.state.results import I_SS_FALL
from minseg_tui.lab.state.session import Session
from minseg_tui.report import content, markdown

LEVELS = (2.5, 3.5, 4.5)


def _falls(tmp_path: Path, currents: dict[float, str]) -> list[str]:
    with Session.create(tmp_path, ["Ada"]) as s:
        for level, typed in currents.items():
            assert s.enter(f"i_ss@{level:g}", typed).ok
        return [n.message for n in s.warnings("task5")]


def test_readings_one_row_off_are_warned_on_the_higher_row(tmp_path):
    (said,) = _falls(tmp_path, {2.5: "29,8", 3.5: "37,2 mA", 4.5: "0.0335 A"})
    assert said.startswith("i_ss falls from 37.2 mA at 3.5 V to 33.5 mA at 4.5 V"), said
    assert "\n" not in said


def test_the_highest_lower_row_is_named_once_per_row(tmp_path):
    said = _falls(tmp_path, {2.5: "37,2", 3.5: "33,5", 4.5: "29,8"})
    assert said[0].startswith("i_ss falls from 37.2 mA at 2.5 V to 33.5 mA at 3.5 V")
    assert said[1].startswith("i_ss falls from 37.2 mA at 2.5 V to 29.8 mA at 4.5 V")
    assert len(said) == 2


@pytest.mark.parametrize(
    "currents",
    [
        {2.5: "29,8", 3.5: "33,5", 4.5: "37,2"},  # rising, as the wheel's current does
        {2.5: "29,8", 3.5: "29,6", 4.5: "29,7"},  # flat within the margin
        {2.5: "29,8", 4.5: "37,2"},  # a row not filled yet
        {3.5: "30", 4.5: str(30 * (1 - I_SS_FALL) + 0.01)},  # just inside the margin
    ],
)
def test_no_warning_without_a_clear_fall(tmp_path, currents):
    assert _falls(tmp_path, currents) == []


def test_the_report_lists_the_warning(tmp_path):
    with Session.create(tmp_path, ["Ada"]) as s:
        for level, typed in {2.5: "29,8", 3.5: "37,2", 4.5: "33,5"}.items():
            s.enter(f"i_ss@{level:g}", typed)
        md = markdown.render(content.build(s))
    warnings = md.split("## Warnings")[1].split("\n## ")[0]
    assert "- Task 5, i_ss at 4.5 V: i_ss falls from 37.2 mA at 3.5 V to 33.5 mA at 4.5 V" in (
        warnings
    )


def _filling(seed: int, options: dict[str, str]) -> dict[float, str]:
    """i_ss as a group reads it off the virtual board's meter (0.1 mA digit): each voltage
    set in turn (F3's order), the wheel left 2 s to settle, then one reading."""
    board = VirtualBoard(settings_from({"seed": str(seed), **options}))
    t = 0.0
    read = {}
    for level in LEVELS:
        board.run_until(t + 0.01)
        board.feed(f"V,{round(level * 1000)}\n".encode())
        for _ in range(8):  # the host's keep-alive, as the app sends it
            t += 0.25
            board.run_until(t)
            board.feed(b"PING\n")
        board.take_output()
        read[level] = f"{board.multimeter().i * 1e3:.1f} mA"
    return read


@pytest.mark.parametrize(
    "options",
    [{}, {"f": "0"}],  # the lab's motor; no viscous friction: the current flat, noise alone
    ids=["virtual board", "flat current"],
)
def test_the_virtual_meters_own_noise_raises_no_warning(tmp_path, options):
    with Session.create(tmp_path, ["Ada"]) as s:
        for seed in range(20):
            read = _filling(seed, options)
            assert float(read[2.5].split()[0]) > 20.0  # the wheel turned: a real filling
            for level, typed in read.items():
                assert s.enter(f"i_ss@{level:g}", typed).ok
            assert s.warnings("task5") == [], (seed, read)
