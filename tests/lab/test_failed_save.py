"""A save that fails for real never crashes and never loses a value.

Three real failures: a drive pulled out (the sessions folder vanishes), a read-only
folder and a full disk (a file-size limit, EFBIG). The last two run in a child process
that obeys permissions as a plain user does (conftest.as_plain_user, also under root)
and reports what it sees as JSON lines; the parent changes the folder between steps.
"""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.lab.saving.store import SessionNotWritable
from minseg_tui.lab.state.session import Session
from minseg_tui.lock import holder

from .conftest import as_plain_user

ROOT = Path(__file__).resolve().parents[2]


def _on_disk(folder: Path) -> dict:
    return json.loads((folder / "session.json").read_text(encoding="utf-8"))


# -- a drive pulled out --------------------------------------------------------------------------


def test_a_pulled_drive_keeps_everything_and_saves_when_it_is_back(tmp_path):
    stick = tmp_path / "stick"
    s = Session.create(stick, ["Ada"], date="2026-11-22")
    s.enter("R", "5.2")
    folder = s.folder
    stick.rename(tmp_path / "gone")  # the drive is pulled out
    e = s.enter("R", "6.1")
    assert e.ok and e.value == 6.1 and s.value("R") == 6.1
    s.enter("i_ss@2.5", "30 mA")
    s.go_to("task4")
    problem = s.save_problem
    assert problem is not None and problem.attempts == 3 and s.unsaved
    assert "No such file or directory" in problem.reason and str(folder) in problem.line
    assert "\n" not in problem.line
    assert not s.save()  # tried again: still gone
    (tmp_path / "gone").rename(stick)  # plugged back in
    assert s.save() and s.save_problem is None and not s.unsaved
    disk = _on_disk(folder)
    assert disk["entries"]["R"]["value"] == 6.1 and disk["current_step"] == "task4"
    assert disk["entries"]["i_ss@2.5"]["value"] == pytest.approx(0.03)
    s.close()
    assert holder(folder / "lock") is None


def test_a_run_recorded_while_the_drive_is_gone_is_kept(tmp_path):
    stick = tmp_path / "stick"
    s = Session.create(stick, ["Ada"])
    rec = s.start_run("free", ts=0.025, flush_interval=0.0)
    for k in range(10):
        rec.append(k, 25000 * k, 3 * k, 2000)
    stick.rename(tmp_path / "gone")  # (the open partial file moves with it)
    for k in range(10, 40):
        rec.append(k, 25000 * k, 3 * k, 2000)
    with pytest.raises(SessionNotWritable, match="40 samples\\) is kept in memory"):
        s.finish_run(rec)
    assert s.runs == [] and s.unsaved
    (tmp_path / "gone").rename(stick)
    assert s.save()
    (info,) = s.runs
    assert info.samples == 40 and not info.interrupted
    assert list(s.load_run(info.name).extra["count"]) == [3 * k for k in range(40)]
    assert _on_disk(s.folder)["runs"][0]["name"] == info.name
    assert not list((s.folder / "runs").glob("*.partial"))
    s.close()


def test_move_to_another_folder_brings_the_runs(tmp_path):
    s = Session.create(tmp_path / "a", ["Ada"])
    rec = s.start_run("free", ts=0.025)
    for k in range(20):
        rec.append(k, 25000 * k, k, 0)
    info = s.finish_run(rec)
    s.enter("R", "5.3")
    old = s.folder
    moved = s.move_to(tmp_path / "b")
    assert moved.folder == tmp_path / "b" / old.name and moved.left_behind == ()
    assert s.folder == moved.folder and s.id == old.name
    assert _on_disk(moved.folder)["entries"]["R"]["value"] == 5.3
    assert len(s.load_run(info.name)) == 20
    assert holder(old / "lock") is None and holder(moved.folder / "lock").pid == os.getpid()
    s.enter("R", "5.4")
    assert _on_disk(moved.folder)["entries"]["R"]["value"] == 5.4
    assert _on_disk(old)["entries"]["R"]["value"] == 5.3  # the old folder is left as it was
    s.close()


