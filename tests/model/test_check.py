"""The model check finds hidden effects in generated logs, and does not cry wolf.

Logs come from minseg_tui.model.synth: the real plant simulation (plant.record), 720-count
encoder, 300 us loop jitter, steps of 1.55/2.55/3.55 V (u_A) every second. The truth is
what the generator put in; tolerances are stated per cause.
"""

import math
import re
from dataclasses import replace

import numpy as np
import pytest

from minseg_tui.lab.content.log_says import refusal_words
from minseg_tui.lab.views.check_says import as_json, evidence, lead_why
from minseg_tui.model.check import check
from minseg_tui.model.check.effects import BY_CAUSE, CANDIDATES, effects_of
from minseg_tui.model.check.fit import whiten
from minseg_tui.model.check.simulate import Effects, Stretches, pieces
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import Plant, PlantParams
from minseg_tui.model.runlog import LogRefused, PeriodOutOfRange, SpeedStill, TooLarge
from minseg_tui.model.synth import make_log

# cause -> (absolute tolerance, relative tolerance) of its parameter: |est - true| <= abs +
# rel * true; a cause not here is held to DEFAULT_TOLERANCE
TOLERANCE = {
    "coulomb_friction": (0.02, 0.05),
    "dead_time": (0.003, 0.05),
    "velocity_filter": (1.0, 0.0),
    "coast_on_zero": (0.0, 0.15),
    "second_pole": (0.004, 0.15),
}
DEFAULT_TOLERANCE = (0.0, 0.05)
SEEDS = (101, 102, 103)
HIDDEN = sorted(c.cause for c in CANDIDATES if c.hidden is not None)
"""Every cause synth's make_log can hide (its entry's ``hidden``): a cause added to
CANDIDATES is tested here without a line of its own."""


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("cause", HIDDEN)
def test_finds_hidden_effect_and_its_parameter(cause, seed):
    log = make_log(cause, seed=seed)
    r = check(log.t, log.u, log.omega)
    assert r.finding.cause == cause, evidence(r.finding)
    name = BY_CAUSE[cause].param
    tol_abs, tol_rel = TOLERANCE.get(cause, DEFAULT_TOLERANCE)
    est = r.extended.params[name]
    assert abs(est - log.param) <= tol_abs + tol_rel * log.param, (est, log.param)
    # T and K stay those of the motor behind the effect (published T about 0.043 s)
    assert r.extended.params["T"] == pytest.approx(0.043, rel=0.1)
    assert r.extended.rmse <= r.baseline.rmse


@pytest.mark.parametrize("seed", (1, 2, 3, 4, 5))
def test_clean_first_order_data_is_none(seed):
    log = make_log("none", seed=seed, amplitudes=(3.0,) if seed % 2 else (2.0, 3.0, 4.0))
    r = check(log.t, log.u, log.omega)
    assert r.finding.cause == "none", evidence(r.finding)
    assert r.extended == r.baseline
    assert r.baseline.params["T"] == pytest.approx(0.043, rel=0.05)
    assert r.baseline.params["K"] == pytest.approx(1.98, rel=0.02)
    assert not r.anomalies


@pytest.mark.parametrize(
    ("cause", "seed"), [("none", 7), ("coulomb_friction", 8), ("velocity_filter", 9)]
)
def test_wild_sample_does_not_decide_and_is_reported(cause, seed):
    clean = make_log(cause, seed=seed)
    messy = make_log(cause, seed=seed, wild=True)
    assert messy.wild_row is not None
    a, b = check(clean.t, clean.u, clean.omega), check(messy.t, messy.u, messy.omega)
    assert b.finding.cause == a.finding.cause == cause
    for k, v in a.extended.params.items():
        assert b.extended.params[k] == pytest.approx(v, rel=0.02, abs=1e-3)
    wild = [x for x in b.anomalies if x.kind == "wild_sample"]
    assert [x.row for x in wild] == [messy.wild_row]


