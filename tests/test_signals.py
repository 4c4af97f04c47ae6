"""Angle and velocity from encoder counts, against values worked out by hand."""

import math

import numpy as np
import pytest

from minseg_tui.signals import (
    angle,
    euler_velocity,
    lab_velocity,
    moving_average,
    timestamp_velocity,
)


def test_angle_scaling_is_2pi_per_720_counts():
    assert angle([0, 720, -360]) == pytest.approx([0.0, 2 * math.pi, -math.pi])


def test_euler_velocity_uses_the_nominal_period():
    th = np.array([0.0, 0.1, 0.3, 0.6])
    assert euler_velocity(th, 0.025) == pytest.approx([0.0, 4.0, 8.0, 12.0])


def test_moving_average_starts_from_rest_like_a_fir():
    x = np.ones(25)
    y = moving_average(x, 20)
    assert y[0] == pytest.approx(0.05)
    assert y[9] == pytest.approx(0.5)
    assert y[19:] == pytest.approx(np.ones(6))
    assert moving_average([2.0, 4.0, 6.0], 2) == pytest.approx([1.0, 3.0, 5.0])


def test_lab_velocity_of_a_constant_speed_settles_after_20_samples():
    # 10 counts per 25 ms sample = 10 * 2pi/720 / 0.025 rad/s
    counts = np.arange(40) * 10
    w = lab_velocity(counts)
    expected = 10 * 2 * math.pi / 720 / 0.025
    assert w[20:] == pytest.approx(np.full(20, expected))
    assert w[10] < expected


def test_timestamp_velocity_is_immune_to_late_samples():
    # constant 34.9 rad/s; the samples come late by varying amounts, counts follow the true time
    t = np.array([0.0, 0.0251, 0.0503, 0.0749, 0.1012])
    speed = 2 * math.pi / 720 * 4000  # 4000 counts per second
    counts = np.round(t * 4000)  # 0, 100, 201, 300, 405
    w = timestamp_velocity(t, counts)
    assert w[0] == 0.0
    assert np.all(np.abs(w[1:] - speed) < speed * 0.01)
    euler = euler_velocity(angle(counts), 0.025)
    assert np.max(np.abs(euler[1:] - speed)) > np.max(np.abs(w[1:] - speed))


def test_timestamp_velocity_over_a_window():
    t = np.arange(10) * 0.01
    counts = np.arange(10) * 2
    w = timestamp_velocity(t, counts, window=0.05)
    rate = 2 / 0.01 * 2 * math.pi / 720
    assert w[1:] == pytest.approx(np.full(9, rate))
