"""identify on the real logs, stop 34 (issue 17): each test pins a sentence that the plotted
log showed false, and fails before its fix."""

import numpy as np
import pytest

from minseg_tui.cli.identify import render
from minseg_tui.lab.content.identify_says import sentence
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.model.identify import identify
from tests.model.identgen import table
from tests.shared_data import SHARED_DATA

REAL = SHARED_DATA / "real-motors"


@pytest.mark.shared_data
def test_the_wheel_s_first_move_is_said_where_the_log_shows_it():
    # n20-12v-pwm25 (plotted): the step is at 0.622 s and the counts of the rows after it are
    # 1, 0, 1, 2, 1, 3: the first count comes in the row at 0.632 s, one sample (10 ms) after
    # the step, within the sampling's lateness. The onset the fit is bounded by is read off a
    # 3-row running median of the speed, which first leaves 0 at 0.642 s (the median of 1, 0,
    # 1). identify said "the wheel answers later than the sampling's lateness explains", "The
    # wheel first moves 20.00 ms after the steps" and "up to where the wheel is first seen to
    # move (20.00 ms after the steps)": none of them true of the log. The fit is unchanged
    log = read_run_log(REAL / "n20-12v-pwm25" / "step.csv")
    t, w = np.asarray(log.t), np.asarray(log.omega)
    step = int(np.flatnonzero(np.asarray(log.u) > 0)[0])
    moved = step + int(np.flatnonzero(w[step:] > 0)[0])
    assert t[step] == pytest.approx(0.622) and t[moved] - t[step] == pytest.approx(0.010)
    r = identify(table(7.9), 5.0, log)
    s = r.step
    assert s is not None and s.fit.shift_on_bound and s.fit.free_T is not None
    assert s.T == pytest.approx(0.08929, abs=5e-6)
    assert s.T_ci == pytest.approx((0.05197, 0.17519), abs=5e-6)
    said = [sentence(o) for o in r.observations if o.code == "shift_on_bound"]
    assert len(said) == 1
    words = said[0]
    assert "the wheel answers later than the sampling's lateness explains" not in words
    assert "The wheel first moves 20.00 ms" not in words
    assert "first seen to move (20.00 ms" not in words
    assert (
        "the first-order response fits best starting later than that, although the wheel "
        "is first seen to move 10.00 ms after the steps, within the sampling's lateness: there "
        "is no dead time to fit. One count per sample is 1.80 rad/s, 19 % of the rise" in words
    )
    assert (
        "With the shift free up to where the speed, a running median over 3 rows, first leaves "
        "its level (20.00 ms after the steps), the fit starts the response +20.0 ms" in words
    )
    assert words in " ".join(render(r).split())


@pytest.mark.shared_data
def test_where_the_first_move_and_the_smoothed_onset_agree_the_words_stay():
    # ev3-large-duty30: the speed is 0 on the rows to 25 ms after the step and its first count
    # comes at 30 ms, where the running median also leaves 0
    log = read_run_log(REAL / "ev3-large-duty30" / "step.csv")
    r = identify(table(1.93), 5.0, log)
    said = [sentence(o) for o in r.observations if o.code == "shift_on_bound"]
    assert len(said) == 1
    assert said[0].startswith(
        "The time shift of the steps against the samples ended on its bound of one sample "
        "period (+5.00 ms): the wheel answers later than the sampling's lateness explains."
    )
    assert "up to where the wheel is first seen to move (30.00 ms after the steps)" in said[0]


@pytest.mark.shared_data
def test_the_rows_after_the_falling_edge_are_said_to_make_t_s_rows_apart():
    # n20-12v-pwm25 (plotted): after the power is cut at 16.454 s the speed runs down 5, 4, 3,
    # 2, 1 counts a sample in near-equal stairs and stands from 16.726 s, 0.27 s: slower than
    # the rise's time constant gives (coasting, or dry friction). The rows up to 4 T after each
    # edge give 156.2 ms, every row 89.29 ms, and the rows after the rising edge alone 91.75
    # ms: the falling edge's rows make the difference. identify said "the later rows, long
    # after the rise, pull T shorter: the rise and the speed after it do not follow one time
    # constant", which puts it on the rise and the speed after it
    log = read_run_log(REAL / "n20-12v-pwm25" / "step.csv")
    r = identify(table(7.9), 5.0, log)
    s = r.step
    assert s is not None and s.fit.rise_T is not None and s.fit.rise_up_T is not None
    assert s.fit.rise_T == pytest.approx(0.1562, abs=5e-5)
    assert s.fit.rise_up_T == pytest.approx(0.09175, abs=5e-5)
    # the run-down, against an exponential of the rise's own T from the steady speed
    t, w, u = np.asarray(log.t), np.asarray(log.omega), np.asarray(log.u)
    off = int(np.flatnonzero(np.diff(u) < 0)[0]) + 1
    since = t - t[off]
    stop = off + int(np.flatnonzero(w[off:] == 0)[0])
    assert since[stop] == pytest.approx(0.272, abs=0.001)
    mid = (since > 0.08) & (since < 0.14)
    exp_model = 9.29 * np.exp(-since[mid] / s.fit.rise_up_T)
    assert float(np.mean(w[mid])) > 1.4 * float(np.mean(exp_model))
    said = [sentence(o) for o in r.observations if o.code == "T_rows_apart"]
    assert len(said) == 1
    assert "the later rows, long after the rise, pull T shorter" not in said[0]
    assert (
        "the rows up to 4 T after each edge, rising and falling, alone give 156.2 ms (95 % "
        "137.3 – 175.2 ms), all the rows the fit uses 89.29 ms and the rows after the rising "
        "edges alone 91.75 ms: the rows after the falling edges make the difference. There the "
        "wheel slows down more slowly than one time constant of its rise gives" in said[0]
    )
    assert said[0] in " ".join(render(r).split())
