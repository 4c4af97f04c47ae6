"""A multimeter's reading outside what a multimeter can show is refused, and the refusal says
that range (s38 attack, left: R = 1e9 Ω, or 1e-300 Ω, was accepted with only a warning,
since the only bound was the quantity's ceiling of 1000 MΩ). R, u_ss and i_ss, typed into a
real session and given to the real CLI; the reading accepted before is kept."""

from __future__ import annotations

import json

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from tests.seeded import Clock

TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.1,3.6,30\n3.5,3.05,5.5,35\n4.5,4.0,7.2,40\n"


@pytest.mark.parametrize(
    ("key", "text", "said"),
    [
        ("R", "1e308", "a multimeter on Ω shows, 1 mΩ to 500 MΩ"),
        ("R", "1e9", "a multimeter on Ω shows, 1 mΩ to 500 MΩ"),
        ("R", "1e-300", "a multimeter on Ω shows, 1 mΩ to 500 MΩ"),
        ("R", "0,5 mΩ", "a multimeter on Ω shows, 1 mΩ to 500 MΩ"),
        ("u_ss@2.5", "1001", "a multimeter on V= shows, 1 µV to 1000 V"),
        ("u_ss@2.5", "1e-7", "a multimeter on V= shows, 1 µV to 1000 V"),
        ("i_ss@2.5", "21 A", "a multimeter on mA or A shows, 0.01 µA to 20 A"),
        ("i_ss@2.5", "1e-6 mA", "a multimeter on mA or A shows, 0.01 µA to 20 A"),
    ],
)
def test_a_reading_no_multimeter_shows_is_refused_with_the_range(tmp_path, key, text, said):
    kept = {"R": "5.22 Ω", "u_ss@2.5": "2.05", "i_ss@2.5": "29.8 mA"}[key]
    with Session.create(tmp_path, ["Ada"], date="2026-11-28", clock=Clock()) as s:
        s.enter(key, kept)
        e = s.enter(key, text)
        assert e.refused is not None and e.refused[0] == text
        assert f"'{text}' is outside the range {said}; expected " in e.refused[1]
        assert e.ok and e.text == kept  # the reading before stays in effect
        folder = s.folder
    stored = json.loads((folder / "session.json").read_text(encoding="utf-8"))["entries"][key]
    assert stored["text"] == kept


@pytest.mark.parametrize(
    ("key", "text", "value"),
    [
        ("R", "1 mΩ", 1e-3),
        ("R", "500 MΩ", 5e8),
        ("u_ss@2.5", "1000", 1000.0),
        ("i_ss@2.5", "20 A", 20.0),
    ],
)
def test_the_ends_of_the_range_are_readings(tmp_path, key, text, value):
    with Session.create(tmp_path, ["Ada"], date="2026-11-28", clock=Clock()) as s:
        e = s.enter(key, text)
        assert e.ok and e.value == pytest.approx(value)


def test_identify_refuses_R_1e308_with_the_range(tmp_path, capsys):
    (tmp_path / "table.csv").write_text(TABLE)
    with pytest.raises(SystemExit) as exit_:
        main(["identify", str(tmp_path / "table.csv"), "--R", "1e308"])
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "'1e308' is outside the range a multimeter on Ω shows, 1 mΩ to 500 MΩ" in err
