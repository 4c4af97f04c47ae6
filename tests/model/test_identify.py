"""Tasks 6-15: hand-computed table values, and T and K recovered from simulated run logs."""

import math
import re

import numpy as np
import pytest

from minseg_tui.lab.content.identify_says import as_json, identify_refusal, sentence
from minseg_tui.lab.content.log_says import angle_words
from minseg_tui.lab.content.u_ss_says import U_SS_SAYS, u_ss_words
from minseg_tui.model.identify import U_SS_HOW, Reading, identify, steady_state, u_ss_at
from minseg_tui.model.identify.refusals import (
    IdentifyRefused,
    MedianKvNotPositive,
    NoRisingEdge,
    RNotPositive,
    RowNotPositive,
)
from minseg_tui.model.identify.steady import table_of
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import PlantParams, record, square_wave
from minseg_tui.model.runlog import RunLog
from minseg_tui.quantities import format_number
from minseg_tui.signals import timestamp_velocity

R = 5.0
TABLE = [
    Reading(2.5, 2.1, 3.6, 30.0),
    Reading(3.5, 3.05, 5.5, 35.0),
    Reading(4.5, 4.0, 7.2, 40.0),
]


def codes(result):
    return [f.code for f in result.observations]


def test_table_by_hand():
    rows, k_v, k_a, f = steady_state(TABLE, R)
    kv_hand = [(2.1 - 5.0 * 0.030) / 3.6, (3.05 - 5.0 * 0.035) / 5.5, (4.0 - 5.0 * 0.040) / 7.2]
    assert [r.k_v for r in rows] == pytest.approx(kv_hand, rel=1e-12)
    assert k_v == pytest.approx(sorted(kv_hand)[1], rel=1e-12)
    assert k_a == pytest.approx(0.65 * sorted(kv_hand)[1], rel=1e-12)
    f_hand = [k_a * 0.030 / 3.6, k_a * 0.035 / 5.5, k_a * 0.040 / 7.2]
    assert [r.f for r in rows] == pytest.approx(f_hand, rel=1e-12)
    assert f == pytest.approx(sorted(f_hand)[1], rel=1e-12)


def test_falling_f_is_called_dry_friction_with_the_line_through_the_rows():
    result = identify(TABLE, R)
    assert "dry_friction" in codes(result)
    msg = next(sentence(f) for f in result.observations if f.code == "dry_friction")
    # k_a i = f w + tau_c through (3.6, k_a 0.030), (5.5, k_a 0.035), (7.2, k_a 0.040)
    w = np.array([3.6, 5.5, 7.2])
    torque = result.k_a * np.array([0.030, 0.035, 0.040])
    wm, tm = w.mean(), torque.mean()
    slope = ((w - wm) * (torque - tm)).sum() / ((w - wm) ** 2).sum()
    # tau_c in mN m beside f in mN m s/rad (it was N m beside mN m s/rad: walk 7, D10)
    assert f"tau_c = {format_number((tm - slope * wm) * 1e3)} mN m" in msg
    # f in mN m s/rad, as the table and Task 9's entry show it (it was N m s/rad here)
    # with the table's four digits (it had three here)
    assert f"viscous f = {format_number(slope * 1e3)} mN m s/rad" in msg
    f = sorted(row.f for row in result.rows)
    assert f"from {f[-1] * 1e3:.4g} mN m s/rad at" in msg
    assert " N m s/rad" not in msg.replace("mN m s/rad", "")


def test_constant_f_is_not_dry_friction():
    # i proportional to omega: f the same on every row
    rows = [
        Reading(2.5, 2.0, 4.0, 20.0),
        Reading(3.5, 3.0, 6.0, 30.0),
        Reading(4.5, 4.0, 8.0, 40.0),
    ]
    assert "dry_friction" not in codes(identify(rows, R))


def test_a_bad_row_is_named():
    rows = [*TABLE[:2], Reading(4.5, 4.0, 5.0, 40.0, line=4)]  # omega misread
    result = identify(rows, R)
    msgs = [sentence(f) for f in result.observations if f.code == "k_v_outlier"]
    assert len(msgs) == 1 and "row 3" in msgs[0] and "line 4" in msgs[0]


def test_current_in_amperes_is_pointed_out():
    rows = [Reading(2.5, 2.1, 3.6, 0.030), *TABLE[1:]]
    assert "i_ss_units" in codes(identify(rows, R))


@pytest.mark.parametrize("R_bad", [0.0, -5.0, math.nan])
def test_bad_R(R_bad):
    with pytest.raises(IdentifyRefused) as refused:
        identify(TABLE, R_bad)
    assert isinstance(refused.value.why, RNotPositive)
    assert re.search("positive resistance", str(identify_refusal(refused.value)))


