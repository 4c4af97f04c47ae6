"""The model check on real motors: ten run logs measured by others (../shared/data/
real-motors, see its README and each PROVENANCE.txt) and the probes made from them.

Each test pins what a look at the data supports (plots of data, predictions and residuals,
full and zoomed on the edges), with the reason in a comment, and no more: where a log
cannot show something (steps inferred from the speed, a filtered speed, one level only),
the test pins only what is certain (no crash, no false filter, no sentence about what the
log does not have). The NXT motor's own counts are tested end to end in
tests/cli/test_analyze.py.
"""

import re

import numpy as np
import pytest

from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.views.check_says import (
    anomaly as anomaly_words,
)
from minseg_tui.lab.views.check_says import (
    close_up_what,
    evidence,
    lead_why,
    resolution_how,
    runner_up_why,
    shown,
    where,
)
from minseg_tui.lab.views.check_text import text
from minseg_tui.model.check import CheckResult, check
from tests.model.realcheck import LOGS, PROBES, REAL, analyze, ev3_gap, logs, on

pytestmark = pytest.mark.shared_data


def causes(r: CheckResult) -> set[str]:
    return {r.finding.cause, *(o.cause for o in r.finding.others)} - {"none"}


def kinds(r: CheckResult, what: str = "caveats") -> list[str]:
    items = r.finding.caveats if what == "caveats" else r.anomalies
    return [x.kind for x in items]


def test_the_ten_logs_and_six_probes_are_there():
    assert len(LOGS) == 10 and len(PROBES) == 6


@pytest.mark.parametrize("name", logs(*LOGS, *PROBES))
def test_every_log_gets_a_result_whose_model_holds_all_it_names(name):
    r, words = analyze(name)
    # the extended model holds every cause named, largest first, each with its parameter
    # and a 95 % interval
    assert r.extended.model == "+".join(
        ["first_order", *(c for c in [r.finding.cause, *(o.cause for o in r.finding.others)])]
    ).replace("first_order+none", "first_order")
    for key in r.extended.params:
        lo, hi = r.extended.intervals[key]
        assert lo <= r.extended.params[key] <= hi
    # sentences that were false on these logs before, never again
    assert "step-downs stop in finite time" not in words
    assert "leaves 0." not in words  # "the next best explanation leaves 0.4x as much"
    assert "a coast no slower than braking)" not in words
    assert r.lead is not None and r.gain.has(r.lead.figure) and lead_why(r.lead)
    assert r.close_up is not None and r.close_up.start < r.close_up.end


# -- ev3-large-duty100 / duty30: EV3 large motor, one rise, 1 s, angle resampled to 5 ms ----
# A plain first-order rise (T ~ 80 / 60 ms) under a scatter far above the fit's error:
# duty100 scatters 3.4 rad/s (timing noise of the Python loop and the interpolation), duty30
# sits at ~1.3 counts per sample. Nothing else can be judged: one level, no step-down, and
# the first 20 ms are lost in the noise.


@pytest.mark.parametrize("name", logs("ev3-large-duty100", "ev3-large-duty30"))
def test_ev3_is_first_order_under_its_noise(name):
    r, words = analyze(name)
    assert r.finding.cause == "none" and r.finding.explained
    # the low fit % is explained by the noise, not presented beside a claim it contradicts
    assert r.baseline.fit_percent < 60
    assert "because that noise is large" in words
    # one level and no step-down: friction and coast cannot be judged, and it says so
    judged = [c.cause for c in r.finding.caveats if c.kind == "cannot_judge"]
    assert set(judged) == {"coulomb_friction", "coast_on_zero"}


# -- micromouse-n20: firmware polls the mode once a second, so motion starts late ---------


