"""A focused widget of the step keeps the characters it binds: it says so through Textual's
``check_consume_key`` (the step form asks it before it takes a character for the first
empty entry), and what it says matches its bindings, so a character bound later is not
typed into an entry in place of running its binding."""

from __future__ import annotations

from textual.binding import Binding
from textual.keys import key_to_character

from minseg_tui.ui.panels.results import ResponsePlot


def _bound_characters(cls: type) -> set[str]:
    """The printable characters among the keys ``cls``'s own BINDINGS name."""
    chars = set()
    for binding in Binding.make_bindings(cls.__dict__.get("BINDINGS", [])):
        char = key_to_character(binding.key)
        if char is not None and char.isprintable():
            chars.add(char)
    return chars


def test_the_run_log_keeps_exactly_the_characters_it_binds():
    plot = ResponsePlot("run log", "t (s)", "omega (rad/s)")
    bound = _bound_characters(ResponsePlot)
    assert bound == {"[", "]", "z"}
    for char in bound:
        assert plot.check_consume_key(char, char)
    for key, char in (("a", "a"), ("5", "5"), ("space", " "), ("left", None), ("home", None)):
        assert not plot.check_consume_key(key, char), key
