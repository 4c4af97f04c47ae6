"""Every sentence of the model check true of the log in hand (issue 17, item 7): hostile but
valid logs from the independent generator (tests/model/physics_gen.py), each read as a lab
assistant reads ``minseg-tui analyze``, and the sentence that was false on it pinned."""

import math
import re
from dataclasses import replace
from functools import cache

import numpy as np
import pytest

from minseg_tui.lab.content.identify_says import fit_why
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.views.check_says import anomaly, caveat, evidence, lead_why
from minseg_tui.lab.views.check_text import text
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.check.figures import lead
from minseg_tui.model.identify import identify
from tests.model import physics_gen as pg
from tests.model.identgen import table
from tests.shared_data import SHARED_DATA


def _motor(delay: float = 0.0, tau_f: float = 0.0) -> pg.Motor:
    """An NXT-like motor: K = 15 rad/s/V, T = 80 ms, 5 ohm."""
    R, K, beta, T = 5.0, 15.0, 0.05, 0.08
    k = 1.0 / (K * (1.0 + beta))
    return pg.Motor(
        R=R,
        L=R * T * 0.001,
        k=k,
        J=T * k * k * (1.0 + beta) / R,
        b=beta * k * k / R,
        tau_f=tau_f,
        delay=delay,
    )


def _log(
    m: pg.Motor,
    at: list[float],
    vals: list[float],
    t_end: float,
    ts: float = 0.01,
    cpr: int = 720,
    stall: tuple[int, float] | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(t s, u V, omega rad/s): late-only jitter of 0.3 ms, Euler speed of counts over ts;
    ``stall`` (row, gap s): the logger stalls before that row, whose counts are read 0.8 of
    the gap before its timestamp."""
    rng = np.random.default_rng(1)
    n = int(t_end / ts)
    t = np.arange(n) * ts + rng.uniform(0.0, 3e-4, n)
    t_count = t.copy()
    if stall is not None:
        r0, gap = stall
        t[r0:] += gap
        t_count[r0:] += gap
        t_count[r0] -= 0.8 * gap
    grid, _, th = pg.simulate(
        m, float(t[-1]) + ts, np.array(at), np.array(vals), (math.inf, math.inf, 0.0)
    )
    counts = np.floor(np.interp(t_count, grid, th) * cpr / (2 * math.pi) + 0.37)
    omega = np.concatenate(([0.0], np.diff(counts) * 2 * math.pi / cpr / ts))
    idx = np.searchsorted(np.array(at), t, side="right") - 1
    u = np.where(idx >= 0, np.array(vals)[np.maximum(idx, 0)], 0.0)
    return t, u, omega


def test_reversals_are_not_said_to_be_one_driven_level_without_a_step_down():
    # +-12 V reversals every second: two driven levels (+12 V and -12 V) and a step down at
    # every reversal; dry friction is not tried on it (one size of voltage), but the reason
    # said must be true of the log: it said "the log has one driven level and no step-down"
    at = [0.5 + k for k in range(5)]
    vals = [12.0 if k % 2 == 0 else -12.0 for k in range(5)]
    t, u, omega = _log(_motor(), at, vals, 5.8)
    r = check(t, u, omega, ts=0.01, cpr=720)
    words = text(r)
    assert "one driven level" not in words
    judged = {c.cause: caveat(c) for c in r.finding.caveats if c.kind == "cannot_judge"}
    if "coulomb_friction" in judged:
        assert "one size of voltage only (12 V, forward and reversed)" in judged["coulomb_friction"]


@cache
def _steps_check() -> CheckResult:
    """The check of a 0/4 V square wave with a 60 ms dead time (named dead_time)."""
    at = [0.5, 1.5, 2.5, 3.5, 4.5]
    vals = [4.0, 0.0, 4.0, 0.0, 4.0]
    t, u, omega = _log(_motor(delay=0.06), at, vals, 5.2)
    return check(t, u, omega, ts=0.01, cpr=720)


def test_an_interval_over_a_factor_of_ten_and_a_t_on_its_bound_are_not_printed_as_numbers():
    # the log: glitch rows pulled T to its 2 ms bound, printed with the interval
    # '95 %: 2e-7-20 s'; and a filter's T printed as '95 %: 2.76e-24-2.62e+22'. The words of
    # such a fit (the same result with those numbers put in) say what is true instead
    r = _steps_check()
    assert r.finding.cause == "dead_time"
    base = replace(
        r.baseline,
        params={**r.baseline.params, "T": 0.002},
        intervals={**r.baseline.intervals, "T": (2e-7, 20.0)},
    )
    lo = r.extended.params["delay"] / 30.0
    ext = replace(
        r.extended, intervals={**r.extended.intervals, "delay": (lo, 3e3 * lo), "T": (0, 0.2)}
    )
    words = text(replace(r, baseline=base, extended=ext))
    baseline = next(s for s in words.splitlines() if s.startswith("Baseline"))
    extended = next(s for s in words.splitlines() if s.startswith("Extended model"))
    assert "T = 2.000 ms (on the lower end of the range the fit tries, 0.002000-3.000 s" in baseline
    assert "2e-07" not in baseline and "2.00e-07" not in baseline
    assert "delay = " in extended and extended.count("not determined by this log") == 2
    # a determined interval still reads as numbers, with its unit as on the screens
    assert re.search(r"K = [\d.]+ rad/s/V \(95 %: [\d.]+ – [\d.]+ rad/s/V\)", extended)


def test_a_moving_average_of_one_length_only_is_not_said_to_be_undetermined():
    # rtl-dc-5to15V: 'taps = 23.00 samples (95 %: not determined: the interval has no width)'
    # where the width 0 meant that no length but 23 fits as well: the length is determined
    r = _steps_check()
    fx = replace(
        r.extended,
        model="first_order+velocity_filter",
        params={"T": 0.08, "K": 15.0, "taps": 23.0},
        intervals={"T": (0.07, 0.09), "K": (14.9, 15.1), "taps": (23.0, 23.0)},
    )
    words = text(replace(r, extended=fx))
    assert "taps = 23 samples (95 %: 23 only: no other length fits as well)" in words
    assert "no width" not in words


@cache
def _seed11() -> tuple[pg.PhysLog, CheckResult]:
    lg = pg.make(11, ("velocity_filter", "coast_on_zero"), artefacts=False)
    return lg, check(lg.t, lg.u, lg.omega, ts=lg.ts, cpr=lg.cpr)


def test_a_coast_that_never_falls_to_half_is_not_said_to():
    # independent generator, seed 11: a 5-tap average with coasting (T_coast 0.96 s) at 10 ms;
    # after the drop at 10.41 s the wheel coasts from 68 rad/s and is driven again 0.42 s
    # later at 45 rad/s, never under half. The evidence said "a line through the speed from
    # the row before the drop to the first reading under half, 390 ms after the drop"
    lg, r = _seed11()
    assert r.finding.cause == "coast_on_zero"
    m = re.search(r"drops to 0 at t = ([\d.]+) s", evidence(r.finding))
    assert m
    a = int(np.searchsorted(lg.t, float(m.group(1)) - 1e-6))
    nxt = a + int(np.flatnonzero(lg.u[a:] != 0)[0])
    w0 = float(np.mean(lg.omega[a - 10 : a]))
    assert np.all(np.abs(lg.omega[a:nxt]) > 0.5 * w0)  # the log: never under half
    assert "first reading under half" not in evidence(r.finding)
    assert f"staying above half of its {w0:.3g} rad/s" in evidence(r.finding)


def test_the_noise_floor_of_an_averaged_speed_says_it_is_not_the_counts_floor():
    # the same log: 'Log: ... a noise floor of 0.713 rad/s' (one count per sample), then the
    # gain's details 'noise floor 0.143 rad/s' without a word: the floor of the 5-sample average
    _, r = _seed11()
    assert "velocity_filter" in {o.cause for o in r.finding.others}
    words = text(r)
    counts = r.sampling.floor
    assert f"a noise floor of {counts:.3g} rad/s" in words
    assert (
        f"noise floor {r.gain.noise_floor:.3g} rad/s (the counts' {counts:.3g} rad/s over the "
        "5-sample average)" in words
    )


def test_a_scatter_the_simulation_follows_is_not_called_noise_no_model_explains():
    # independent generator, seed 32 (dead time, a hand, 25 ms with up to 2.5 ms of late
    # jitter, the speed over the nominal period): the rows' late times scatter the speed by
    # 0.8 rad/s, which the simulation at the log's own times reproduces (the extended model's
    # rms error is 0.099 rad/s); it said "timing jitter, ripple or resampling add noise no
    # model of the motor explains"
    lg = pg.make(32, ("dead_time",), touch=True, artefacts=False)
    r = check(lg.t, lg.u, lg.omega, ts=lg.ts, cpr=lg.cpr)
    noise = [caveat(c) for c in r.finding.caveats if c.kind == "noise"]
    assert r.extended.rmse < 0.2 * r.gain.noise
    assert noise and "no model of the motor explains" not in noise[0]
    assert f"follows it to {r.extended.rmse:.3g} rad/s rms" in noise[0]


@pytest.mark.shared_data
@pytest.mark.parametrize("name", ["ubc-motor-7V", "ev3-large-duty30"])
def test_identify_does_not_speak_of_falling_edges_a_log_has_not(name):
    # one step up from rest, no step down: identify said "one first-order model fits the
    # whole log as well as the steps fitted one by one do (...), so every edge, rising and
    # falling, is used"
    log = read_run_log(SHARED_DATA / "real-motors" / name / "step.csv")
    r = identify(table(72.0), 5.3, log)
    assert r.step is not None
    why = fit_why(r.step.fit.why)
    assert "fits the whole log as well as the rise fitted alone does" in why
    assert "rising and falling" not in why and "one by one" not in why
    assert "the log has 1 rising edge and no falling one" in why


def test_a_held_out_error_that_gets_worse_is_said_to():
    # the issue: 'Gain: error on held-out steps 1.16 -> 1.29 rad/s (leads because the models
    # predict steps they were not fitted on: the honest judge of a gain)', without a word
    # that the named cause made the prediction of the held-out steps worse
    r = _steps_check()
    assert r.lead is not None and r.lead.figure == "heldout_extended_rmse"
    assert "worse" not in lead_why(r.lead)  # 60 ms dead time: held out, the delay predicts better
    worse = replace(r.gain, heldout_baseline_rmse=1.16, heldout_extended_rmse=1.29)
    why = lead_why(lead(worse, True))
    assert "here the extended model predicts them worse (1.16 -> 1.29 rad/s)" in why


def test_a_stall_spike_left_out_is_left_out_of_every_figure():
    # a 0/4 V square wave whose logger stalls 60 ms at 5 s, in a driven stretch, reading the
    # counts of the row after the gap 48 ms before its timestamp: rows 500 and 501 read
    # -287 and +287 rad/s off the model. It said "row 500 ... left out of the fit" while
    # the headline's rmse and fit were "over all 720 rows" (the two rows repaired with the
    # model's values) and the regions under it counted 718
    at = [0.5, 1.5, 2.5, 3.5, 4.5, 5.5, 6.5]
    vals = [4.0, 0.0, 4.0, 0.0, 4.0, 0.0, 4.0]
    t, u, omega = _log(_motor(), at, vals, 7.2, stall=(500, 0.06))
    r = check(t, u, omega, ts=0.01, cpr=720)
    words = text(r)
    art = [a for a in r.anomalies if a.kind == "logging_artefact"]
    assert art and art[0].row == 500 and "rows 500-501 left out of the fit" in anomaly(art[0])
    assert "hand" not in words
    assert r.baseline.rows == 718 == sum(d.rows for d in r.deviations)
    assert "over the 718 of 720 rows the fit used (2 left out, see the anomalies)" in words


def test_times_under_a_second_are_in_ms_in_the_parameters_as_in_the_evidence():
    # n20-12v-pwm25 read 'T = 0.08836 s', 'T_coast = 0.2468 s' on the model's line, and
    # 'a braked motor (T = 88 ms)', 'a time constant of 0.247 s' in the evidence: the same
    # quantities in s in one place and ms in the next; now ms wherever under a second
    _, r = _seed11()
    words = text(r)
    ext = next(s for s in words.splitlines() if s.startswith("Extended model"))
    T, tc = r.extended.params["T"], r.extended.params["T_coast"]
    assert tc < 1.0
    assert f"T = {1e3 * T:.4g} ms" in ext and f"T_coast = {1e3 * tc:.4g} ms" in ext
    assert f"(T = {1e3 * T:.0f} ms)" in evidence(r.finding)
    assert f"a time constant of {1e3 * tc:.0f} ms at zero command" in evidence(r.finding)
    assert not re.search(r"\b0\.\d+ s\b", ext)
