"""F8 on the class view writes the class's report (walk 14, D10: the footer offered
"f8 Export" there, and F8 answered "start or resume a session first", the session's export,
while an instructor on the class view expects the class's, as ``minseg-tui class --out``
writes it)."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import DataTable

from minseg_tui.cli.classview import write as cli_write
from minseg_tui.lab.views import classread
from minseg_tui.report.write import CLASS_FILES, write_class
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.screens.classview import ClassScreen
from minseg_tui.ui.screens.start import StartScreen
from minseg_tui.ui.widgets.footer import KeyFooter
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import class_view, settle

from .build import group


def _app(root: Path) -> LabApp:
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: QuietDevice(seed=1), None, write_class)


def _sessions(root: Path) -> dict[str, bytes]:
    return {str(p): p.read_bytes() for p in root.rglob("*") if p.is_file()}


async def test_f8_on_the_class_view_writes_what_class_out_writes(tmp_path):
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1)
    group(root, ["Cy", "Di"], seed=2, R="5,30 Ω")
    before = _sessions(root)
    app = _app(root)
    notices: list[str] = []
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await class_view(pilot)
        assert screen.query_one(DataTable).row_count == 2
        shown = " ".join(str(w.render()) for w in screen.query_one(KeyFooter).children)
        assert "Export class" in shown, shown
        app.notify = lambda message, **kw: notices.append(str(message))  # type: ignore[method-assign]
        await pilot.press("f8")
        await settle(pilot, lambda: bool(notices))
    assert notices == [f"written: {', '.join(CLASS_FILES)}, in {root}"], notices
    assert "start or resume a session first" not in " ".join(notices)
    # the same files as `minseg-tui class --out` writes, byte for byte
    cli_out = tmp_path / "cli-out"
    cli_write(classread.build(root, workers=1), cli_out)
    for name in CLASS_FILES:
        assert (root / name).read_bytes() == (cli_out / name).read_bytes(), name
    # nothing in a group's session was written
    after = _sessions(root)
    assert {k: v for k, v in after.items() if Path(k).parent != root} == {
        k: v for k, v in before.items() if Path(k).parent != root
    }


async def test_f8_before_the_class_is_read_says_so_and_a_folder_that_cannot_be_written_too(
    tmp_path,
):
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1)
    app = _app(root)
    notices: list[str] = []
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: isinstance(app.screen, StartScreen))
        app.notify = lambda message, **kw: notices.append(str(message))  # type: ignore[method-assign]
        screen = ClassScreen(root, write_class)
        screen._read = lambda: None  # type: ignore[method-assign] # the class never read
        await app.push_screen(screen)
        await pilot.press("f8")
        await settle(pilot, lambda: bool(notices))
        assert notices[-1].startswith("the class is still being read: F8 writes its report")
        assert not any((root / name).exists() for name in CLASS_FILES)
        screen.view = classread.build(root, workers=1)
        screen.root = root / "session.json-is-not-a-folder" / "x"
        (root / "session.json-is-not-a-folder").write_text("", encoding="utf-8")
        await pilot.press("f8")
        await settle(pilot, lambda: len(notices) == 2)
    assert notices[-1].startswith(f"cannot write the class report in {screen.root} ("), notices
