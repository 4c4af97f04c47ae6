"""Every sentence of the model check true of the log in hand (issue 17, item 7): hostile but
valid logs from the independent generator (tests/model/physics_gen.py), each read as a lab
assistant reads ``minseg-tui analyze``, and the sentence that was false on it pinned."""

import math

import numpy as np

from minseg_tui.model.check import check, text
from tests.model import physics_gen as pg


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
    m: pg.Motor, at: list[float], vals: list[float], t_end: float, ts: float = 0.01, cpr: int = 720
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(t s, u V, omega rad/s): late-only jitter of 0.3 ms, Euler speed of counts over ts."""
    rng = np.random.default_rng(1)
    n = int(t_end / ts)
    t = np.arange(n) * ts + rng.uniform(0.0, 3e-4, n)
    grid, _, th = pg.simulate(
        m, float(t[-1]) + ts, np.array(at), np.array(vals), (math.inf, math.inf, 0.0)
    )
    counts = np.floor(np.interp(t, grid, th) * cpr / (2 * math.pi) + 0.37)
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
    judged = {c.cause: c.text for c in r.finding.caveats if c.kind == "cannot_judge"}
    if "coulomb_friction" in judged:
        assert "one size of voltage only (12 V, forward and reversed)" in judged["coulomb_friction"]
