"""Issue 20: the verdict on a value the group worked out stands right under the entry they
typed it in, in view at 80x24 (it stood only in the comparison under the last entry of the
step, below the screen's edge after the first entry), with its mark: ✓ right, ✗ wrong,
○ stored, not judged yet. Pilot, a real session folder, the seeded plant's run."""

from __future__ import annotations

from textual.widget import Widget

from minseg_tui.quantities import format_number, format_quantity
from minseg_tui.ui.screens.lab import StepPane
from minseg_tui.ui.widgets.fields import FieldRow, field_id
from tests.ui.helpers import settle, start_with_a_run, type_in


def _message(app, key: str) -> tuple[str, Widget]:
    row = app.screen.query_one(f"#{field_id(key)}", FieldRow)
    return " ".join(row.message.split()), row.query_one(".field-msg")


def _in_view(app, widget: Widget) -> bool:
    """Every line of ``widget`` inside the step's visible area, none under its heading."""
    pane = app.screen.query_one(StepPane)
    view = pane.scrollable_content_region
    top = view.y + pane.heading_rows
    region = widget.region
    return bool(region) and region.y >= top and region.bottom <= view.bottom


async def test_the_verdict_stands_under_the_entry_typed_in_at_80x24(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        with app.session as s:
            st = s.results().identification.step
        u_ss = st.u_ss
        # omega_ss read off a rise, a third too high: wrong; then K from it, right their way
        omega = st.omega_ss * 1.33
        await type_in(pilot, "own.omega_step", format_number(omega, 3))
        said, msg = _message(app, "own.omega_step")
        assert said.startswith("✗ wrong: +") and "the program's steady speed" in said, said
        assert "off by more than the 15 %" in said and _in_view(app, msg)
        await type_in(pilot, "own.K", format_number(omega / u_ss, 4))
        await settle(pilot)
        said, msg = _message(app, "own.K")
        assert said.startswith("✓ right:") and "computed your way" in said, said
        assert f"least squares {format_quantity(st.K, 'rad/s/V')}" in said
        assert _in_view(app, msg)

        await pilot.press("pagedown")
        await settle(pilot)
        await type_in(pilot, "own.T", format_number(st.T_63 * 1e3 * 2, 3) + " ms")
        await settle(pilot)
        said, msg = _message(app, "own.T")
        assert "✗ wrong: +100 % from" in said and "ms, the program's 63 % reading" in said, said
        assert "least squares" in said and _in_view(app, msg)
