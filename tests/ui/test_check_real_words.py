"""Walk 16's D8 and the reading of the ten real logs at the model check (stop 38): every
sentence and mark on the model check's screen true of the log imported there.

On the EV3 log (one step up, none down, no cause named) the screen drew an extended model
in the legend ("+ ext.") and titled the close-up "where the cause acts", with nothing
extended and no cause; the fold said "Enter opens" while open; Details said "what the model
get wrong"; once the group judged Tasks 11-15 on the import, Details said the check fits
the speed "over the whole run, steps down included" on a log with no step down, and the
report said the same. The close-up's span "-0.100-0.480 s" read as one from 0.100 s. On the
rtl brake log a second lag of 165 ms was put down to "the current builds up in the
winding" (a small motor's builds up within a few ms; the story already said "a slow second
lag"). Walking the ten logs again at 80x24: on the two rtl logs (a tachometer's smooth speed,
the angle its sum) the angle's figure said "drifts from the one the encoder counted"; on the
micromouse log at 100/255 an 18 ms delay "cannot be told from a slow current build-up"."""

from __future__ import annotations

from pathlib import Path

import pytest
from textual.widgets import Collapsible

from minseg_tui.report.write import write_report
from minseg_tui.ui.widgets.plots import TracePlot
from minseg_tui.ui.widgets.prose import Prose
from minseg_tui.ui.widgets.textbox import TextBox
from tests.shared_data import SHARED_DATA
from tests.ui.helpers import TABLE, enter_all, lab_screen, settle, shown, start

REAL = SHARED_DATA / "real-motors"


def _flat(text: str) -> str:
    return " ".join(text.split())


def _title_line(fold: Collapsible) -> str:
    title = fold.query_one("CollapsibleTitle")
    return "".join(s.text for s in title.render_lines(title.region.reset_offset)).strip()


async def _import(pilot, log: Path, run: str = "imported-1") -> Prose:
    """The palette's "Import a run log", ``log`` typed in its box and Enter; the model
    check's story once it speaks of the import."""
    app = pilot.app
    app.import_log()
    await settle(pilot, lambda: shown(app, "model_check"))
    box = app.screen.query_one("#import-path", TextBox)
    await settle(pilot, lambda: app.focused is box)
    box.value = str(log)
    await pilot.press("enter")
    story = app.screen.query_one("#check-story", Prose)
    await settle(pilot, lambda: story.text.startswith(f"run {run}"))
    return story


async def _open_details(pilot) -> tuple[Collapsible, str]:
    fold = pilot.app.screen.query_one("#check-details", Collapsible)
    fold.query_one("CollapsibleTitle").focus()
    await pilot.press("enter")
    await settle(pilot, lambda: not fold.collapsed)
    return fold, _flat(pilot.app.screen.query_one("#check-lines", Prose).text)


@pytest.mark.shared_data
async def test_the_ev3_log_is_told_as_it_is(quiet, tmp_path):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        story = await _import(pilot, REAL / "ev3-large-duty100" / "step.csv")
        assert "nothing needs adding for this run" in story.text  # no cause named
        plot = app.screen.query_one("#plot-check", TracePlot)
        await settle(pilot, lambda: bool(plot.traces))
        # the close-up: measured and the first-order model only, under a title of its own
        assert [t.label for t in plot.traces] == ["first order", "measured"]
        assert "ext." not in plot.legend, plot.legend
        assert plot.plot_title == "close-up"
        residual = app.screen.query_one("#plot-residual", TracePlot)
        assert "extended" not in [t.label for t in residual.traces]
        assert "close-up -0.100 to 0.480 s: a rise" in _flat(story.text), story.text
        await pilot.press("f9")  # the whole log: one model, not "models"
        await settle(pilot, lambda: plot.plot_title != "close-up")
        assert plot.plot_title == "measured vs model"
        assert "ext." not in plot.legend, plot.legend
        fold, details = await _open_details(pilot)
        assert _title_line(fold).endswith("Enter closes"), _title_line(fold)
        assert "which hides what the model gets wrong" in details, details
        await pilot.press("enter")
        await settle(pilot, lambda: fold.collapsed)
        assert _title_line(fold).endswith("Enter opens"), _title_line(fold)
        # Tasks 11-15 judged on the import: the two T told apart, true of a log with no
        # step down, on the screen and in the report
        lab_screen(app).use_run("imported-1")
        lines = app.screen.query_one("#check-lines", Prose)
        await settle(pilot, lambda: "least-squares reading" in lines.text)
        said = _flat(lines.text)
        assert "while the model check fits the speed over the whole run; here the two T" in said
        assert "steps down" not in said, said
        with app.session as s:
            folder = s.folder
            write_report(s)
        report = _flat((folder / "report.md").read_text(encoding="utf-8"))
        assert "the model check fits the speed over the whole run; here the two T" in report
        assert "steps down included" not in report


@pytest.mark.shared_data
async def test_a_slow_second_lag_is_not_put_down_to_the_winding(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        story = await _import(pilot, REAL / "rtl-dc-5to15V-brake" / "step.csv")
        assert "The check finds a slow second lag too." in _flat(story.text), story.text
        _, details = await _open_details(pilot)
        assert "builds up in the winding" not in details, details
        assert (
            "a second, slow lag, T2 = 165 ms: the torque follows the voltage that much later, "
            "too late for the current in the winding, which in a small motor builds up within "
            "a few ms" in details
        ), details
        # a tachometer's smooth speed: its angle is not "the one the encoder counted"
        assert "counted in encoder steps (a tachometer" in details
        assert "encoder counted" not in details, details
        assert "drifts from the logged angle: 11.0 → 0.235 rad" in details, details
        # a delay the run cannot tell from a second lag: not "a slow current build-up"
        story = await _import(pilot, REAL / "micromouse-n20-duty100" / "step.csv", "imported-2")
        said = _flat(story.text)
        assert "the motor answers about 18 ms after the command" in said, said
        assert "This run cannot tell it from a second lag." in said, said
        assert "current build-up" not in said, said


@pytest.mark.shared_data
async def test_a_cause_the_check_calls_uncertain_is_not_told_as_likely(quiet, tmp_path):
    """s38-late's EV3 toss-up: with data rows 74-76 dropped the check names a current cap
    0.3 points over the 25 % bar, and the CLI's text calls the cause uncertain; the screen's
    lead said "Likely cause: the driver limits the current" as if it were sure."""
    lines = (REAL / "ev3-large-duty100" / "step.csv").read_text().splitlines()
    head = next(i for i, x in enumerate(lines) if not x.startswith("#"))
    gap = tmp_path / "ev3-gap.csv"
    gap.write_text("\n".join(lines[: head + 75] + lines[head + 78 :]) + "\n")
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        story = _flat((await _import(pilot, gap)).text)
        assert "Likely cause" not in story, story
        assert "Possible cause, uncertain (it only just clears the check's bar" in story, story
        _, details = await _open_details(pilot)
        assert "so the cause is uncertain" in details, details