@pytest.mark.parametrize("seed", (11, 12))
def test_step_between_samples_is_an_anomaly_not_a_cause(seed):
    log = make_log("none", seed=seed, late_step=True)
    r = check(log.t, log.u, log.omega)
    assert r.finding.cause == "none"
    assert [a.row for a in r.anomalies if a.kind == "late_step"] == [log.late_step_row]


@pytest.mark.parametrize("seed", (21, 22))
def test_slow_creep_is_an_anomaly_not_a_cause(seed):
    log = make_log("none", seed=seed, creep=0.08)
    r = check(log.t, log.u, log.omega)
    assert r.finding.cause == "none"
    assert [a.kind for a in r.anomalies] == ["creep"]


def test_json_shape():
    log = make_log("dead_time", param=0.03, seed=5)
    d = as_json(check(log.t, log.u, log.omega))
    assert d["baseline"]["model"] == "first_order"
    assert set(d["baseline"]["params"]) == {"T", "K"}
    assert set(d["baseline"]) >= {"model", "params", "rmse", "fit_percent"}
    assert set(d["finding"]) >= {"cause", "evidence", "others"}
    assert d["finding"]["cause"] == "dead_time" and isinstance(d["finding"]["others"], list)
    assert set(d["extended"]["params"]) == {"T", "K", "delay"}
    assert "rmse_reduction_percent" in d["gain"]
    assert d["gain"]["rmse_reduction_percent"] == pytest.approx(
        100 * (1 - d["extended"]["rmse"] / d["baseline"]["rmse"])
    )


def test_reported_figures_recompute_from_predictions():
    log = make_log("second_pole", param=0.03, seed=6)
    r = check(log.t, log.u, log.omega)
    y = log.omega
    for fit, pred in ((r.baseline, r.baseline_pred), (r.extended, r.extended_pred)):
        assert fit.rmse == pytest.approx(math.sqrt(np.mean((y - pred) ** 2)), rel=1e-12)
        assert fit.fit_percent == pytest.approx(
            100 * (1 - np.linalg.norm(y - pred) / np.linalg.norm(y - y.mean())), rel=1e-12
        )


# -- the exact simulators against the plant (an independent implementation) ---------------

MOTOR = MotorParams(R=5.0, k_v=0.5, k_a=0.3, f=1e-3, J=1e-3)  # T = 0.032258 s, K = 1.935


def _plant_angles(params, times, values):
    plant = Plant(params)
    out = []
    ends = list(times[1:]) + [times[-1] + 0.3]
    for t0, t1, v in zip(times, ends, values, strict=True):
        plant.set_command(v)
        for tau in np.linspace(t0, t1, 7)[1:]:
            plant.advance(tau - plant.t)
            out.append((tau, plant.theta))
    return np.array(out)


FRICTIONLESS = MotorParams(R=5.0, k_v=0.5, k_a=0.3, f=0.0, J=1e-3)  # T = 0.0333 s, K = 2
A_MAX = 40.0  # rad/s^2


def _case(name):
    """(plant parameters, the same effects for the check's simulator) for one combination.

    The motor is frictionless where a current limit is in: the check's limit is a constant
    acceleration, the plant's a constant current (with viscous friction its acceleration
    falls as the speed rises)."""
    m = FRICTIONLESS if "cap" in name else MOTOR
    base = PlantParams(motor=m, tau_c=0.0, v_drop=0.0, v_supply=12.0)
    i_max = A_MAX * m.J / m.k_a
    t_coast = m.J / m.f if m.f else 25.0
    parts = {
        "fric": ({"tau_c": 0.009}, {"u_c": 0.009 * m.R / m.k_a}),
        "coast": ({"zero_mode": "coast"}, {"T_coast": t_coast}),
        "pole": ({"T2": 0.012}, {"T2": 0.012}),
        "cap": ({"i_max": i_max}, {"rate": A_MAX / m.K}),
    }
    plant, fx = {}, {}
    for part in name.split("+"):
        plant.update(parts[part][0])
        fx.update(parts[part][1])
    return replace(base, **plant), Effects(**fx), m


