"""identify on the real logs, stop 32 (issue 17, items 3, 5 and 7): each test pins a figure or
sentence that plots of the data, the fitted model and its residuals showed false or
misleading on that log, and fails before its fix."""

import math

import numpy as np
import pytest

from minseg_tui.cli.identify import render
from minseg_tui.lab.content.identify_says import as_json, sentence
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.model.identify import identify
from minseg_tui.model.identify.risefit import fit_time_constant
from minseg_tui.model.runlog import RunLog
from tests.model.identgen import make, table
from tests.shared_data import SHARED_DATA

REAL = SHARED_DATA / "real-motors"


@pytest.mark.shared_data
def test_a_wheel_that_stands_after_the_step_gets_its_dead_time_though_a_tail_hides_it():
    # micromouse-n20-duty100: the logged step is at 0.460 s; the speed is 0 on every row to
    # 0.495 s and its first count comes at 0.500 s (the firmware polls the mode, so the PWM
    # starts late). The angle's first counts (1, 3, 5, 8 at 0.500-0.520 s) lie on a rise that
    # starts at 0.489-0.491 s. After the rise the speed creeps on for seconds, and that tail
    # held identify's fit of every row at a time shift of -5 ms (its bound, before the step)
    # with T = 177.5 ms and no dead time, while the model check found a dead time (18 ms)
    log = read_run_log(REAL / "micromouse-n20-duty100" / "step.csv")
    t, w = np.asarray(log.t), np.asarray(log.omega)
    step = int(np.flatnonzero(np.asarray(log.u) > 0)[0])
    first = int(np.flatnonzero(w > 0)[0])
    assert t[step] == pytest.approx(0.460) and t[first] == pytest.approx(0.500)
    r = identify(table(13.5), 5.0, log)
    s = r.step
    assert s is not None
    assert 0.025 < s.dead_time < 0.035 and s.fit.dead_time_from_rise
    assert not s.fit.shift_on_bound and s.fit.shift == pytest.approx(s.dead_time)
    # the rise's own T from its start (the rows up to 4 T after it), 105-110 ms: a careful
    # 63 % reading from 0.490 s (26.0 rad/s of 41.2 at 0.602 s less half a sample) is 110 ms
    assert s.fit.rise_T is not None and 0.100 < s.fit.rise_T < 0.115
    assert s.T_ci[0] <= 0.110 <= s.T_ci[1]
    said = [sentence(o) for o in r.observations if o.code == "dead_time"]
    assert len(said) == 1 and "The rows of the rise alone show it" in said[0]
    assert "starting before the wheel moves" in said[0]
    assert "shift_on_bound" not in [o.code for o in r.observations]
    words = " ".join(render(r).split())
    assert "u_A(t - 0.0" in words and "earlier than the steps" not in words
    assert math.isclose(as_json(r)["step"]["dead_time"], s.dead_time)


@pytest.mark.parametrize("seed", [1, 3])
def test_switch_on_glitches_after_a_zeroed_first_row_are_named_and_left_out(seed):
    # a log whose speed is the Euler difference of counts has no speed at row 0 and writes 0
    # there; a logger whose counter is not yet settled then writes one or two rows far above
    # any speed the wheel reaches, the wheel at rest. The run of glitches was looked for from
    # row 0 only, so the zeroed row hid them: not named, and kept in the speed before the step
    # that the 63 % reading starts from (tests/model/identgen.py, one rise after 6 rows of rest)
    g = make(seed, ts=0.025, periods=1, rest_rows=6)
    w = np.asarray(g.log.omega, dtype=float).copy()
    assert w[0] == 0.0 and not np.any(w[:6])
    top = float(np.max(w))
    w[1], w[2] = 1.6 * top, 1.3 * top
    log = RunLog(t=g.log.t, u=g.log.u, omega=w, extra=g.log.extra, source="zeroed first row")
    r = identify(table(g.K), 5.0, log)
    s = r.step
    assert s is not None and s.glitch_rows == 3
    said = [sentence(o) for o in r.observations if o.code == "glitch_rows"]
    assert len(said) == 1
    assert said[0].startswith("Row 1 reads 0 rad/s, as the first row of a speed taken from counts")
    assert "(rows 2-3) read" in said[0] and "switch-on glitches of the logging" in said[0]
    assert "the fit starts at row 4" in said[0]
    assert s.rises[0].omega0 == 0.0
    assert abs(s.T / g.T - 1) < 0.02