@on("micromouse-n20-duty255")
def test_micromouse_duty255_starts_355_ms_after_the_command():
    # first count at 1.135 s, command at 0.780 s: a dead time of ~0.35 s, far beyond the old
    # 0.15 s bound (which turned it into a 40-tap "filter"); then a fast first-order rise
    r, words = analyze("micromouse-n20-duty255")
    assert "first moves 355 ms later" in words  # first count at 1.135 s
    assert r.finding.cause == "dead_time"
    assert 0.30 <= r.extended.params["delay"] <= 0.40
    assert 0.015 <= r.extended.params["T"] <= 0.07
    assert "velocity_filter" not in causes(r)
    assert r.finding.explained


@on("micromouse-n20-duty100")
def test_micromouse_duty100_starts_late_too():
    # motion starts 30-40 ms after the logged mode change (first count at 0.500 s, command at
    # 0.460 s); at one count = 3.5 rad/s nothing finer can be judged
    r, words = analyze("micromouse-n20-duty100")
    assert r.finding.cause == "dead_time"
    assert 0.005 <= r.extended.params["delay"] <= 0.045
    assert "velocity_filter" not in causes(r)
    # the wheel stands at exactly 0 before the step, so its first count (one count, 3.5 rad/s,
    # at 0.500 s) is its first motion: the text says 40 ms, not the 55 ms at which the speed
    # first exceeds four times the noise of the moving wheel
    assert "first moves 40 ms later" in words


@on("mm255_aligned.csv")
def test_micromouse_aligned_probe_has_no_delay():
    # the duty-255 log with the step moved to the motion onset: a clean fast rise
    r, _ = analyze("mm255_aligned.csv")
    assert r.extended.params.get("delay", 0.0) <= 0.015
    assert "velocity_filter" not in causes(r)
    assert r.baseline.params["T"] == pytest.approx(0.044, rel=0.3)


# -- n20-12v: on/off instants inferred from the speed, so no dead time can be judged --------


@on("n20-12v-pwm255")
def test_n20_pwm255_coasts_against_dry_friction():
    # after the supply is cut (5.371 s) the wheel slows nearly linearly, its deceleration
    # falling from ~83 to ~42 rad/s^2, and stands still at 6.234 s: a free (coasting) wheel
    # stopped in finite time by dry friction. Both effects are in the run-down.
    r, words = analyze("n20-12v-pwm255")
    assert {"coast_on_zero", "coulomb_friction"} <= causes(r)
    assert not {"dead_time", "velocity_filter"} & causes(r)
    assert r.extended.params["T_coast"] > 5 * r.extended.params["T"]
    stop = re.search(r"stands still (\d+) ms later", words)
    assert stop and 700 <= int(stop.group(1)) <= 1000  # measured: 863 ms (never "17 ms")
    # its speed is counts over the real 10/11 ms interval divided by the nominal 10 ms
    assert r.sampling is not None and not r.sampling.over_interval


@on("n20-12v-pwm25")
def test_n20_pwm25_is_at_the_encoder_floor():
    # 5-6 counts per sample: the error of the first-order model is near the floor
    # (one count = 1.8 rad/s, floor 0.73 rad/s); the run-down ends abruptly at 16.726 s, but
    # a dead time, a filter, a pole or a current limit cannot be judged at this resolution
    r, _ = analyze("n20-12v-pwm25")
    assert not {"dead_time", "velocity_filter", "second_pole", "current_limit"} & causes(r)
    assert r.gain.noise_floor == pytest.approx(0.733, abs=0.01)
    assert r.baseline.rmse < 1.2 * r.gain.noise_floor


@on("n20-12v-pwm25")
def test_n20_pwm25_speed_before_the_cut_is_the_speed_the_wheel_ran_at():
    # the wheel ran at 8.8-9.2 rad/s (5 counts per sample, some 4s and 6s); the three rows
    # before the inferred cut read 8.98, 7.18, 7.18, whose median (7.18) was given as "the
    # speed before": the sentence now averages the 100 ms before the drop, and says so
    _, words = analyze("n20-12v-pwm25")
    before = re.search(r"from ([\d.]+) rad/s, its mean over the (\d+) ms before the drop", words)
    assert before, words
    assert 8.5 <= float(before.group(1)) <= 9.3
    assert "from 7.18 rad/s" not in words


