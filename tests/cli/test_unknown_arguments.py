"""An unknown argument is said by the subcommand it was given to, and an argument holding a
newline or a terminal escape stays on its one line (s37 attack: 'minseg-tui class --bogus'
said 'minseg-tui: unrecognized arguments: --bogus (see minseg-tui --help)', naming no
command, and 'class $'a\\nb\\x1b[2J'' split the line and cleared the terminal)."""

from __future__ import annotations

import pytest

from minseg_tui.cli import main


@pytest.mark.parametrize(
    "argv",
    [
        ["class", "--bogus"],
        ["ports", "-"],
        ["board-check", "/dev/stdin"],
        ["sim", "--nope"],
        ["flash", "extra"],
        ["identify", "t.csv", "--R", "5", "--bogus"],
        ["analyze", "log.csv", "--bogus"],
        ["report", "g", "--bogus"],
        ["tui", "--bogus"],
    ],
)
def test_an_unknown_argument_is_said_by_its_subcommand(capsys, argv):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert err == (
        f"minseg-tui {argv[0]}: unrecognized arguments: {argv[-1]} "
        f"(see minseg-tui {argv[0]} --help)\n"
    )


def test_an_argument_with_a_newline_and_an_escape_stays_on_one_line(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["class", "a\nb\x1b[2J"])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert err == (
        "minseg-tui class: unrecognized arguments: a\\nb\\x1b[2J (see minseg-tui class --help)\n"
    )
