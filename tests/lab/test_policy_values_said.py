"""lab.toml with a value of the wrong type (s38 attack): the line said it in Python's
spelling ("got 'false'", "got [False]"), which the instructor never typed; it says it as
lab.toml spells it now. Real files in a sessions folder."""

from __future__ import annotations

import pytest

from minseg_tui.lab.state.compare import POLICY_FILE, read_policy


@pytest.mark.parametrize(
    ("typed", "said"),
    [
        ('answers_first = "false"', 'got "false"'),
        ("answers_first = [false]", "got [false]"),
        ("answers_first = 0", "got 0"),
        ('answers_first = { on = "yes" }', 'got {"on": "yes"}'),
    ],
)
def test_a_wrong_type_is_said_as_lab_toml_spells_it(tmp_path, typed, said):
    (tmp_path / POLICY_FILE).write_text(typed + "\n", encoding="utf-8")
    policy = read_policy(tmp_path)
    assert policy.answers_first and policy.file
    assert policy.problem == (
        f"{tmp_path / POLICY_FILE}: answers_first must be true or false, {said}; answers first"
    )
