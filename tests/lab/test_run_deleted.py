"""A run CSV deleted by hand while its session is open (s36 attack, left; s37): the session
holds what it wrote of each run and writes it back with its next save, byte for byte; a run
whose file was gone before the session was opened is said to be lost, with its samples."""

from __future__ import annotations

import shutil

from minseg_tui.lab.state.session import Session
from tests.seeded import Clock, record_square_wave


def _session_with_a_run(tmp_path) -> tuple[Session, str, bytes]:
    s = Session.create(tmp_path / "s", ["Ada", "Bo"], date="2026-11-22", clock=Clock())
    s.enter("R", "5.2")
    info = record_square_wave(s, seed=3)
    assert info is not None
    return s, info.name, (s.folder / info.file).read_bytes()


def test_a_run_deleted_while_recorded_this_session_is_written_back(tmp_path):
    s, name, kept = _session_with_a_run(tmp_path)
    path = s.run_path(name)
    path.unlink()
    s.enter("u_ss@2.5", "2.05")  # any change saves
    assert path.read_bytes() == kept
    said = s.take_restored()
    assert said == [
        f"runs/{name}.csv was deleted: written back from memory ({s.runs[0].samples} samples)"
    ]
    assert s.take_restored() == []
    assert s.save_problem is None and not s.unsaved
    s.close()


def test_a_run_deleted_after_the_session_was_opened_is_written_back(tmp_path):
    s, name, kept = _session_with_a_run(tmp_path)
    s.close()
    s = Session.open(s.folder, clock=Clock())
    shutil.rmtree(s.folder / "runs")  # the whole folder
    assert s.save()
    assert s.run_path(name).read_bytes() == kept
    assert s.load_run(name).t.size == s.runs[0].samples
    s.close()


def test_a_run_gone_before_the_session_was_opened_is_said_lost(tmp_path):
    s, name, _ = _session_with_a_run(tmp_path)
    samples = s.runs[0].samples
    s.close()
    s.run_path(name).unlink()
    s = Session.open(s.folder, clock=Clock())
    assert s.recovery_notes == [
        f"runs/{name}.csv is gone (deleted?) and no copy of it was held: the {samples} "
        f"samples of run {name} are lost (Tasks 11-15 and the model check use it)"
    ]
    assert s.save() and s.take_restored() == []  # said once, at open
    s.close()


def test_a_run_that_cannot_be_written_back_stays_held_until_it_can(tmp_path):
    s, name, kept = _session_with_a_run(tmp_path)
    shutil.rmtree(s.folder / "runs")
    (s.folder / "runs").write_text("a file where the runs folder was\n")
    assert not s.save()
    assert s.save_problem is not None and s.unsaved
    assert s.take_restored() == []
    (s.folder / "runs").unlink()
    assert s.save()
    assert s.run_path(name).read_bytes() == kept
    assert s.save_problem is None and not s.unsaved
    assert len(s.take_restored()) == 1
    s.close()


def test_a_session_folder_deleted_whole_is_saved_elsewhere_with_its_runs(tmp_path):
    """Its folder is not made again (its lock went with it): the save says why, and saving
    elsewhere brings the run from memory (it was left behind: 'No such file')."""
    s, name, kept = _session_with_a_run(tmp_path)
    shutil.rmtree(s.folder)
    assert not s.save()
    assert s.save_problem is not None and not s.folder.exists()
    moved = s.move_to(tmp_path / "elsewhere")
    assert moved.left_behind == ()
    assert s.run_path(name).read_bytes() == kept
    assert s.save_problem is None and not s.unsaved
    s.close()


def test_the_copies_held_are_bounded(tmp_path, monkeypatch):
    """A run that would take the copies past their bound is not held: deleted, it is said
    lost (with its samples), never written back from a copy that is not there."""
    import minseg_tui.lab.state.session as session_module

    s, first, _ = _session_with_a_run(tmp_path)
    size = s.run_path(first).stat().st_size
    monkeypatch.setattr(session_module, "MAX_RUN_COPIES", size + size // 2)
    second = record_square_wave(s, seed=4)
    assert second is not None
    s.run_path(second.name).unlink()
    s.run_path(first).unlink()
    assert s.save()
    assert s.run_path(first).is_file() and not s.run_path(second.name).exists()
    said = s.take_restored()
    assert said[0] == f"runs/{first}.csv was deleted: written back from memory (500 samples)"
    assert said[1].startswith(f"runs/{second.name}.csv is gone (deleted?) and no copy")
    s.close()
