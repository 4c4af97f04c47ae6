"""The test generator: logs with one or two hidden effects, and a hand on the wheel."""

import math

import numpy as np
import pytest

from minseg_tui.model.synth import PARAM_RANGES, make_log, plant_with


def test_two_effects_are_both_in_the_plant_and_in_the_truth():
    log = make_log("coulomb_friction", seed=8, also="coast_on_zero")
    assert set(log.effects) == {"coulomb_friction", "coast_on_zero"}
    p = plant_with(log.effects)
    assert p.zero_mode == "coast" and p.u_coulomb == pytest.approx(log.effects["coulomb_friction"])
    assert p.motor.J / p.motor.f == pytest.approx(log.effects["coast_on_zero"])
    for cause, value in log.effects.items():
        _, lo, hi = PARAM_RANGES[cause]
        assert lo <= value <= hi


def test_a_filter_as_second_effect_averages_the_speed():
    log = make_log("dead_time", seed=9, also="velocity_filter", also_param=12)
    assert log.taps == 12 and log.effects["velocity_filter"] == 12
    euler = np.diff(log.count) * (2 * math.pi / 720) / 0.025
    k = 400
    assert log.omega[k] == pytest.approx(np.mean(euler[k - 12 : k]))


def test_the_same_seed_gives_the_same_log():
    a = make_log("second_pole", seed=11, also="current_limit", touch=True)
    b = make_log("second_pole", seed=11, also="current_limit", touch=True)
    assert np.array_equal(a.count, b.count) and a.effects == b.effects and a.touch == b.touch


def test_a_current_limit_caps_the_acceleration():
    log = make_log("current_limit", param=30.0, seed=12, jitter_us=0.0)
    w = log.omega_true
    acc = np.diff(w) / np.diff(log.t)
    # no faster than the cap (the viscous load only takes from it); without it the
    # first-order start would reach K u / T = 1.98 * 3.55 / 0.043 = 160 rad/s^2
    assert acc.max() <= 30.0 * 1.001
    assert acc.max() >= 25.0


def test_a_hand_on_the_wheel_slows_it_in_a_settled_stretch():
    log = make_log("none", seed=13, touch=True)
    assert log.touch is not None
    a, b = log.touch
    assert 0.15 <= b - a <= 0.3
    inside = (log.t > a + 0.1) & (log.t < b)
    k0 = int(np.searchsorted(log.t, a))
    before = log.omega_true[k0 - 3 : k0]
    assert np.all(log.u_req[k0 - 14 : int(np.searchsorted(log.t, b)) + 10] == log.u_req[k0])
    assert log.omega_true[inside].max() < 0.8 * before.min()


@pytest.mark.parametrize(
    ("kw", "says"),
    [
        ({"cause": "dead_time", "also": "dead_time"}, "another cause"),
        ({"cause": "none", "also": "dead_time"}, "not none"),
        ({"cause": "dead_time", "also": "wind"}, "unknown cause"),
    ],
)
def test_impossible_combinations_are_refused(kw, says):
    with pytest.raises(ValueError, match=says):
        make_log(seed=1, **kw)