# -- a read-only folder and a full disk, in a child that obeys permissions ----------------------

CHILD = textwrap.dedent(
    """
    import json, resource, signal, sys
    from pathlib import Path
    from minseg_tui.errors import MinsegError
    from minseg_tui.lab.state.session import Session

    def say(**kw):
        print(json.dumps(kw), flush=True)

    def state(s):
        p = s.save_problem
        return dict(R=s.value("R"), problem=p.line if p else None, unsaved=s.unsaved)

    root, other, mode = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3]
    if mode == "full":
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    s = Session.create(root, ["Ada"], date="2026-11-22")
    s.enter("R", "5.2")
    if mode == "full":
        rec = s.start_run("free", ts=0.025, flush_interval=0.0)
    say(folder=str(s.folder))
    input()  # the parent makes the folder read-only (or the disk full)
    if mode == "full":
        hard = resource.getrlimit(resource.RLIMIT_FSIZE)[1]
        resource.setrlimit(resource.RLIMIT_FSIZE, (2000, hard))
        for k in range(200):  # more than 2000 bytes: the flushes fail, nothing is lost
            rec.append(k, 25000 * k, 3 * k, 2000)
        try:
            s.finish_run(rec)
            started = None
        except MinsegError as exc:
            started = str(exc)
    e = s.enter("R", "6.1")
    s.enter("summary.unclear", "why " * 1000)  # more than a full disk takes
    if mode != "full":
        try:
            s.start_run("free")
            started = None
        except MinsegError as exc:
            started = str(exc)
    say(entered=e.value, started=started, **state(s))
    input()  # the parent gives the space back (or nothing, for a move)
    if mode == "full":
        resource.setrlimit(resource.RLIMIT_FSIZE, (hard, hard))
        say(saved=s.save(), runs=[r.samples for r in s.runs], **state(s))
    else:
        try:
            Session.create(s.folder.parent, ["Bo"])
            refused = None
        except MinsegError as exc:
            refused = str(exc)
        moved = s.move_to(other)
        s.enter("i_ss@2.5", "30 mA")
        say(moved=str(moved.folder), refused=refused, **state(s))
    s.close()
    say(closed=True)
    """
)


def _child(tmp_path, mode):
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.Popen(
        [sys.executable, "-c", CHILD, str(tmp_path / "sessions"), str(tmp_path / "other"), mode],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        preexec_fn=as_plain_user,
    )


def _step(child, line="go"):
    child.stdin.write(line + "\n")
    child.stdin.flush()
    out = child.stdout.readline()
    assert out, child.stderr.read()
    return json.loads(out)


def test_a_read_only_folder_keeps_everything_and_the_session_moves(tmp_path):
    child = _child(tmp_path, "readonly")
    try:
        folder = Path(json.loads(child.stdout.readline())["folder"])
        for p in (folder, folder / "runs", folder.parent):
            p.chmod(stat.S_IRUSR | stat.S_IXUSR | stat.S_IRGRP | stat.S_IXGRP)
        got = _step(child)
        assert got["entered"] == 6.1 and got["R"] == 6.1 and got["unsaved"]
        assert "Permission denied" in got["problem"] and str(folder) in got["problem"]
        assert "cannot record a run here" in got["started"]
        assert _on_disk(folder)["entries"]["R"]["value"] == 5.2  # the old file, untouched
        got = _step(child)
        assert "cannot make a session folder here" in got["refused"]
        moved = Path(got["moved"])
        assert moved == tmp_path / "other" / folder.name and got["problem"] is None
        assert json.loads(child.stdout.readline()) == {"closed": True}
        assert child.wait(20) == 0, child.stderr.read()
    finally:
        child.kill()
        for p in (folder.parent, folder, folder / "runs"):
            p.chmod(0o755)
    disk = _on_disk(moved)
    assert disk["entries"]["R"]["value"] == 6.1
    assert disk["entries"]["summary.unclear"]["text"] == "why " * 1000
    assert disk["entries"]["i_ss@2.5"]["value"] == pytest.approx(0.03)
    assert holder(folder / "lock") is None and holder(moved / "lock") is None


