"""A run CSV deleted while its session is open (s36 attack): the report and its notice name
only the files that are there, and the report says the run cannot be read."""

from __future__ import annotations

from minseg_tui.cli import main
from tests.classview.build import group


def test_a_deleted_run_csv_is_not_listed_as_written(tmp_path, capsys):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    (folder / "runs" / "steps-1.csv").unlink()
    code = main(["report", str(folder)])
    out, err = capsys.readouterr()
    listed = out.split()
    assert code == 0 and err == ""
    assert listed == [str(folder / "report.md"), str(folder / "report.html")]
    assert "Run steps-1 cannot be read" in (folder / "report.md").read_text(encoding="utf-8")
