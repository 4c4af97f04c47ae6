"""Hostile sessions folders for `minseg-tui class` (s36 attack): renamed, copied and lost
session files. Real session folders, the real CLI, each test its own cache."""

from __future__ import annotations

import json
import shutil

import pytest

from minseg_tui.cli import main

from .build import group


def _ids(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str], str]:
    code = main(["class", *argv, "--json", "--workers", "1"])
    out, err = capsys.readouterr()
    return code, [g["id"] for g in json.loads(out)["groups"]], err


def test_a_renamed_session_is_named_by_its_new_folder_when_its_row_is_cached(
    tmp_path, capsys, own_cache
):
    root = tmp_path / "s"
    folder = group(root, ["Ada", "Bo"], seed=1, run=False)
    code, ids, _ = _ids(capsys, "--sessions", str(root))
    assert code == 0 and ids == [folder.name] and list(own_cache.glob("*.json"))
    folder.rename(root / "Ada & Bo, bench 3 ü")  # same files, same key: the cached row
    code, ids, _ = _ids(capsys, "--sessions", str(root))
    assert code == 0 and ids == ["Ada & Bo, bench 3 ü"]


def test_a_copy_named_on_the_second_reading_too(tmp_path, capsys, own_cache):
    root = tmp_path / "s"
    folder = group(root, ["Ada"], seed=1, run=False)
    _ids(capsys, "--sessions", str(root))
    shutil.copytree(folder, root / "ada-copy")
    _, ids, _ = _ids(capsys, "--sessions", str(root))
    assert sorted(ids) == sorted([folder.name, "ada-copy"])


def test_a_session_that_lost_its_file_is_listed_not_left_out(tmp_path, capsys):
    root = tmp_path / "s"
    kept = group(root, ["Ada"], seed=1, run=False)
    lost = group(root, ["Bo"], seed=2)
    (lost / "session.json").unlink()  # deleted by hand: runs/ is still there
    (root / "photos").mkdir()  # a folder that never was a session stays out
    code = main(["class", "--sessions", str(root), "--json", "--workers", "1"])
    out, err = capsys.readouterr()
    groups = {g["id"]: g for g in json.loads(out)["groups"]}
    assert code == 2 and set(groups) == {kept.name, lost.name}
    assert groups[lost.name]["damaged"] and groups[kept.name]["damaged"] is None
    assert err == f"minseg-tui class: {lost}: no session here (no session.json)\n"


@pytest.mark.parametrize("name", ["notes.txt", "/dev/null"])
def test_an_out_that_is_a_file_is_named_as_such(tmp_path, capsys, name):
    root = tmp_path / "s"
    group(root, ["Ada"], seed=1, run=False)
    out = tmp_path / name if not name.startswith("/") else name
    if name == "notes.txt":
        (tmp_path / name).write_text("keep me\n", encoding="utf-8")
    code = main(["class", "--sessions", str(root), "--out", str(out)])
    _, err = capsys.readouterr()
    assert code == 2
    assert (
        err
        == f"minseg-tui class: {out}: is a file, not a folder: give a folder for --out DIR (made if needed)\n"
    )
    if name == "notes.txt":
        assert (tmp_path / name).read_text(encoding="utf-8") == "keep me\n"
