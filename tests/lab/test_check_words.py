"""The model check told to a student (issue 20, item 4): on seeded logs of every cause, the
sentences speak of the step the close-up shows, name the cause in everyday words, and give
the gain in the figure that leads, whichever it is (the held-out error too)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from minseg_tui.lab.views import check_text, check_words
from minseg_tui.lab.views.check_says import evidence
from minseg_tui.model.check.effects import NAMES
from tests.lab.checked_logs import GROUP, synth

NUM = r"[0-9]+(?:\.[0-9]+)?"
JARGON = ("whitened", "criterion", "residual", "interval", "noise floor", "_")


pytestmark = GROUP
"""Every log here is synth's, checked once per process (tests/lab/checked_logs.py), and
test_check_plain.py reads the seed-3 logs too: one worker checks each."""


@pytest.mark.parametrize("cause", NAMES)
def test_the_sentences_speak_of_the_close_up_in_everyday_words(cause):
    log, r = synth(cause)
    lead = check_words.lead(r, log.u)
    text = " ".join(lead)
    assert 1 <= len(lead) <= 3
    for word in JARGON:
        assert word not in text, (word, text)
    m = re.search(rf"(?:drops|steps) from ({NUM}) V to ({NUM}) V at t = ({NUM}) s", text)
    assert m is not None, text
    cu = r.close_up
    assert cu is not None and cu.t0 < float(m.group(3)) < cu.t1
    # the step it names is in the log: the voltage changes there
    k = int(np.searchsorted(log.t, float(m.group(3)) - 1e-9))
    assert log.u[k] != log.u[k - 1]
    if r.finding.cause != "none":
        assert f"Likely cause: {check_words.everyday(r)}." in text
        b, e = check_text.figure(r.gain, r.lead.figure)
        assert b is not None and e is not None
        shown = re.search(rf"falls from ({NUM}) (rad/s|rad) to ({NUM}) (rad/s|rad)", text)
        assert shown is not None, text  # the held-out figure leads too: it was left out
        assert float(shown.group(1)) == pytest.approx(b, rel=0.05)
        assert float(shown.group(3)) == pytest.approx(e, rel=0.05)


def test_a_log_the_first_order_model_explains_says_so():
    log, r = synth("none")
    assert r.finding.cause == "none"
    (said,) = check_words.lead(r, log.u)
    assert "follows the measured speed to within its noise" in said


def test_a_hand_on_the_wheel_is_said_as_such():
    log, r = synth("none", touch=True)
    assert r.close_up is not None and r.close_up.cause == "disturbance"
    assert "something braked the wheel" in check_words.lead(r, log.u)[0]


def test_without_the_input_the_first_sentence_stays_general():
    log, r = synth("coulomb_friction")
    first = check_words.lead(r, None)[0]
    assert "misses the measured speed" in first and "t =" not in first


def test_the_held_out_figure_is_found_under_its_own_keys():
    gain = {"heldout_baseline_rmse": 0.4, "heldout_extended_rmse": 0.1, "baseline_rmse": 1.0}
    assert check_text.figure(gain, "heldout_extended_rmse") == (0.4, 0.1)
    assert check_text.figure(gain, "heldout_rmse") == (0.4, 0.1)
    assert check_text.figure(gain, "extended_rmse") == (1.0, None)
    assert check_text.figure(gain, "angle_rms") == (None, None)


@pytest.mark.parametrize("cause", ["coulomb_friction", "coast_on_zero"])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_lead_the_evidence_and_the_close_up_speak_of_one_drop(cause, seed):
    """The walk's Details named the drop at 4.625 s while the lead and the close-up showed
    the one at 1.62 s: the evidence took the fastest stop, the close-up the first drop."""
    log, r = synth(cause, seed=seed)
    assert r.finding.cause == cause
    said = re.search(rf"drops (?:to 0 )?at t = ({NUM}) s", evidence(r.finding))
    assert said is not None, evidence(r.finding)
    lead = " ".join(check_words.lead(r, log.u))
    led = re.search(rf"drops from {NUM} V to {NUM} V at t = ({NUM}) s", lead)
    assert led is not None, lead
    assert float(led.group(1)) == pytest.approx(float(said.group(1)), abs=5e-4)
    cu = r.close_up
    assert cu is not None and cu.t0 < float(said.group(1)) < cu.t1


@pytest.mark.parametrize("cause", ["coulomb_friction", "none"])
def test_the_first_sentence_names_the_model_it_simulated(cause):
    """The walk of 11-27: "the simple (first-order) model says it still turns at 0.27 rad/s"
    was read by a group as their own Task 14 model; it is the check's fit of the run, and the
    sentence says so with its T and K (the fitted ones, not the least-squares or the group's)."""
    log, r = synth(cause)
    first = check_words.lead(r, log.u)[0]
    T, K = r.baseline.params["T"], r.baseline.params["K"]
    m = re.search(
        rf"the first-order model the check fitted to this run \(T = ({NUM}) ms, "
        rf"K = ({NUM}) rad/s/V\)",
        first,
        re.I,
    )
    assert m is not None, first
    assert float(m.group(1)) == pytest.approx(T * 1e3, rel=0.005)
    assert float(m.group(2)) == pytest.approx(K, rel=0.005)
    assert "simple (first-order) model says" not in first


def test_every_cause_has_words_for_people():
    from minseg_tui.lab.views.check_says import CAUSE_WORDS, in_words
    from minseg_tui.model.check.effects import CANDIDATES

    assert all(
        CAUSE_WORDS[c.cause].label and "_" not in CAUSE_WORDS[c.cause].label for c in CANDIDATES
    )
    assert in_words("first_order+coulomb_friction+velocity_filter") == (
        "first order + dry friction + averaged speed (velocity filter)"
    )
    assert in_words("current_limit") == "current limit" and in_words("none") == "none"


def test_a_cause_within_the_first_sample_is_said_by_what_it_is():
    from minseg_tui.lab.views.check_says import reason
    from minseg_tui.model.check.decide import Reason

    said = reason(Reason("within_sample", cause="dead_time", value=0.004, ts=0.025))
    assert said.startswith("a delay of 4 ms, under a quarter of the 25 ms sample period")
    assert reason(Reason("within_sample", cause="second_pole", value=0.0031, ts=0.02)).startswith(
        "a pole of 3.1 ms, under a quarter of the 20 ms sample period"
    )
