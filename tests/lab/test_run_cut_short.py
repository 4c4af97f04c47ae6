"""A run's file cut short after the recording, mid-row (a stick pulled out while a copy was
written; s39 attack): the class view said "it holds the 500 samples recorded, but not the
bytes written; what is computed from it uses the file as it is now" of a file that no longer
reads at all, and the report, which said it cannot be read, did not say it was changed.
Now all say the one true line. Real session folders, the real report CLI."""

from __future__ import annotations

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views.classview import read_group
from tests.classview.build import group

SAID = (
    "run steps-1: its file runs/steps-1.csv was changed after the recording (edited by "
    "hand?): it no longer reads as a run log, so nothing is computed from it"
)


@pytest.fixture(autouse=True)
def _own_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(tmp_path / "cache"))


def test_a_run_file_cut_mid_row_is_said_changed_and_unreadable_everywhere(tmp_path):
    folder = group(tmp_path / "sessions", ["Ada"], seed=3)
    path = folder / "runs" / "steps-1.csv"
    data = path.read_bytes()
    cut = data.index(b"\n", len(data) // 2) + 8  # eight bytes into a row
    path.write_bytes(data[:cut])
    with Session.open(folder, readonly=True) as s:
        changed = s.run_changed("steps-1")
    assert changed is not None and changed.edited and changed.text == SAID
    assert SAID in read_group(folder).flags
    assert main(["report", str(folder)]) == 0
    report = (folder / "report.md").read_text(encoding="utf-8").replace("\u00a0", " ")
    assert "Run steps-1 cannot be read: " in report
    assert SAID[0].upper() + SAID[1:] + "." in report
    assert "samples recorded, but not the bytes written" not in report