@on("n20-12v-pwm25")
def test_n20_pwm25_fall_rate_is_the_slope_of_the_readings_not_one_count():
    # after the cut the wheel reads 8.98, then 7.18 for 60 ms, then 5.39 (one count = 1.8
    # rad/s): the two-point rate from the 100 ms mean (8.8) to that first 5.39 read 42.6 rad/s^2;
    # a line through the readings until half the speed gives 24-25 rad/s^2, a parabola
    # through the angle 22, and the wheel stands still 272 ms after the cut (8.8/0.272 = 32)
    _, words = analyze("n20-12v-pwm25")
    rate = re.search(r"the speed falls at ([\d.]+) rad/s\^2", words)
    assert rate, words
    assert 18 <= float(rate.group(1)) <= 32


@on("micromouse-n20-duty255", "micromouse-n20-duty100")
def test_an_extended_model_within_the_noise_is_not_said_to_be_all_noise():
    # duty 255: after the 345 ms delay is in the model its rms error (1.52 rad/s) is below the
    # speed's scatter (1.76 rad/s); "-> 0 rad/s" alone read like a perfect model. But its
    # error is not all noise: averaged over 0.25 s (where one-count noise falls to 0.07 rad/s,
    # a count over the block's time) it reads -1.08 after the rise and +0.80 at the end, a slow
    # drift no model here has; duty 100 the same (-1.29). The rms comparison is what is said
    for name in ("micromouse-n20-duty255", "micromouse-n20-duty100"):
        r, words = analyze(name)
        assert r.gain.extended_above_noise == 0
        assert "all noise" not in words
        rms = f"{r.extended.rmse:.3g}"
        assert f"-> 0 rad/s, the extended model's rms error ({rms} rad/s) is no larger" in words


@on("micromouse-n20-duty100")
def test_the_gain_details_give_the_error_above_the_noise_the_tui_shows():
    # duty 100: the TUI's panel lists "speed error above the noise first order 0.477 rad/s ->
    # extended 0" (scatter 1.52 rad/s; sqrt(1.592^2 - 1.52^2) = 0.47); the CLI's details line
    # gave the floor's figure only, so the TUI said what the CLI did not
    _, words = analyze("micromouse-n20-duty100")
    details = words.split("\nGain: ")[1].splitlines()[1]
    assert "speed error above the measured noise 0.477 -> 0 rad/s" in details, details


@on("mm255_aligned.csv")
def test_aligned_probe_is_not_said_to_be_explained_down_to_its_noise():
    # the first-order model's rms error (1.50 rad/s) is under the scatter (1.75), but after
    # the rise it misses in one direction for 200 ms: 20 ms means of its error +2.0, +3.4,
    # +1.3, 0, -1.1, -1.6, -2.2, -2.3, -1.1, -1.5, -1.7 rad/s (one count over 20 ms is 0.9),
    # and the deviations line says it is worst there. Only the rms comparison is said
    _, words = analyze("mm255_aligned.csv")
    assert "down to its noise" not in words
    assert "rms error is at the level of the speed's noise: 1.5 rad/s against" in words


@on("n20_255_uponly.csv")
def test_n20_probe_cut_before_the_run_down_says_nothing_of_stops():
    # the same rise without its run-down: nothing to see friction or coasting by
    r, words = analyze("n20_255_uponly.csv")
    assert not {"coast_on_zero", "coulomb_friction"} & causes(r)
    assert "stands still" not in words
    assert r.sampling is not None and not r.sampling.over_interval


# -- rtl-dc-5to15V: a smooth (tachometer or filtered) speed, 5 V -> 15 V, no step-down -----


