"""Walk 7's report defects (real session folders, real report files): a formula the group
typed is kept as typed with its value beside it (D8); one figure, one set of digits, and a
second fit of the same quantity says it is another fit (D9); one unit per quantity in a
sentence, and one rule for a difference too small to show (D10)."""

from __future__ import annotations

import re
from pathlib import Path

from minseg_tui.lab.state.session import Session
from minseg_tui.quantities import format_diff
from minseg_tui.report.write import write_report
from tests.report.test_own_first import _row, _section, _tables
from tests.report.test_report import _session


def _files(s: Session) -> tuple[str, str]:
    written = write_report(s)
    md = written.markdown.read_text(encoding="utf-8").replace("\u00a0", " ")
    html = written.html.read_text(encoding="utf-8").replace("\u00a0", " ")
    return md, html


def test_a_formula_typed_stays_as_typed_with_its_value_beside_it(tmp_path: Path) -> None:
    """D8: Prep 4 '1-exp(-1)' and Prep 10 '2*pi/720' came out as 0.6321 and 0.008727 while
    the formulas in symbols of Prep 11-15 were kept as typed."""
    s = _session(tmp_path)
    s.enter("prep4.fraction", "1-exp(-1)")
    s.enter("prep10.gain", "2*pi/720")
    s.enter("prep6.y10", "3,79")  # a plain number: normalised as before, no "="
    s.enter("own.K", "7.9/4.05")  # arithmetic for one of the group's own values
    md, html = _files(s)
    s.close()
    (prep,) = _tables(_section(md, "Preparation"))
    assert _row(prep, "Preparation 4")["answer"] == "1-exp(-1) = 0.6321"
    assert _row(prep, "Preparation 10")["answer"] == "2*pi/720 = 0.008727"
    assert _row(prep, "Preparation 6")["answer"] == "3.79"
    assert "1-exp(-1) = 0.6321" in html and "2*pi/720 = 0.008727" in html
    (table,) = _tables(_section(md, "Step response and model"))
    assert _row(table, "K (Task 11)")["the group's value"] == "7.9/4.05 = 1.951 rad/s/V"


def test_one_rule_for_a_difference_too_small_to_show() -> None:
    """D10: K 1.95 against 1.951 read '< 0.05 %', omega at 5 V 9.75 against 9.750 read '0 %':
    both are matches to the digits shown, said the same way."""
    assert format_diff(1.95 / (7.9 / 4.05) - 1.0) == format_diff(0.0) == "0 %"
    assert format_diff(-0.0004) == "0 %" and format_diff(0.0006) == "+0.1 %"
    assert format_diff(0.003) == "+0.3 %" and format_diff(0.39) == "+39 %"


def test_tau_c_is_in_the_unit_of_the_torques_beside_it(tmp_path: Path) -> None:
    """D10: the dry-friction warning gave 'viscous f = 0.600 mN m s/rad and a dry friction
    torque tau_c = 0.00727 N m': mN m beside N m."""
    s = Session.create(tmp_path, ["Lena Berg"], date="2026-11-27")
    s.enter("R", "5.3")
    for lv, u, w, i in (
        (2.5, "2.05", "3.827", "29.8 mA"),
        (3.5, "3.05", "5.799", "33.4 mA"),
        (4.5, "4.05", "7.79", "37.2 mA"),
    ):
        s.enter(f"u_ss@{lv:g}", u)
        s.enter(f"omega_ss@{lv:g}", w)
        s.enter(f"i_ss@{lv:g}", i)
    md, _ = _files(s)
    s.close()
    warnings = " ".join(_section(md, "Warnings").split())
    m = re.search(r"tau_c = (\S+) (\S+ \S+)", warnings)
    assert m is not None, warnings
    assert m.group(2) == "mN m.", warnings
    # the line through the walk's rows (k_a i_ss against omega_ss), worked by hand: 7.274 mN m
    assert m.group(1) == "7.274", warnings
    # and the speeds it names with the table's digits
    assert "at 3.827 rad/s" in warnings, warnings


def test_one_figure_one_set_of_digits_and_another_fit_says_so(tmp_path: Path) -> None:
    """D9: one report gave u_c = 0.123 V (Tasks 11-12's fit), 0.121 V and 0.1206 V (the
    model check's one figure rounded two ways); the check's lead gave K = 1.92 rad/s/V and
    its angle errors 0.013 and 0.0040 rad where its details give 1.919, 0.0130 and 0.00397."""
    s = _session(tmp_path)  # its run has dry friction: both fits find a u_c
    md, _ = _files(s)
    s.close()
    step = " ".join(_section(md, "Step response and model").split())
    check = " ".join(_section(md, "Model check").split())
    (fitted,) = re.findall(r"u_c = ([0-9.]+) V([^.;]*)", step)
    assert fitted[1].startswith(" in this fit (the model check's fit"), fitted
    in_check = set(re.findall(r"u_c = ([0-9.]+) V", check))
    assert len(in_check) == 1, in_check  # the evidence and the extended model: one figure
    for value in (fitted[0], *in_check):
        assert len(value.lstrip("0.")) == 4, value  # four significant digits, as every fit
    # the lead names the check's first-order fit with the digits of the details
    lead = check.split("### Details", 1)[0]
    details = check.split("### Details", 1)[1]
    (K_lead,) = re.findall(r"K = ([0-9.]+) rad/s/V\)", lead)
    assert f"K = {K_lead} rad/s/V (95 %" in details, (K_lead, details)
    m = re.search(r"falls from ([0-9.]+) (\S+) to ([0-9.]+) \2", lead)
    assert m is not None, lead
    rows = [r for r in _tables(_section(md, "Model check"))[0][1:] if "(leads)" in r[0]]
    assert rows and rows[0][1:] == [f"{m.group(1)} {m.group(2)}", f"{m.group(3)} {m.group(2)}"]
