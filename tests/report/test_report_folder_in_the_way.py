"""A folder where a report's file goes (s37 attack: `mkdir report.md`, then the report):
one line naming that file, not its temporary `.report.md.PID.tmp`, saying what to do (it
said "copy the folder where it can be written", which does not help), exit 2, no
temporary file left; in the lab assistant F8's notice says the same in the system's words
(it was Python's "[Errno 21] Is a directory: '...'")."""

from __future__ import annotations

from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from tests.classview.build import group
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import TABLE, burst, enter_all, goto, heard_notifications, settle, start


@pytest.mark.parametrize("name", ["report.md", "report.html", "report-figure-1.svg"])
def test_a_folder_of_a_report_file_name(tmp_path, capsys, name):
    folder = group(tmp_path / "s", ["Ada", "Bo"], seed=3)
    (folder / name).mkdir()
    assert main(["report", str(folder)]) == 2
    err = capsys.readouterr().err
    assert err == (
        f"minseg-tui report: {folder}: cannot write the report into the session folder "
        f"(Is a directory ({folder / name})): a folder stands where the report's file goes; "
        "move or rename it and run the report again\n"
    )
    assert not [p for p in folder.iterdir() if p.name.endswith(".tmp")]


async def test_f8_with_a_folder_named_report_md(tmp_path: Path):
    cfg = UiConfig(device="auto", sessions=tmp_path, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: QuietDevice(seed=1), lambda s: write_report(s).paths)
    async with app.run_test(size=(100, 30), notifications=True) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            folder = s.folder
        (folder / "report.md").mkdir()
        await goto(pilot, "summary")
        said = heard_notifications(app)
        await burst(pilot, "f8")
        await settle(pilot, lambda: any("cannot write the report" in x for x in said))
        assert f"cannot write the report (Is a directory ({folder / 'report.md'}))" in said