@pytest.mark.parametrize("name", logs("rtl-dc-5to15V-noload", "rtl-dc-5to15V-brake"))
def test_rtl_offset_and_a_lag_it_cannot_attribute(name):
    # the steady speeds at 5 V and 15 V are not proportional to the voltage: the line through
    # them meets zero speed at ~0.71 / 0.73 V; the rise starts smoothly (S-shaped). No
    # step-down: no sentence about stopping; a smooth speed: a filter and an extra pole look
    # alike, and it says so
    r, words = analyze(name)
    assert "coulomb_friction" in causes(r)
    assert 0.5 <= r.extended.params["u_c"] <= 0.9
    assert "stands still" not in words and "the step-downs" not in words
    assert "no step-down" in words
    if {"velocity_filter", "second_pole"} & causes(r):
        assert "cannot_tell" in kinds(r)
    assert "starts_moving" in kinds(r, "anomalies")
    assert r.sampling is not None and r.sampling.smooth


# -- ubc-motor: a capped ramp bent by the drag, then a knee: a current limit --------------


@pytest.mark.parametrize(
    ("name", "lo", "hi"),
    [
        pytest.param("ubc-motor-7V", 500, 750, marks=on("ubc-motor-7V")),
        pytest.param("ubc-motor-9V", 500, 800, marks=on("ubc-motor-9V")),
    ],
)
def test_ubc_ramps_at_a_capped_acceleration(name, lo, hi):
    # the speed ramps almost straight (slope 520 -> 350 rad/s^2 at 7 V) to ~460 rad/s, then
    # bends into the plateau at a knee; the old check called it a 40-tap filter plus a
    # 0.12 s pole, both on their bounds. The ramp is not straight: under the cap the wheel's
    # viscous drag still brakes (the back-EMF no longer does), so the cap's a_max is the
    # acceleration at rest, above the slope seen later in the ramp (a straight ramp put it at
    # 462 and 529 rad/s^2, between the slopes, and missed the bend: rms 4.5 and 7.7 rad/s,
    # where the bent ramp leaves 2.4 and 4.3)
    r, words = analyze(name)
    assert r.finding.cause == "current_limit"
    assert lo <= r.extended.params["a_max"] <= hi
    assert "velocity_filter" not in causes(r)
    assert r.extended.rmse < 0.6 * {"ubc-motor-7V": 4.52, "ubc-motor-9V": 7.69}[name]


@pytest.mark.parametrize("name", logs("ubc-motor-7V", "ubc-motor-9V"))
def test_a_cap_is_not_said_to_brake_on_a_log_without_a_step_down(name):
    # one step up from rest and no step down: nothing in the log shows how the drive brakes,
    # so the evidence must not speak of the speed falling along a ramp after a step down
    r, words = analyze(name)
    assert r.finding.cause == "current_limit"
    assert "step down" not in evidence(r.finding)
    assert "both ways" not in words


@pytest.mark.parametrize(
    ("name", "slow"),
    [
        pytest.param("ubc-motor-7V", True, marks=on("ubc-motor-7V")),
        pytest.param("ubc-motor-9V", False, marks=on("ubc-motor-9V")),
    ],
)
def test_a_pole_beside_a_cap_is_judged_against_the_ramp_not_the_first_order_model(name, slow):
    # Beside a cap the first-order model starts steeper than the speed because of the cap
    # itself: "285 ms after the step the speed has risen 153 rad/s where the first-order
    # model rises 212" (9 V) was the cap's evidence told as the pole's "zero slope". Read off
    # the data: at 9 V the speed climbs 235 rad/s^2 over the first 20 ms and 474-583 from
    # then on, and after 285 ms it has risen 153 rad/s, what its own ramp at the measured
    # 516 rad/s^2 gives (146): no slow start at the pole's span; the fitted pair rounds the
    # knee into the plateau (the plot: the cap and pole model follows the knee at 1.7-2.0 s
    # within 2 rad/s). At 7 V the pole's span is 55 ms, where the speed has risen 17.1 rad/s
    # and its own ramp at 452 rad/s^2 24 rad/s: a slower start, which the sentence may say.
    r, _ = analyze(name)
    pole = next(o for o in r.finding.others if o.cause == "second_pole")
    said = shown(pole.evidence)
    ramp = re.search(
        r"has risen ([0-9.]+) rad/s,? (?:where|as) a straight ramp at its own "
        r"mean slope \(([0-9.]+) rad/s\^2, measured\) rises ([0-9.]+) rad/s",
        said,
    )
    assert ramp, said
    got, rate, rise = (float(x) for x in ramp.groups())
    assert 400 < rate < 600
    assert "first-order model rises" not in said
    if slow:
        assert got < 0.8 * rise and "starts with zero slope" in said
    else:
        assert got > 0.95 * rise and "starts at once, not with zero slope" in said
        assert "starts with zero slope (an S-shaped start)" not in said