@pytest.mark.parametrize(
    "name",
    [
        "fric",
        "coast",
        "fric+coast",
        "pole",
        "pole+fric",
        "pole+coast",
        "cap",
        "cap+fric",
        "cap+pole",
        "cap+pole+fric",
    ],
)
def test_simulator_matches_the_plant(name):
    """Every combination the check simulates in closed form against the plant (an
    independent implementation: closed form per event, its extra pole sub-stepped)."""
    p, fx, m = _case(name)
    times, values = [0.0, 0.2, 0.45, 0.6, 0.9], [3.0, 0.0, 0.1, -2.0, 0.0]
    ref = _plant_angles(p, times, values)
    table = pieces(Stretches(np.array(times), np.array(values)), m.T, fx)
    # the plant sub-steps its extra pole (20 per T2): agreement to its accuracy there
    tol = 1e-4 if "pole" in name else 1e-9
    assert m.K * table.angle(ref[:, 0]) == pytest.approx(ref[:, 1], abs=tol)


def test_whitening_turns_differenced_noise_white():
    rng = np.random.default_rng(3)
    q = rng.uniform(-0.5, 0.5, 20000)
    for taps in (1, 5):
        diffed = np.concatenate((q[:taps], q[taps:] - q[:-taps]))
        e = whiten(diffed, taps)
        lag = np.corrcoef(diffed[taps:], diffed[:-taps])[0, 1]
        lag_w = np.corrcoef(e[taps:], e[:-taps])[0, 1]
        assert lag == pytest.approx(-0.5, abs=0.03)
        assert abs(lag_w) < 0.1


def test_effects_of_parameters():
    assert effects_of({"velocity_filter": 4.6, "dead_time": 0.02}) == Effects(taps=5, delay=0.02)


@pytest.mark.parametrize("seed", (41, 42))
def test_two_effects_name_the_main_one_and_list_the_other(seed):
    from dataclasses import replace

    from minseg_tui.model.plant import record
    from minseg_tui.model.synth import commands, plant_for

    p = replace(plant_for("coulomb_friction", 0.3), dead_time=0.03)
    u_req = commands(np.random.default_rng(seed), (2.0, 3.0, 4.0), 20.0)
    rec = record(p, u_req, seed=seed, jitter_us=300)
    omega = np.concatenate(([0.0], np.diff(rec.count) * (2 * math.pi / 720) / 0.025))
    u = np.array([p.u_applied(v) for v in u_req])
    r = check(rec.t, u, omega)
    assert r.finding.cause == "coulomb_friction"
    assert r.extended.params["u_c"] == pytest.approx(0.3, abs=0.02)
    assert [o.cause for o in r.finding.others] == ["dead_time"]
    assert r.finding.others[0].params["delay"] == pytest.approx(0.03, abs=0.003)


def test_where_it_deviates_with_an_exact_steady_state():
    from minseg_tui.lab.views.check_says import where
    from minseg_tui.model.check.deviations import Deviation

    text = where(
        [Deviation("after_rising_edges", 4, 0.2, 0.1), Deviation("steady_state", 5, 0.0, 0.0)]
    )
    assert "inf" not in text and "exact in steady state" in text and "0.200 rad/s" in text


@pytest.mark.parametrize(
    ("change", "says", "record"),
    [
        ({"omega": 0.0}, "omega stays at 0", SpeedStill),
        ({"t_scale": 1000.0}, "sample period", PeriodOutOfRange),
        ({"u_scale": 1e300}, "|u (V)| below", TooLarge),
    ],
)
def test_logs_it_cannot_work_on_are_refused_in_words(change, says, record):
    """The model refuses with a record (model/runlog), worded by lab/content/log_says."""
    log = make_log("none", seed=1, duration=3.0)
    t = log.t * change.get("t_scale", 1.0)
    u = log.u * change.get("u_scale", 1.0)
    omega = np.full_like(log.omega, change["omega"]) if "omega" in change else log.omega
    with pytest.raises(LogRefused) as refused:
        check(t, u, omega)
    why = refused.value.why
    assert isinstance(why, record)
    assert re.search(re.escape(says), refusal_words(why))


