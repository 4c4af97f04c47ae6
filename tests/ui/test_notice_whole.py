"""A notice shows every line it has (issue 20, walk 14's D5: at 80x24, F8's notice "report
written: report.md, report.html and 3 run CSV, in /work/wt/walk/sessions/" ended there, the
session's own folder, the part that says where, cut off, in one session of two).

Textual's rack of notices scrolls, and measured its height with the notices as wide as the
rack without its scrollbar's two columns; it drew them two columns narrower, where a line
could wrap once more, and the rack then showed the notice's last line only on a scroll. It
happened where a line fit the wider notice exactly: "written: report.md, report.html and 3"
is 37 characters, one more than the narrower notice holds, with three runs and a sessions
folder of up to 25 characters."""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import pytest
from textual.content import Content

import minseg_tui.ui.app as app_module
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import TABLE, burst, enter_all, goto, record_response_run, settle, start


def _writing_app(root: Path) -> LabApp:
    """The app on the device double, with the report writer the CLI gives it."""
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: QuietDevice(seed=1), lambda s: write_report(s).paths)


def _shown(app, toast) -> tuple[list[str], bool]:
    """The lines of notice ``toast`` as it wraps them at its width, and whether the screen
    shows all of it (its region inside the part of its rack on screen)."""
    drawn = toast.render()
    content = drawn if isinstance(drawn, Content) else Content.from_rich_text(drawn)
    lines = [line.plain for line in content.wrap(toast.content_size.width)]
    where = app.screen.find_widget(toast)
    return lines, where.region.intersection(where.clip) == where.region


@pytest.mark.parametrize("step", ["summary", "model_check"], ids=["top", "bottom"])
@pytest.mark.parametrize("pad", [0, 3, 6])
async def test_f8_notice_shows_the_session_folder_whole_at_80x24(
    monkeypatch: pytest.MonkeyPatch, step: str, pad: int
):
    """F8 with three runs recorded, sessions folders of 23, 26 and 29 characters (as
    '/work/wt/walk/sessions/' and '/home/ada/minseg/sessions/'), the notice at the top
    (Summary) and at the bottom (the model check): every line of it on screen, the
    sessions folder and the session's own folder among them."""
    monkeypatch.setattr(app_module, "NOTICE_S", 600.0)  # held long enough to be looked at
    base = Path(tempfile.mkdtemp(prefix="n", dir="/tmp"))  # '/tmp/nXXXXXXXX': 14 characters
    root = base / ("s" * pad) / "sessions" if pad else base / "sessions"
    app = _writing_app(root)
    try:
        async with app.run_test(size=(80, 24), notifications=True) as pilot:
            await start(pilot, "Mia K, Omar S")
            enter_all(app, TABLE)
            with app.session as s:
                for seed in (5, 6, 7):
                    record_response_run(s, seed)
                folder = s.folder
            await goto(pilot, step)
            app.exported = ()
            await burst(pilot, "f8")
            await settle(pilot, lambda: bool(app.exported) and bool(app.screen.query("Toast")))
            toasts = list(app.screen.query("Toast"))
            assert len(toasts) == 1
            lines, whole = _shown(app, toasts[0])
            assert "and 3 run CSV, in" in " ".join(lines), lines
            assert any(line.endswith(f"{root.resolve().as_posix()}/") for line in lines), lines
            assert folder.name in lines, lines
            assert whole, (lines, app.screen.find_widget(toasts[0]))
    finally:
        shutil.rmtree(base)