@on("ubc7_2ms.csv", "ubc-motor-7V", "ubc7_20ms.csv")
def test_ubc_limit_does_not_follow_the_resampling_period():
    # the same 7 V log resampled at 2, 5 and 20 ms: the old "filter" length followed the
    # period (40, 40, 21 taps); the acceleration cap is a property of the motor
    found = [analyze(n)[0] for n in ("ubc7_2ms.csv", "ubc-motor-7V", "ubc7_20ms.csv")]
    assert [r.finding.cause for r in found] == ["current_limit"] * 3
    a = [r.extended.params["a_max"] for r in found]
    assert max(a) / min(a) < 1.07  # 580, 613, 608 rad/s^2 (the cap's acceleration at rest)


# -- the EV3 probes: raw irregular sample times -------------------------------------------


@on("ev3_100_irregular_actualdt.csv", "ev3_100_irregular_nominaldt.csv")
def test_irregular_times_are_jitter_and_the_speed_definition_is_detected():
    # 3.4-9 ms from a Python loop: an irregular clock, not lost samples; one probe's speed is
    # over the real interval, the other's over the nominal period (on a lattice of
    # 1 degree / 4.4 ms), and neither says so in a header
    actual, _ = analyze("ev3_100_irregular_actualdt.csv")
    nominal, _ = analyze("ev3_100_irregular_nominaldt.csv")
    for r in (actual, nominal):
        assert r.sampling is not None and not r.sampling.regular and r.sampling.how == "detected"
        assert "gap" not in kinds(r, "anomalies")
        assert r.finding.cause == "none"
    assert actual.sampling.over_interval and not nominal.sampling.over_interval
    # simulated the way each was measured, both give the same motor
    assert actual.baseline.params["T"] == pytest.approx(nominal.baseline.params["T"], rel=0.05)


# -- sentences checked against the data (independent fits and plots in the real-truth notes) --


@pytest.mark.parametrize("name", logs("micromouse-n20-duty100", "ubc-motor-7V", "ubc-motor-9V"))
def test_a_runner_up_that_misses_the_speed_more_is_not_said_to_fit_better(name):
    # The runner-up here is a 40-tap average (its bound). Fitted by hand (least squares on the
    # speed, first order followed by a 40-sample moving average) it misses the measured speed
    # far more than the named model: micromouse-100 1.93 rad/s rms against 1.49 for a 20 ms
    # delay (even the plain first order: 1.64); ubc-7V 12.8 against 4.4 for a current limit.
    # Its whitened residual is smaller only because an average's residual cancels in the
    # whitening sums; "leaves less whitened residual" alone reads as "fits better", which the
    # speed contradicts, so the sentence must say how the runner-up matches the speed.
    r, _ = analyze(name)
    why = runner_up_why(r.finding)
    # (on the ubc logs, since the cap's ramp bends with the drag, the named pair is a bent
    # cap with a pole and the runner-up the same cap with an average on its bound: 2.70
    # against 2.43 rad/s at 7 V, 4.46 against 4.32 at 9 V)
    assert "velocity_filter" in r.finding.runner_up.split("+")
    nums = re.search(r"rmse ([0-9.]+) rad/s against ([0-9.]+) rad/s", why)
    assert nums, why
    runner, named = float(nums.group(1)), float(nums.group(2))
    assert named == pytest.approx(r.extended.rmse, rel=5e-3)
    assert runner > (1.2 if name == "micromouse-n20-duty100" else 1.02) * named
    assert "misses the measured speed by more" in why