def test_a_none_finding_says_which_test_the_best_candidate_failed():
    """The evidence for `none` names the rule that held the best extension back."""
    from minseg_tui.lab.views.check_says import lost
    from minseg_tui.model.check.decide import PENALTY, Reason, Selection, Verdict
    from minseg_tui.model.check.fit import Fit
    from minseg_tui.model.check.pipeline import _none_runner

    def fit(causes, sse):
        return Fit(causes, 0.043, 2.0, Effects(), sse, 800)

    base, cand = fit((), 1.0), fit(("dead_time",), 0.2)

    def why(verdict, left_out=None):
        sel = Selection(base, base, {"dead_time": cand}, {"dead_time": verdict})
        sel.left_out.update(left_out or {})
        name, why = _none_runner(sel)
        return name, lost(why)

    name, few = why(Verdict(900.0, 0.10, False))
    assert name == "dead_time"
    assert "removes only 10.0 %" in few and "at least 25 %" in few
    threshold = PENALTY * math.log(800)
    _, weak = why(Verdict(threshold - 1, 0.78, False))
    assert "removes 78.0 %" in weak and "criterion gain" in weak and "only" not in weak
    _, held = why(Verdict(threshold + 100, 0.78, True), {"dead_time": Reason("bound", "upper")})
    assert "held back: its parameter sits on" in held


# -- sample times as they are ----------------------------------------------------------------


def _irregular(over_interval, seed=61, lost=()):
    """A clean first-order log sampled by a loop with 3-9 ms intervals (or a regular 5 ms
    clock that loses the samples in ``lost``), the speed from 720 counts over the real
    interval or over the nominal (median) one."""
    rng = np.random.default_rng(seed)
    if lost:
        t = np.delete(np.arange(1200) * 0.005, list(lost))
        ts = 0.005
    else:
        t = np.cumsum(rng.uniform(0.003, 0.009, 1200))
        t -= t[0]
        ts = float(np.median(np.diff(t)))
    u = np.where((t % 2.0) >= 1.0, 0.0, 3.0)
    u[t < 0.25] = 0.0
    plant = Plant(PlantParams(tau_c=0.0, v_drop=0.0, v_supply=12.0))
    count = np.empty(t.size, dtype=np.int64)
    for k in range(t.size):
        plant.advance(t[k] - plant.t)
        count[k] = plant.count
        plant.set_command(u[k])
    dth = np.diff(count) * (2 * math.pi / 720)
    div = np.diff(t) if over_interval else ts
    return t, u, np.concatenate(([0.0], dth / div)), ts


@pytest.mark.parametrize("over_interval", [True, False])
def test_irregular_samples_are_simulated_as_measured(over_interval):
    t, u, omega, _ = _irregular(over_interval)
    r = check(t, u, omega)
    assert r.sampling.how == "detected" and r.sampling.over_interval == over_interval
    assert not r.sampling.regular  # a loop without a clock: jitter, not lost samples
    assert "gap" not in [a.kind for a in r.anomalies]
    assert r.finding.cause == "none"
    assert r.baseline.params["T"] == pytest.approx(PlantParams().motor.T, rel=0.05)
    # simulated the way it was measured, the model misses by about the noise only (the
    # other way it would predict speed spikes after every long interval)
    assert r.baseline.rmse < 3.0 * r.gain.noise_floor


