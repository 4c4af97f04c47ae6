"""The plant simulation against closed-form answers worked out by hand."""

import math

import numpy as np
import pytest

from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import Plant, PlantParams, record, square_wave

# A motor with round numbers: damping = R f + k_v k_a = 5*0.001 + 0.5*0.3 = 0.155
MOTOR = MotorParams(R=5.0, k_v=0.5, k_a=0.3, f=1e-3, J=1e-3)
T_HAND = 5.0 * 1e-3 / 0.155  # 0.032258 s
K_HAND = 0.3 / 0.155  # 1.935 rad/s/V


def linear(**kw) -> PlantParams:
    base = dict(motor=MOTOR, tau_c=0.0, v_drop=0.0, v_supply=12.0)
    base.update(kw)
    return PlantParams(**base)


def test_first_order_step_matches_closed_form():
    plant = Plant(linear())
    plant.set_command(4.0)
    for t in (0.01, 0.03, 0.1):
        plant.advance(t - plant.t)
        assert plant.omega == pytest.approx(K_HAND * 4.0 * (1 - math.exp(-t / T_HAND)), rel=1e-9)
    # angle is the integral of the speed
    t = plant.t
    theta_hand = K_HAND * 4.0 * (t - T_HAND * (1 - math.exp(-t / T_HAND)))
    assert plant.theta == pytest.approx(theta_hand, rel=1e-9)


def test_driver_loss_and_saturation():
    p = PlantParams(motor=MOTOR, v_drop=0.5, v_supply=5.0)
    assert p.u_applied(4.5) == pytest.approx(4.0)
    assert p.u_applied(-2.5) == pytest.approx(-2.0)
    assert p.u_applied(0.3) == 0.0
    assert p.u_applied(9.0) == pytest.approx(4.5)


def test_coulomb_friction_lowers_speed_and_sticks():
    tau_c = 0.006  # u_c = tau_c R / k_a = 0.1 V
    p = linear(tau_c=tau_c)
    assert p.u_coulomb == pytest.approx(0.1)
    plant = Plant(p)
    plant.set_command(3.0)
    plant.advance(1.0)
    assert plant.omega == pytest.approx(K_HAND * (3.0 - 0.1), rel=1e-9)
    # below breakaway it never starts
    still = Plant(p)
    still.set_command(0.09)
    still.advance(1.0)
    assert still.omega == 0.0 and still.theta == 0.0


def test_braking_with_dry_friction_stops_in_finite_time():
    p = linear(tau_c=0.006)
    plant = Plant(p, omega0=5.0)
    # brake: u = 0, omega' = (-omega - K u_c)/T; zero at T ln(1 + omega0/(K u_c))
    t_stop = T_HAND * math.log(1 + 5.0 / (K_HAND * 0.1))
    plant.advance(t_stop * 0.999)
    assert plant.omega > 0
    plant.advance(t_stop * 0.002)
    assert plant.omega == 0.0
    plant.advance(1.0)
    assert plant.omega == 0.0


def test_coast_runs_down_on_friction_alone():
    p = linear(zero_mode="coast")
    plant = Plant(p, omega0=5.0)
    plant.advance(0.5)
    assert plant.omega == pytest.approx(5.0 * math.exp(-0.5 * 1e-3 / 1e-3), rel=1e-9)
    assert plant.current == 0.0
    assert plant.u_A == pytest.approx(0.5 * plant.omega)  # terminals show the back-emf


def test_dead_time_delays_the_response():
    p = linear(dead_time=0.012)
    plant = Plant(p)
    plant.set_command(2.0)
    plant.advance(0.012)
    assert plant.omega == 0.0
    plant.advance(0.02)
    assert plant.omega == pytest.approx(K_HAND * 2.0 * (1 - math.exp(-0.02 / T_HAND)), rel=1e-9)


def test_extra_pole_gives_second_order_step():
    T2 = 0.01
    plant = Plant(linear(T2=T2))
    plant.set_command(2.0)
    t = 0.05
    plant.advance(t)
    a, b = T_HAND, T2  # y/Ku = 1 - (a e^-t/a - b e^-t/b)/(a - b)
    hand = K_HAND * 2.0 * (1 - (a * math.exp(-t / a) - b * math.exp(-t / b)) / (a - b))
    assert plant.omega == pytest.approx(hand, rel=2e-4)


def test_encoder_counts_720_per_revolution():
    plant = Plant(linear())
    plant.theta = 2 * math.pi
    assert plant.count == 720
    plant.theta = -0.5 * 2 * math.pi / 720
    assert plant.count == -1


def test_record_is_seeded_and_samples_on_the_board_clock():
    cmd = square_wave(0.0, 4.5, 40, 2, lead=4)
    a = record(PlantParams(), cmd, ts=0.025, seed=3, jitter_us=300)
    b = record(PlantParams(), cmd, ts=0.025, seed=3, jitter_us=300)
    c = record(PlantParams(), cmd, ts=0.025, seed=4, jitter_us=300)
    assert np.array_equal(a.count, b.count) and np.array_equal(a.t_us, b.t_us)
    assert not np.array_equal(a.t_us, c.t_us)
    lateness = a.t_us - np.arange(cmd.size) * 25000
    assert lateness.min() >= 0 and lateness.max() <= 300 and np.all(a.t_us % 4 == 0)
    assert cmd.size == 4 + 2 * 80
    # the published motor at 4.5 V request lands in the manual's ranges
    p = PlantParams()
    w = p.omega_ss(4.5)
    assert 5.0 < w < 8.5
    i_ss = (p.motor.f * w + p.tau_c) / p.motor.k_a
    assert 0.020 < i_ss < 0.050