def test_zero_speed_row_is_refused_with_its_line():
    with pytest.raises(IdentifyRefused) as exc:
        identify([TABLE[0], Reading(3.5, 3.0, 0.0, 30.0, line=3)], R, source="t.csv")
    assert exc.value.why == RowNotPositive("omega_ss", 0.0)
    assert str(identify_refusal(exc.value)).startswith("t.csv:3: expected omega_ss > 0")


def test_u_ss_lookup_by_hand():
    rows, *_ = steady_state(TABLE, R)
    table = table_of(rows)
    assert table == [(2.5, 2.1), (3.5, 3.05), (4.5, 4.0)]
    assert u_ss_at(table, 3.5) == (3.05, "row")
    u, how = u_ss_at(table, 4.0)
    assert how == "interpolated" and u == pytest.approx(3.05 + (4.0 - 3.05) * 0.5)
    u, how = u_ss_at(table, 5.0)  # beyond the table: the 4.5 V row's drop of 0.5 V
    assert how == "extrapolated" and u == pytest.approx(4.5)


def test_u_ss_mapping_edges():
    table = [(4.5, 3.8), (2.5, 2.1)]  # order does not matter; a row needs only its u_ss
    assert u_ss_at(table, 4.5) == (3.8, "row")
    assert u_ss_at(table, -4.5) == (-3.8, "row")  # the sign follows u_req
    assert u_ss_at(table, 0.0) == (0.0, "off")
    assert u_ss_at([], 4.5) == (4.5, "requested")  # no u_ss yet: the drop is not known
    u, how = u_ss_at(table, 1.0)  # below the rows: the 2.5 V row's drop of 0.4 V
    assert how == "extrapolated" and u == pytest.approx(0.6)
    assert u_ss_at(table, 0.3) == (0.0, "extrapolated")  # never past 0 V
    u, how = u_ss_at([(4.5, 3.8), (4.5, 3.9)], 4.5)  # the same level twice: their mean
    assert how == "row" and u == pytest.approx(3.85)


# -- run logs from the plant ---------------------------------------------------------------

MOTOR = MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=1.3e-3)
DAMP = 5.0 * 6e-4 + 0.5 * 0.325  # R f + k_v k_a
T_TRUE = 5.0 * 1.3e-3 / DAMP
K_TRUE = 0.325 / DAMP
V_DROP = 0.4


def plant_log(params, high=4.5, seed=1, with_count=True, half=40, periods=4):
    rec = record(
        params, square_wave(0.0, high, half, periods, lead=20), ts=0.025, seed=seed, jitter_us=2000
    )
    extra = {"u_req": rec.u_req, "t_us": rec.t_us}
    if with_count:
        extra["count"] = rec.count
    omega = timestamp_velocity(rec.t, rec.count)
    return RunLog(t=rec.t, u=rec.u_A, omega=omega, extra=extra, source="log.csv")


def linear_table(motor, u_reqs=(2.5, 3.5, 4.5)):
    """Table rows a linear motor gives exactly: omega = K u_A, i = (u_A - k_v omega)/R."""
    K = motor.k_a / (motor.R * motor.f + motor.k_v * motor.k_a)
    out = []
    for u_req in u_reqs:
        u_a = u_req - V_DROP
        w = K * u_a
        out.append(Reading(u_req, u_a, w, (u_a - motor.k_v * w) / motor.R * 1e3))
    return out


@pytest.fixture(scope="module")
def linear_result():
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=V_DROP)
    return identify(linear_table(MOTOR), MOTOR.R, plant_log(params))


def test_linear_plant_recovers_the_motor(linear_result):
    r = linear_result
    assert r.k_v == pytest.approx(0.5, rel=1e-9)
    assert r.f == pytest.approx(6e-4, rel=1e-9)
    s = r.step
    assert s.T == pytest.approx(T_TRUE, rel=0.02)
    assert s.T_ci[0] < T_TRUE < s.T_ci[1]
    assert s.T_ci[1] - s.T_ci[0] < 0.05 * T_TRUE
    assert s.K == pytest.approx(K_TRUE, rel=0.01)
    assert s.u_ss == pytest.approx(4.5 - V_DROP)
    # J = T (R f + k_v k_a) / R with the identified values; the true J is 1.3e-3
    assert s.J == pytest.approx(s.T * (r.R * r.f + r.k_v * r.k_a) / r.R, rel=1e-12)
    assert s.J == pytest.approx(1.3e-3, rel=0.03)
    assert r.model.T == s.T and r.model.K == s.K
    assert r.omega_at_5V == pytest.approx(5.0 * s.K)