def test_lost_samples_on_a_regular_clock_are_gaps():
    t, u, omega, ts = _irregular(True, lost=(300, 301, 700))
    r = check(t, u, omega, ts=ts)
    assert r.sampling.regular and r.sampling.lost == 3
    assert [a.kind for a in r.anomalies] == ["gap"]
    assert r.finding.cause == "none"


def test_the_gain_survives_the_encoder_noise():
    """A 5 ms run of the virtual MinSeg (dry friction 0.12 V): quantisation (1.7 rad/s per
    count) dominates both rms errors, so the gain leads with the angle error, which shows
    the friction plainly, and says why."""
    from minseg_tui.model.plant import record

    p = PlantParams(v_drop=0.0, v_supply=12.0)  # the published MinSeg, with its dry friction
    u_req = np.tile(np.concatenate((np.zeros(200), np.full(200, 3.0))), 5)
    rec = record(p, u_req, ts=0.005, seed=7, jitter_us=300)
    omega = np.concatenate(([0.0], np.diff(rec.count) * (2 * math.pi / 720) / np.diff(rec.t)))
    r = check(rec.t, u_req, omega, cpr=720)
    assert r.finding.cause == "coulomb_friction"
    assert r.extended.params["u_c"] == pytest.approx(p.u_coulomb, rel=0.2)
    g = r.gain
    assert g.noise_floor == pytest.approx(2 * math.pi / 720 / 0.005 / math.sqrt(6))
    assert g.rmse_reduction_percent < 20  # the plain rmse hardly moves...
    assert g.extended_angle_rms < 0.5 * g.baseline_angle_rms  # ...the angle does
    assert r.lead.figure == "extended_angle_rms" and "noise" in lead_why(r.lead)
    assert g.heldout_extended_rmse <= g.heldout_baseline_rmse


def test_json_keeps_every_key_and_adds_what_the_ui_needs():
    """The keys the TUI, the report and the lab read stay; the new ones are there too."""
    log = make_log("coulomb_friction", seed=7, also="second_pole")
    d = as_json(check(log.t, log.u, log.omega))
    assert set(d) >= {"baseline", "finding", "extended", "gain", "deviations", "anomalies", "rows"}
    assert set(d) >= {"sampling", "lead", "close_up"}
    assert set(d["finding"]) >= {"cause", "evidence", "others", "caveats", "explained"}
    assert set(d["finding"]) >= {"runner_up", "runner_up_why"}
    assert set(d["gain"]) >= {
        "rmse_reduction_percent",
        "fit_percent_gain",
        "whitened_reduction_percent",
        "criterion_gain",
        "noise_floor",
        "noise",
        "baseline_above_floor",
        "extended_above_floor",
        "baseline_angle_rms",
        "extended_angle_rms",
        "angle_floor",
        "heldout_baseline_rmse",
        "heldout_extended_rmse",
    }
    assert d["lead"]["figure"] in d["gain"] and d["lead"]["why"]
    assert set(d["close_up"]) == {"t0", "t1", "row0", "row1", "what", "noise", "cause"}
    assert set(d["extended"]["intervals"]) == set(d["extended"]["params"])
    assert d["extended"]["model"] == "first_order+" + "+".join(
        [d["finding"]["cause"], *(o["cause"] for o in d["finding"]["others"])]
    )
    assert set(d["sampling"]) >= {"omega_over", "how", "regular", "lost_samples", "noise_floor"}
    for a in d["anomalies"]:
        assert set(a) >= {"kind", "row", "t", "t_end", "size", "unit", "text"}


def _fine(t_end, dt, u_of, T, rate, both):
    """The first-order model with a cap on the acceleration, by small Euler steps (K = 1):
    the cap holds while accelerating and, ``both``, while braking."""
    n = int(round(t_end / dt))
    w, out = 0.0, []
    for k in range(n + 1):
        out.append(w)
        acc = (u_of(k * dt) - w) / T
        s = math.copysign(1.0, w) if w != 0 else math.copysign(1.0, acc)
        if s * acc > rate or (both and -s * acc > rate):
            acc = math.copysign(rate, acc)
        w += dt * acc
    return np.array(out)


