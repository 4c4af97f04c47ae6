"""A 95 % interval shows its width: never 'x-x' with both ends alike."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from minseg_tui.quantities import NO_WIDTH, format_interval
from minseg_tui.report import content, markdown
from tests.classview.build import group


def test_the_ends_get_the_digits_that_tell_them_apart() -> None:
    assert format_interval(1.9661, 1.9739, "rad/s/V", digits=3, sep="-") == "1.966-1.974 rad/s/V"
    assert format_interval(12.30041, 12.30049, "rad/s/V") == "12.3004 – 12.3005 rad/s/V"
    assert format_interval(0.0397, 0.0411, "s") == "0.03970 – 0.04110 s"  # wide: as before
    assert format_interval(12.3, 12.3, "rad/s/V") == NO_WIDTH
    assert format_interval(12.3, 12.2) == NO_WIDTH


@pytest.fixture(scope="module")
def run_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return group(tmp_path_factory.mktemp("s"), ["Ada"], seed=0)


def _intervals(text: str) -> list[tuple[str, str]]:
    return re.findall(r"95 %: ([-+0-9.e]+) ?[-–] ?([-+0-9.e]+)", text)


def test_analyze_and_the_report_never_print_an_interval_as_one_number(run_folder, capsys):
    # the extended model's K on this seeded run lies within 1.966-1.974 rad/s/V: at three
    # digits both ends read 1.97, which analyze printed as '95 %: 1.97-1.97'
    assert main(["analyze", str(run_folder / "runs" / "steps-1.csv")]) == 0
    out = capsys.readouterr().out
    found = _intervals(out)
    assert len(found) >= 4 and all(a != b for a, b in found), found
    with Session.open(run_folder, readonly=True) as s:
        md = markdown.render(content.build(s))
    found = _intervals(md)
    assert found and all(a != b for a, b in found), found