@pytest.mark.parametrize("name", logs("rtl-dc-5to15V-noload", "rtl-dc-5to15V-brake"))
def test_a_negligible_noise_does_not_lead_the_gain(name):
    # The tachometer speed scatters 0.01-0.05 rad/s from sample to sample (last 4 s: robust
    # and plain sd of the differences / sqrt 2), against model errors of 0.9-9 rad/s:
    # "the error above the noise" is the rms error to three digits, and "a noise that no
    # model can remove; only the part of the error above it tells the models apart" gives a
    # reason that does not hold here. The plain rms error leads, and the text says why.
    r, words = analyze(name)
    noise = r.gain.noise
    assert noise < 0.05 * r.extended.rmse
    assert r.lead.figure == "extended_rmse"
    assert "small against" in lead_why(r.lead)
    assert "Gain: rms error" in words


@pytest.mark.parametrize("name", logs("ev3-large-duty100", "ev3-large-duty30"))
def test_the_angle_lead_of_a_log_without_a_cause_speaks_of_one_model(name):
    # No cause is named (a plain first-order rise under its noise), so there is one model:
    # "the angle error tells them apart" spoke of two.
    r, words = analyze(name)
    assert r.finding.cause == "none" and r.lead.figure == "baseline_angle_rms"
    assert "tells them apart" not in lead_why(r.lead) and "models' difference" not in lead_why(
        r.lead
    )
    assert "the angle error judges the model" in lead_why(r.lead)


@on("n20_255_uponly.csv", "micromouse-n20-duty100")
def test_a_region_barely_worse_than_steady_state_is_not_called_the_worst():
    # n20 cut before its run-down: the first-order residual is 2.32 rad/s rms on the 15 rows
    # after the rise and 2.21 rad/s on the rest (computed from the predictions): the same
    # within the scatter (2.2 rad/s), so "the model is worst after rising edges (1.0x)" put
    # a weight on the rise that the data do not; micromouse-100 (1.6x) keeps its "worst".
    r, _ = analyze("n20_255_uponly.csv")
    assert where(r.deviations).startswith("the model is about equally good everywhere")
    # the larger of the two is still named, with its rms; each log has one rise, said so
    assert "after the rise: rms" in where(r.deviations)
    r2, _ = analyze("micromouse-n20-duty100")
    assert where(r2.deviations).startswith("the model is worst after the rise")


@pytest.mark.parametrize("name", logs("n20-12v-pwm255", "n20-12v-pwm25"))
def test_the_step_down_close_up_shows_the_wheel_stop(name):
    # "a step-down, where the wheel slows and stops": the raw speed is zero for good from
    # 6.234 s (pwm255, cut at 5.371 s) and 16.726 s (pwm25, cut at 16.454 s). The pwm255
    # window ended at 5.602 s, the wheel still at 35 rad/s: it showed no stop.
    stop = {"n20-12v-pwm255": 6.234, "n20-12v-pwm25": 16.726}[name]
    r, _ = analyze(name)
    cu = r.close_up
    assert "stops" in close_up_what(cu)
    assert cu.t1 > stop
    assert cu.t1 - stop < 0.5  # and still a close-up, not the rest of the log