def test_63_percent_reading_lags_when_T_is_short(linear_result):
    s = linear_result.step
    # the Euler speed is half a sample late and the rise spans two samples
    assert s.T_63 > T_TRUE + 0.005
    assert "T_short" in codes(linear_result)
    assert "dry_friction" not in codes(linear_result)
    assert len(s.rises) == 4


def test_slow_motor_63_percent_reading_agrees():
    slow = MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=8e-3)  # T about 0.24 s
    T_slow = 5.0 * 8e-3 / DAMP
    params = PlantParams(motor=slow, tau_c=0.0, v_drop=V_DROP)
    r = identify(linear_table(slow), slow.R, plant_log(params, half=80, periods=2))
    assert r.step.T == pytest.approx(T_slow, rel=0.01)
    assert r.step.T_63 == pytest.approx(T_slow + 0.0125, abs=0.012)
    assert "T_short" not in codes(r)


def test_dry_friction_plant_and_log_without_count():
    params = PlantParams(motor=MOTOR, tau_c=7e-3, v_drop=V_DROP)
    log = plant_log(params, with_count=False, seed=5)
    r = identify(linear_table(MOTOR), MOTOR.R, log)
    assert angle_words(r.step.fit.angle_source).startswith("the omega column")
    assert r.step.T == pytest.approx(T_TRUE, rel=0.03)
    # omega_ss = K (u_A - tau_c R / k_a), lower than the linear table's row
    w_hand = K_TRUE * (4.5 - V_DROP - 7e-3 * 5.0 / 0.325)
    assert r.step.omega_ss == pytest.approx(w_hand, rel=0.01)
    assert "step_vs_table" not in codes(r)  # 2.6 % apart, under the 10 % threshold


def test_step_disagreeing_with_table_is_reported():
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=V_DROP)
    table = [Reading(x.u_req, x.u_ss, x.omega_ss * 1.2, x.i_ss) for x in linear_table(MOTOR)]
    assert "step_vs_table" in codes(identify(table, MOTOR.R, plant_log(params)))


def test_step_level_not_in_table_is_interpolated():
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=V_DROP)
    r = identify(linear_table(MOTOR, (2.5, 4.5)), MOTOR.R, plant_log(params, high=4.0))
    assert "u_ss_interpolated" in codes(r)
    assert r.step.u_ss == pytest.approx(4.0 - V_DROP)
    assert r.step.K == pytest.approx(K_TRUE, rel=0.01)


def test_log_without_u_req_uses_the_applied_voltage():
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=V_DROP)
    full = plant_log(params)
    log = RunLog(t=full.t, u=full.u, omega=full.omega, extra={"count": full.extra["count"]})
    r = identify(linear_table(MOTOR), MOTOR.R, log)
    assert "u_ss_from_log" in codes(r)
    assert r.step.u_ss == pytest.approx(4.5 - V_DROP)


def test_k_divides_by_a_row_that_has_only_its_u_ss():
    """identify's u_ss_table holds rows the table of Tasks 6-9 leaves out: K follows it."""
    params = PlantParams(motor=MOTOR, tau_c=0.0, v_drop=V_DROP)
    log = plant_log(params)
    table = linear_table(MOTOR)
    u_45 = 4.5 - V_DROP  # the 4.5 V row's u_ss, its omega_ss and i_ss not measured yet
    partial = identify(table[:2], MOTOR.R, log, u_ss_table=[(2.5, 2.1), (3.5, 3.1), (4.5, u_45)])
    assert partial.step.u_ss_how == "row" and partial.step.u_ss == pytest.approx(u_45)
    assert partial.step.K == pytest.approx(partial.step.omega_ss / u_45)
    assert partial.step.K == pytest.approx(K_TRUE, rel=0.01)
    assert not any(o.code.startswith("u_ss_") for o in partial.observations)
    without = identify(table[:2], MOTOR.R, log)  # the 4.5 V row not given: extrapolated, said
    assert without.step.u_ss_how == "extrapolated"
    assert without.step.u_ss == pytest.approx(4.5 - V_DROP)  # the 3.5 V row's drop
    (found,) = [sentence(o) for o in without.observations if o.code == "u_ss_extrapolated"]
    assert "No table row has u_req = 4.5 V" in found and "extrapolated" in found


def test_log_with_only_a_falling_step_is_refused():
    t = np.arange(60) * 0.025
    u = np.where(t < 0.5, 4.0, 0.0)
    log = RunLog(t=t, u=u, omega=np.zeros(60), source="down.csv", lines=np.arange(60) + 2)
    with pytest.raises(IdentifyRefused) as exc:
        identify(TABLE, R, log)
    assert isinstance(exc.value.why, NoRisingEdge)
    assert str(identify_refusal(exc.value)).startswith("down.csv:2: expected a rising edge")