@pytest.mark.shared_data
def test_the_rise_s_T_and_every_row_s_T_are_told_apart_by_what_the_log_does():
    # micromouse-n20-duty100 (plotted: data, the model of every row, T 152.6 ms, and of the
    # rise's rows, 107.3 ms): the rise's rows follow 107-111 ms within 0.1 rad/s; after them
    # the speed creeps on, 39.0 -> 41.4 rad/s over the next 3 s, and the fit of every row,
    # which the model of Task 14 uses, stretches T to 152.6 ms and rises up to 3.8 rad/s
    # (a 5-row mean) behind the wheel. identify said only "the later rows, long after the
    # rise, pull T longer", without which T the rise follows or what the model uses
    log = read_run_log(REAL / "micromouse-n20-duty100" / "step.csv")
    r = identify(table(13.5), 5.0, log)
    s = r.step
    assert s is not None and s.fit.rise_T is not None
    said = [sentence(o) for o in r.observations if o.code == "T_rows_apart"]
    assert len(said) == 1
    assert "After the rise the speed keeps creeping up, from 39.0 to 41.4 rad/s" in said[0]
    assert "its model rises more slowly than the wheel, by up to 3.8 rad/s on the rise" in said[0]
    # since s34-rise the model follows the rise (tests/model/test_identify_rise.py)
    assert "the model (Task 14) follow the rise: T = 107.3 ms" in said[0]
    assert "152.6 ms, the T of every row, is the other reading" in said[0]
    # the figures, from the log itself: the speed over the first and the last 0.3 s after the
    # rise's 4 T (the wheel answers 28.6 ms after the step at 0.460 s)
    t, w = np.asarray(log.t), np.asarray(log.omega)
    after = t > 0.460 + s.dead_time + 4 * s.fit.rise_T
    early = after & (t < t[after][0] + 0.29)
    late = t > t[-1] - 0.29
    assert float(np.mean(w[early])) == pytest.approx(39.0, abs=0.15)
    assert float(np.mean(w[late])) == pytest.approx(41.4, abs=0.15)
    # the model of every row behind the wheel on the rise, the rise's model not
    every = fit_time_constant(log)
    assert every is not None and every.T == s.fit.every_row_T
    rise = (t[1:] > 0.489) & (t[1:] < 0.489 + 4 * s.fit.rise_T)
    model = np.diff(every.predicted) / np.diff(t)
    assert float(np.mean((w[1:] - model)[rise])) > 1.0
    model = np.diff(s.fit.predicted) / np.diff(t)
    assert abs(float(np.mean((w[1:] - model)[rise]))) < 0.3


@pytest.mark.shared_data
def test_T_s_interval_holds_the_start_the_counts_cannot_pin():
    # ev3-large-duty30: a 1-degree encoder at 4.6 rad/s; the speed is 0 on the rows to 25 ms
    # after the step and the first count comes by 30 ms, as a first-order rise starting 5-6
    # ms after the step gives (one count takes 21 ms from the start at T = 56 ms). The angle
    # fixes T plus the start (the line through the last 40 % of the angle lies 61.7 ms of the
    # final speed below the angle at the step), not each: the fit held the time shift on its
    # bound (+5 ms) and gave T's interval as 55.77-57.24 ms, as if the start were known; with
    # the shift free up to where the wheel is seen to move, the same rows give 55.78 ms at +5.97
    # ms, +- 2.3 ms. (The benchmark's area reading, 46.7 ms, counts from an onset at 15 ms that
    # the smoothed counts put late; from the fitted start it is 61.7 - 6.0 = 55.7 ms.)
    log = read_run_log(REAL / "ev3-large-duty30" / "step.csv")
    r = identify(table(1.93), 5.0, log)
    s = r.step
    assert s is not None and s.fit.shift_on_bound and s.dead_time == 0
    assert s.fit.free_T is not None and s.fit.free_ci is not None and s.fit.free_shift is not None
    assert s.fit.shift < s.fit.free_shift <= s.fit.onset
    assert s.T_ci[0] <= s.fit.free_ci[0] < 0.0545 and s.T_ci[1] >= s.fit.free_ci[1]
    t, theta = np.asarray(log.t), log.angle()[0]
    late = t >= 0.6 * t[-1]
    slope, cut = np.polyfit(t[late], theta[late], 1)
    T_plus_start = float(-cut / slope)  # the angle at the step is 0
    assert T_plus_start == pytest.approx(0.0617, abs=0.0005)
    assert s.T_ci[0] <= T_plus_start - s.fit.free_shift <= s.T_ci[1]
    said = [sentence(o) for o in r.observations if o.code == "shift_on_bound"]
    assert len(said) == 1 and "With the shift free up to where the wheel is first seen" in said[0]
    assert "so the 95 % interval of T holds both fits" in said[0]
    j = as_json(r)["step"]["T_shift_free"]
    assert j == {"T": s.fit.free_T, "T_ci": list(s.fit.free_ci), "shift": s.fit.free_shift}


