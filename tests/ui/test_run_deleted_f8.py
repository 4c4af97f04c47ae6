"""F8 after a run CSV was deleted by hand while the session is open (s36 attack, left): the
report is written with the run (written back from memory first) and a notice says so."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    burst,
    enter_all,
    goto,
    heard_notifications,
    record_response_run,
    settle,
    start,
)


async def test_f8_writes_back_a_run_csv_deleted_by_hand(tmp_path: Path):
    cfg = UiConfig(device="auto", sessions=tmp_path, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: QuietDevice(seed=1), lambda s: write_report(s).paths)
    async with app.run_test(size=(100, 30), notifications=True) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            name = record_response_run(s)
            path = s.run_path(name)
        kept = path.read_bytes()
        path.unlink()
        await goto(pilot, "summary")
        said = heard_notifications(app)
        app.exported = ()
        await burst(pilot, "f8")
        await settle(pilot, lambda: bool(app.exported))
        assert path.read_bytes() == kept
        assert str(path) in app.exported
        assert f"runs/{name}.csv was deleted: written back from memory" in "\n".join(said)
        report = (path.parent.parent / "report.md").read_text(encoding="utf-8")
        assert f"Run {name} cannot be read" not in report