@on("ev3_100_irregular_actualdt.csv", "ev3_100_irregular_nominaldt.csv")
def test_speeds_over_their_own_interval_are_not_said_to_lie_on_a_lattice():
    # ev3 irregular, speed over the real interval: 9.7 % of the nonzero speeds lie within 2 %
    # of a multiple of 1 degree / 4.39 ms = 3.98 rad/s (3.883, 4.845, 2.638, ...); it is the
    # angle steps (speed x interval) that are whole degrees. Over the nominal period all do.
    r, words = analyze("ev3_100_irregular_actualdt.csv")
    assert "the speeds lie on a lattice" not in words
    assert "speed times its interval" in resolution_how(r.sampling)
    assert r.sampling.resolution == pytest.approx(3.98, rel=0.01)
    r2, words2 = analyze("ev3_100_irregular_nominaldt.csv")
    assert "the speeds lie on a lattice of 3.98 rad/s" in words2


@on("ev3_100_irregular_actualdt.csv", "ev3_100_irregular_nominaldt.csv")
def test_the_angle_error_integrates_the_speed_over_the_period_it_was_taken_over():
    # Both EV3 probes hold the same angles; one divides each angle step by its real interval,
    # the other by the nominal 4.39 ms. The angle error must be the same motor's: integrating
    # the nominal-period probe's residual over the real intervals (3.4-9 ms) gave 0.179 rad,
    # seven times the 0.025 rad of the other, and 15.6 rad of travel became 16.65 rad.
    actual, _ = analyze("ev3_100_irregular_actualdt.csv")
    nominal, _ = analyze("ev3_100_irregular_nominaldt.csv")
    a, n = actual.gain.baseline_angle_rms, nominal.gain.baseline_angle_rms
    assert n == pytest.approx(a, rel=0.3)
    assert n < 0.05  # rad: the log's angle is known to a degree (0.0175 rad)


def check_ev3_gap(tmp_path) -> CheckResult:
    """The check of ev3-large-duty100 with data rows 74-76 (t = 0.270-0.280 s) dropped:
    benchmarks/real_variants.py's 'gap' of it, seed 37."""
    lines = (REAL / "ev3-large-duty100" / "step.csv").read_text().splitlines()
    head = [x for x in lines if x.startswith("#")]
    body = [x for x in lines if not x.startswith("#")]
    rows = body[1:]
    path = tmp_path / "ev3-gap.csv"
    path.write_text("\n".join([*head, body[0], *rows[:74], *rows[77:]]) + "\n")
    log = read_run_log(path)
    return check(log.t, log.u, log.omega, ts=float(log.metadata["ts"]), cpr=log.declared_cpr)


@on("ev3-large-duty100")
def test_one_uneven_interval_is_not_said_to_show_over_which_time_the_speed_was_taken(tmp_path):
    # the EV3 100 % log with three rows dropped has one uneven interval (20 ms) in 217 rows:
    # the row after it still holds the 5 ms speed of the original, so the log does not show
    # whether speeds are taken over their own interval or the nominal one; "(detected from
    # the data)" said the check had read it off the log
    r = check_ev3_gap(tmp_path)
    line = text(r).splitlines()[0]
    assert r.sampling.uneven == 1
    assert "detected from the data" not in line, line
    assert "(assumed: 1 uneven interval in the log, too few to tell)" in line, line


