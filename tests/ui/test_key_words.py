"""Issue 20 (walk 11): a key reads the same wherever it is named. Alt+←/→ was 'Rise' in the
footer, 'Step' on the plot's line and 'previous / next step of the log' in F1's help, and a
bare 'step' there is a lab step, not a rise after a voltage step up. Each word is read off
the screen: the footer's, the line under the plot and F1's list."""

from __future__ import annotations

import re

from minseg_tui.ui.screens.help import HelpScreen, KeyList
from minseg_tui.ui.widgets.footer import KeyFooter, KeyLabel
from minseg_tui.ui.widgets.prose import Prose
from tests.ui.helpers import goto, settle, start, start_with_a_run

BARE_STEP = re.compile(r"(?<!voltage )(?<!lab )\bstep\b", re.IGNORECASE)
"""'step' that is neither a lab step nor a voltage step ('steps-1', a run's name, is not)."""


def _footer_words(app) -> dict[str, str]:
    """What the footer calls each key it shows: {'f9': 'Zoom', 'alt+→': ...}."""
    footer = app.screen.query_one(KeyFooter)
    return {k.key_display: k.description for k in footer.query(KeyLabel) if k.display}


async def _help_lines(pilot) -> dict[str, str]:
    """F1's list as shown, {'F9': 'Zoom: the next rise, ...'}, then F1 closed again."""
    await pilot.press("f1")
    await settle(pilot, lambda: isinstance(pilot.app.screen, HelpScreen))
    text = pilot.app.screen.query_one(KeyList).text
    await pilot.press("escape")
    await settle(pilot, lambda: not isinstance(pilot.app.screen, HelpScreen))
    lines = {}
    for line in text.splitlines():
        key, _, said = line.partition("  ")
        lines[key.strip()] = said.strip()
    return lines


async def _footer_on_task12(pilot) -> dict[str, str]:
    """A new session with a step run, on Task 12 (its first rise): the footer's words."""
    await start_with_a_run(pilot, "task12")
    await settle(pilot)
    return _footer_words(pilot.app)


async def test_the_footer_the_plots_line_and_f1_name_alt_arrows_and_f9_alike(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        words = await _footer_on_task12(pilot)
        rise, zoom = words["alt+→"], words["f9"]  # Task 12 opens on the first rise
        note = app.screen.query_one("#zoom-note", Prose).text
        assert f"alt+←/→ {rise} ·" in note and f"f9 {zoom} (rise 2)" in note, note
        assert "rise 1 of 4" in note and not BARE_STEP.search(note), note
        for _ in range(3):  # on the last rise F9 goes to the whole log, and says so
            await pilot.press("f9")
            await settle(pilot)
        note = app.screen.query_one("#zoom-note", Prose).text
        assert "rise 4 of 4" in note and f"f9 {zoom} (the whole log)" in note, note
        await pilot.press("f9")
        await settle(pilot)
        note = app.screen.query_one("#zoom-note", Prose).text
        assert "whole log" in note and f"f9 {zoom} (rise 1)" in note, note
        help_ = await _help_lines(pilot)
        assert help_["Alt+← →"].startswith(f"{rise}: "), help_["Alt+← →"]
        assert help_["F9"].startswith(f"{zoom}: "), help_["F9"]
        assert "voltage step" in help_["Alt+← →"]
        for key in ("Alt+← →", "F9", "[ ] z"):
            assert not BARE_STEP.search(help_[key]), help_[key]


async def test_every_key_the_footer_shows_reads_the_same_in_f1(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        words = await _footer_on_task12(pilot)
        help_ = await _help_lines(pilot)
        in_help = {"alt+→": "Alt+← →", "^r": "Ctrl+R", "^p": "Ctrl+P", "pgdn": "PgDn/PgUp"}
        for shown, word in words.items():
            if not word:  # the palette's key, Textual's own
                continue
            line = help_[in_help.get(shown, shown.upper())]
            assert line.startswith(f"{word}: "), (shown, word, line, words)


async def test_the_model_checks_line_names_f9_as_the_footer_does(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "model_check")
        await settle(pilot)
        zoom = _footer_words(app)["f9"]
        story = app.screen.query_one("#check-story", Prose).text
        first = story.splitlines()[0]
        assert f"f9 {zoom} (the whole log)" in first, first
        await pilot.press("f9")
        await settle(pilot)
        first = app.screen.query_one("#check-story", Prose).text.splitlines()[0]
        assert f"f9 {zoom} (the close-up the words speak of)" in first, first


async def test_the_live_plots_line_names_f3_f2_and_f4_as_the_footer_does(quiet):
    """Task 4's line under the live plot said 'F3 next voltage · F2 stop · F4 capture'
    where the footer says 'f3 Set V', 'f2 STOP' and 'f4 Capture'."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        steady = app.screen.query_one("#steady", Prose)
        await settle(pilot, lambda: "requested" in steady.text)
        words = _footer_words(app)
        for key in ("f3", "f2", "f4"):
            assert f"{key} {words[key]}" in steady.text, (key, words[key], steady.text)