def test_a_full_disk_keeps_everything_until_there_is_room(tmp_path):
    child = _child(tmp_path, "full")
    try:
        folder = Path(json.loads(child.stdout.readline())["folder"])
        got = _step(child)
        assert got["entered"] == 6.1 and got["R"] == 6.1 and got["unsaved"]
        assert "File too large" in got["problem"]
        assert "(200 samples) is kept in memory" in got["started"]
        assert "summary.unclear" not in _on_disk(folder)["entries"]  # it did not fit
        assert not [p for p in folder.iterdir() if p.name.endswith(".tmp")]
        got = _step(child)
        assert got["saved"] and got["problem"] is None and not got["unsaved"]
        assert got["runs"] == [200]
        assert json.loads(child.stdout.readline()) == {"closed": True}
        assert child.wait(20) == 0, child.stderr.read()
    finally:
        child.kill()
    disk = _on_disk(folder)
    assert disk["entries"]["R"]["value"] == 6.1
    assert disk["entries"]["summary.unclear"]["text"] == "why " * 1000
    assert disk["runs"][0]["samples"] == 200
    assert not list((folder / "runs").glob("*.partial"))


# -- the command line ----------------------------------------------------------------------------


def _cli(*args, cwd):
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run(
        [sys.executable, "-m", "minseg_tui", *args],
        capture_output=True,
        text=True,
        timeout=60,
        env=env,
        cwd=cwd,
        preexec_fn=as_plain_user,
        stdin=subprocess.DEVNULL,
    )


def test_report_on_a_read_only_session_is_one_line(tmp_path):
    s = Session.create(tmp_path / "sessions", ["Ada"])
    s.enter("R", "5.2")
    s.close()
    s.folder.chmod(0o555)
    try:
        done = _cli("report", str(s.folder), cwd=tmp_path)
    finally:
        s.folder.chmod(0o755)
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr and done.stderr.count("\n") == 1
    assert "cannot write the report" in done.stderr and "Permission denied" in done.stderr


def test_an_unreadable_sessions_folder_is_one_line(tmp_path):
    sessions = tmp_path / "sessions"
    sessions.mkdir()
    sessions.chmod(0)
    try:
        done = _cli("--sessions", str(sessions), cwd=tmp_path)
    finally:
        sessions.chmod(0o755)
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr and done.stderr.count("\n") == 1
    assert "cannot list the sessions folder" in done.stderr


def test_create_where_nothing_can_be_written_says_so(tmp_path):
    code = (
        "import sys; from minseg_tui.lab.state.session import Session\n"
        "from minseg_tui.errors import MinsegError\n"
        "try:\n    Session.create(sys.argv[1], ['Ada'])\n"
        "except MinsegError as exc:\n    print(exc)\n"
    )
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o555)
    try:
        done = subprocess.run(
            [sys.executable, "-c", code, str(ro / "sessions")],
            capture_output=True,
            text=True,
            env={**os.environ, "PYTHONPATH": str(ROOT)},
            preexec_fn=as_plain_user,
        )
    finally:
        ro.chmod(0o755)
    assert "cannot make a session folder here (Permission denied" in done.stdout, done.stderr
    assert done.stderr == ""
    np.testing.assert_equal(list(ro.iterdir()), [])


def test_move_to_stays_in_the_folder_asked_for_whatever_the_file_says_its_id_is(tmp_path):
    """The id comes from session.json: '../../x' there must not move the session outside
    the folder the group chose."""
    s = Session.create(tmp_path / "a", ["Ada"], date="2026-11-23")
    s.close()
    path = s.folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data["id"] = "../../escaped"
    path.write_text(json.dumps(data), encoding="utf-8")
    with Session.open(s.folder) as again:
        moved = again.move_to(tmp_path / "b" / "c")
        assert moved.folder.parent == tmp_path / "b" / "c"
    assert not (tmp_path / "escaped").exists()
