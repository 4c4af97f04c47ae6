"""The class report's table of the groups' own values reads as the session's report does
(lab.views.own_first): the group's value, the value computed the group's way, the
difference, the program's least-squares value and when the group was shown it, no cell
left blank, read cold and again from the cache."""

from __future__ import annotations

from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import own_first
from tests.report.test_own_first import _section, _tables

from .build import group


def _class_md(root: Path, out: Path, capsys: pytest.CaptureFixture[str]) -> str:
    assert main(["class", "--sessions", str(root), "--out", str(out)]) == 0
    capsys.readouterr()
    return (out / "class.md").read_text(encoding="utf-8")


def test_own_values_read_as_in_the_sessions_report(tmp_path, capsys):
    """The table had 'theirs', 'computed' and 'difference' only: the model's difference
    cell was blank, and neither the least-squares value nor when the group was shown it
    appeared. Now its rows are own_first's, the group's id before them."""
    root = tmp_path / "sessions"
    folder = group(root, ["Ada", "Bo"], seed=3, own_T="0.05 s")
    s = Session.open(folder)
    s.enter("own.f", "1,9 mN m s/rad")
    s.enter("own.K", "2.2")
    s.enter("own.model", "0.05 omega' = -omega + 2.2 u_A")
    s.enter("own.J", "0.002 kg m^2")
    want_steady = [list(r.cells) for r in own_first.table_rows(s) if r.key == "own.f"]
    want_step = [
        list(r.cells)
        for r in own_first.step_rows(s)
        if r.key in ("own.K", "own.T", "own.J", "own.model")
    ]
    s.close()
    for out in ("cold", "cached"):
        md = _class_md(root, tmp_path / out, capsys)
        steady, step = _tables(_section(md, "The groups' own values against the computed ones"))
        assert steady[0] == ["group", *own_first.TABLE_HEADER]
        assert step[0] == ["group", *own_first.STEP_HEADER]
        assert [r[1:] for r in steady[1:]] == want_steady
        # the program's value: the same number; the class view reads it as the session
        # file keeps it (no interval), the report from the fit
        assert [r[1:5] + r[6:] for r in step[1:]] == [w[:4] + w[5:] for w in want_step]
        for r, w in zip(step[1:], want_step, strict=True):
            assert r[5].split(" (")[0] == w[4].split(" (")[0]
        for row in (*steady[1:], *step[1:]):
            assert row[0].startswith("#1 ") and all(c.strip() for c in row), row
        model = next(r for r in step[1:] if r[1] == own_first.TASK["own.model"])
        assert model[4] != "" and "u_A" in model[5]  # compared, and the program's model
