"""Two restyles of Textual's that the app leaves out, and why nothing is lost: a screen's
first show (``StatusScreen.post_message``) and the step form's focus
(``FieldForm.watch_has_focus``). Pilot at 80x24 on the device double, a real session folder."""

from __future__ import annotations

from textual.css.model import CombinatorType, SelectorSet, SelectorType

from minseg_tui.ui.screens.lab import StepPane
from tests.ui.helpers import settle, start, start_with_a_run

FOCUS = {"focus", "focus-within", "blur"}


def _styles(screen) -> dict[int, str]:
    """Every node of ``screen`` and its own styles, as CSS text."""
    return {id(n): n.styles.css for n in screen.walk_children(with_self=True)}


def _by_an_ancestors_focus(selectors: SelectorSet, parts: set[str]) -> bool:
    """The selector picks a widget by the focus of a widget it is in: a focus pseudo-class on
    a part followed by a descendant or child combinator, unless the widget picked is one of
    ``parts`` (the widgets' component classes, styled with the widget itself:
    ``OptionList:focus > .option-list--option-highlighted``)."""
    chain = selectors.selectors
    last = chain[-1]
    if last.type == SelectorType.CLASS and last.name in parts:
        return False
    return any(
        FOCUS & part.pseudo_classes
        and any(later.combinator != CombinatorType.SAME for later in chain[k + 1 :])
        for k, part in enumerate(chain)
    )


async def test_a_restyle_after_a_screens_first_show_would_change_nothing(quiet):
    """The start screen and the lab screen, once shown (the lab on Task 11, with the plots and
    the entries), are styled as Textual's restyle of the whole screen would style them."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        before = _styles(app.screen)
        app.stylesheet.update(app.screen)
        assert _styles(app.screen) == before
        await start_with_a_run(pilot, "task11")
        before = _styles(app.screen)
        app.stylesheet.update(app.screen)
        assert _styles(app.screen) == before


async def test_no_rule_styles_a_widget_by_the_focus_of_a_widget_it_is_in(quiet):
    """The step form restyles itself alone when its focus changes: no rule of the app's CSS
    (its own, its widgets' and Textual's, as loaded once the lab shows) may style a widget in
    it by the form's focus."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        parts = {
            name
            for node in app.screen.walk_children(with_self=True)
            for cls in type(node).__mro__
            for name in getattr(cls, "COMPONENT_CLASSES", ())
        }
        by_focus = [
            sel.css
            for rule in app.stylesheet.rules
            for sel in rule.selector_set
            if _by_an_ancestors_focus(sel, parts)
        ]
        assert by_focus == ["App:blur HeaderTitle"]  # Textual's: the app's focus, no widget's


async def test_the_form_styled_alike_with_and_without_the_focus(quiet):
    """Ctrl+L (the list of steps takes the focus) and back: every widget in the step form is
    styled as a restyle of the whole form gives."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task5")
        pane = app.screen.query_one(StepPane)
        for key in ("ctrl+l", "tab"):
            await pilot.press(key)
            await settle(pilot)
            before = _styles(pane)
            app.stylesheet.update(pane)
            assert _styles(pane) == before, key