@on("ev3-large-duty100")
def test_a_runner_up_as_good_as_the_cause_is_not_told_as_a_worse_fit(tmp_path):
    # The EV3 100 % log with three rows dropped after its rise (benchmarks/real_variants.py's
    # 'gap', seed 37: data rows 74-76, t = 0.270-0.280 s): a log the check was never read
    # against. Its first-order model's error is at the speed's noise (3.0 against 3.8 rad/s,
    # the plot of the original shows no shape left), yet three extensions come within 1.5
    # points of the 25 % a cause needs: a cap 25.3 % (named), a pole 24.9 %, a delay 23.9 %.
    # The pole leaves 1.006 times the cap's whitened residual; "leaves 1.0 times as much
    # whitened residual" gave as a reason what is a tie. The sentence must say that the two
    # fit about as well and why the pole is not named.
    r = check_ev3_gap(tmp_path)
    why = runner_up_why(r.finding)
    ru = r.finding.runner_up_why
    assert ru is not None and ru.kind == "leaves_more" and ru.ratio < 1.05, ru
    assert "fits about as well" in why and "hardly tells the two apart" in why, why
    share = re.search(r"removes ([0-9.]+) % of the whitened residual, where a cause needs", why)
    assert share and 24.0 < float(share.group(1)) < 25.0, why
    assert "times as much" not in why


@on("n20-12v-pwm25")
def test_rows_lost_whole_across_a_gap_are_not_said_to_make_the_speed_jump(tmp_path):
    # n20-12v-pwm25 with three rows dropped (benchmarks/real_variants.py's 'gap', seed 37:
    # t = 5.762-5.782 s, a driven stretch), as a logger that loses whole lines does: the
    # speed column reads 8.98 rad/s before the 40 ms gap and after it. The simulation takes
    # the speed over the nominal period, so it expects four periods of counts in the row
    # after the gap and misses it by -27.8 rad/s; the anomaly said "the speed jumps by
    # -27.8 rad/s and straight back, as when the logger stalls", which the log does not show
    # (s37-real: then said "reads on as around it (8.98 rad/s) ... lost whole").
    src = REAL / "n20-12v-pwm25" / "step.csv"
    lines = src.read_text().splitlines()
    drop = {"5.762000", "5.772000", "5.782000"}
    kept = [x for x in lines if x.split(",")[0] not in drop]
    assert len(kept) == len(lines) - 3
    path = tmp_path / "n20-gap.csv"
    path.write_text("\n".join(kept) + "\n")
    log = read_run_log(path)
    r = check(log.t, log.u, log.omega, ts=float(log.metadata["ts"]), cpr=log.declared_cpr)
    i = int(np.searchsorted(log.t, 5.79))
    assert abs(log.omega[i] - log.omega[i - 1]) < 2.0  # the column runs on: one count at most
    # the log's clock stamps whole ms (10 or 11 ms), and its rows stamped 11 ms after the last
    # read no faster: the check simulates each row as the mean speed over its interval (a
    # coarse clock, REAL37's 11 ms rows), so it now expects no jump after the gap either, and
    # has no departure to explain there: the gap is said as samples lost, nothing else
    assert r.sampling.coarse is not None
    assert abs(log.omega[i] - r.extended_pred[i]) < 2.0
    assert not [a for a in r.anomalies if a.kind == "logging_artefact"]
    for a in r.anomalies:
        said = anomaly_words(a)
        assert "jumps" not in said and "stalls" not in said, said
    gap = [a for a in r.anomalies if a.kind == "gap"]
    assert len(gap) == 1 and "about 3 sample(s) were lost" in anomaly_words(gap[0])


def test_a_cause_just_over_the_bar_is_said_to_be_uncertain(tmp_path):
    # ev3-large-duty100 names no cause (the best, a current cap, removes 17.5 % of the whitened
    # residual, a cause needs 25 %); with three of its 217 rows dropped (data rows 74-76,
    # REAL37's 'gap' variant) it names a cap at 25.3 %, and with rows 73-75 dropped none again:
    # the share moves by points with a few rows, so a cause named 0.3 points over the bar is a
    # toss-up, and the text says so (it said the cause as sure as any)
    log, r = ev3_gap(tmp_path)
    assert r.finding.cause == "current_limit"
    assert 0.25 <= r.finding.evidence.reduction < 0.26
    said = evidence(r.finding)
    assert "only 0.3 points over the 25 % a cause needs" in said, said
    assert "a few rows more or fewer can put it under, so the cause is uncertain" in said
