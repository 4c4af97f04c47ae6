"""The one lock (minseg_tui.lock): held while open, named, let go by the kernel when its holder dies."""

from __future__ import annotations

import gc
import os
import signal
import subprocess
import sys

import pytest

from minseg_tui.lock import FileLock, LockHeld, holder

HOLD = (
    "import sys, time; from pathlib import Path; from minseg_tui.lock import FileLock; "
    "lock = FileLock(Path(sys.argv[1]), 'tester'); lock.acquire(); print('held', flush=True); "
    "time.sleep(60)"
)


def _child_holding(path):
    child = subprocess.Popen(
        [sys.executable, "-c", HOLD, str(path)], stdout=subprocess.PIPE, text=True
    )
    assert child.stdout.readline().strip() == "held"
    return child


def test_one_holder_named_and_the_file_goes_on_release(tmp_path):
    path = tmp_path / "lock"
    a = FileLock(path, "prog-a")
    a.acquire()
    assert a.held and path.read_text().split() == ["prog-a", str(os.getpid())]
    assert holder(path).pid == os.getpid() and holder(path).program == "prog-a"
    with pytest.raises(LockHeld) as info:  # a second open, even in this process, is refused
        FileLock(path, "prog-b").acquire()
    assert str(info.value.holder) == f"prog-a (pid {os.getpid()})"
    a.release()
    assert not a.held and not path.exists() and holder(path) is None
    with FileLock(path) as b:
        assert b.held
    assert not path.exists()


def test_a_kill_9_leaves_no_lock(tmp_path):
    path = tmp_path / "lock"
    child = _child_holding(path)
    try:
        with pytest.raises(LockHeld, match=f"tester \\(pid {child.pid}\\)"):
            FileLock(path).acquire()
        assert holder(path).pid == child.pid
    finally:
        os.kill(child.pid, signal.SIGKILL)
        child.wait()
    assert path.exists()  # the file stays behind, naming a dead program ...
    assert holder(path) is None  # ... but nobody holds it
    with FileLock(path, "next") as lock:
        assert lock.held and path.read_text().split() == ["next", str(os.getpid())]


def test_a_pid_file_of_a_dead_program_is_no_lock(tmp_path):
    dead = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True
    )
    path = tmp_path / "lock"
    path.write_text(f"minseg-tui {dead.stdout.strip()}\n")
    assert holder(path) is None
    with FileLock(path) as lock:
        assert lock.held


def test_a_folder_that_cannot_be_written_is_an_os_error(tmp_path):
    with pytest.raises(OSError):
        FileLock(tmp_path / "no such folder" / "lock").acquire()


def test_a_lock_whose_object_is_collected_is_let_go(tmp_path):
    """A held lock whose object nobody can reach any more (a port object dropped without
    its close) no longer blocks the next program."""
    path = tmp_path / "port.lock"
    lock = FileLock(path)
    lock.acquire()
    assert holder(path) is not None
    del lock
    gc.collect()
    assert holder(path) is None
    with FileLock(path):
        pass