@pytest.mark.parametrize("both", [False, True])
def test_a_cap_while_braking_too_is_simulated_as_a_ramp_down(both):
    # 4 V for 0.6 s then 0: T = 0.1 s, cap 20 V/s (a_max 20 K rad/s^2). Braking from 4 V
    # asks for 40 V/s: with the cap on both ways the speed ramps down at 20 V/s
    T, rate = 0.1, 20.0
    st = Stretches(start=np.array([0.0, 0.6]), value=np.array([4.0, 0.0]))
    t = np.arange(0.0, 1.2, 0.005)
    tab = pieces(st, T, Effects(rate=rate, cap_both=both))
    w = np.diff(tab.angle(t)) / 0.005
    ref = _fine(1.2, 1e-5, lambda x: 4.0 if x < 0.6 else 0.0, T, rate, both)
    mid = np.interp(t[:-1] + 0.0025, np.arange(ref.size) * 1e-5, ref)
    assert np.max(np.abs(w - mid)) < 0.01
    fall = w[(t[:-1] > 0.61) & (t[:-1] < 0.65)]
    slope = np.polyfit(np.arange(fall.size) * 0.005, fall, 1)[0]
    assert slope == pytest.approx(-rate, rel=0.02) if both else slope < -1.3 * rate


def test_a_pole_on_the_measurement_lags_the_angle_exactly():
    # lag() against small Euler steps of tau y' = x - y, x straight between irregular samples
    from minseg_tui.model.check.simulate import lag

    rng = np.random.default_rng(3)
    t = np.cumsum(np.r_[0.0, rng.uniform(0.009, 0.012, 800)])
    x = 3.0 * np.sin(2.0 * t) + t
    tau, dt = 0.03, 2e-5
    fine_t = np.arange(0.0, t[-1], dt)
    fine_x = np.interp(fine_t, t, x)
    y = np.empty(fine_t.size)
    y[0] = x[0] - tau * (x[1] - x[0]) / (t[1] - t[0])
    for k in range(1, y.size):
        y[k] = y[k - 1] + dt / tau * (fine_x[k - 1] - y[k - 1])
    assert np.max(np.abs(lag(t, x, tau) - np.interp(t, fine_t, y))) < 1e-3
    # far shorter than a sample, and far longer than the log: no overflow, the right limits
    assert np.allclose(lag(t, x, 1e-7), x, atol=1e-4)
    assert np.all(np.isfinite(lag(t, x, 50.0)))


def test_a_residual_too_large_to_square_gives_unbounded_intervals_without_a_warning(monkeypatch):
    # a Task 10 run recorded on a busy machine once made the interval's residual overflow
    # numpy's squares: a RuntimeWarning (an error in these tests) inside fit.intervals. Here
    # the residual the intervals are worked out from is made that large on purpose: the
    # intervals are unbounded (the fit pins nothing down), the check's result stands
    from minseg_tui.model.check import fit, pipeline

    inside: list[bool] = []
    real_intervals, real_fit_k = fit.intervals, fit.Model.fit_k

    def intervals(*args, **kwargs):
        inside.append(True)
        try:
            return real_intervals(*args, **kwargs)
        finally:
            inside.pop()

    def fit_k(self, g, taps, cols=()):
        r, k, sizes = real_fit_k(self, g, taps, cols)
        return (r * 1e200 if inside else r), k, sizes

    monkeypatch.setattr(pipeline, "intervals", intervals)
    monkeypatch.setattr(fit.Model, "fit_k", fit_k)
    log = make_log("coulomb_friction", seed=1)
    r = check(log.t, log.u, log.omega)
    assert r.finding.cause == "coulomb_friction"
    lo, hi = r.baseline.intervals["K"]
    assert lo == -math.inf and hi == math.inf
