"""Issue 20: the model check's story gave the first-order T in ms, its details (and the
report's) in s. T and the delays are now in ms everywhere a person reads them, written by
the one function that says so (:func:`minseg_tui.quantities.format_constant`); JSON keeps
SI. Pilot at 80x24 on the seeded plant's run, and the report of the same session."""

from __future__ import annotations

import re

from minseg_tui.quantities import format_constant
from minseg_tui.report.write import write_report
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import start_with_a_run

IN_S = re.compile(r"\b(?:T|T2|T_coast|delay) = [0-9.]+ s\b")
"""A time constant or a delay written in seconds."""


async def test_the_check_gives_T_in_ms_in_its_story_its_details_and_the_report(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        story = " ".join(app.screen.query_one("#check-story", Prose).text.split())
        details = " ".join(app.screen.query_one("#check-lines", Prose).text.split())
        with app.session as s:
            T = s.model_check().result.baseline.params["T"]
            T_ls = s.results().identification.step.T
            md = " ".join(write_report(s).markdown.read_text(encoding="utf-8").split())
    check = md.split("## Model check", 1)[1].split(" ## ", 1)[0]
    for text in (story, details, check):
        assert not IN_S.search(text), IN_S.search(text)
    assert f"T = {format_constant(T, 's')}, K = " in story
    for text in (details, check):
        assert f"T = {format_constant(T, 's')}" in text and " ms" in format_constant(T, "s")
        assert f"gives T = {format_constant(T_ls, 's')} and K = " in text
