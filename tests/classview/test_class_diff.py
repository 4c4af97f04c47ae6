"""The class view writes a small difference with its digit, never "+0 %" (issue 20)."""

from __future__ import annotations

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views.classview import own_cell, read_group

from .build import group


def test_a_difference_under_half_a_percent_keeps_its_digit(tmp_path):
    folder = group(tmp_path, ["Ada", "Bo"], seed=4)
    with Session.open(folder) as s:
        ident = s.results().identification
        assert ident is not None and ident.step is not None and ident.step.T_63 is not None
        s.enter("own.T", f"{ident.step.T_63 * 1.003:.6f} s")
    cell = own_cell(read_group(folder))
    assert cell == "T +0.3 %", cell
