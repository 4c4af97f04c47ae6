"""The class view takes a group's model check and Tasks 11-13's numbers from what its
session file keeps, while they hold for the run and table as they are now, and computes
them otherwise; either way the rows are the same, and the sessions are never written."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views.check_says import in_words

from .build import group


def _class(capsys: pytest.CaptureFixture[str], root: Path, cache: Path) -> str:
    shutil.rmtree(cache, ignore_errors=True)  # no row from the cache: each read anew
    code = main(["class", "--sessions", str(root), "--json", "--workers", "1"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return out


def _as_the_lab_does(folder: Path) -> None:
    with Session.open(folder) as s:
        s.results()
        s.model_check()


def _files(root: Path) -> dict[str, bytes]:
    return {str(p): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_rows_from_kept_results_are_the_rows_computed(tmp_path, capsys, own_cache):
    root = tmp_path / "s"
    folders = [group(root, [f"G{k}"], seed=k, own_T="0.05 s" if k == 0 else None) for k in range(4)]
    folders.append(
        group(root, ["Rpm", "Man"], seed=11, R="12 Ω", rows={4.5: ("4.6", "74.3", "37 mA")})
    )
    folders.append(group(root, ["No", "Amps"], seed=12, rows={2.5: ("2.05", "3.8", "")}))
    cold = _class(capsys, root, own_cache)
    for f in folders:
        _as_the_lab_does(f)
    assert all("kept" in json.loads((f / "session.json").read_text("utf-8")) for f in folders)
    before = _files(root)
    assert _class(capsys, root, own_cache) == cold
    assert _files(root) == before  # read only


def test_the_kept_cause_is_taken_while_it_holds_and_computed_once_it_does_not(
    tmp_path, capsys, own_cache
):
    root = tmp_path / "s"
    folder = group(root, ["Ada", "Bo"], seed=3)
    _as_the_lab_does(folder)
    path = folder / "session.json"
    data = json.loads(path.read_text("utf-8"))
    assert data["kept"]["check"]["cause"] == "coulomb_friction"
    data["kept"]["check"]["cause"] = "dead_time"  # what a kept result says, the view shows
    path.write_text(json.dumps(data), encoding="utf-8")
    (g,) = json.loads(_class(capsys, root, own_cache))["groups"]
    assert g["cause"] == in_words("dead_time")
    with Session.open(folder) as s:  # the group types another u_ss: that no longer holds
        s.enter("u_ss@4.5", "3.95 V")
    (g,) = json.loads(_class(capsys, root, own_cache))["groups"]
    assert g["cause"] == in_words("coulomb_friction")
