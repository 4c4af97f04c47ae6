"""The real logs of ../shared/data/real-motors and their model check as ``minseg-tui analyze``
runs it, made once per test process: tests/model/test_check_real.py pins what each log
supports, tests/lab/test_check_plain.py the student's words on four of them. Each log's tests
share an xdist group (:func:`on`), so one worker checks it once."""

from functools import cache
from pathlib import Path

import pytest

from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.views.check_text import text
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.runlog import RunLog
from tests.shared_data import SHARED_DATA

REAL = SHARED_DATA / "real-motors"
# without ../shared one placeholder each, so the tests are listed and say why they did not run
LOGS = sorted(p.parent.name for p in REAL.glob("*/step.csv")) or ["real-motors absent"]
PROBES = sorted(p.name for p in (REAL / "probes").glob("*.csv")) or ["probes absent"]


@cache
def analyze(name: str) -> tuple[CheckResult, str]:
    """The check of a real log as ``minseg-tui analyze`` runs it (its header read), and its text."""
    path = REAL / name / "step.csv" if (REAL / name).is_dir() else REAL / "probes" / name
    log = read_run_log(path)
    ts = float(log.metadata["ts"]) if "ts" in log.metadata else None
    r = check(log.t, log.u, log.omega, ts=ts, cpr=log.declared_cpr, omega_over=log.omega_over)
    return r, text(r)


# Under pytest-xdist (make test: --dist loadgroup) a log's check is cached per worker
# (analyze), so every test reading a log goes to the one worker that checks it: the logs some
# test reads together share a group, each other log has its own, and the groups still spread
# over the workers. Spread test by test, the 16 logs were checked 28 times on two workers.
# tests/lab/test_check_plain.py reads four of these logs through analyze and the same groups.
TOGETHER = (
    ("micromouse-n20-duty255", "micromouse-n20-duty100", "n20_255_uponly.csv"),
    ("ubc-motor-7V", "ubc7_2ms.csv", "ubc7_20ms.csv"),
    ("ev3_100_irregular_actualdt.csv", "ev3_100_irregular_nominaldt.csv"),
)


def on(*names: str) -> pytest.MarkDecorator:
    """The xdist group of the tests that read the logs ``names`` (one group, see TOGETHER)."""
    groups = {next((s[0] for s in TOGETHER if n in s), n) for n in names}
    assert len(groups) == 1, f"{names} are read together: put them in one TOGETHER entry"
    return pytest.mark.xdist_group(f"real-{groups.pop()}")


def logs(*names: str) -> list[object]:
    """``names`` as parameters, each in its log's xdist group (:func:`on`)."""
    return [pytest.param(n, marks=on(n)) for n in names]


def ev3_gap(folder: Path) -> tuple[RunLog, CheckResult]:
    """ev3-large-duty100 with its data rows 74-76 dropped (REAL37's 'gap' variant), written in
    ``folder``, and its check: a current cap named 0.3 points over the bar, a toss-up."""
    lines = (REAL / "ev3-large-duty100" / "step.csv").read_text().splitlines()
    head = next(i for i, x in enumerate(lines) if not x.startswith("#"))
    path = folder / "ev3-gap.csv"
    path.write_text("\n".join(lines[: head + 75] + lines[head + 78 :]) + "\n")
    log = read_run_log(path)
    r = check(log.t, log.u, log.omega, ts=float(log.metadata["ts"]), cpr=log.declared_cpr)
    return log, r
