"""The import's copy is the very bytes read and checked (s38 attack: a 227 MB log was read in
39 s, then formatted and written again in 44 s more, 2.7 GB at the peak, and its values cut
to 10 digits). Real files, the session's own import."""

from __future__ import annotations

import hashlib
import os

import numpy as np
import pytest

from minseg_tui.errors import InputError
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.saving.runs import changed_file
from minseg_tui.lab.saving.store import SessionNotWritable
from minseg_tui.lab.state.session import Session

LOG = (
    "\ufeff# ts: 0.025\r\n# from: another lab\r\nT,Omega,U,note\r\n"
    "0,0,0,start\r\n0.025,1.234567890123456,4.000000000001,a\r\n"
    "0.05,2.000000000000002,4.000000000001,b\r\n# a comment\r\n0.075,2.5,4.000000000001,c"
)


def test_the_copy_is_the_bytes_read_after_the_line_naming_them(tmp_path):
    src = tmp_path / "elsewhere.csv"
    src.write_bytes(LOG.encode("utf-8"))
    with Session.create(tmp_path / "s", ["A"]) as s:
        info = s.import_run(src)
        data = (s.folder / info.file).read_bytes()
        assert data == f"# imported_from: {src}\n".encode() + LOG.encode("utf-8")[3:]
        assert info.sha256 == hashlib.sha256(data).hexdigest()
        assert changed_file(s.folder, info) is None
        taken, original = s.load_run(info.name), read_run_log(src)
        assert info.samples == len(original) == 4 and info.ts == 0.025
        for name in original.columns:  # every digit kept (10 before)
            assert np.array_equal(taken.column(name), original.column(name)), name
        assert taken.metadata["imported_from"] == str(src)
        assert taken.metadata["from"] == "another lab"
        assert sorted(os.listdir(s.folder / "runs")) == ["imported-1.csv"]


def test_a_log_refused_halfway_leaves_nothing(tmp_path):
    src = tmp_path / "elsewhere.csv"
    src.write_text("t,u,omega\n0,0,0\n0.025,4,1\n0.05,4,x\n", encoding="utf-8")
    with Session.create(tmp_path / "s", ["A"]) as s:
        with pytest.raises(InputError) as got:
            s.import_run(src)
        assert f"{src}, line 4" in str(got.value) or f"{src}:4" in str(got.value), got.value
        assert s.runs == [] and os.listdir(s.folder / "runs") == []


def test_a_copy_that_cannot_be_written_is_said_and_not_taken(tmp_path):
    """The temporary file cannot be made (a folder stands in its place): one line, the
    session unchanged."""
    src = tmp_path / "elsewhere.csv"
    src.write_text("t,u,omega\n0,0,0\n0.025,4,1\n0.05,4,2\n", encoding="utf-8")
    with Session.create(tmp_path / "s", ["A"]) as s:
        runs = s.folder / "runs"
        (runs / f".imported-1.csv.{os.getpid()}.build").mkdir()
        with pytest.raises(SessionNotWritable) as got:
            s.import_run(src)
        said = str(got.value)
        assert said.startswith(f"{runs}: cannot copy the log here (Is a directory"), said
        assert said.endswith(f"({runs / 'imported-1.csv'}))"), said  # the file meant
        assert s.runs == [] and s.check_run() is None
        assert os.listdir(runs) == [f".imported-1.csv.{os.getpid()}.build"]
