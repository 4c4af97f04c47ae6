"""identify's sentences that no other test pinned whole, each on a seeded synthetic log or a
set table: written in lab/content/identify_says.py from the model's records (issue 19 item
4), and the same, character for character, as the model wrote them at e85640f."""

import numpy as np
import pytest

from minseg_tui.lab.content.identify_says import sentence
from minseg_tui.model.identify import Reading, identify
from minseg_tui.model.identify.observations import Observation
from minseg_tui.model.motor import MotorParams
from minseg_tui.model.plant import PlantParams
from minseg_tui.model.runlog import RunLog
from tests.model.identgen import make, table
from tests.model.test_identify import V_DROP, linear_table, plant_log


def _plant(J, half=4, high=4.5):
    m = MotorParams(R=5.0, k_v=0.5, k_a=0.325, f=6e-4, J=J)
    log = plant_log(PlantParams(motor=m, tau_c=0.0, v_drop=V_DROP), high=high, half=half)
    return identify(linear_table(m), 5.0, log)


def _cut():
    g = make(3)
    u = np.asarray(g.log.extra["u_req"])
    n = int(np.flatnonzero(np.diff(u) > 0)[-1]) + 2
    log = RunLog(
        t=g.log.t[:n],
        u=g.log.u[:n],
        omega=g.log.omega[:n],
        extra={k: v[:n] for k, v in g.log.extra.items()},
        source="cut.csv",
    )
    return identify(table(g.K), 5.0, log)


def _no_u_req():
    g = make(0)
    return identify(table(g.K), 5.0, RunLog(t=g.log.t, u=g.log.u, omega=g.log.omega, source="x"))


CASES = {
    "i_ss_units": lambda: identify(
        [
            Reading(2.0, 1.6, 16.0, 0.045),
            Reading(3.0, 2.6, 26.0, 50.0),
            Reading(4.0, 3.5, 35.0, 55.0, line=4),
        ],
        5.0,
    ),
    "i_ss_high": lambda: identify(
        [Reading(2.0, 1.6, 16.0, 145.0, line=2), Reading(3.0, 2.6, 26.0, 50.0)], 12.0
    ),
    "k_v_nonpositive": lambda: identify(
        [
            Reading(2.0, 0.2, 16.0, 60.0),
            Reading(3.0, 2.6, 26.0, 50.0),
            Reading(4.0, 3.5, 35.0, 55.0),
        ],
        5.0,
    ),
    "k_v_disagree": lambda: identify(
        [Reading(2.0, 1.6, 16.0, 45.0), Reading(4.0, 3.5, 25.0, 55.0)], 5.0
    ),
    "u_ss_from_log": _no_u_req,
    "several_levels": lambda: identify(table(make(1).K), 5.0, make(1).log),
    "u_ss_interpolated": lambda: _plant(1.3e-3, high=4.0),
    "step_vs_table": lambda: _plant(1.3e-2),
    "T_short": lambda: _plant(1.3e-3),
    "not_settled": lambda: _plant(1.3e-3),
    "T_not_determined": lambda: _plant(1.3e-4),
    "T_on_bound": lambda: _plant(1.3e-5),
    "steps_skipped": _cut,
}


SAID = {
    "i_ss_units": "row 1 (u_req 2 V): i_ss = 0.045 looks like amperes; the table wants mA (45 mA?).",
    "i_ss_high": "row 1 (u_req 2 V, line 2): i_ss = 145 mA is above 100 mA; the manual says the meter is probably measuring the wrong thing or is in the wrong mode.",
    "k_v_nonpositive": "row 1 (u_req 2 V): R i_ss = 0.300 V is not below u_ss = 0.2 V, so k_v comes out -0.00625; check R and i_ss.",
    "k_v_disagree": "The two rows give k_v = 0.08594 and 0.1290 V s/rad, 40 % apart: one is probably a bad reading, and with two rows the median cannot tell which. Measure a third voltage.",
    "u_ss_from_log": "The log has no u_req column, so K divides by the applied voltage the log recorded (1.55 V) instead of u_ss from the table.",
    "several_levels": "The rising edges go to several levels (2, 4 V); K is the median of omega_ss / u_ss over the steps and omega_ss the median of their speeds.",
    "u_ss_interpolated": "No table row has u_req = 4 V, the step's requested level; u_ss = 3.60 V is interpolated between the table's rows.",
    "step_vs_table": "The step at t = 0.501 s settles at 1.52 rad/s, but the table gives 8.05 rad/s at u_req = 4.5 V (81 % apart): the two experiments do not agree (a different wheel load, battery level, or a misread value).",
    "T_short": "T = 39.19 ms is shorter than 3 sample periods (Ts = 25 ms): the speed rises within a few samples. The 63 % reading, the manual's way, reads T off those samples, so the sampling and the velocity computation move it as much as the motor does; the least-squares T fits whole stretches of the run with the sampling modelled, so the two differ. Both are fair readings of T; the program's model and its least-squares J use the least-squares one.",
    "not_settled": "4 step(s) last less than 5 T (195.9 ms): the speed has not quite settled by their end, so omega_ss is the final speed of the fitted response rather than a reading of it (a mean over the end of a step would come out low); longer steps would check it.",
    "T_not_determined": "T's 95 % interval spans more than a factor of ten: T is not determined by this log; 1.586 ms is only the best fit. Longer steps, more of them, or a faster sampling would tell it.",
    "T_on_bound": "T = 1.248 ms ended on the bound of the range the fit tries (1.25 ms to 1.01 s): this log cannot tell T beyond it, and the first-order model does not describe it well.",
    "steps_skipped": "1 rise(s) were too short or too close to the start of the log to use.",
}


@pytest.mark.parametrize("code", list(CASES))
def test_a_sentence_reads_as_the_model_wrote_it(code):
    found = [o for o in CASES[code]().observations if o.code == code]
    assert len(found) == 1
    assert sentence(found[0]) == SAID[code]


def _records(cls):
    for sub in cls.__subclasses__():
        yield sub
        yield from _records(sub)


def test_every_finding_of_identify_has_its_words():
    """A record added to model/identify/observations.py without its sentence in
    identify_says would reach the screen as a TypeError: each has its own."""
    records = list(_records(Observation))
    assert len(records) >= 27
    fallback = sentence.dispatch(Observation)
    assert [r.__name__ for r in records if sentence.dispatch(r) is fallback] == []
    assert all(r.code for r in records)
