"""Two effects at once, and a hand on the wheel: the model check on generated logs.

Logs come from minseg_tui.model.synth (the plant, 720-count encoder, 300 us jitter, 20 s of
steps every second), seeded. Tolerances are those of the issue: both causes named and
nothing more, T within 15 %, each parameter within 25 % (taps within one); a touch reported
within 0.15 s of its start, and the log's own cause (or none) still named alone. The rates
over many seeds are printed by benchmarks/model_check_pairs.py.
"""

import itertools

import pytest

from minseg_tui.lab.views.check_says import close_up_what, evidence, other
from minseg_tui.model.check import check
from minseg_tui.model.synth import CAUSES, PARAM_RANGES, make_log, plant_with

PAIRS = list(itertools.combinations(PARAM_RANGES, 2))


def named(r):
    return sorted(c for c in [r.finding.cause, *(o.cause for o in r.finding.others)] if c != "none")


def close(cause, est, truth):
    if cause == "velocity_filter":
        return abs(est - truth) <= 1
    return abs(est - truth) <= 0.25 * truth


@pytest.mark.parametrize(("a", "b"), PAIRS)
def test_both_effects_are_named_with_both_parameters(a, b):
    log = make_log(a, seed=3001, also=b)
    r = check(log.t, log.u, log.omega)
    assert named(r) == sorted((a, b)), evidence(r.finding)
    # the extended model holds both: largest first, both parameters, one T and K
    assert r.extended.model == "first_order+" + "+".join(
        [r.finding.cause, *(o.cause for o in r.finding.others)]
    )
    t_true = plant_with(log.effects).motor.T
    assert r.extended.params["T"] == pytest.approx(t_true, rel=0.15)
    for c in (a, b):
        p = PARAM_RANGES[c][0]
        assert close(c, r.extended.params[p], log.effects[c]), (p, r.extended.params[p])
        lo, hi = r.extended.intervals[p]
        assert lo <= r.extended.params[p] <= hi
    # every sentence is about this log's own numbers; the others say what each adds
    assert all("taking it out of the model" in other(o) for o in r.finding.others)


@pytest.mark.parametrize("cause", CAUSES)
def test_a_hand_on_the_wheel_is_an_anomaly_not_a_cause(cause):
    log = make_log(cause, seed=4002, touch=True)
    assert log.touch is not None
    r = check(log.t, log.u, log.omega)
    found = [a for a in r.anomalies if a.kind == "disturbance"]
    assert len(found) == 1
    assert abs(found[0].t - log.touch[0]) <= 0.15
    assert found[0].t_end is not None and found[0].t_end >= log.touch[1] - 0.05
    assert found[0].size < 0  # it braked the wheel
    assert named(r) == ([] if cause == "none" else [cause])
    # the same log without the hand gives the same parameters: the touch was left out
    clean = check(*(lambda x: (x.t, x.u, x.omega))(make_log(cause, seed=4002)))
    for k, v in clean.extended.params.items():
        assert r.extended.params[k] == pytest.approx(v, rel=0.1, abs=0.002)


def test_the_close_up_shows_where_the_cause_acts():
    friction = check(*(lambda x: (x.t, x.u, x.omega))(make_log("coulomb_friction", seed=5)))
    cu = friction.close_up
    assert cu is not None and "step-down" in close_up_what(cu)
    # the window holds a fall of the input and the rows it names are those times
    u = make_log("coulomb_friction", seed=5).u
    assert any(u[k] < u[k - 1] for k in range(cu.start + 1, cu.end))
    assert friction.t[cu.start] == cu.t0 and friction.t[cu.end - 1] == cu.t1
    delay = check(*(lambda x: (x.t, x.u, x.omega))(make_log("dead_time", seed=5)))
    assert "rise" in close_up_what(delay.close_up)
    touch = make_log("none", seed=4002, touch=True)
    r = check(touch.t, touch.u, touch.omega)
    assert close_up_what(r.close_up).startswith("the stretch where something braked")
    assert r.close_up.t0 <= touch.touch[0] and r.close_up.t1 >= touch.touch[1]
