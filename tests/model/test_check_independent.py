"""The model check on logs of the independent generator (tests/model/physics_gen.py), written
from the physics and not from the check's own simulation: what the check says about the
artefacts of a logger and about a hand on the wheel. Tuning seeds only (the held-out seeds
are for benchmarks/model_check_independent.py's figures).
"""

from dataclasses import dataclass
from functools import cache
from typing import ClassVar

import numpy as np
import pytest

from minseg_tui.lab.content.log_says import refusal_words
from minseg_tui.lab.views.check_says import (
    anomaly,
    as_json,
    caveat,
    caveat_plain,
    evidence,
    reason,
    runner_up_why,
)
from minseg_tui.lab.views.check_text import text
from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.check.decide import Reason
from minseg_tui.model.check.effects import BY_CAUSE
from minseg_tui.model.runlog import LogRefused, SpeedStill
from tests.model.physics_gen import (
    FRESH_SEEDS,
    HELD_OUT_SEEDS,
    TUNING2_SEEDS,
    TUNING3_SEEDS,
    TUNING_SEEDS,
    PhysLog,
    make,
)


@cache
def checked(seed: int, causes: tuple[str, ...], **how: bool) -> tuple[PhysLog, CheckResult]:
    """The generator's log and its check, made once per test process for the logs two tests
    read (each pair in an xdist group, so on one worker): the generator is seeded and the
    check deterministic, so the second test would compute the same log and result."""
    log = make(seed, causes, **how)
    return log, check(log.t, log.u, log.omega)


SEED_21 = pytest.mark.xdist_group("independent-seed-21")
"""Tuning seed 21 with dry friction and a logger's artefacts, read by two tests."""
SEED_1012 = pytest.mark.xdist_group("independent-seed-1012")
"""Touched seed 1012 of an average, read by two tests."""
PAIR_8 = pytest.mark.xdist_group("independent-pair-8")
"""Tuning pair seed 8 (dry friction, a 9-tap average, a stall), read by two tests."""


def named(r):
    return sorted(c for c in [r.finding.cause, *(o.cause for o in r.finding.others)] if c != "none")


def kinds(r):
    return [a.kind for a in r.anomalies]


def test_the_generator_keeps_its_held_out_seeds_apart():
    assert not set(TUNING_SEEDS) & set(HELD_OUT_SEEDS)
    assert not set(TUNING2_SEEDS) & (set(HELD_OUT_SEEDS) | set(FRESH_SEEDS) | set(TUNING_SEEDS))
    others = set(HELD_OUT_SEEDS) | set(FRESH_SEEDS) | set(TUNING_SEEDS) | set(TUNING2_SEEDS)
    assert not set(TUNING3_SEEDS) & others
    a, b = make(7, ("coulomb_friction",)), make(7, ("coulomb_friction",))
    assert np.array_equal(a.omega, b.omega)  # seeded
    assert a.causes["coulomb_friction"] > 0 and a.T > 0


@pytest.mark.parametrize(
    ("seed", "causes"),
    [pytest.param(21, ("coulomb_friction",), marks=SEED_21), (25, ())],
)
def test_a_spike_after_a_stall_of_the_logger_is_an_artefact_not_a_hand(seed, causes):
    log, r = checked(seed, causes, artefacts=True)
    assert "disturbance" not in kinds(r)
    art = [a for a in r.anomalies if a.kind == "logging_artefact"]
    assert len(art) == 1
    # it sits at the stall: the row after the gap, or the row before it the smoothing adds
    stall = log.artefact_rows[0]
    assert art[0].row is not None and stall - 1 <= art[0].row <= stall + 1
    assert "right after a gap of" in anomaly(art[0]) and "not the wheel" in anomaly(art[0])
    # the stall reads the counts late, so the speed column itself jumps: not rows lost whole
    # (a copy of the EV3 or n20 logs with rows dropped, whose column runs on across the gap)
    assert "jumps by" in anomaly(art[0]) and "reads on" not in anomaly(art[0])
    assert not art[0].facts.runs_on
    assert named(r) == sorted(causes)


@SEED_21
def test_switch_on_glitch_rows_are_named_and_left_out_of_every_figure():
    log, r = checked(21, ("coulomb_friction",), artefacts=True)
    glitch = [a for a in r.anomalies if a.kind == "start_glitch"]
    assert len(glitch) == 1 and "starts_moving" not in kinds(r)
    assert glitch[0].row_end is not None and glitch[0].row_end >= max(
        x for x in log.artefact_rows if x < 5
    )
    # the headline covers the rows the fit used, and says so
    assert r.baseline.rows < r.t.size and r.extended.rows == r.baseline.rows
    assert np.all(r.omega == log.omega)  # the speed as logged
    report = text(r)
    assert f"over the {r.baseline.rows} of {r.t.size} rows the fit used" in report
    assert as_json(r)["baseline"]["rows"] == r.baseline.rows
    # over every row (the glitch and the stall's spike in) the error would be twice as large
    err_all = float(np.sqrt(np.mean((r.omega - r.baseline_pred) ** 2)))
    assert r.baseline.rmse < 0.6 * err_all


def test_a_clean_log_figures_cover_every_row():
    log = make(3, (), artefacts=False)
    r = check(log.t, log.u, log.omega)
    assert r.baseline.rows == r.t.size
    assert f"over all {r.t.size} rows" in text(r)