def test_json_shape(linear_result):
    j = as_json(linear_result)
    assert list(j) == [
        *("R", "rows", "k_v", "k_a", "f", "step", "model", "omega_at_5V"),
        "omega_at_5V_with_friction",
    ]
    assert list(j["rows"][0]) == ["u_req", "u_ss", "omega_ss", "i_ss", "k_v", "f"]
    # the contract's fields first and unchanged, then the added ones
    assert list(j["step"]) == [
        "K",
        "T",
        "T_63",
        "T_ci",
        "J",
        "omega_ss",
        "K_ci",
        "T_63_model",
        "T_63_note",
        "method",
        "shift",
        "u_c",
        "dead_time",
        "T_determined",
        "T_on_bound",
        "shift_on_bound",
        "glitch_rows",
        "left_out_rows",
        "T_rise_rows",
        "T_shift_free",
    ]
    assert list(j["model"]) == ["T", "K", "dead_time", "u_c", "K_above_u_c"]
    assert j["rows"][0]["i_ss"] == pytest.approx(linear_table(MOTOR)[0].i_ss)  # mA as entered
    assert len(j["step"]["T_ci"]) == 2
    assert list(as_json(identify(TABLE, R))) == ["R", "rows", "k_v", "k_a", "f"]


@pytest.mark.parametrize(
    ("zero_mode", "low", "with_u_req"),
    [
        ("coast", 0.0, True),
        ("coast", 0.0, False),
        ("brake", 2.5, True),
        ("coast", 2.5, False),
    ],
)
def test_T_recovered_when_the_wheel_coasts_or_keeps_moving(zero_mode, low, with_u_req):
    params = PlantParams(motor=MOTOR, tau_c=7e-3, v_drop=V_DROP, zero_mode=zero_mode)
    rec = record(params, square_wave(low, 4.5, 40, 4, lead=20), ts=0.025, seed=11, jitter_us=2000)
    extra = {"count": rec.count, "t_us": rec.t_us}
    if with_u_req:
        extra["u_req"] = rec.u_req
    log = RunLog(t=rec.t, u=rec.u_A, omega=timestamp_velocity(rec.t, rec.count), extra=extra)
    r = identify(linear_table(MOTOR), MOTOR.R, log)
    assert len(r.step.rises) == 4
    assert r.step.T == pytest.approx(T_TRUE, rel=0.03)
    if with_u_req or zero_mode == "brake":
        # without u_req a coasting wheel's voltage hides where the low level began, so only a
        # few rows before each step pin the slowing-down speed: T stays within 3 %, but the
        # interval (which assumes the model is exact) can miss by a hair
        assert r.step.T_ci[0] < T_TRUE < r.step.T_ci[1]


def test_a_table_whose_median_k_v_is_not_positive_is_refused():
    # R = 4 ohm: (2 - 4 * 0.125) / 3 = +0.5 and (1 - 4 * 0.375) / 1 = -0.5, median 0
    rows = [Reading(2.5, 2.0, 3.0, 125.0, line=2), Reading(1.5, 1.0, 1.0, 375.0, line=3)]
    with pytest.raises(IdentifyRefused) as refused:
        identify(rows, 4.0, source="t.csv")
    assert isinstance(refused.value.why, MedianKvNotPositive)
    assert re.search("positive k_v", str(identify_refusal(refused.value)))


def test_every_way_u_ss_is_found_is_said_in_words():
    """Each provenance u_ss_at gives (and 'log', a log without u_req) has its words, and the
    detail names the levels where it needs them: the model gives the code, its words are in
    lab/content/u_ss_says.py, in the model's order (least direct first)."""
    table = [(2.5, 2.1), (4.5, 4.0)]
    found = {u_ss_at(table, lv)[1] for lv in (0.0, 2.5, 3.5, 6.0)} | {u_ss_at([], 3.5)[1]}
    assert found | {"log"} == set(U_SS_HOW)
    assert tuple(U_SS_SAYS) == U_SS_HOW
    assert all(u_ss_words(how) != how for how in U_SS_HOW)
    assert u_ss_words("extrapolated") == "extrapolated from the table"
    assert u_ss_words("extrapolated", [4.5, 4.5]) == (
        "extrapolated from the table: no table row at 4.5 V, the nearest row's driver drop"
    )
    assert u_ss_words("interpolated", [3.5, 2.5]) == (
        "interpolated between the table's rows: no row at 2.5 V and 3.5 V"
    )
    assert u_ss_words("row", [4.5]) == "the table's row"
    assert u_ss_words("log", []) == "the log's applied voltage: it has no u_req column"
