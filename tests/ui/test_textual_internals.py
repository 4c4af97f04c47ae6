"""What tests/ui/textual_internals.py does with Textual's public names instead of its private
ones still does what the private ones did: the wait for the screen ends when the app fails
(App.return_code, not App._exception_event), and the process-wide CSS cache parses a source
again for other variables (the variables noted from Stylesheet's constructor and
set_variables, not read off its _variables)."""

from __future__ import annotations

import pytest
from textual.app import App
from textual.color import Color
from textual.css.stylesheet import Stylesheet

from tests.ui.textual_internals import FAILED, wait_for_screen

CSS = "Static { color: $ink; }"
"""One rule whose colour is a variable."""


def _ink(sheet: Stylesheet) -> Color | None:
    """The colour ``sheet``'s one rule gives (its CSS read with its variables)."""
    sheet.add_source(CSS, read_from=("test_textual_internals.py", "CSS"))
    (rule,) = sheet.rules
    return rule.styles.color


async def test_the_wait_for_the_screen_ends_when_the_app_fails() -> None:
    """A handler raises: the wait returns False (not every node handled what was queued),
    well before its 30 s hang guard, which would raise WaitForScreenTimeout."""

    def fail() -> None:
        raise RuntimeError("a handler fails")

    app: App[None] = App()
    waited: bool | None = None
    with pytest.raises(RuntimeError, match="a handler fails"):  # run_test raises it at its end
        async with app.run_test() as pilot:
            app.call_later(fail)
            waited = await wait_for_screen(pilot, timeout=10.0)
    assert waited is False
    assert app.return_code == FAILED


def test_the_css_cache_parses_again_for_other_variables() -> None:
    """The same source with other variables, given at making or by set_variables, is parsed
    with them, not taken from the cache (the cache is in force: tests/conftest.py)."""
    red, blue = {"ink": "#ff0000"}, {"ink": "#0000ff"}
    assert _ink(Stylesheet(variables=red)) == Color(255, 0, 0)
    assert _ink(Stylesheet(variables=blue)) == Color(0, 0, 255)
    again = Stylesheet(variables=red)
    again.set_variables(blue)
    assert _ink(again) == Color(0, 0, 255)
