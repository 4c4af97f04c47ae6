"""Sentences of the model check judged against the log in hand (issue 17, item 7; the
verdicts are in the s29-logs note). Each test pins one sentence that plots of the data, the
first-order and extended predictions and the residuals showed false or misleading."""

import re
from functools import cache

import numpy as np
import pytest

from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.views.check_says import runner_up_why
from minseg_tui.lab.views.check_text import text
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.check.guess import first_motion
from tests.model.physics_gen import PhysLog, make
from tests.shared_data import SHARED_DATA

SEED_17 = pytest.mark.xdist_group("logs29-seed-17")
"""The two tests of tuning seed 17's log, on one xdist worker so that it is checked once."""


@cache
def seed_17() -> tuple[PhysLog, CheckResult]:
    """The independent generator's tuning seed 17 and its check, made once per test process
    (the generator is seeded and the check deterministic: the second test would compute the
    same log and the same result, 2.2 s CPU)."""
    g = make(17, ("velocity_filter",), artefacts=True)
    return g, check(g.t, g.u, g.omega, ts=g.ts, cpr=g.cpr)


@SEED_17
def test_a_delay_is_not_called_pure_when_the_speed_moves_before_it_ends():
    # the independent generator's tuning seed 17: a 22-tap moving average of the speed (25 ms
    # rows), a stall and a switch-on glitch. Most steps come while the speed still moves from
    # the step before; there the speed "first moves 0 ms later", and the check said so, then
    # "a first-order response that starts 86 ms after the command fits (a pure delay; ...)".
    # A speed still falling at a step says nothing of when the step acts, and a speed that
    # moves before the fitted delay ends has a slow start, not a late one.
    g, r = seed_17()
    words = text(r)
    assert "first moves 0 ms later" not in words
    for lag, d in re.findall(
        r"first moves ([\d.]+) ms later: a first-order response that starts ([\d.]+) ms", words
    ):
        if float(lag) < float(d) - 0.5 * g.ts * 1e3:
            assert "slow rather than late" in words, words
            assert "(a pure delay;" not in words and "(a pure delay:" not in words
    # the steps the speed was settled before keep their reading: the first, from rest, at
    # 74 ms (the average's first 5 % of the change); the ones from a moving speed are left out
    all_lags = first_motion(g.t, g.u, g.omega, 0.3)
    settled = first_motion(g.t, g.u, g.omega, 0.3, settled=True)
    assert all_lags.count(0.0) >= 5 and 0.0 not in settled
    assert np.isclose(settled[0], all_lags[0]) and len(settled) < len(all_lags)


def test_a_runner_up_does_not_lose_on_an_rmse_that_prints_the_same():
    # the independent generator's tuning seed 15: a second pole on the inductance (25 ms rows,
    # a stall, glitch rows). The runner-up (a pole with an averaged speed) was said to lose
    # because "its simulated speed misses the measured speed by more (rmse 1.8 rad/s against
    # 1.8 rad/s)": 1.804 against 1.803, no reason at all; its other reason (the scatter an
    # average of counts cannot leave) now stands alone
    g = make(15, ("second_pole",), artefacts=True)
    r = check(g.t, g.u, g.omega, ts=g.ts, cpr=g.cpr)
    why = runner_up_why(r.finding)
    assert why
    for a, b in re.findall(r"rmse ([\d.]+) rad/s against ([\d.]+) rad/s", why):
        assert a != b and float(a) > 1.01 * float(b), why
    assert "far more than an average of counts" in why


@pytest.mark.shared_data
def test_a_one_count_creep_after_a_rise_is_not_a_hand():
    # micromouse-n20-duty100 (../shared/data/real-motors; 3.51 rad/s a count): after its rise
    # the speed sits one count low (38.6 rad/s) and creeps to 42 rad/s over a second or two,
    # a slow process the first-order model lacks. Through s29-hands' running median of 9 rows
    # the one-count step (3.45 rad/s) read as "something other than the input moved the
    # wheel (a hand on it, a snag)", and 187 rows were left out of the fit
    log = read_run_log(SHARED_DATA / "real-motors" / "micromouse-n20-duty100" / "step.csv")
    r = check(log.t, log.u, log.omega, ts=0.005, cpr=log.declared_cpr, omega_over=log.omega_over)
    assert not [a for a in r.anomalies if a.kind == "disturbance"], text(r)
    assert r.extended.rows == 770 and "a hand on it" not in text(r)


@SEED_17
def test_a_stalls_spike_spread_by_an_average_chosen_late_is_a_logging_artefact():
    # tuning seed 17 again (a 22-tap average, a stall of 75 ms at 7.35 s): the first pass
    # names a delay and a pole (no average, so no rows are left out after the gap), and the
    # average is chosen only on the pass that relaxes its noise test. The stall's late read,
    # a one-row spike of 7.8 rad/s, then stood in the average for 22 rows (7.38-7.90 s) with
    # no word and in the fit (T 0.0906 s, true 0.0824), and "the speed departs ... after 5
    # rising edges" was the first pass's model's miss (4-6 rad/s), not the average's (0.1)
    g, r = seed_17()
    gap = next(k for k in range(1, g.t.size) if g.t[k] - g.t[k - 1] > 1.5 * g.ts)
    left = [a for a in r.anomalies if a.kind in ("gap_rows_left_out", "logging_artefact")]
    assert left and left[0].row == gap and (left[0].row_end or 0) >= gap + 22, text(r)
    assert not [a for a in r.anomalies if a.kind in ("disturbance", "model_miss")], text(r)
    assert "a hand on it" not in text(r)
    assert r.finding.cause == "velocity_filter" and not r.finding.others
    assert abs(r.extended.params["T"] - g.T) <= 0.03 * g.T
