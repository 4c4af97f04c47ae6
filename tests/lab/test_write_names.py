"""A write refused by the system names the file meant, never the temporary file it goes
through (s36 attack: "Read-only file system (full/s/.class.md.19918.tmp)")."""

from __future__ import annotations

import errno
import os

import pytest

from minseg_tui.lab.saving.store import atomic_write_text, os_reason


def test_a_folder_that_cannot_be_written_is_named_by_the_file_meant(tmp_path):
    blocker = tmp_path / "blocker"
    blocker.write_text("x", encoding="utf-8")
    target = blocker / "class.md"  # a file where the folder should be: ENOTDIR, for root too
    with pytest.raises(NotADirectoryError) as got:
        atomic_write_text(target, "report")
    assert got.value.errno == errno.ENOTDIR and got.value.filename == str(target)
    assert os_reason(got.value) == f"{os.strerror(errno.ENOTDIR)} ({target})"
    assert ".tmp" not in os_reason(got.value)
