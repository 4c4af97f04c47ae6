"""An empty folder argument is refused in one line (s39 attack): ``class --out ''`` wrote
class.md, class.html and class.csv into the folder the command was started in (Path('') is
'.'), ``report ''`` looked for the session there, ``report /abs`` said the path it looked
at twice, and ``class --workers abc`` said argparse's 'invalid int value'. Through main(),
in a real folder; nothing is written."""

from __future__ import annotations

import pytest

from minseg_tui.cli import main
from tests.classview.build import group


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (["class", "--out", ""], "minseg-tui class: argument --out: expected a folder, got ''"),
        (["class", "--sessions", ""], "argument --sessions: expected a folder, got ''"),
        (
            ["class", "--workers", "abc"],
            "argument --workers: expected a whole number of at least 1, got 'abc'",
        ),
        (
            ["report", ""],
            "minseg-tui report: SESSION: expected a session folder or a session id, got ''",
        ),
        (["report", "x", "--sessions", ""], "argument --sessions: expected a folder, got ''"),
    ],
)
def test_an_empty_folder_argument_is_refused_and_nothing_written(
    tmp_path, monkeypatch, capsys, args, said
):
    group(tmp_path / "sessions", ["Ada"], seed=1, run=False, at="table")
    monkeypatch.chdir(tmp_path)
    before = sorted(p.name for p in tmp_path.iterdir())
    try:
        code = main(args)
    except SystemExit as exc:
        code = int(exc.code or 0)
    err = capsys.readouterr().err
    assert code == 2 and said in err and err.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_a_missing_session_by_its_absolute_path_is_said_once(tmp_path, capsys):
    missing = tmp_path / "nothing"
    try:
        code = main(["report", str(missing)])
    except SystemExit as exc:
        code = int(exc.code or 0)
    err = capsys.readouterr().err
    assert code == 2
    assert err == (
        f"minseg-tui report: {missing}: no session found (looked for {missing}/session.json)\n"
    )
