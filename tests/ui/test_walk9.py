"""Walk 9's defects (issue 20), each with the keys the tester typed, Pilot at 80x24 on a real
session folder."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.panels.report import ReportPanel
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from minseg_tui.ui.widgets.plots import Canvas, TracePlot
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    box_text,
    goto,
    settle,
    shown,
    start,
    start_with_a_run,
    stored_text,
    typing_box,
)


def _said(app, key: str) -> str:
    row = app.screen.query_one(f"#{field_id(key)}", FieldRow)
    return " ".join(row.message.split())


async def test_a_share_typed_as_a_fraction_is_quoted_as_typed_never_as_the_answer(quiet):
    """D1: on Prep 5 every fraction below 1 got "that reads as 0.63 %: type the percentage,
    63 %": the group's value misquoted and the answer given away. Keys as walked: '0.63'
    Enter, Ctrl+U '0.5' Enter, Ctrl+U '0.9' Enter."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "prep5")
        said = []
        for typed in ("0.63", "0.5", "0.9"):
            await pilot.press("ctrl+u", *typed, "enter")
            await settle(pilot)
            said.append(_said(app, "prep5.percent"))
        assert "that reads as 0.63 %: did you mean 63 %?" in said[0]
        assert "that reads as 0.5 %: did you mean 50 %?" in said[1]
        assert "that reads as 0.9 %: did you mean 90 %?" in said[2]
        for line in said[1:]:
            assert "63" not in line, line
        assert stored_text(app, "prep5.percent") == "0.9"


async def test_f8_on_the_summary_says_in_view_where_the_report_is_with_the_whole_path(tmp_path):
    """D2: on the summary, typed from its last entry, F8 said where the files went only in
    the step's first lines, scrolled out of view, and nowhere the sessions folder's path:
    "in the session folder 2026-11-27-mia-k-olle (under the sessions folder)". The notice
    now gives the session folder's whole path, in view, off the entry typed in; the step's
    own line too. Keys as walked: Down Space Tab for Q1-Q6, the last entry typed, Enter, F8."""
    dev = QuietDevice(seed=1)
    root = tmp_path / "walk9-sessions"
    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: dev, lambda session: write_report(session).paths)
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start(pilot, "Mia K, Olle")
        await goto(pilot, "summary")
        for _ in range(6):
            await pilot.press("down", "space", "tab")
        await pilot.press(*"why the 63 % T and the fitted T differ", "enter")
        await settle(pilot)
        box = typing_box(app)
        assert box is not None
        await pilot.press("f8")
        await settle(pilot, lambda: bool(app.exported))
        await settle(pilot, lambda: bool(app.screen.query("Toast")))
        folder = Path(app.exported[0]).parent.resolve().as_posix()
        assert folder.startswith(root.resolve().as_posix())
        screen = app.screen.region
        said = [
            (" ".join(str(t.render()).split()), t.region)
            for t in app.screen.query("Toast")
            if "written:" in str(t.render())
        ]
        assert len(said) == 1, said
        text, region = said[0]
        assert f"in{folder}" in text.replace(" ", ""), text  # a long path may wrap
        assert screen.contains_region(region) and not region.overlaps(box.region)
        panel = " ".join(str(app.screen.query_one(ReportPanel).render()).split())
        assert f"writtenin{folder}:" in panel.replace(" ", ""), panel  # two lines: see D7


def _label_line(plot: TracePlot) -> str:
    """The canvas's line of axis labels (its last), as drawn."""
    canvas = plot.query_one(Canvas)
    lines = [s.text for s in canvas.render_lines(canvas.region.reset_offset)]
    return lines[-1]


async def test_the_model_checks_close_up_says_its_x_axis_is_time(quiet):
    """D3: on the model check (PgDn from Task 15) the left plot, the close-up of where the
    cause acts, had no x label: "omega [rad/s]" filled its line of labels and its ticks,
    seconds into the run (7.6 ... 7.9), read as speeds. Both plots now say "t [s]"."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task15")
        await pilot.press("pagedown")
        await settle(pilot, lambda: shown(app, "model_check"))
        await settle(pilot)
        for plot_id in ("#plot-check", "#plot-residual"):
            plot = app.screen.query_one(plot_id, TracePlot)
            assert "t [s]" in _label_line(plot), (plot_id, _label_line(plot))
        assert "rad/s" in _label_line(app.screen.query_one("#plot-check", TracePlot))


async def test_a_captured_omega_ss_keeps_its_digits(quiet):
    """D8: a capture of 5.800098 rad/s was stored and shown as "5.8" while the other
    captures showed three decimals ("3.823"): a measured reading keeps its digits. The wheel
    here stands at 5.8 rad/s for the whole capture window (real samples, as F4 hands them
    to the session)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        t = [0.025 * k for k in range(120)]
        with app.session as s:
            s.capture_omega(3.5, t, [5.800098] * len(t))
        await goto(pilot, "task4")
        assert stored_text(app, "omega_ss@3.5") == "5.800"
        assert box_text(app, "omega_ss@3.5") == "5.800"
