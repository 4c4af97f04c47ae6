"""The report says what it says in words: no internal id (a finding's code, an entry's key,
a cause's contract name) stands in its text."""

from __future__ import annotations

import re
from pathlib import Path

from minseg_tui.lab.state.session import Session
from minseg_tui.model.check.effects import CANDIDATES
from minseg_tui.report import content, markdown
from tests.classview.build import group

IDS = re.compile(r"\b[A-Za-z]+(?:_[A-Za-z0-9]+)+:|\w+@\d")
"""A code or key before a colon ('k_v_outlier:', 'dry_friction:', 'T_short:') or an entry's
key ('omega_ss@2.5')."""


def test_warnings_and_the_model_check_speak_in_words(tmp_path: Path) -> None:
    folder = group(
        tmp_path,
        ["Ada", "Bo"],
        seed=5,
        rows={2.5: ("2.05", "36.5", "30.1 mA"), 3.5: ("3.05", "5.8", "0.0335 mA")},
    )
    with Session.open(folder, readonly=True) as s:
        md = markdown.render(content.build(s))
        codes = {n.source for n in s.warnings()}
    assert {"omega_ss_units", "T_short"} <= codes  # findings the report has to put in words
    warnings = md.split("## Warnings")[1].split("\n## ")[0]
    assert "- Task 4, omega_ss at 2.5 V: faster than this motor goes" in warnings
    assert "- row 1 (u_req 2.5 V): omega_ss = 36.5 is" in warnings
    assert not IDS.findall(md), IDS.findall(md)
    check = md.split("## Model check")[1]
    assert "Why dry friction, over the whole run: " in check
    contract = [c.cause for c in CANDIDATES] + [c.param for c in CANDIDATES]
    assert not [n for n in contract if re.search(rf"\({n}[;)]", check)]
    assert "The next best explanation, " in check  # named, in words
    runner = check.split("The next best explanation, ")[1].split(",")[0]
    assert "_" not in runner, runner
