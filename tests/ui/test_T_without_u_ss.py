"""Walk 18's D4: Task 12's plot, its reveal (Ctrl+R) and T waited for u_ss (Task 4), though
T and the 63 % reading need only the speed. Without a u_ss the zoomed rise, its 63 % level
and T are there; K and what follows from it say they wait for u_ss."""

from __future__ import annotations

from minseg_tui.ui.panels.results import ResponsePlot, ResultsPanel
from tests.ui.helpers import burst, enter_all, goto, record_response_run, settle, start


async def _task12_without_u_ss(pilot) -> ResultsPanel:
    app = pilot.app
    await start(pilot)
    enter_all(app, {"R": "5.3"})  # no row of the table: no u_ss
    with app.session as s:
        record_response_run(s)
    await goto(pilot, "task12")
    panel = app.screen.query_one(ResultsPanel)
    await settle(pilot, lambda: panel.view is not None)
    return panel


def _said(panel: ResultsPanel) -> str:
    return (
        str(panel.screen.query_one("#results-lines").render())
        + "\n"
        + str(panel.query_one("#zoom-note").render())
    )


async def test_task12_shows_its_rise_and_reveals_T_without_u_ss(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        panel = await _task12_without_u_ss(pilot)
        view = panel.view
        assert view is not None and view.rises, _said(panel)  # the zoomed rise to read T off
        assert "63 %" in {t.label for t in app.screen.query_one(ResponsePlot).traces}
        said = _said(panel)
        assert "rise 1 of" in said, said
        assert "T: shown once you enter yours (Ctrl+R" in said, said
        assert "K, J, the model and omega at 5 V: not yet, needs u_ss" in said, said
        await burst(pilot, "ctrl+r")
        await settle(pilot, lambda: "T (63 %) =" in _said(panel))
        said = _said(panel)
        assert "T (least squares) =" in said and "after the edge" in said, said
        with app.session as s:
            assert s.revealed() == {"own.T"}  # recorded: revealed before answering
        assert "K =" not in said  # K of the requested voltage is never shown


async def test_T_typed_without_u_ss_is_compared_with_the_63_percent_reading(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        panel = await _task12_without_u_ss(pilot)
        enter_all(app, {"own.T": "57 ms"})
        app.lab_changed.publish(None)
        await settle(
            pilot, lambda: "read your way" in str(panel.screen.query_one("#compare").render())
        )
        compared = str(panel.screen.query_one("#compare").render())
        assert "56." in compared or "57." in compared, compared
