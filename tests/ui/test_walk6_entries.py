"""Walk 6 at 80x24 on the virtual MinSeg (issue 20, item 5): a value the program itself
calls impossible or unlikely ('!' under its entry) does not make its step look done; the
numbers on the screen keep one unit and the digits typed (Pilot, real session folder)."""

from __future__ import annotations

import re
from pathlib import Path

from textual.content import Content

from minseg_tui.quantities import format_constant
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.panels.meter import MeterPanel
from minseg_tui.ui.panels.report import ReportPanel
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    Heard,
    enter_all,
    goto,
    nav_mark,
    record_response_run,
    settle,
    start,
    start_with_a_run,
    type_in,
)


async def test_an_impossible_u_ss_is_not_ticked(quiet):
    """Walk 6, defect 3: 40.5 typed for u_ss at 4.5 V (above the request, which the driver
    cannot give) was stored with its '!' warning and Task 4 read '✓'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "task4")
        row = await type_in(pilot, "u_ss@4.5", "40.5")
        await settle(pilot)
        assert "above the requested 4.5 V" in " ".join(row.message.split())
        assert nav_mark(app, "task4") == "!"
        await type_in(pilot, "u_ss@4.5", "4.05")
        await settle(pilot)
        assert nav_mark(app, "task4") == "✓"


async def test_a_falling_current_and_an_unlikely_f_are_not_ticked(quiet):
    """The other warnings of Tasks 4-9 alike: a Task 5 current that falls as the voltage
    rises, and an f a thousand times this motor's."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "task5")
        await type_in(pilot, "i_ss@4.5", "30 mA")
        await settle(pilot)
        assert nav_mark(app, "task5") == "!"
        await type_in(pilot, "i_ss@4.5", "36 mA")
        await settle(pilot)
        assert nav_mark(app, "task5") == "✓"
        await goto(pilot, "table")
        await type_in(pilot, "own.f", "0.00001 N m s/rad")
        await settle(pilot)
        assert nav_mark(app, "table") in ("!", "✗")


def _lines(widget) -> list[str]:
    """What ``widget`` shows, line by line, wrapped at its width as it is drawn."""
    drawn = widget.render()
    content = drawn if isinstance(drawn, Content) else Content.from_rich_text(drawn)
    return [line.plain for line in content.wrap(widget.content_size.width)]


async def test_f8_names_the_folder_and_files_whole_at_80x24(tmp_path):
    """Walk 6, defect 7: F8's notice broke the session path mid-name
    ('…2026-11-27-mira-/k-jonas-b/report.md') and the summary's list of files broke a run's
    name ('runs/steps-1' / '.csv'). Both name the session folder relative to the sessions
    folder, and the files relative to it, each whole on one line."""
    dev = QuietDevice(seed=1)
    root = tmp_path / "a sessions folder nested somewhat deeper than most" / "sessions"
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: dev, lambda session: write_report(session).paths)
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start(pilot, "Mira K, Jonas B")
        with app.session as s:
            record_response_run(s)
            folder = s.folder.name
        await goto(pilot, "summary", focus=None)
        await pilot.press("f8")
        await settle(pilot, lambda: bool(app.exported))
        await settle(pilot, lambda: bool(app.screen.query("Toast")))
        (toast,) = [t for t in app.screen.query("Toast") if "written" in " ".join(_lines(t))]
        lines = _lines(toast)
        assert any(folder in line for line in lines), lines
        assert any("report.md" in line for line in lines), lines
        panel = _lines(app.screen.query_one(ReportPanel))
        run = next(p for p in app.exported if p.endswith(".csv"))
        assert any(f"runs/{Path(run).name}" in line for line in panel), panel
        assert any(folder in line for line in panel), panel


async def test_the_virtual_meter_shows_what_each_step_measures(quiet):
    """Walk 6, defect 7: the virtual meter showed i_ss already on Task 4 ('4.05 V · 37.2
    mA'), before Task 5 pulls the jumper to measure the current. A meter shows what it is
    set to: Ω on Task 2, V= on Task 4, mA (jumper out) on Task 5."""
    app = quiet()
    heard = Heard()  # the readings come with the device stream, at its pace
    async with app.run_test(size=(80, 24), message_hook=heard.hook) as pilot:
        await start(pilot)
        said = {}
        for step_id, mode in (("task2", "on Ω"), ("task4", "on V="), ("task5", "on mA")):
            await goto(pilot, step_id, focus=None)

            def read(mode: str = mode) -> bool:  # the step's meter, past its 'reading…'
                shown = [str(m.render()) for m in app.screen.query(MeterPanel)]
                return any(mode in t and not t.endswith("reading…") for t in shown)

            await heard.until(pilot, read)
            said[step_id] = str(app.screen.query_one(MeterPanel).render())
        assert re.search(r"on Ω\) · [\d.]+ Ω$", said["task2"]) and "mA" not in said["task2"], said
        assert re.search(r"on V=\) · [\d.]+ V$", said["task4"]) and "mA" not in said["task4"], said
        assert re.search(r" · [\d.]+ mA$", said["task5"]) and " V " not in said["task5"], said


async def test_f_typed_in_N_m_s_per_rad_is_judged_in_the_tables_unit(quiet):
    """Walk 6, defect 6: f typed in N m s/rad was judged 'from 0.001861 N m s/rad' under its
    entry, where the table and the entry's label say mN m s/rad."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        await goto(pilot, "table")
        row = await type_in(pilot, "own.f", "0,00186 N m s/rad")
        await settle(pilot)
        said = " ".join(row.message.replace("\u00a0", " ").split())
        said = said.replace("(typed 0,00186 N m s/rad)", "")  # what was typed, named once
        assert "mN m s/rad" in said and " N m s/rad" not in said.replace("mN m s/rad", ""), said


async def test_task_12_gives_T_in_ms_only(quiet):
    """Walk 6, defect 6: one screen gave the same T as '0.05693 s' (the results lines) and
    '56.93 ms' (the comparison and the zoom); T is in ms wherever it is shown."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        await type_in(pilot, "own.T", "57")
        await settle(pilot)
        lines = " ".join(str(app.screen.query_one("#results-lines").render()).split())
        compare = " ".join(str(app.screen.query_one("#compare").render()).split())
        assert "T (63 %) = " in lines and "T (least squares) = " in lines, lines
        for said in (lines, compare):
            assert not re.search(r"T[^=]*= [\d.]+ s\b", said), said
            assert not re.search(r"\d s\b", said.replace("rad/s", "")), said
        with app.session as s:
            st = s.results().identification.step
        assert f"T (63 %) = {format_constant(st.T_63, 's')}" in lines, lines
        assert "yours 57 ms" in compare, compare
