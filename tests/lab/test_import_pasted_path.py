"""A run log dropped on the terminal into the import's box (s38 attack): GNOME Terminal and
others paste it in quotes, '/home/ada/step log.csv', and the import said "cannot read the
file (No such file or directory)" of a file that is there. The quotes are taken off when the
quoted name is no file. Real files, the session's own import (the call the TUI makes)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from minseg_tui.lab.state.session import Session
from tests.classview.build import group


@pytest.mark.parametrize("quote", ["'", '"'])
def test_a_path_pasted_in_quotes_is_imported(tmp_path, quote):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=1)
    log = tmp_path / "step log.csv"
    shutil.copyfile(folder / "runs" / "steps-1.csv", log)
    with Session.open(folder) as s:
        info = s.import_run(Path(f"{quote}{log}{quote}"))
        assert info.samples == 500 and (folder / info.file).is_file()


def test_a_file_whose_name_has_quotes_is_still_read_as_named(tmp_path):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=1)
    odd = tmp_path / "'odd'"
    shutil.copyfile(folder / "runs" / "steps-1.csv", odd)
    with Session.open(folder) as s:
        assert s.import_run(odd).samples == 500