def test_T_s_interval_covers_more_often_where_the_start_lies_between_samples():
    # tests/model/identgen.py at 5 ms, one rise of a slow wheel (K = 2 rad/s per V: 2-5 counts
    # a sample), a dead time of 1.2-2 sample periods: past the shift's bound of one period, too
    # short for the wheel to be seen standing. The shift ends on its bound on most logs, and
    # T's interval, computed with the shift held there, held the true T on 4 of 20 logs; with
    # the fit with the shift free held too, 13 of 20. The rest was the encoder's rounding: on
    # one rise the lagged residual estimate cancels (the scores sum to zero), while the
    # rounding of 2-5 counts a sample moves T by twice that; its spread over the phases of the
    # counts' grid is now in the interval (18 of 20)
    hits = 0
    for seed in range(20):
        d = float(np.random.default_rng(1000 + seed).uniform(1.2, 2.0)) * 0.005
        g = make(seed, ts=0.005, T_range=(0.03, 0.08), delay=d, periods=1, rest_rows=20, K=2.0)
        s = identify(table(g.K), 5.0, g.log).step
        assert s is not None
        hits += s.T_ci[0] <= g.T <= s.T_ci[1]
    assert hits >= 18


@pytest.mark.shared_data
def test_T_s_interval_on_one_rise_of_coarse_counts_holds_the_rounding():
    # the same slow wheel with no dead time: the start is known, and T's spread over 40 logs
    # of one rise (T = 50 ms, 2-5 counts a sample) is 0.85 ms, where the interval from the
    # residuals of one rise said 0.44 ms (a standard error) and held T on 67 % of them. The
    # rounding's share now widens it to what the spread is, not beyond: a log of four rises
    # (eight clusters of rows, their own spread in the interval) keeps its interval
    T, hits, se = 0.05, 0, []
    for seed in range(40):
        g = make(seed, ts=0.005, T_range=(T, T), periods=1, rest_rows=20, K=2.0)
        fit = identify(table(g.K), 5.0, g.log).step
        assert fit is not None
        hits += fit.T_ci[0] <= T <= fit.T_ci[1]
        se.append(fit.fit.se)
    assert hits >= 36
    assert 0.6e-3 < float(np.median(se)) < 1.0e-3
    four = identify(table(2.0), 5.0, make(0, ts=0.005, T_range=(T, T), K=2.0).log).step
    assert four is not None and four.fit.dof > 4 and four.fit.se < 0.5e-3


@pytest.mark.shared_data
def test_an_s_shaped_start_does_not_widen_T_for_a_start_the_samples_show():
    # ubc-motor-7V: a dead time was refused because the wheel had come 19 % of the way before
    # it would end; the start is seen, the shape is the misfit. Widening T's interval with the
    # shift free there said "the samples do not pin the start" beside "the wheel already moves
    # before it would end", which contradict each other
    log = read_run_log(REAL / "ubc-motor-7V" / "step.csv")
    r = identify(table(72.0), 5.0, log)
    s = r.step
    assert s is not None and s.fit.shift_on_bound and s.fit.moved_early is not None
    assert s.fit.free_T is None and as_json(r)["step"]["T_shift_free"] is None
    said = " ".join(sentence(o) for o in r.observations)
    assert "the wheel already moves before it would end" in said
    assert "the samples do not pin where" not in said


def test_a_dead_time_found_on_the_rise_s_rows_is_held_no_later_than_they_need():
    # tests/model/identgen.py seed 2 at 5 ms (as above): a dead time of 7.5 ms on 2-5 counts a
    # sample. The rise's own rows find one (11.3 ms), and holding every row's fit to start no
    # earlier than that gave T = 35.1 ms for 38.8 (-9.5 %): on coarse counts a start between
    # samples trades against T, and the rows allow a start as early as 9.2 ms within the 95 %
    # level of their residual. (Before the rise's rows were asked: the shift on its bound, T
    # 42.9 ms, +10.5 %.)
    d = float(np.random.default_rng(1002).uniform(1.2, 2.0)) * 0.005
    g = make(2, ts=0.005, T_range=(0.03, 0.08), delay=d, periods=1, rest_rows=20, K=2.0)
    s = identify(table(g.K), 5.0, g.log).step
    assert s is not None and s.fit.dead_time_from_rise
    assert d < s.dead_time < 0.0105
    assert abs(s.T / g.T - 1) < 0.06
