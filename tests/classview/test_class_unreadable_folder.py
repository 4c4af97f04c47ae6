"""A session folder this user may not read (s38 attack: ``chmod 000`` on one group's folder).
It was left out in silence, by the class view and the start screen alike: os.path.lexists
says False for a file in a folder it may not look into. It is now listed as a session that
cannot be read, with a reason that offers no repair of a file that is not damaged.

Real folders, read by a child process that obeys file permissions as a plain user does
(tests/lab/conftest.py's as_plain_user: root drops the two capabilities that let it past
them)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from tests.lab.conftest import as_plain_user

from .build import group

LIST = (
    "import sys; from pathlib import Path; "
    "from minseg_tui.lab.saving.store import list_sessions; "
    "[print(s.id, '|', s.damaged) for s in list_sessions(Path(sys.argv[1]))]"
)


def _as_plain_user(*argv: str, cache: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, *argv],
        capture_output=True,
        text=True,
        timeout=120,
        preexec_fn=as_plain_user,
        env={**os.environ, "MINSEG_TUI_CACHE": str(cache)},
    )


def _class_of_two(root: Path) -> tuple[Path, Path]:
    shut = group(root, ["Ada", "Bo"], seed=1, run=False)
    open_ = group(root, ["Cy", "Di"], seed=2, run=False)
    shut.chmod(0)
    return shut, open_


def test_the_class_view_lists_a_folder_it_may_not_read(tmp_path, own_cache):
    root = tmp_path / "s"
    shut, open_ = _class_of_two(root)
    try:
        done = _as_plain_user(
            "-m", "minseg_tui", "class", "--sessions", str(root), "--json", "--workers", "1",
            cache=own_cache,
        )  # fmt: skip
    finally:
        shut.chmod(0o755)
    assert done.returncode == 2, done.stderr  # listed, as one that cannot be read
    rows = {g["id"]: g for g in json.loads(done.stdout)["groups"]}
    assert sorted(rows) == sorted([shut.name, open_.name])
    assert rows[open_.name]["damaged"] is None and rows[shut.name]["damaged"]
    lacks = " ".join(rows[shut.name]["lacks"])
    assert "Permission denied" in lacks and f"chmod -R u+rwX {shut.name}" in lacks
    assert "repair" not in lacks  # nothing is damaged
    assert len(done.stderr.strip().splitlines()) == 1 and shut.name in done.stderr


def test_the_start_screen_lists_a_folder_it_may_not_read(tmp_path, own_cache):
    root = tmp_path / "s"
    shut, open_ = _class_of_two(root)
    try:
        done = _as_plain_user("-c", LIST, str(root), cache=own_cache)
    finally:
        shut.chmod(0o755)
    assert done.returncode == 0, done.stderr
    lines = dict(line.split(" | ", 1) for line in done.stdout.splitlines())
    assert sorted(lines) == sorted([shut.name, open_.name])
    assert lines[open_.name] == "None"
    assert "cannot be read (Permission denied)" in lines[shut.name]


def test_lost_and_found_is_not_a_session(tmp_path, own_cache):
    """The root of an ext4 USB stick holds lost+found, which a plain user may not read."""
    root = tmp_path / "s"
    _, open_ = _class_of_two(root)
    (root / "lost+found").mkdir(mode=0o700)
    (root / "lost+found").chmod(0)
    try:
        done = _as_plain_user("-c", LIST, str(root), cache=own_cache)
    finally:
        for p in root.iterdir():  # every folder readable again, for pytest to remove
            p.chmod(0o755)
    assert done.returncode == 0, done.stderr
    ids = [line.split(" | ", 1)[0] for line in done.stdout.splitlines()]
    assert "lost+found" not in ids and open_.name in ids
