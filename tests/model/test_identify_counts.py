"""The encoder's count read off the angle values themselves (issue 17, stop 34): a theta column
written to a few significant digits sits on the count's grid only within what the digits keep,
and an encoder whose counts per revolution are not a whole number (a 12-count encoder read X4
behind a 29.861:1 gear: 358.33) cannot say so in a ``# cpr:`` header. T's interval on one rise
of coarse counts holds the rounding's spread only where the count is known."""

import math
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.model.identify import identify
from minseg_tui.model.identify.counts import count_quantum
from tests.model.identgen import Q, make, table
from tests.shared_data import SHARED_DATA

REAL = SHARED_DATA / "real-motors"


def _write(path: Path, t, u, omega, theta, header: dict[str, str]) -> Path:
    """A run log as the real logs' converter writes one: t to the microsecond, every other
    column to 6 significant digits."""
    lines = [f"# {k}: {v}" for k, v in header.items()] + ["t,u,omega,theta"]
    for row in zip(t, u, omega, theta, strict=True):
        lines.append(f"{row[0]:.6f}," + ",".join(f"{v:.6g}" for v in row[1:]))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("cpr", "header"),
    [(720.0, {}), (12 * 29.861, {})],
    ids=["720 counts, the default", "358.33 counts, no header can say"],
)
def test_T_s_interval_on_one_rise_holds_the_rounding_when_theta_is_written_rounded(
    tmp_path, cpr, header
):
    # tests/model/test_identify_logs32.py's slow wheel (one rise, T = 50 ms at 5 ms, 2-5
    # counts a sample), its angle written as a theta column to 6 significant digits: the
    # values miss the count's grid by up to 5e-6 rad (6e-4 counts), and the grid was looked
    # for to 1e-6 counts only, so the rounding's spread was left out of T's interval, which
    # held T on 27 of 40 logs (with the counts exact: 37)
    T, hits = 0.05, 0
    q = 2.0 * math.pi / cpr
    for seed in range(40):
        g = make(seed, ts=0.005, T_range=(T, T), periods=1, rest_rows=20, K=2.0)
        counts = np.rint(np.cumsum(np.asarray(g.log.omega) * g.ts / Q))
        theta = counts * q
        omega = np.concatenate(([0.0], np.diff(counts) * q / g.ts))
        path = _write(
            tmp_path / f"{seed}.csv",
            g.log.t,
            g.log.u,
            omega,
            theta,
            {"ts": "0.005", **header},
        )
        log = read_run_log(path)
        assert np.max(np.abs(np.asarray(log.extra["theta"]) - theta)) > 1e-6 * q
        fit = identify(table(g.K * q / Q), 5.0, log).step
        assert fit is not None
        hits += fit.T_ci[0] <= T <= fit.T_ci[1]
    assert hits >= 36


def test_the_grid_is_read_off_values_written_to_six_digits():
    rng = np.random.default_rng(7)
    q = 2.0 * math.pi / (12 * 29.861)
    counts = np.cumsum(rng.integers(0, 6, 400))
    theta = np.array([float(f"{v:.6g}") for v in counts * q])
    assert count_quantum(theta, 358) == pytest.approx(q, rel=1e-6)
    assert count_quantum(theta, 720) == pytest.approx(q, rel=1e-6)
    # the same values a third of a count off on one row sit on no grid
    theta[200] += q / 3.0
    assert count_quantum(theta, 358) is None
    # a long log: past 100 rad the 6 digits leave 4 decimals, a gap between two such values is
    # uncertain by 6 % of a count, and the step is counted from the surer small values
    counts = np.cumsum(rng.integers(0, 12, 20000))
    long = np.array([float(f"{v:.6g}") for v in counts * q])
    assert long[-1] > 1000.0
    assert count_quantum(long, 358) == pytest.approx(q, rel=1e-6)


def test_no_grid_where_the_values_sit_on_none_or_too_few_to_tell():
    rng = np.random.default_rng(8)
    q = 2.0 * math.pi / 720
    counts = np.cumsum(rng.integers(0, 6, 400)).astype(float)
    # an angle interpolated between counts onto other instants (the EV3 and UBC logs' angles)
    between = np.interp(np.arange(400) + 0.37, np.arange(400), counts) * q
    assert count_quantum(np.round(between, 6), 720) is None
    # two distinct values written to 3 digits: any grid of their step fits them
    assert count_quantum(np.array([0.0, 0.0, 0.0175, 0.0175]), 720) is None
    # whole counts of the header's count, exact: the grid
    assert count_quantum(counts * q, 720) == q


@pytest.mark.shared_data
@pytest.mark.parametrize(
    ("name", "cpr"),
    [
        ("micromouse-n20-duty100", 12 * 29.861),  # theta = count x 2 pi / 358.33 (convert.py)
        ("micromouse-n20-duty255", 12 * 29.861),
        ("n20-12v-pwm25", 350.0),
        ("n20-12v-pwm255", 350.0),
        ("ev3-large-duty100", None),  # angle interpolated from irregular times onto 5 ms
        ("ev3-large-duty30", None),
        ("ubc-motor-7V", None),  # the same
        ("ubc-motor-9V", None),
        ("rtl-dc-5to15V-brake", None),  # omega integrated, no angle measured
        ("rtl-dc-5to15V-noload", None),
    ],
)
def test_the_real_logs_count_is_the_grid_their_angle_sits_on(name, cpr):
    log = read_run_log(REAL / name / "step.csv")
    q = count_quantum(log.angle()[0], log.cpr)
    if cpr is None:
        assert q is None
    else:
        assert q is not None and 2.0 * math.pi / q == pytest.approx(cpr, abs=0.01)
