"""Walk 8, D3: J typed 0.00182 beside 0.001819 computed the group's way read "0 %" (the full
0.0018192 is 0.04 % off, under the 0.05 % that reads as a match) although the two numbers
side by side are 0.06 % apart. The difference is now taken from the computed value as it is
shown, on the screen's texts, the report and the class view alike (real session files)."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.lab.views.classview import own_cell, read_group
from minseg_tui.quantities import format_number
from minseg_tui.report.write import write_report
from tests.report.test_own_first import _row, _section, _tables
from tests.report.test_report import _session


def test_a_difference_reads_from_the_numbers_shown(tmp_path: Path) -> None:
    s = _session(tmp_path)
    (j,) = [c for c in s.comparisons() if c.key == "own.J"]
    assert isinstance(j.computed, float)
    # J grows in proportion to the group's T: a T that makes J 0.0018192 kg m^2 (walk 8's)
    per_second = j.computed / 0.09
    s.enter("own.T", f"{1.8192e-3 / per_second * 1e3:.6f} ms")
    s.enter("own.J", "1,82e-3")
    (j,) = [c for c in s.comparisons() if c.key == "own.J"]
    assert isinstance(j.computed, float) and format_number(j.computed) == "0.001819"
    assert abs(0.00182 / j.computed - 1.0) < 0.0005  # the full value: under 0.05 %
    md = write_report(s).markdown.read_text(encoding="utf-8")
    folder = s.folder
    s.close()
    (table,) = _tables(_section(md, "Step response and model"))
    row = _row(table, "J (Task 13)")
    assert "0.001819 kg m^2" in " ".join(row.values()), row
    assert any(v.startswith("+0.1 %") for v in row.values()), row
    assert "J +0.1 %" in own_cell(read_group(folder))
