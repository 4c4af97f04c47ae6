"""The palette's import given a FIFO or a device (s38 attack): a FIFO made the import wait 10 s
for data that never came ("expected data, but nothing arrived for 10 s"), the lab frozen
meanwhile (the import runs as the lab handles the request); a link to /dev/zero was read
until its first 4 KiB line. Both are refused at once now, as a run's own file is (s37).
Real files, the session's own import."""

from __future__ import annotations

import os

import pytest

from minseg_tui.errors import InputError
from minseg_tui.lab.state.session import Session
from tests.classview.build import group


@pytest.mark.parametrize(
    ("make", "what"),
    [
        (os.mkfifo, "a FIFO (a named pipe)"),
        (lambda p: os.symlink("/dev/zero", p), "a device or a socket"),
    ],
)
def test_an_import_of_a_fifo_or_a_device_is_refused_without_a_read(tmp_path, make, what):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=1, run=False)
    special = tmp_path / "log.csv"
    make(special)
    with Session.open(folder) as s:
        with pytest.raises(InputError) as got:
            s.import_run(special)
        assert str(got.value) == f"{special}: expected a run log file; this is {what}, not read"
        assert s.runs == []
    assert sorted(os.listdir(folder / "runs")) == []
