"""Ten kilobytes pasted into an entry (s39 attack): a value, formula or choice field refuses
any text over MAX_TYPED characters at once, in one short line, without reading it; it was
read, taking 10 s in a formula field, or ended in RecursionError ('1+1+...'), MemoryError
('2^2^...', '---...1') or decimal.InvalidOperation (R '1e999...9'). The answer in effect
stays, and the pasted text is kept beside it. Real session files."""

from __future__ import annotations

import json

import pytest

from minseg_tui.lab.state.entries import MAX_TYPED
from minseg_tui.lab.state.session import Session
from tests.seeded import Clock

PASTED = {
    "digits": "5" * 10_000,
    "sum": "1+" * 5000 + "1",
    "power": "2^" * 3000 + "2",
    "minus": "-" * 10_000 + "1",
    "product": "0.65*" * 2000 + "1",
}
KEPT = {"R": "5.2 Ω", "prep11.k_v": "(u_ss - R i_ss) / omega_ss", "prep4.fraction": "1 - exp(-1)"}


@pytest.mark.parametrize("key", sorted(KEPT))
@pytest.mark.parametrize("what", sorted(PASTED))
def test_a_paste_of_ten_kilobytes_is_refused_in_one_short_line(tmp_path, key, what):
    text = PASTED[what]
    with Session.create(tmp_path, ["Ada"], date="2026-11-28", clock=Clock()) as s:
        s.enter(key, KEPT[key])
        e = s.enter(key, text)
        assert e.ok and e.text == KEPT[key]  # the answer in effect stays
        assert e.refused is not None and e.refused[0] == text  # and the paste is kept
        said = e.refused[1]
        assert f"{len(text)} characters, more than any answer here (at most {MAX_TYPED})" in said
        assert len(said) < 200 and "\n" not in said
        folder = s.folder
    stored = json.loads((folder / "session.json").read_text(encoding="utf-8"))["entries"][key]
    assert stored["text"] == KEPT[key] and stored["refused"][0] == text


def test_an_exponent_beyond_any_number_is_not_a_finite_number(tmp_path):
    with Session.create(tmp_path, ["Ada"], date="2026-11-28", clock=Clock()) as s:
        e = s.enter("R", "1e" + "9" * 190)
        assert not e.ok and "is not a finite number; expected a resistance in Ω" in e.message


def test_notes_take_a_long_paste_whole(tmp_path):
    with Session.create(tmp_path, ["Ada"], date="2026-11-28", clock=Clock()) as s:
        e = s.enter("prep1.notes", "x" * 10_000)
        assert e.ok and len(e.text) == 10_000