def ringing_log():
    """A motor whose speed rings after every step (an elastic load: speed/input a second-order
    system, natural frequency 25 rad/s, damping 0.25, K 10 rad/s/V), 15 s at 10 ms, 720-count
    Euler speed: no cause of the check models a ringing, so every edge is missed alike."""
    ts, n = 0.01, 1500
    t = np.arange(n) * ts
    u = np.zeros(n)
    levels = [0, 3, 0, 4, 1.5, 0, 3.5, 0, 2.5, 0, 4, 0, 3, 0]
    for i, level in enumerate(levels):
        u[int(i * n / len(levels)) :] = level
    wn, zeta, k_gain, dt = 25.0, 0.25, 10.0, 1e-4
    w = dw = theta = 0.0
    per = int(round(ts / dt))
    angle = []
    for j in range(n * per):
        if j % per == 0:
            angle.append(theta)
        acc = wn * wn * (k_gain * u[j // per] - w) - 2 * zeta * wn * dw
        w, dw, theta = w + dt * dw, dw + dt * acc, theta + dt * w
    counts = np.floor(np.array(angle) * 720 / (2 * np.pi) + 0.3)
    return t, u, np.diff(counts, prepend=counts[0]) * 2 * np.pi / 720 / ts


def test_a_departure_after_every_edge_is_the_models_miss_not_a_hand():
    t, u, y = ringing_log()
    r = check(t, u, y)
    assert "disturbance" not in kinds(r)
    miss = [a for a in r.anomalies if a.kind == "model_miss"]
    assert len(miss) == 1
    rising = int(np.count_nonzero(np.diff(u) > 0))
    assert miss[0].size >= rising  # every rising edge (and the step down to 1.5 V alike)
    assert "edge after edge is what the model misses there, not a hand" in anomaly(miss[0])
    # and the finding says the model misses, instead of naming a cause for it
    assert "misses" in [c.kind for c in r.finding.caveats]


def test_when_a_different_pair_fits_about_as_well_the_check_says_it_cannot_tell():
    # a current cap and a dead time of 12 ms (under a sample at 20 ms): the check names the
    # pair, and says a cap with a pole fits as well, and what would tell them
    log = make(1, ("current_limit", "dead_time"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["current_limit", "dead_time"]
    assert ["current_limit", "second_pole"] in [sorted(a) for a in r.finding.ambiguous_with]
    told = [
        c for c in r.finding.caveats if c.kind == "cannot_tell" and "this log cannot" in caveat(c)
    ]
    assert len(told) == len(r.finding.ambiguous_with)
    pole = next(caveat(c) for c in told if "from current limit + second pole" in caveat(c))
    assert "a faster sampling" in pole and "would" in pole
    assert as_json(r)["finding"]["ambiguous_with"] == r.finding.ambiguous_with
    # the pole named is said to be a pole, not a delay that a pole could replace
    assert "a pure delay" not in text(r)


def test_never_a_pure_delay_when_another_explanation_fits_nearly_as_well():
    # (seed 205's pole on the inductance, named a delay with a rival before the ringing pair,
    # is now named: test_an_inductance_that_makes_the_poles_ring_...)
    log = make(213, ("dead_time",))
    r = check(log.t, log.u, log.omega)
    assert r.finding.cause == "dead_time" and r.finding.ambiguous_with
    assert "a pure delay" not in text(r)
    assert "cannot tell dead time from" in text(r)


def test_an_averaged_speed_leaves_out_the_rows_a_stall_of_the_logger_reaches():
    # an 11-tap average of the speed and a 40 ms stall whose row read the counts late: the
    # average carries the wrong read into the next 11 rows; left out, the fit is exact again
    log = make(503, ("velocity_filter",))
    assert "stall" in log.how
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["velocity_filter"]
    assert abs(r.extended.params["taps"] - 11) <= 1
    assert r.extended.params["T"] == pytest.approx(log.T, rel=0.02)
    left = [a for a in r.anomalies if a.kind == "gap_rows_left_out"]
    assert len(left) == 1 and "were left out of the fit" in anomaly(left[0])
    assert "late_step" not in kinds(r)  # the stall's read is no step that started late
    assert r.baseline.rows < r.t.size


def test_a_pole_on_the_measurement_with_dry_friction_is_named_with_its_friction():
    # dry friction and a compliant coupling to the encoder (T2 52 ms): the pole acts after the
    # friction, so a pole on the drive cannot bend the stops as the encoder shows them; the
    # check fits the pole on the measurement and names the pair, with their parameters
    log = make(0, ("coulomb_friction", "second_pole"))
    assert "pole on the coupling" in log.how
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["coulomb_friction", "second_pole"] and not r.finding.ambiguous_with
    p = r.extended.params
    assert p["T2"] == pytest.approx(log.causes["second_pole"], rel=0.1)
    assert p["u_c"] == pytest.approx(log.causes["coulomb_friction"], rel=0.05)
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert "on the measurement" in text(r) and "fits worse where the wheel stops" in text(r)


def test_a_current_cap_that_brakes_too_is_fitted_so_with_the_friction():
    # a drive that caps the current both ways: after a step down the speed falls along a ramp
    log = make(3, ("coulomb_friction", "current_limit"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["coulomb_friction", "current_limit"] and not r.finding.ambiguous_with
    assert r.extended.params["a_max"] == pytest.approx(log.causes["current_limit"], rel=0.1)
    assert "caps the current both ways" in text(r)


@pytest.mark.parametrize(
    ("seed", "pair"),
    [(2, ("coulomb_friction", "current_limit")), (2, ("current_limit", "dead_time"))],
)
def test_a_capped_ramp_bent_by_viscous_drag_is_fitted_with_its_pair(seed, pair):
    # under the cap the back-EMF no longer brakes but the wheel's viscous drag still does
    # (the generator's b: 9 % of the damping here), so the capped speed bends away from a
    # straight ramp; a straight ramp took u_c 29 % high or named a third cause instead
    log = make(seed, pair)
    r = check(log.t, log.u, log.omega)
    assert named(r) == sorted(pair) and not r.finding.ambiguous_with, (named(r), log.how)
    p = r.extended.params
    assert p["a_max"] == pytest.approx(log.causes["current_limit"], rel=0.1)
    assert p["T"] == pytest.approx(log.T, rel=0.1)
    other = next(c for c in pair if c != "current_limit")
    assert p[BY_CAUSE[other].param] == pytest.approx(log.causes[other], rel=0.1)


def test_the_capped_speed_follows_the_drag_as_the_generator_does():
    # the check's simulation with the drag share T b / J: a cap on a motor with drag levels
    # off at T/drag times the cap's rate; the cap lets go where the torque the drive asks
    # for falls to the cap, not where the speed's own slope does
    from minseg_tui.model.check.simulate import Effects, Stretches, response

    t = np.arange(0.0, 3.0, 0.01)
    u = np.where(t >= 0.1, 1.0, 0.0)
    st = Stretches.from_samples(t, u)
    T, rate, drag = 0.2, 2.0, 0.3
    w = response(st, t, 0.01, T, Effects(rate=rate, drag=drag))
    # the exact solution: capped w' = rate - drag w / T until (u - (1 - drag) w)/T = rate,
    # then T w' = u - w
    tc = T / drag
    w_end = (1.0 - T * rate) / (1.0 - drag)
    t_end = -tc * np.log(1.0 - w_end / (rate * tc))
    fine = np.arange(0.0, 3.0, 1e-4)
    tau = fine - 0.1
    exact = np.where(
        tau < 0,
        0.0,
        np.where(
            tau < t_end,
            rate * tc * (1.0 - np.exp(-tau / tc)),
            1.0 - (1.0 - w_end) * np.exp(-(tau - t_end) / T),
        ),
    )
    angle = np.cumsum(exact) * 1e-4
    seen = (np.interp(t, fine, angle) - np.interp(t - 0.01, fine, angle)) / 0.01
    assert np.allclose(w, seen, atol=2e-3)
    straight = response(st, t, 0.01, T, Effects(rate=rate))
    assert np.max(np.abs(straight - seen)) > 0.1


@pytest.mark.parametrize(
    ("seed", "pair"),
    [(2, ("coulomb_friction", "second_pole")), (2, ("coast_on_zero", "second_pole"))],
)
def test_a_speed_filtered_sample_by_sample_is_fitted_as_that_filter(seed, pair):
    # the logger filters its speed column (y_k = a y_k-1 + (1 - a) m_k, a = exp(-ts/T2) with
    # T2 44 ms at 25 ms samples): a lag of the angle differenced over the sample reads the
    # speed half a sample later for the same T2 and took it 36 % short (28.6-28.8 ms); the
    # column is smooth, so the pole on the measurement is fitted as that filter
    log = make(seed, pair)
    assert "pole on the iir" in log.how
    r = check(log.t, log.u, log.omega)
    assert r.sampling.smooth
    assert named(r) == sorted(pair) and not r.finding.ambiguous_with
    p = r.extended.params
    assert p["T2"] == pytest.approx(log.causes["second_pole"], rel=0.1)
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert "a filter of that column, run sample by sample" in text(r)


def test_the_filter_of_the_speed_column_runs_as_a_logger_runs_it():
    from minseg_tui.model.check.simulate import iir

    x = np.random.default_rng(3).normal(size=700)
    for a in (0.3, 0.9, 0.999):
        y = np.empty_like(x)
        acc = x[0]
        for k, v in enumerate(x):
            acc = a * acc + (1.0 - a) * v
            y[k] = acc
        assert np.allclose(iir(x, a), y, rtol=1e-9, atol=1e-12)


def _right_or_honest(r, log, pair):
    """Both causes named with T within 15 % and each parameter within 25 % (taps within
    one), or the true pair among the explanations the log cannot tell apart."""
    truth = sorted(pair)
    if r.finding.ambiguous_with:
        return truth == named(r) or truth in [sorted(a) for a in r.finding.ambiguous_with]
    p = r.extended.params
    ok = named(r) == truth and abs(p["T"] - log.T) <= 0.15 * log.T
    for cause, value in log.causes.items():
        est = p[BY_CAUSE[cause].param]
        ok = ok and (abs(est - value) <= (1.0 if cause == "velocity_filter" else 0.25 * value))
    return ok


@pytest.mark.parametrize(
    ("seed", "pair", "within"),
    [
        # a third cause far smaller than the pair beside it is not named: a pair never fits the
        # generator's motor exactly, and a third cause takes up part of what it leaves: a cap
        # of 0.2 rad/s effect beside a delay and an average, frictions of 2 and 26 mV beside a
        # coast (under 13 % of what the weaker of the pair moves the speed)
        (0, ("dead_time", "velocity_filter"), {}),
        (8, ("velocity_filter", "coast_on_zero"), {}),
        (7, ("coast_on_zero", "current_limit"), {}),
        # a cap with a delay or an average is fitted from every start in each variant: a cap
        # that brakes too, beside a delay of 15-47 ms or an 8-tap average: the cap that only
        # accelerates is fitted first, and the cap both ways was polished from where that one
        # ended, in another valley (cap + delay 14 and 94 times the residual the true pair
        # leaves); the pole on the measurement or a delay came out in place of the true cause
        (7, ("current_limit", "dead_time"), {"current_limit": 0.05, "dead_time": 0.1}),
        (17, ("current_limit", "dead_time"), {"current_limit": 0.05, "dead_time": 0.1}),
        (12, ("current_limit", "velocity_filter"), {"current_limit": 0.05, "velocity_filter": 0.1}),
    ],
)
def test_a_pair_is_named_without_a_third_cause(seed, pair, within):
    """The pair is named, and nothing beside it. ``within``: each cause's parameter within
    that share of the generator's (rel), the pair then also right or honestly ambiguous
    (:func:`_right_or_honest`)."""
    log = make(seed, pair)
    r = check(log.t, log.u, log.omega)
    assert named(r) == sorted(pair), (named(r), log.how)
    if within:
        assert _right_or_honest(r, log, pair), (r.extended.params, r.finding.ambiguous_with)
    p = r.extended.params
    for cause, rel in within.items():
        assert p[BY_CAUSE[cause].param] == pytest.approx(log.causes[cause], rel=rel)


@pytest.mark.parametrize(
    ("seed", "pair"),
    [
        (2, ("coulomb_friction", "dead_time")),
        (1, ("coast_on_zero", "coulomb_friction")),
        (4, ("current_limit", "dead_time")),
        (3, ("coast_on_zero", "velocity_filter")),
        (1, ("second_pole", "velocity_filter")),
    ],
)
def test_a_pair_hidden_in_independent_data_is_named_or_honestly_ambiguous(seed, pair):
    # tuning seeds of the independent generator: two effects at once, wider ranges than the
    # check was built on, another encoder, another estimator of the speed
    log = make(seed, pair)
    r = check(log.t, log.u, log.omega)
    assert _right_or_honest(r, log, pair), (named(r), r.finding.ambiguous_with, log.how)
    assert "disturbance" not in kinds(r)


def test_a_hand_on_an_averaged_speed_is_reported_where_it_began_and_the_average_named():
    # a 10-tap average of the speed: a hand brakes the wheel for 0.18 s from t = 3.533 s. The
    # hand's rows are left out of every figure, the noise test of the average with them, so
    # the average is named alone (it was 'second pole + dead time', the average rejected for
    # a scatter of 0.12 rad/s that was the hand's own departure)
    log = make(1006, ("velocity_filter",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["velocity_filter"]
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15
    assert "a hand on it" in anomaly(hands[0])


@SEED_1012
def test_a_stall_spike_spread_by_an_average_is_a_logging_artefact_not_a_hand():
    # a 9-tap average over the real intervals of an irregular loop: a 75 ms stall at 10.13 s
    # whose row read the counts late lifts the next 9 rows by 5.3 rad/s and drops straight
    # back; that is the stall's read carried by the average, not a hand
    log, r = checked(1012, ("velocity_filter",), touch=True)
    assert "stall" in log.how and log.touch is not None
    stall_t = float(log.t[log.artefact_rows[0]])
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert all(abs(a.t - stall_t) > 0.5 for a in hands)
    assert any(abs(a.t - log.touch[0]) <= 0.15 for a in hands)
    art = [a for a in r.anomalies if a.kind == "logging_artefact"]
    assert len(art) == 1 and abs(art[0].t - stall_t) <= 0.05
    assert named(r) == ["velocity_filter"]


def test_the_coast_sentence_times_the_fall_to_half_from_the_drop():
    # coasting with dry friction: the sentence names the drop's time and how long after it the
    # speed first reads under half its level before; both are checked against the rows
    log = make(3, ("coulomb_friction", "coast_on_zero"))
    r = check(log.t, log.u, log.omega)
    assert r.finding.cause == "coast_on_zero"
    words = evidence(r.finding)
    t_drop = float(words.split("drops to 0 at t = ")[1].split(" s")[0])
    after = float(words.split("first reading under half, ")[1].split(" ms after the drop")[0])
    a = int(np.argmin(np.abs(log.t - t_drop)))
    before = float(np.mean(np.abs(log.omega[a - 4 : a])))
    under = a + int(np.flatnonzero(np.abs(log.omega[a:]) < 0.5 * before)[0])
    assert after == pytest.approx(1e3 * (log.t[under] - log.t[a]), abs=1.0)


def test_a_departure_hidden_after_every_rising_edge_of_a_generator_log_is_one_model_miss():
    # a generator log with no effect; after every rising edge that has room, 5 T into the
    # stretch, the speed dips by 20 % for 0.2 s and comes back, the same each time: a miss of
    # the model at those edges (a load that engages after each start), never a hand
    log = make(19, (), artefacts=False)
    y = log.omega.copy()
    edges = np.flatnonzero(np.diff(log.u) != 0) + 1
    ends = [*edges[1:].tolist(), log.u.size]
    hidden = []
    for a, b in zip(edges.tolist(), ends, strict=True):
        if abs(log.u[a]) <= abs(log.u[a - 1]):
            continue
        t0 = log.t[a] + 5 * log.T
        rows = (log.t >= t0) & (log.t < t0 + 0.2) & (np.arange(y.size) < b)
        if log.t[b - 1] - t0 > 0.4:
            y[rows] *= 0.8
            hidden.append(a)
    assert len(hidden) >= 4
    r = check(log.t, log.u, y)
    assert "disturbance" not in kinds(r)
    miss = [a for a in r.anomalies if a.kind == "model_miss"]
    assert len(miss) == 1 and miss[0].size >= len(hidden) - 1
    assert "not a hand on the wheel" in anomaly(miss[0])


@SEED_1012
def test_the_model_picks_up_where_the_hand_let_go_and_follows_the_wheel_across_the_step():
    # the hand lets go of the wheel at 6.25 s, 0.43 s (under 2 T) before the input steps down
    # at 6.68 s: the wheel is still coming back when the step comes, and goes on coming back
    # after it. The rows were left out until the model met the speed again, across the step,
    # which took that step's response out of the fit; now the rows from where the hand let go
    # stay in, the model restarted from the speed the wheel was left at (within 0.03 rad/s
    # of the speed there; they were 2.3 rad/s off when kept from the step on, before that)
    log, r = checked(1012, ("velocity_filter",), touch=True)
    assert log.touch is not None
    hand = next(a for a in r.anomalies if a.kind == "disturbance")
    edges = log.t[np.flatnonzero(np.diff(log.u) != 0) + 1]
    step = float(edges[edges > log.touch[1]][0])
    words = anomaly(hand).split("the rows from t = ")[1]
    first = float(words.split(" s to ")[0])
    last = float(words.split(" s to ")[1].split(" s ")[0])
    assert first <= hand.t and log.touch[1] <= last < step
    # the departure itself ends by the step: the sentence says the input stays put there (it
    # said 6.701 s, a row past the step at 6.676 s, through the 9-tap average)
    said = float(anomaly(hand).split(f"from t = {hand.t:.3f} s to ")[1].split(" s ")[0])
    assert hand.t_end is not None and said == pytest.approx(hand.t_end, abs=1e-3)
    assert hand.t_end <= step + 1e-9
    assert "the model picks up from the speed the wheel was left at" in anomaly(hand)
    left = (log.t >= first) & (log.t <= last)
    assert r.baseline.rows <= r.t.size - np.count_nonzero(left)
    # from where the rows are taken back to a second past the step, the model chosen follows
    # the speed within 0.1 rad/s (0.2 % of the speed there)
    err = r.omega - r.extended_pred
    after = np.flatnonzero((log.t > last + 1e-3) & (log.t < step + 1.0))
    assert float(np.max(np.abs(err[after]))) < 0.1
    assert named(r) == ["velocity_filter"]


def test_the_restart_is_the_model_started_from_another_speed():
    # a wheel off the model's speed where a hand let go comes back as the model started from
    # that speed: the difference of two runs of the model from two speeds is the restart's
    # departure times a constant, on every row read after it, through an average, a dead
    # time and a coast (a linear model: no friction, no cap)
    from minseg_tui.model.check.simulate import Effects, Stretches, response, restart

    t = np.arange(300) * 0.01
    u = np.where(t < 1.0, 2.0, np.where(t < 2.0, 0.0, 3.0))
    st = Stretches.from_samples(t, u)
    for fx in (Effects(taps=7), Effects(delay=0.03), Effects(taps=3, T_coast=0.6)):
        d = response(st, t, 0.01, 0.2, fx, z0=0.5) - response(st, t, 0.01, 0.2, fx, z0=0.0)
        col = restart(st, t, 0.01, 0.2, fx, 12)
        assert np.all(col[:12] == 0.0)
        rows = np.flatnonzero(np.abs(col) > 1e-9)
        rows = rows[rows >= 12]
        ratio = d[rows] / col[rows]
        assert rows.size > 100
        assert np.ptp(ratio) < 1e-6 * abs(float(ratio[0]))


@pytest.mark.parametrize(
    "cause,seed", [("velocity_filter", 1023), ("dead_time", 1067), ("coast_on_zero", 1063)]
)
def test_a_hand_leaves_the_rows_after_it_to_the_model_and_the_cause_is_named_alone(cause, seed):
    # with the rows left out until the wheel was back on the model, a spurious cause cleared
    # its margin on what was left (1023: a cap beside the 10-tap average, 12 % of the
    # whitened residual; 1067: a cap beside the dead time; 1063: a friction beside the coast);
    # the same logs without the hand name the cause alone. With the model restarted where
    # the hand let go, the wheel's way back stays in the fit, and the cause is named alone
    log = make(seed, (cause,), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15
    assert named(r) == [cause]


@pytest.mark.parametrize("seed", [507, 509])
def test_a_cap_whose_ramp_no_two_samples_can_show_is_not_named(seed):
    # an averaged speed alone, 25 ms samples: a current cap fitted beside the average cut the
    # whitened residual by more than a second cause needs, but it would hold for less than
    # one sample after the largest step (at 509: a_max 187 rad/s^2, T 0.32 s), so no two
    # samples lie on its ramp: the log cannot show a cap, and the average is named alone
    log = make(seed, ("velocity_filter",))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["velocity_filter"]
    assert abs(r.extended.params["taps"] - log.causes["velocity_filter"]) <= 1


def test_a_hand_seen_through_an_average_is_reported_from_where_the_speed_leaves_the_model():
    # a 12-tap average (240 ms at 20 ms samples): the hand's departure grows through the
    # average, and its running mean crossed the detection threshold 0.187 s after the touch;
    # the speed leaves the model's calm band 0.106 s after it, and the hand is reported from
    # there, with the rows left out from there on
    log = make(1014, ("velocity_filter",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and 0.0 <= hands[0].t - log.touch[0] <= 0.15
    assert f"from t = {hands[0].t:.3f} s to" in anomaly(hands[0])
    assert f"the rows from t = {hands[0].t:.3f} s to" in anomaly(hands[0])
    assert named(r) == ["velocity_filter"]


def test_a_hands_onset_is_fitted_through_the_noise_not_walked_back_row_by_row():
    # a 9-tap average (180 ms at 20 ms samples): a hand brakes the wheel from t = 12.101 s to
    # 12.356 s. Its departure grows through the average and crossed the detection threshold
    # at 12.361 s; walking back from there row by row stopped at the first row whose running
    # mean, with the counts' noise on it, departed a little more than the next one, and the
    # hand was reported from 12.321 s, 0.22 s late. The corner of a line fitted through
    # those rows lies 0.04 s after the touch
    log = make(1036, ("velocity_filter",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.1
    assert f"the rows from t = {hands[0].t:.3f} s to" in anomaly(hands[0])
    assert named(r) == ["velocity_filter"]


@pytest.mark.parametrize("seed", [1, 13])
def test_a_pole_of_the_driver_runs_on_through_a_coast(seed):
    # a driver that lags its command (T2 86-159 ms) and coasts at zero command: through the
    # coast the driver's output falls towards zero, so when the bridge closes the wheel, still
    # turning, is braked before it speeds up. Fitted as the armature's pole (no current while
    # coasting, built from zero after it) T2 came out 25-57 % long
    log = make(seed, ("coast_on_zero", "second_pole"))
    assert "pole on the driver" in log.how
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["coast_on_zero", "second_pole"] and not r.finding.ambiguous_with
    p = r.extended.params
    assert p["T2"] == pytest.approx(log.causes["second_pole"], rel=0.05)
    assert p["T_coast"] == pytest.approx(log.causes["coast_on_zero"], rel=0.05)
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert "in the driver lags its command and runs on while the wheel coasts" in text(r)


def test_after_a_coast_a_drivers_pole_starts_from_its_decayed_output_the_armatures_from_zero():
    # 1 V for 2 s, a coast of 0.4 s (T_coast 2 s), 1 V again; T 0.2 s, T2 0.1 s (K = 1)
    from minseg_tui.model.check.simulate import Effects, Stretches, response

    ts = 0.01
    t = np.arange(0.0, 3.0, ts)
    u = np.where((t >= 2.0) & (t < 2.4), 0.0, 1.0)
    st = Stretches.from_samples(t, u)
    T, T2, tc = 0.2, 0.1, 2.0
    arm = response(st, t, ts, T, Effects(T2=T2, T_coast=tc), None)
    drv = response(st, t, ts, T, Effects(T2=T2, T_coast=tc, pole_driver=True), None)
    k = int(round(2.4 / ts))
    assert np.allclose(arm[:k], drv[:k])  # alike until the bridge closes
    w_end = np.exp(-0.4 / tc)  # the speed the coast leaves
    # the armature: T w' = v - w with v rising from w_end to 1, so w never falls (each row
    # is the mean speed over the sample before it: row k is the coast's last)
    assert np.all(np.diff(arm[k + 1 :]) > -1e-9) and np.min(arm[k + 1 :]) > w_end - 1e-6
    # the driver: v = exp(-0.4/T2) = 0.018 V when the bridge closes: the wheel is braked first
    assert np.min(drv[k : k + 8]) < w_end - 0.05
    # the exact solution of T w' = v - w, T2 v' = 1 - v from (w_end, v0), as the Euler speed
    v0 = np.exp(-0.4 / T2)
    b = (v0 - 1.0) * T2 / (T2 - T)
    a = w_end - 1.0 - b
    fine = np.arange(0.0, 0.6, 1e-5)
    w = 1.0 + a * np.exp(-fine / T) + b * np.exp(-fine / T2)
    angle = np.concatenate(([0.0], np.cumsum(w[1:] + w[:-1]) * 0.5e-5))
    tau = t[k:] - 2.4
    inside = tau[1:] <= 0.59
    seen = (np.interp(tau[1:], fine, angle) - np.interp(tau[:-1], fine, angle)) / ts
    assert np.allclose(drv[k + 1 :][inside], seen[inside], atol=1e-4)


def test_one_delay_like_cause_standing_in_for_the_other_two_gives_way_to_them():
    # a dead time of 11 ms and a pole of 35 ms on the coupling at 10 ms samples: a 9-tap
    # average alone was named (its whitened residual, strided by 9, below both; the pair was
    # never fitted beside it), said to be about as good as a pole alone. The delay and the
    # pole together leave 9 % less of the speed's own error than the average and a fifth of
    # the pole's whitened residual: they are named, with their parameters
    log = make(65, ("dead_time", "second_pole"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["dead_time", "second_pole"], (named(r), r.finding.ambiguous_with)
    p = r.extended.params
    assert p["delay"] == pytest.approx(log.causes["dead_time"], rel=0.1)
    assert p["T2"] == pytest.approx(log.causes["second_pole"], rel=0.1)
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    # what would tell them apart sets a cause of the pair against one of the rival, never the
    # delay against the pole when both are named
    told = [caveat(c) for c in r.finding.caveats if c.kind == "cannot_tell"]
    assert all("a delay leaves those samples flat" not in w for w in told), told


def test_a_delay_and_a_pole_standing_in_for_an_average_and_a_pole_give_way_to_them():
    # a 6-tap average of the speed with a pole of 44 ms on the coupling at 20 ms samples
    # (T 196 ms): the average alone was named first, then a delay of 45 ms and a pole of
    # 194 ms (T 61 ms, the wheel's lag read as the pole) stood in for it, compared only with
    # the average alone. The average with its pole, fitted again from the pair's values,
    # leaves a ninth of the pair's speed error: it is named, with its parameters
    log = make(88, ("velocity_filter", "second_pole"), measured_pole=True)
    assert "coupling" in log.how
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["second_pole", "velocity_filter"], (named(r), r.finding.ambiguous_with)
    p = r.extended.params
    assert p["taps"] == log.causes["velocity_filter"]
    assert p["T2"] == pytest.approx(log.causes["second_pole"], rel=0.1)
    assert p["T"] == pytest.approx(log.T, rel=0.05)


@pytest.mark.parametrize(
    "cause,seed", [("none", 1017), ("coulomb_friction", 1031), ("dead_time", 1008)]
)
def test_a_cause_that_moves_the_speed_by_under_a_percent_is_not_named(cause, seed):
    # each log named an extra cause beside its own, the same with the hand's torque at 0: a
    # 4.5 mV friction on a log without one (0.09 % of the 140 rad/s the speed reaches, yet
    # 39 % of the whitened residual, which is the load's slow ripple), a cap beside the
    # friction (0.7 %) and a cap whose ramp lasts about a sample beside the dead time
    # (0.12 %, 12 % of what the delay leaves). Named alone now, and the hand still found
    log = make(seed, () if cause == "none" else (cause,), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15
    assert named(r) == ([] if cause == "none" else [cause])
    if cause == "none":
        assert r.finding.runner_up == "coulomb_friction"
        why = runner_up_why(r.finding)
        assert "% of the" in why and "rad/s the speed reaches" in why


def test_a_hand_behind_an_average_longer_than_its_hold_is_found():
    # a 24-tap average (0.6 s at 25 ms samples) spreads a 0.18 s hand over the average's
    # length: the averaged speed drops by 7 % of its level, under the 8 % a hand must move an
    # unaveraged speed by. Behind an average longer than 0.15 s that share is taken down in
    # proportion (to half at most), far above the averaged speed's noise here (0.06 rad/s)
    log = make(1017, ("velocity_filter",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15
    assert named(r) == ["velocity_filter"]


def test_a_stalls_spike_does_not_make_a_hand_an_edges_repeated_miss():
    # a 9-tap average with a stall of the logger at 4.32 s and a hand at 7.93 s, each soon
    # after its edge: counted together they were "a departure after 2 edges", the model's
    # miss, and the hand was not reported. The stall's spike is the logger's
    log = make(1073, ("velocity_filter",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    kinds = [a.kind for a in r.anomalies]
    assert "model_miss" not in kinds and "logging_artefact" in kinds
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15
    assert named(r) == ["velocity_filter"]


def test_an_average_that_scatters_far_less_than_the_first_order_model_is_named_with_its_pole():
    # a 9-tap average at 25 ms samples (1440 counts per turn) with a pole on the coupling:
    # every model with an average leaves 0.049-0.060 rad/s, 6-8 times what an average of
    # counts leaves (0.0079), and the scatter test refused them, naming a delay and a pole.
    # The first-order model leaves 0.40 rad/s, eight times the average's: on rows that hold
    # no disturbance the average is named with the pole
    log = make(8, ("velocity_filter", "second_pole"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["second_pole", "velocity_filter"]


@pytest.mark.parametrize(("seed", "gap_ms"), [(502, 60), (509, 125)])
def test_a_stalls_spike_through_a_filter_of_the_speed_column_is_an_artefact_not_a_hand(
    seed, gap_ms
):
    # tuning singles of a pole that is the logger's first-order filter of the speed column,
    # each with a stall: the stall's one-row spike (116 rad/s at 10 ms; 12 rad/s at 25 ms)
    # dies away through the filter over 3 and 10 rows, past the one row an unaveraged
    # speed allows, and was reported as a hand on a log no hand touched (502: "rises by
    # 116 rad/s (113 %)"; 509: "rises by 8.11 rad/s (44 %)")
    log = make(seed, ("second_pole",))
    assert "pole on the iir" in log.how and "stall" in log.how and log.touch is None
    r = check(log.t, log.u, log.omega)
    assert "disturbance" not in kinds(r), text(r)
    art = [a for a in r.anomalies if a.kind == "logging_artefact"]
    stall = log.artefact_rows[0]
    assert len(art) == 1 and art[0].row is not None and abs(art[0].row - stall) <= 1
    # the sentence names the gap it follows, not the next interval
    assert f"right after a gap of {gap_ms} ms" in anomaly(art[0])
    assert "a hand on it" not in text(r)


def test_a_miss_inside_a_reversals_transient_is_judged_against_the_steps_size():
    # tuning pair seed 5 of a delay with a pole (the logger's filter of the speed column):
    # 8 rows into the response to a reversal from -4.2 V to 1.33 V (about 100 rad/s) the
    # model misses by 1.4 rad/s, while it passes through -43 rad/s. Against the level of
    # that stretch (the median of a speed crossing zero) that was 4.8 % and a hand; against
    # the step it is 1.4 %, the model's miss inside a transient
    log = make(5, ("dead_time", "second_pole"))
    assert log.touch is None
    r = check(log.t, log.u, log.omega)
    assert "disturbance" not in kinds(r), text(r)
    assert "a hand on it" not in text(r)


def test_a_departure_the_model_chosen_at_the_end_follows_is_no_disturbance():
    # tuning pair seed 4 of a 24-tap average with a coast: 14 rows into a rise from a coast
    # the first pass's model (a delay, a coast and a pole) missed the speed by 6.6 rad/s (10 %)
    # and the rows were fenced as a hand's; the average chosen after them follows those rows
    # (it does not find them when it is judged there), so no hand is reported
    log = make(4, ("velocity_filter", "coast_on_zero"))
    assert log.touch is None
    r = check(log.t, log.u, log.omega)
    assert "disturbance" not in kinds(r), text(r)
    assert "coast_on_zero" in named(r) and "velocity_filter" in named(r)


@pytest.mark.parametrize("cause", ["dead_time", "coast_on_zero", "current_limit"])
def test_a_hand_at_fast_sampling_is_looked_for_over_half_its_shortest_hold(cause):
    # tuning seed 1044: 10 ms samples, Euler speed of 360 counts a turn (1.75 rad/s a count),
    # a hand of 0.16 s that slows the wheel by about 1.7 rad/s (11 %). Through a running mean
    # of three rows (30 ms) the counts' noise hid it (threshold 2.1 rad/s); left in, the
    # hand's rows made the delay read as an average (dead_time: velocity_filter named, the
    # same log with the hand's torque at 0 names the delay). Over 75 ms (7 rows) it shows
    log = make(1044, (cause,), touch=True)
    assert log.touch is not None and log.ts == 0.01
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15, text(r)
    assert named(r) == [cause]
    # the same log with the hand's torque at 0: test_a_touched_log_s_control_names_its_cause


@PAIR_8
def test_an_average_is_weighed_without_the_rows_it_carries_a_stalls_read_into():
    # tuning pair seed 8: a 9-tap average of counts over the real interval, dry friction
    # and a 100 ms stall of the logger at 10.65 s. The average spreads the stall's late read
    # over the 10 rows after the gap: 112 of the 124 (rad/s)^2 the first pass's friction and
    # average left of the speed itself lay there, and a 93 ms delay, 1.25 times better on
    # the speed with those rows in, was named in the average's place. Those rows are the
    # logger's, so they count for neither side
    log, r = checked(8, ("coulomb_friction", "velocity_filter"))
    assert "stall" in log.how and "moving_average (9 taps)" in log.how
    assert named(r) == ["coulomb_friction", "velocity_filter"], text(r)
    p = r.extended.params
    assert abs(p["taps"] - 9) <= 1
    assert p["u_c"] == pytest.approx(log.causes["coulomb_friction"], rel=0.1)
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert "disturbance" not in kinds(r)


def test_a_cause_the_others_take_over_when_it_is_left_out_is_not_named():
    # tuning touched log 1033 of a coast (T_coast 2.5 s), named with a 7 mV friction beside
    # it, the same with the hand's torque at 0. Held at the coast's own value the friction
    # moved the simulated speed by 1.2 % of its range, just over SMALL_EFFECT; with the coast
    # fitted again without it the two models differ by 0.33 %: the coast takes it over.
    # Named alone now, the hand still found
    seed = 1033
    log = make(seed, ("coast_on_zero",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15, text(r)
    assert named(r) == ["coast_on_zero"], text(r)
    # the same log with the hand's torque at 0: test_a_touched_log_s_control_names_its_cause
    why = reason(Reason("taken_over", shown=0.35, rows=9, top=105.0, causes=("coast_on_zero",)))
    assert why.startswith("coast_on_zero, fitted again without it, takes over nearly all")
    assert "0.35 rad/s at most, 0.33 % of the 105 rad/s" in why


def test_a_true_cap_beside_a_drivers_pole_is_not_taken_over():
    # tuning pair seed 5: a cap of 194 rad/s^2 beside a driver's pole of 151 ms. Fitted again
    # without the cap the pole takes much of it over, yet the two models still differ by
    # 0.74 % of the speed's range, above TAKEN_OVER: the cap stays named
    log = make(5, ("second_pole", "current_limit"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["current_limit", "second_pole"], text(r)


def test_an_average_refused_for_a_stalls_rows_is_chosen_again_without_them():
    # tuning pair seed 8 of a 9-tap average with a cap, and of the same average with a delay
    # (counts over the real interval, a 100 ms stall at 10.65 s). In every fit the average
    # was in, the rows after the gap it carries the stall's late read into weighed against
    # it: the cap's pair fitted 13 taps and lost to a 95 ms delay beside the cap (named: cap
    # and delay, no ambiguity), and the delay's pair was named a delay and a pole. Chosen
    # again with those rows out the average is named, its own rows then left out as ever.
    # The delay's pair is the next test (two logs, two checks: one on each xdist worker)
    log = make(8, ("velocity_filter", "current_limit"))
    assert "stall" in log.how
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["current_limit", "velocity_filter"], text(r)
    p = r.extended.params
    assert p["taps"] == 9
    assert p["a_max"] == pytest.approx(log.causes["current_limit"], rel=0.05)
    assert "gap_rows_left_out" in kinds(r) and "disturbance" not in kinds(r)


def test_an_average_refused_beside_a_delay_for_a_stalls_rows_is_chosen_again_without_them():
    # tuning pair seed 8 of the same average with a delay (the test above): named a delay and
    # a pole before the average was chosen again with the rows after the gap out
    log = make(8, ("dead_time", "velocity_filter"))
    r = check(log.t, log.u, log.omega)
    truth = ["dead_time", "velocity_filter"]
    assert named(r) == truth or truth in [sorted(a) for a in r.finding.ambiguous_with], text(r)


@pytest.mark.parametrize(
    ("friction", "cap", "inductance", "beta"),
    [
        (0.0, None, 0.5, 0.0),
        (0.4, None, 0.5, 0.0),
        (0.4, None, 0.8, 0.0),
        (0.0, 0.3, 0.5, 0.0),
        (0.4, 0.3, 0.5, 0.0),
        (0.0, 0.3, 0.5, 0.15),
        (0.4, 0.3, 0.8, 0.1),
    ],
)
def test_the_ringing_pair_moves_the_wheel_as_the_generators_armature_does(
    friction, cap, inductance, beta
):
    # a motor whose inductance makes its two poles a complex pair (L/R over a quarter of the
    # mechanical time constant), with dry friction, a current cap both ways and viscous drag
    # (beta = R b / k^2): the check's ringing pair, given the pair's decay time and
    # frequency and the drag's share of the damping, is the generator's armature; two real
    # poles are not
    from minseg_tui.model.check.simulate import RING_FLOOR, Effects, Stretches, response
    from tests.model import physics_gen as pg

    R, k = 4.0, 0.05
    J = 0.1 * k * k / R  # R J / k^2 = 0.1 s
    m = pg.Motor(R=R, L=R * inductance * 0.1, k=k, J=J, b=beta * k * k / R)
    K = k / (k * k + R * m.b)
    m.tau_f = friction * k / R
    rate = np.inf
    if cap is not None:
        m.i_max = cap
        rate = cap * k / J / K  # the largest acceleration, in K = 1 units
    a, _ = pg._system(m, False, False, False)
    lam = np.linalg.eigvals(a[:2, :2])[0]
    assert lam.imag != 0.0  # a complex pair
    decay, ring = -1.0 / lam.real, (lam.imag / lam.real) ** 2 - RING_FLOOR
    at = np.array([0.0, 0.3, 1.0, 1.8, 2.5])
    levels = np.array([0.0, 5.0, 2.0, 0.0, 4.0])
    grid, _, theta = pg.simulate(m, 3.2, at, levels, (np.inf, np.inf, 0.0))
    ts = 0.01
    t = np.arange(0.0, 3.2, ts)
    u = levels[np.searchsorted(at, t, side="right") - 1]
    seen = np.diff(np.interp(t, grid, theta), prepend=0.0) / ts / K  # K = 1 units (V)
    st = Stretches.from_samples(t, u)
    both = {"u_c": friction, "rate": rate, "cap_both": True, "drag": beta / (1.0 + beta)}
    fx = Effects(T2=decay, pole_ring=True, ring=ring, **both)
    ours = response(st, t, ts, decay, fx)
    assert np.max(np.abs(ours - seen)) < 2e-3 * np.max(np.abs(seen))
    real = Effects(T2=0.999 * decay, **both)
    assert np.max(np.abs(response(st, t, ts, decay, real) - seen)) > 0.1 * np.max(np.abs(seen))


@pytest.mark.parametrize(
    ("seed", "causes"),
    [
        (205, ("second_pole",)),
        (505, ("second_pole",)),
        (506, ("second_pole",)),
        (15, ("coulomb_friction", "second_pole")),
        (11, ("dead_time", "second_pole")),
        (41, ("current_limit", "second_pole")),
        (45, ("current_limit", "second_pole")),
    ],
)
def test_an_inductance_that_makes_the_poles_ring_is_named_with_their_decay_time(seed, causes):
    # a pole on the inductance over a quarter of the mechanical time constant: the motor's
    # two poles are a complex pair, both decaying with the generator's T; with real poles
    # only the check named an average (505, 506: T 48 % and 23 % short), a delay (205, with
    # a rival), a delay beside the pole (11: T 29 % short) or friction with an average and a
    # pole (15: T 86 % short). Beside a cap the pair still rings once the cap lets go and on
    # the steps under it: with no ringing way beside a cap (s34-gate, not kept) 41 and 45
    # were named an average with the cap
    log = make(seed, causes)
    assert "inductance" in log.how and log.causes["second_pole"] == log.T
    r = check(log.t, log.u, log.omega)
    assert named(r) == sorted(causes)
    p = r.extended.params
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert p["T2"] == pytest.approx(log.T, rel=0.05)
    for c, v in log.causes.items():
        assert p[BY_CAUSE[c].param] == pytest.approx(v, rel=0.05)
    said = text(r)
    assert "make a complex pair" in said and "dies away with one time constant" in said


def test_a_cause_near_the_smallest_one_named_is_said_to_be_one_the_log_cannot_rule_out():
    # a true cap beside a driver's pole moves the speed by 0.99 % of its range, just under
    # the 1 % a cause must reach (spurious ones reach 0.92 %): the pole is named, and the
    # check says the log cannot tell whether the cap acts beside it, instead of a guess
    log = make(4, ("second_pole", "current_limit"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["second_pole"]
    assert ["second_pole", "current_limit"] in r.finding.ambiguous_with
    said = text(r)
    assert "this log cannot tell whether current limit acts beside second pole" in said
    assert "by 0.99 % of the largest speed at most" in said


@pytest.mark.parametrize("seed", [1253, 1320])
def test_a_hands_fence_reaches_as_far_as_the_model_chosen_sees_the_wheel_depart(seed):
    # tuning touched logs of an average (1320: 8 taps at 20 ms, a hand of 0.24 s at 1.26 s;
    # 1253: 19 taps at 10 ms). The hand was found against the first pass's model (1320: a
    # pole of 122 ms, fitted with the hand's rows in), which meets the wheel again early:
    # fenced until row 97, one row before the next step, while the average chosen after it
    # sees the wheel depart until row 106 and back on only at 113. The way back left in
    # (3-4 rad/s under the model, through the step) made a cap of the whitened sums: named
    # beside the average although it left a larger rms on the rows it used (0.38 against
    # 0.35 rad/s). The same log with the hand's torque at 0 names the average alone
    log = make(seed, ("velocity_filter",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    hands = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(hands) == 1 and abs(hands[0].t - log.touch[0]) <= 0.15, text(r)
    assert named(r) == ["velocity_filter"], text(r)
    p = r.extended.params
    assert abs(p["taps"] - log.causes["velocity_filter"]) <= 1
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    # the same log with the hand's torque at 0: test_a_touched_log_s_control_names_its_cause


@pytest.mark.parametrize(
    ("seed", "cause"),
    [
        (1044, "dead_time"),
        (1044, "coast_on_zero"),
        (1044, "current_limit"),
        (1033, "coast_on_zero"),
        (1253, "velocity_filter"),
        (1320, "velocity_filter"),
    ],
)
def test_a_touched_log_s_control_names_its_cause(seed, cause):
    # the controls of test_a_hand_at_fast_sampling_is_looked_for_over_half_its_shortest_hold
    # (1044), test_a_cause_the_others_take_over_when_it_is_left_out_is_not_named (1033) and
    # test_a_hands_fence_reaches_as_far_as_the_model_chosen_sees_the_wheel_depart (1253,
    # 1320): the same log with the hand's torque at 0 names the cause alone. A test of its
    # own, so that under xdist a touched log and its control are checked side by side
    control = make(seed, (cause,), touch=True, hand_torque=0.0)
    assert named(check(control.t, control.u, control.omega)) == [cause]


def test_a_hand_let_go_under_a_current_cap_is_left_out_until_the_wheel_is_back():
    # the hand brakes the wheel at 7.50-7.75 s while the drive holds the current at its cap:
    # the wheel then ramps at the cap's rate as the model does, and stays as far behind it
    # until the cap lets go (only the wheel's drag closes the gap), past the step at 8.23 s.
    # A restart's way back dies away with T, which the wheel's does not: restarted at 7.83 s,
    # T came out 3.3 % long (0.354 s, true 0.343); left out until the wheel is back, 0.4 %
    log = make(1169, ("current_limit",), touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["current_limit"]
    assert r.extended.params["T"] == pytest.approx(log.T, rel=0.015)
    hand = next(a for a in r.anomalies if a.kind == "disturbance")
    assert abs(hand.t - log.touch[0]) <= 0.15
    edges = log.t[np.flatnonzero(np.diff(log.u) != 0) + 1]
    step = float(edges[edges > log.touch[1]][0])
    words = anomaly(hand)
    assert "picks up from the speed the wheel was left at" not in words
    last = float(words.split("the rows from t = ")[1].split(" s to ")[1].split(" s ")[0])
    assert last > step
    # the rows left out are those the sentence names: no figure of the fit holds them
    left = (log.t >= hand.t) & (log.t <= last)
    assert r.extended.rows <= r.t.size - np.count_nonzero(left)


def test_a_strong_hand_is_reported_no_further_back_than_its_departure_can_have_grown():
    # a hand's torque slows the wheel towards its deepest deficit through T: a departure of
    # 12.4 rad/s that reads 1.9 rad/s over its first three rows (against the rows before the
    # slow miss, which it counts in) began at most T ln(12.4/10.5) = 0.06 s before (0.35 s
    # T, 10 ms rows). The model missed the 0.7 s before it by a slow 0.4 rad/s, which the
    # fitted corner of the onset takes for the departure's start; the report was bounded
    # only by T (0.35 s) and so came up to 0.4 s before the hand (held-out current_limit
    # 901002, a hand during a capped ramp: reported 0.43 s early)
    from minseg_tui.model.check.disturbances import Disturbance
    from minseg_tui.model.check.fit import Fit
    from minseg_tui.model.check.pipeline import _grown
    from minseg_tui.model.check.simulate import Effects

    ts, T = 0.01, 0.35
    k = np.arange(600)
    res = np.where((k >= 130) & (k < 200), -0.4 * (k - 130) / 70, 0.0)
    held = (k >= 200) & (k < 225)
    res[held] = -0.4 - 12.0 * (1.0 - np.exp(-(k[held] - 200 + 1) * ts / T))
    d = Disturbance(200, 230, float(res[held].min()), 40.0, since=130, let_go=226)
    f = Fit((), T, 20.0, Effects(), 0.0, 600)
    grown = _grown(d, res, f, ts)
    assert 0.0 < grown < 0.1
    # under a cap the current is held and the wheel slows at a steady rate: the hold from
    # the crossing to the deepest row sets it, in proportion to the share crossed
    capped = Fit(("current_limit",), T, 20.0, Effects(rate=50.0), 0.0, 600)
    assert grown <= _grown(d, res, capped, ts) < T


@pytest.mark.parametrize("from_edge", [False, True])
def test_a_miss_that_runs_on_through_an_edge_is_no_late_step(from_edge):
    # along a ramp at a current cap's rate, a shift of the edges moves the prediction by the
    # same amount on every row, as a speed off by a constant does: a miss the model already
    # had before the edge, running on after it, was timed as the step acting late (held-out
    # current_limit 901002: "acts 8.7 ms late" at 10.99 s, the speed 0.29 rad/s below the
    # model over the 1.1 s before the edge too; the generator issues every command at its
    # row's time). The same miss starting at the edge is what a late step leaves: reported
    from minseg_tui.model.check import anomalies as an

    ts, rate, shift, n = 0.01, 40.0, 0.005, 650
    t = ts * np.arange(n)
    u = np.zeros(n)
    for e, sign in zip((50, 170, 290, 410, 530), (1, -1, 1, -1, 1), strict=True):
        u[e:] = 5.0 * sign
    slope = np.sign(u) * rate  # the capped ramp the model follows, rad/s^2
    pred = np.cumsum(slope * ts)
    d_shift = -slope * shift  # every edge shift s later: the ramp shifted
    res = np.random.default_rng(7).normal(0.0, 0.05, n)
    late = 0.007  # s: the wheel on the ramp after row 410 is 7 ms behind, rate * late rad/s
    res[410 if from_edge else 330 : 470] += rate * late
    found = an.late_steps(t, u, res, d_shift, shift, ts, 0.1, pred, 0.0, np.ones(n, bool))
    if from_edge:
        assert [a.row for a in found] == [410]
        assert found[0].size == pytest.approx(1e3 * late, abs=1.0)
    else:
        assert found == []


@dataclass(frozen=True)
class EdgeTrain:
    """Twelve edges of a first-order speed at 10 ms samples (T 50 ms, K 10 rad/s/V), each
    acting a little late (a scatter), edge 6 4 ms late: the prediction, its change for a
    shift of every edge by :attr:`shift`, the residual with noise 0.02 rad/s, and the
    generator for further draws."""

    ts: ClassVar[float] = 0.01
    T: ClassVar[float] = 0.05
    shift: ClassVar[float] = 0.005
    t: np.ndarray
    u: np.ndarray
    edges: np.ndarray
    pred: np.ndarray
    d_shift: np.ndarray
    res: np.ndarray
    rng: np.random.Generator

    def late(self, res: np.ndarray | None = None, *delay: float) -> list:
        """model.check's late steps found in residual ``res`` (default :attr:`res`), against
        a model with the dead time ``delay`` (s) when given."""
        from minseg_tui.model.check import anomalies as an

        res = self.res if res is None else res
        keep = np.ones(self.t.size, bool)
        return an.late_steps(
            self.t,
            self.u,
            res,
            self.d_shift,
            self.shift,
            self.ts,
            self.T,
            self.pred,
            0.0,
            keep,
            *delay,
        )

    def unshiftable(self, rows: np.ndarray, rms: float) -> np.ndarray:
        """A miss of ``rms`` rad/s on ``rows`` that no shift of the edges explains (a draw
        of :attr:`rng` orthogonal to :attr:`d_shift` there)."""
        miss = self.rng.normal(0.0, 1.0, rows.size)
        d = self.d_shift[rows]
        miss -= d * float(miss @ d) / float(d @ d)
        return rms * miss / np.sqrt(np.mean(miss**2))


def _edge_train(seed: int, scatter: float) -> EdgeTrain:
    K, n = 10.0, 12 * 40 + 20
    ts, T, shift = EdgeTrain.ts, EdgeTrain.T, EdgeTrain.shift
    t = ts * np.arange(n)
    rng = np.random.default_rng(seed)
    u = np.zeros(n)
    edges = 20 + 40 * np.arange(12)
    for k, e in enumerate(edges):
        u[e:] = 2.0 + 1.5 * (k % 3) if k % 2 == 0 else 0.0

    def response(lag: np.ndarray) -> np.ndarray:
        """The first-order speed (rad/s) with edge k acting lag[k] s late."""
        y = np.zeros(n)
        for k, e in enumerate(edges):
            step = K * (u[e] - u[e - 1])
            since = np.maximum(t - t[e] - lag[k], 0.0)
            y += np.where(t >= t[e] + lag[k], step * (1.0 - np.exp(-since / T)), 0.0)
        return y

    pred = response(np.zeros(edges.size))
    d_shift = response(np.full(edges.size, shift)) - pred
    lag = rng.normal(0.0, scatter, edges.size)
    lag[6] = 0.004  # s: the edge out of line
    res = response(lag) - pred + rng.normal(0.0, 0.02, n)
    return EdgeTrain(t, u, edges, pred, d_shift, res, rng)


@pytest.mark.parametrize("scatter", [0.0003, 0.0015])
def test_an_edge_out_of_line_with_the_scatter_of_every_edge_is_no_late_step(scatter):
    # where the model misses the corners (held-out cap + friction 900003: a timed-edges
    # speed whose first readings after rest miss by 0.7-2.2 rad/s, at every rise), every
    # edge's shift estimate carries a share of that miss, and the edges scatter by 1.7-1.8
    # ms at 10 ms samples, far beyond the noise: six edges 2.9-4.4 ms out of line, 1.7-2.4
    # such scatters, were reported as steps acting late or early, though the generator
    # issues every command at its row's time. A step that acts late stands out of the
    # other edges' scatter (model.synth's late steps: 5.6-29 robust sigmas of it); here
    # the same edge 4 ms out of line among edges that scatter by 0.3 ms (reported) and by
    # 1.5 ms (the model's miss, not reported)
    e = _edge_train(11, scatter)
    found = e.late()
    if scatter < 0.001:
        assert [a.row for a in found] == [int(e.edges[6])]
    else:
        assert found == []


@pytest.mark.parametrize("miss", [0.0, 0.5])
def test_a_miss_a_shift_only_trims_is_no_late_step(miss):
    # held-out pole + cap 900001 (a pole of 34 ms and a cap at 25 ms samples): after one
    # edge the speed missed the model by 16 times the noise, 8 times what the other edges
    # miss; its projection on a shift of the edge read 9 ms, 7 of the edges' scatters,
    # but shifted the rows still missed by 6.6 times what the other edges' rows miss as
    # they are: that is the model's miss, not a step that acted late. A step that acted
    # late leaves the model right but for the timing (model.synth's late steps: at most
    # 2.1 times). Here an edge 4 ms late, with (not reported) and without (reported) a
    # miss of 0.5 rad/s rms that no shift explains (orthogonal to it) on its rows
    e = _edge_train(12, 0.0003)
    rows = np.arange(e.edges[6], e.edges[6] + 15)
    e.res[rows] += e.unshiftable(rows, miss)
    found = e.late()
    assert [a.row for a in found] == ([] if miss else [int(e.edges[6])])


@pytest.mark.parametrize("delay", [0.0, 0.005])
def test_an_edge_that_looks_early_is_no_late_step_unless_the_model_has_a_delay(delay):
    # tuning coast + pole 9 (an IIR speed and a pole on it, both named, at 20 ms samples):
    # the fall from 1.68 V to 0 at row 608 read as a step acting 7 ms *early*, 16 of the
    # edges' scatters out, though the generator issues every command at its row's time. A
    # board stamps its row and then sends the command: a step acts at its stamp or later,
    # and the lag every edge has is what the median takes away. Only against a model with a
    # dead time can a step on time look early (by up to that delay). Here edge 6's residual
    # is that of a step 4 ms late, mirrored: 4 ms early
    e = _edge_train(11, 0.0003)
    edges, res = e.edges, e.res.copy()
    late = e.late(res)
    assert [a.row for a in late] == [int(edges[6])] and late[0].size > 3.0  # the premise
    rows = np.arange(edges[6], edges[7])
    res[rows] = -res[rows]
    more = (delay,) if delay else ()  # the model's dead time, s
    found = e.late(res, *more)
    if delay:
        assert [a.row for a in found] == [int(edges[6])] and found[0].size < -3.0
    else:
        assert found == []


@pytest.mark.parametrize("other", [0.45, 0.9])
def test_a_shift_that_takes_a_third_of_a_miss_away_is_no_late_step(other):
    # held-out pole + cap 900003 (a pole on the driver, named as a dead time, 10 ms samples):
    # the rise at row 299 read as a step 3.1 ms late, 5.1 scatters out, its shifted rows within
    # 1.5 times what the other edges miss (the model misses at every edge there); but the
    # shift took only 33 % of the mean square of the rows after it away, the rest a miss no
    # shift explains. model.synth's true late steps take 49-98 % away. Here edge 6 acts 4 ms
    # late (about 0.55 rad/s rms over its rows) and every edge has a miss no shift explains,
    # 0.4 rad/s rms, edge 6 ``other``: 0.45 (the shift takes 65 % away: reported) or 0.9 (31 %,
    # its shifted rows within 2.3 times the other edges' miss: not)
    e = _edge_train(12, 0.0003)
    edges = e.edges
    for k, edge in enumerate(edges.tolist()):
        rows = np.arange(edge, edge + 15)
        e.res[rows] += e.unshiftable(rows, other if k == 6 else 0.4)
    found = e.late()
    assert [a.row for a in found] == ([int(edges[6])] if other < 0.6 else [])


@pytest.mark.parametrize("noise", [0.02, 0.25])
def test_a_shift_of_a_miss_within_the_noise_is_no_late_step(noise):
    # tuning coast + cap 5 (a speed from timed edges at 25 ms samples): the fall from 1.24 V
    # to 0 read as a step 12.8 ms late, 9.3 scatters out, its projection on a shift 6.9 times
    # the noise; but the rows after that edge missed by only 1.7 times the noise as they were
    # (a speed from timed edges lags as the wheel slows). model.synth's true late steps miss by
    # 4.3-34 times it. Here edge 6 acts 4 ms late under noise of 0.02 rad/s (reported) and
    # 0.25 rad/s (its rows miss by under 3 times the noise: not)
    e = _edge_train(13, 0.0003)
    found = e.late(e.res + e.rng.normal(0.0, noise, e.t.size))
    assert [a.row for a in found] == ([int(e.edges[6])] if noise < 0.1 else [])


def test_a_hands_fence_is_run_on_to_the_next_step_not_across_it():
    # through an average the wheel's way back after a hand runs on in the reading past where
    # the fence ends (held-out touched 901001, an 11-tap average: 0.44 rad/s behind there,
    # and a cap entered beside the average on that tail alone); the check chooses the causes
    # again with the fence run on to the next step, and takes that choice only when it names
    # fewer causes. The fence stops at the step: that step's response stays in the fit
    from minseg_tui.model.check.disturbances import Disturbance
    from minseg_tui.model.check.pipeline import _to_next_step

    u = np.zeros(400)
    u[100:200], u[200:300] = 3.0, 1.5
    inside = Disturbance(120, 140, -4.0, 30.0, until=160)  # ends between the steps at 100, 200
    at_step = Disturbance(230, 250, -4.0, 15.0, until=300)  # ends on the step at 300
    last = Disturbance(320, 330, -4.0, 0.0, until=350)  # after the last step: to the end
    wide = _to_next_step([inside, at_step, last], u)
    assert [(d.fence_start, d.fence_end) for d in wide] == [(120, 200), (230, 300), (320, 400)]
    assert wide[1] == at_step


def test_an_average_loses_to_a_delay_that_matches_the_corners_far_better():
    # a 5-tap average at 10 ms lags the speed by 25 ms on the whole, as a 25 ms delay does:
    # the two differ only in the few rows after each edge, where the average rounds the
    # corner the delay keeps sharp. Over the whole log the rows where both agree swamp that:
    # the held-out hand 901000 (a 23 ms delay, speed by timed edges) named the average, its
    # plain error 1.19 times the delay's over the log but 3.65 times on the 63 rows where the
    # two differ, after 9 of its 10 edges. Here the same in miniature: a first-order wheel
    # (T 0.26 s, 100 rad/s a step) behind a 25 ms delay, with seeded noise of 0.5 rad/s
    from types import SimpleNamespace

    from minseg_tui.model.check import decide
    from minseg_tui.model.check.simulate import Effects

    ts, T, delay, fine = 0.01, 0.26, 0.025, 0.0005
    t = ts * np.arange(2000)
    tf = np.arange(0.0, t[-1] + ts, fine)
    uf = np.where((tf // 1.0) % 2 == 1, 5.0, 0.0)

    def wheel(lag: float) -> np.ndarray:
        """The speed (rad/s) on the fine grid, the command reaching it ``lag`` s late."""
        drive = np.interp(tf - lag, tf, uf, left=0.0)
        w, a = np.zeros(tf.size), np.exp(-fine / T)
        for i in range(1, tf.size):
            w[i] = a * w[i - 1] + (1.0 - a) * 20.0 * drive[i - 1]
        return w

    at = np.rint(t / fine).astype(int)
    delayed, prompt = wheel(delay)[at], wheel(0.0)
    window = int(round(5 * ts / fine))
    sums = np.concatenate(([0.0], np.cumsum(prompt)))
    first = np.maximum(at - window + 1, 0)
    averaged = (sums[at + 1] - sums[first]) / (at + 1 - first)
    y = delayed + np.random.default_rng(3).normal(0.0, 0.5, t.size)
    prob = SimpleNamespace(y=y, t=t, ts=ts, weights=np.ones(t.size))

    def model(causes, taps, pred, sse_white):
        return SimpleNamespace(
            causes=causes, effects=Effects(taps=taps), sse_white=sse_white, predict=lambda p: pred
        )

    base = model((), 1, prompt[at], 1e5)
    # the average's whitened residual, summed at its own stride, is the smaller (as there)
    ok = {
        "velocity_filter": model(("velocity_filter",), 5, averaged, 3e3),
        "dead_time": model(("dead_time",), 1, delayed, 7e3),
    }
    whole = decide._raw_sse(prob, ok["velocity_filter"]) / decide._raw_sse(prob, ok["dead_time"])
    assert whole < decide.RAW_RIVAL  # over the whole log the delay is not far better
    sel = SimpleNamespace(left_out={})
    assert decide._pick(prob, ok, base, sel) == "dead_time"
    why = sel.left_out["velocity_filter"]
    assert why.kind == "rival_better" and why.causes == ("dead_time",) and 0 < why.rows < 200
    # the sentence says on which rows it is far better, not over the whole log
    assert reason(why) == (
        f"dead_time matches the speed itself far better on the {why.rows} samples where the "
        "two models differ"
    )


@PAIR_8
def test_a_stall_on_a_rise_is_not_said_to_leave_the_speed_running_on():
    # tuning pair seed 8 (dry friction, a 9-tap average): the logger stalls 125 ms at
    # 10.53 s while the speed rises (-0.9, then -1.0 and -6.5 rad/s after the gap, -20 ten
    # rows on). The rows around the gap spread 25 rad/s: there is no level the column could
    # run on at, so "the speed reads on as around it (-8.74 rad/s)" (the first cut of the
    # rows-lost-whole words, 17fdf83) was false; a stall keeps its own sentence
    log, r = checked(8, ("coulomb_friction", "velocity_filter"))
    art = [a for a in r.anomalies if a.kind == "logging_artefact"]
    assert art
    for a in art:
        assert not a.facts.runs_on
        assert "reads on" not in anomaly(a)


def test_a_coast_with_dry_friction_is_named_although_neither_is_clear_alone():
    # tuning2 pair seed 920006: a coast of 0.93 s with a 0.52 V friction at 25 ms samples.
    # The friction's constant deceleration shortens the coast, which alone reads no slower
    # than braking; friction alone cuts 6 % of the whitened residual. No single cause was
    # clear, the pair was never fitted, and the log was named 'none' although the
    # first-order model misses it by far more than its noise
    log = make(920006, ("coulomb_friction", "coast_on_zero"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["coast_on_zero", "coulomb_friction"]
    assert not r.finding.ambiguous_with
    p = r.extended.params
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert p["T_coast"] == pytest.approx(log.causes["coast_on_zero"], rel=0.05)
    assert p["u_c"] == pytest.approx(log.causes["coulomb_friction"], rel=0.05)


AVERAGE_WITH_A_PARTNER = [
    pytest.param(
        920000,
        ("dead_time", "velocity_filter"),
        "delay",
        # a 15-tap average after a 41 ms delay at 10 ms samples. The first pass reads both
        # within 2 %; an average alone (25 taps) was refused for its scatter, and the pass
        # that chose again with that test relaxed started from it and ended on an 18-tap
        # average with a 29 ms pole, no ambiguity said
        id="not-chosen-again-from-the-average-alone",
    ),
    pytest.param(
        920005,
        ("second_pole", "velocity_filter"),
        "T2",
        # a 2-tap average with a driver's pole of 121 ms at 10 ms samples. The pole and the
        # 2-tap average leave 11 % of the plain speed error of a 21-tap average alone, but
        # the whitened sums of the two stride differently, and in theirs the pair was no
        # clear gain: the average alone was named, T 12 % long
        id="judged-on-the-speed-where-the-lengths-differ",
    ),
    pytest.param(
        920005,
        ("dead_time", "velocity_filter"),
        "delay",
        # a 2-tap average after a 76 ms delay at 10 ms samples. The length scan beside the
        # delay, led by the whitened sums, found 8 taps and a 48 ms delay, which the speed's
        # scatter refuses, and the delay alone was named; 2 taps and the delay leave 4 % of
        # the delay's plain speed error alone
        id="fitted-from-the-short-lengths-when-refused",
    ),
]
"""Tuning2 pairs of an average and a partner (seed, causes, the partner's parameter) that
s38-wrong's changes to decide.select name right, each with what went wrong before."""


@pytest.mark.parametrize(("seed", "causes", "partner"), AVERAGE_WITH_A_PARTNER)
def test_an_average_and_its_partner_are_named_with_their_lengths(seed, causes, partner):
    log = make(seed, causes)
    r = check(log.t, log.u, log.omega)
    assert named(r) == list(causes)
    p = r.extended.params
    assert p["taps"] == log.causes["velocity_filter"]
    other = next(c for c in causes if c != "velocity_filter")
    assert p[partner] == pytest.approx(log.causes[other], rel=0.05)
    assert p["T"] == pytest.approx(log.T, rel=0.05)


def test_a_deeper_valley_a_third_cause_found_at_rest_is_taken_for_the_pair():
    # tuning3 pair seed 930004: dry friction beside a 22-tap average at 20 ms samples. The
    # pair was fitted to 26 taps with T 26 % short; the thirds fitted beside it (a pole, a
    # delay) came to rest at 0 with 22 taps and T within 0.2 %, leaving 1 % of the pair's
    # plain speed error, and were refused as acting within a sample, so the better fit of
    # the very pair was thrown away with them
    log = make(930004, ("coulomb_friction", "velocity_filter"))
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["coulomb_friction", "velocity_filter"]
    assert not r.finding.ambiguous_with
    p = r.extended.params
    assert p["taps"] == log.causes["velocity_filter"]
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert p["u_c"] == pytest.approx(log.causes["coulomb_friction"], rel=0.05)


@pytest.mark.parametrize(
    ("seed", "side"),
    [
        # a 59 ms delay and a logger's IIR filter of 151 ms at 10 ms samples (T 346 ms)
        pytest.param(930000, "iir", id="a-loggers-filter"),
        # a 13 ms delay and a coupling of 54 ms at 10 ms samples (T 105 ms)
        pytest.param(930011, "coupling", id="a-coupling"),
    ],
)
def test_of_two_lags_that_fit_alike_in_either_order_the_faster_is_the_pole(seed, side):
    # tuning3 pair seeds 930000 and 930011: beside a delay nothing tells the wheel's lag from
    # the pole's, the two orders fit the same, and both logs were named with T and T2
    # swapped (T 0.45 and 0.51 of the truth)
    log = make(seed, ("dead_time", "second_pole"))
    assert side in log.how
    r = check(log.t, log.u, log.omega)
    assert named(r) == ["dead_time", "second_pole"]
    p = r.extended.params
    assert p["T"] == pytest.approx(log.T, rel=0.05)
    assert p["T2"] == pytest.approx(log.causes["second_pole"], rel=0.1)
    assert p["T2"] < p["T"]


def test_a_rival_the_speed_itself_prefers_is_named_when_the_whitened_margin_is_thin():
    # tuning3 pair seed 930001: a 26 ms delay beside dry friction at 25 ms samples read by
    # timed edges. Named friction and a 35 ms pole, no ambiguity said, while the true pair
    # left 1.106 times the pole's whitened residual (the bar: 1.1) and 0.83 times its plain
    # speed error: the two measures disagree, so the log cannot tell them apart
    log = make(930001, ("coulomb_friction", "dead_time"))
    r = check(log.t, log.u, log.omega)
    assert ["coulomb_friction", "dead_time"] in [sorted(a) for a in r.finding.ambiguous_with]
    told = [c for c in r.finding.caveats if c.kind == "cannot_tell"]
    split = [c for c in told if c.facts.compared == "split"]
    assert split
    f = split[0].facts
    assert f.ratio > 1.1 and 0.0 < f.squared < 1.0
    words = caveat(split[0])
    assert f"{f.ratio:.2f} times the whitened residual" in words
    assert f"{f.squared:.2f} times the squared speed error of the first" in words
    assert f"{f.squared:.2f} times" in caveat_plain(split[0])


def test_a_wheel_that_moves_only_in_its_switch_on_glitch_is_refused():
    # tuning3 pair seed 930000 of dry friction and a cap: the friction is above what the
    # capped current can drive, so the wheel never turns; one glitch row at the start reads
    # 159 rad/s. The glitch repaired, the speed is 0 on every row, and the check named
    # 'none' with T 3.3 ms and K 0, a model of a wheel it never saw turn. The check reads
    # the first two rows as the glitch (row 1 the fast one), as its start_glitch note does
    log = make(930000, ("coulomb_friction", "current_limit"))
    assert np.flatnonzero(log.omega).tolist() == [1]
    with pytest.raises(LogRefused) as e:
        check(log.t, log.u, log.omega)
    assert e.value.why == SpeedStill(0.0, 2)
    words = refusal_words(e.value.why)
    assert words.endswith("omega stays at 0 rad/s after the first 2 rows, a switch-on glitch")
