"""identify on the real logs and the generators, stop 31 (issue 17, items 3, 5 and 7): each test
pins a figure or sentence that plots of the data, the fitted model and its residuals showed
false or misleading on that log."""

import math

import numpy as np
import pytest

from minseg_tui.cli.identify import render
from minseg_tui.lab.content.identify_says import as_json, sentence
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.model.identify import Reading, identify
from minseg_tui.model.runlog import RunLog
from tests.model import physics_gen as pg
from tests.model.identgen import make, table
from tests.shared_data import SHARED_DATA

REAL = SHARED_DATA / "real-motors"


def _onset_63(t: np.ndarray, w: np.ndarray, ts: float) -> float:
    """A careful 63 % reading of a log's one rise from rest: from the last row at rest (the
    Euler speed still 0) to the interpolated 63 % crossing of the settled speed (the median
    of the last half), half a sample taken off for the Euler speed's lag (s)."""
    final = float(np.median(w[w.size // 2 :]))
    still = int(np.flatnonzero(w > 0.02 * final)[0]) - 1
    k = int(np.flatnonzero(w >= (1 - math.exp(-1)) * final)[0])
    frac = (w[k] - (1 - math.exp(-1)) * final) / (w[k] - w[k - 1])
    return float(t[k] - frac * (t[k] - t[k - 1]) - 0.5 * ts - t[still])


@pytest.mark.shared_data
def test_the_interval_of_T_holds_the_rise_where_the_tail_pulls_T():
    # micromouse-n20-duty255: after its rise (about 40 ms from the wheel's start) the speed
    # creeps 66.6 -> 70 rad/s for seconds. Fitted to every row, T is 68.4 ms with a 95 %
    # interval of 57.7-79.1 ms; fitted to the rows up to 4 T after the edge it is 39.0 ms
    # (and 34.9 ms on the log cut at 1.3 s). The interval rested on the residuals' noise
    # alone and left out the careful 63 % readings from the wheel's start (37-46 ms) and
    # identify's own reading from the dead time's end (56.8 ms)
    log = read_run_log(REAL / "micromouse-n20-duty255" / "step.csv")
    r = identify(table(8.8), 5.0, log)
    s = r.step
    assert s is not None and s.dead_time > 0.3 and s.T_63 is not None
    assert s.fit.rise_T is not None and s.fit.rise_ci is not None
    # since s34-rise T and the model follow the rise (the speed creeps on after it); every
    # row's T is the other reading
    assert s.fit.every_row_T is not None
    assert 0.035 < s.fit.rise_T < 0.045 and 0.060 < s.fit.every_row_T < 0.075
    assert s.T == s.fit.rise_T
    # the wheel starts within the sample after its last row at rest: the reading from that
    # row (36.6 ms) is known to within half a sample either way
    careful = _onset_63(np.asarray(log.t), np.asarray(log.omega), log.ts)
    assert careful == pytest.approx(0.0366, abs=0.0005)
    assert s.T_ci[0] <= careful + 0.5 * log.ts and s.T_ci[1] >= careful
    # benchmarks/identify_artefacts.py --real: the 63 % reading from the onset of a 5-row
    # centred mean (45.7 ms) and the angle's area reading (64.6 ms); identify's own reading
    # counted from the dead time's end
    for reading in (0.0457, 0.0646, s.T_63 - s.dead_time):
        assert s.T_ci[0] <= reading <= s.T_ci[1], (reading, s.T_ci)
    assert s.T_ci[0] == pytest.approx(s.fit.rise_ci[0]) and s.T_determined
    assert as_json(r)["step"]["T_rise_rows"] == {"T": s.fit.rise_T, "T_ci": list(s.fit.rise_ci)}
    said = [sentence(o) for o in r.observations if o.code == "T_rows_apart"]
    # (the creep is named with its figures since s33: 67.0 -> 69.3 rad/s after the rise)
    assert len(said) == 1 and "spans both fits" in said[0]
    assert "keeps creeping up, from 67.0 to 69.3 rad/s" in said[0]
    assert "the fit of every row takes a longer T that partly follows the creep" in said[0]
    words = " ".join(render(r).split())
    assert "so T is the fit of the rows up to 4 T after each edge alone, the rise's" in words
    assert "the model uses this T; the interval holds both" in words


def test_a_clean_log_keeps_the_interval_of_every_row():
    # the independent generator's first-order logs (tests/model/identgen.py): the rows of
    # the rises alone give the same T within its noise, so the interval is not widened
    for seed in range(4):
        for periods in (4, 1):
            g = make(seed, ts=0.025, periods=periods, rest_rows=6 if periods == 1 else None)
            r = identify(table(g.K), 5.0, g.log)
            assert r.step is not None and r.step.fit.rise_T is None, (seed, periods)
            assert "T_rows_apart" not in [o.code for o in r.observations]
            assert as_json(r)["step"]["T_rise_rows"] is None


def test_a_speed_spike_after_a_gap_early_in_a_fast_rise_is_a_logging_stall():
    # the generator's seed 0 at 10 ms, one rise: the logger stalls 40 ms just after the step
    # (row 8); the Euler speed over the nominal period puts the gap's counts into one row,
    # 12.2 rad/s between 0.87 and 7.0. The angle is the counts, off by under two counts there
    # (the wheel barely moves yet), so the stall was not named and the spike stayed in the
    # speed the 63 % reading and the plots use
    g = make(0, ts=0.01, stall=True, periods=1, rest_rows=6)
    assert g.stall_row == 8 and g.log.omega[8] > 1.5 * g.log.omega[9] > 0
    r = identify(table(g.K), 5.0, g.log)
    s = r.step
    assert s is not None and g.stall_row in s.fit.left_out and not s.fit.angle_mended
    said = [sentence(o) for o in r.observations if o.code == "logging_stall"]
    assert (
        len(said) == 1 and "a logging stall" in said[0] and "It is left out of the fit." in said[0]
    )
    assert s.T == pytest.approx(g.T, rel=0.01)


def _physics_log(seed: int) -> tuple[pg.PhysLog, RunLog]:
    lg = pg.make(seed, (), artefacts=True)
    meta = {"cpr": str(lg.cpr), "ts": str(lg.ts)}
    return lg, RunLog(t=lg.t - lg.t[0], u=lg.u, omega=lg.omega, metadata=meta)


def test_a_stall_inside_a_rise_of_timed_edge_speeds_is_named_and_mended():
    # the independent generator (tests/model/physics_gen.py), tuning seed 11: 10 ms, speed
    # from timed edges, a 40 ms stall 0.16 s (1.6 T) into a rise at 4.47 s (row 443). The
    # speed at the row is an instant's (31.2 rad/s where the fit's mean over the gap is 32.8),
    # so no spike; but the angle, rebuilt from the speed, carries it across the 50 ms and stays
    # 0.076 rad low for good (7 times the residual's scatter). Not named before
    lg, log = _physics_log(11)
    assert "stall of 40 ms at 4.47 s" in lg.how and "speed by edges" in lg.how
    levels = sorted({abs(float(v)) for v in lg.u if v})[:3]
    r = identify([Reading(v, v, 10.0, 50.0) for v in levels], 5.0, log)
    s = r.step
    assert s is not None and s.fit.angle_mended
    assert lg.artefact_rows[0] - s.glitch_rows in s.fit.left_out
    said = [sentence(o) for o in r.observations if o.code == "logging_stall"]
    assert len(said) == 1 and "stayed off after it" in said[0]
    assert abs(s.T / lg.T - 1) < 0.025


@pytest.mark.shared_data
def test_a_log_whose_loop_times_wander_has_no_logging_stall():
    # the probe ev3_100_irregular_nominaldt (../shared/data/real-motors/probes): the EV3's
    # raw loop times (3.4-9 ms, median 4.4 ms) with each speed over the nominal period, so the
    # speed after a 6.7 or 8.3 ms interval is 1.5-1.9 times too high. No stall: the speed test
    # of a stall asks for two samples or more missed (rows 103 and 131 were called stalls)
    log = read_run_log(REAL / "probes" / "ev3_100_irregular_nominaldt.csv")
    dt = np.diff(np.asarray(log.t))
    assert 1.5 < dt.max() / np.median(dt) < 2.5
    r = identify(table(2.1), 5.0, log)
    assert r.step is not None and r.step.fit.left_out == ()
    assert "logging_stall" not in [o.code for o in r.observations]


@pytest.mark.shared_data
def test_a_fit_moved_early_is_not_said_to_rise_steeper_at_first():
    # n20-12v-pwm255: the wheel moves from the step's next sample slowly at first (5.3, 14.1,
    # 23.0 rad/s: an S-shaped start), while the fit of the rises, pulled by the wandering
    # level after them, moves the response one sample early (-10 ms, its bound). The sentence
    # read the shift's sign as "the rise is steeper at first and slower later than one time
    # constant gives", the opposite of the log: over the first T after the step the measured
    # speed is below the fitted response
    log = read_run_log(REAL / "n20-12v-pwm255" / "step.csv")
    r = identify(table(4.3), 5.0, log)
    s = r.step
    assert s is not None and s.fit.shift_on_bound and s.fit.shift < 0
    t, w = np.asarray(log.t), np.asarray(log.omega)
    model = np.full(t.size, np.nan)
    model[1:] = np.diff(s.fit.predicted) / np.diff(t)
    k = s.rises[0].row
    first = np.flatnonzero((t > t[k]) & (t <= t[k] + s.T))
    assert np.mean(w[first]) < np.mean(model[first]) - 0.02 * s.omega_ss
    said = [sentence(o) for o in r.observations if o.code == "shift_on_bound"]
    assert len(said) == 1 and "steeper at first" not in said[0]
    assert "starts before the wheel does and then rises more slowly than the wheel" in said[0]
