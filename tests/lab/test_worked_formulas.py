"""F7's formula with the row's numbers (Tasks 6 and 9): worked out again from the numbers it
shows, it gives the result it prints (walk 4: omega_ss rounded to 3.82 rad/s gave 0.4953
beside the 0.4947 printed), whatever digits the readings were typed or captured with."""

from __future__ import annotations

import re
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.quantities import format_number

NUMBER = re.compile(r"\d+(?:\.\d+)?")


def _check(line: str) -> None:
    left, worked, printed = line.split(" = ")[1:4]
    shown = printed.split()[0]
    nums = [float(n) for n in NUMBER.findall(worked)]
    if left.startswith("(u_ss"):
        u, R, i, w = nums
        value = (u - R * i) / w
    else:
        k_a, i, w = nums
        value = k_a * i / w * 1e3  # printed in mN m s/rad
    digits = len(shown.replace(".", "").lstrip("0"))
    assert format_number(value, digits) == shown, line


@settings(max_examples=15, derandomize=True, deadline=None)
@given(
    R=st.floats(4.0, 7.0),
    rows=st.lists(
        st.tuples(st.floats(1.8, 4.3), st.floats(2.0, 8.0), st.floats(20.0, 50.0)),
        min_size=3,
        max_size=3,
    ),
)
def test_each_row_formula_gives_the_result_it_prints(tmp_path_factory, R, rows):
    folder: Path = tmp_path_factory.mktemp("s")
    with Session.create(folder, ["Ada"]) as s:
        s.enter("R", repr(R))
        for level, (u, w, i) in zip((2.5, 3.5, 4.5), rows, strict=True):
            s.enter(f"u_ss@{level:g}", repr(u))
            s.enter(f"omega_ss@{level:g}", repr(w))
            s.enter(f"i_ss@{level:g}", f"{i!r} mA")
        lines = [c.formula for row in views.table(s).rows for c in row[4:6]]
    checked = [line for line in lines if " = (" in line or "N m/A ×" in line]
    assert len(checked) == 6, lines
    for line in checked:
        assert " ≈ " not in line, line
        _check(line)
