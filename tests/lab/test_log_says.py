"""A run log's refusals and its angle's source: the model gives a record (model/runlog:
BadHeader, LogProblem, ClockApart, StillAngle, AngleFrom), the words are made in
lab/content/log_says.py, and the reader of a log file, the CLI and the session show them in
one line."""

from __future__ import annotations

import numpy as np
import pytest

from minseg_tui.errors import InputError
from minseg_tui.lab.content.log_says import angle_words, header_words, refusal_words
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.state.session import Session
from minseg_tui.model.runlog import (
    MAX_CPR,
    MEAN_SPEED,
    AngleFrom,
    BadHeader,
    ClockApart,
    NotFinite,
    PeriodOutOfRange,
    RunLog,
    SpeedStill,
    StillAngle,
    TimeNotIncreasing,
    TooFewRows,
    TooLarge,
    UnequalColumns,
    clock_problem,
    header_problem,
    problem,
)


@pytest.mark.parametrize(
    ("key", "value", "bad"),
    [
        ("cpr", " 72o ", BadHeader("cpr", "72o")),
        ("cpr", "0", BadHeader("cpr", "0")),
        ("cpr", str(MAX_CPR + 1), BadHeader("cpr", str(MAX_CPR + 1))),
        ("cpr", "+720", None),
        ("omega_over", "sometimes", BadHeader("omega_over", "sometimes")),
        ("omega_over", " nominal", None),
        ("motor", "anything at all", None),  # a key the format does not define is free text
    ],
)
def test_a_header_the_format_does_not_take_is_a_record(key, value, bad):
    assert header_problem(key, value) == bad


def test_the_reader_says_a_bad_header_in_words(tmp_path):
    path = tmp_path / "log.csv"
    path.write_text("# motor: n20\n# omega_over: sometimes\nt,u,omega\n0,0,0\n0.1,1,1\n")
    with pytest.raises(InputError) as refused:
        read_run_log(str(path))
    assert str(refused.value) == (
        f"{path}:2: expected # omega_over: interval or nominal, got 'sometimes'"
    )
    assert header_words(BadHeader("cpr", "72o")) == (
        f"expected # cpr: a whole number of counts per revolution above 0 and at most {MAX_CPR} "
        "(the MinSeg's encoder has 720), got '72o'"
    )
    # the log's own reading of its header takes only what the format does
    log = RunLog(t=[0.0], u=[0.0], omega=[0.0], metadata={"cpr": "72o", "omega_over": "x"})
    assert log.declared_cpr is None and log.omega_over is None


T = np.arange(20) * 0.025
U = np.where(T > 0.2, 4.0, 0.0)
W = np.where(T > 0.2, 30.0, 0.0)
BACK = np.where(np.arange(20) == 5, T[4], T)


@pytest.mark.parametrize(
    ("log", "record", "words"),
    [
        (
            (T, U[:-1], W, None),
            UnequalColumns(20, 19, 20),
            "expected t, u and omega of the same length, got 20, 19 and 20 rows",
        ),
        ((T[:5], U[:5], W[:5], None), TooFewRows(5), "expected at least 8 rows to analyse, got 5"),
        ((T, U, W * np.nan, None), NotFinite("omega"), "expected finite numbers in omega (rad/s)"),
        ((T, U * 1e7, W, None), TooLarge("u", 4e7), "expected |u (V)| below 1e+06, got 4e+07"),
        ((BACK, U, W, None), TimeNotIncreasing(), "expected t (s) to increase from row to row"),
        (
            (T * 1e-3, U, W, None),
            PeriodOutOfRange(pytest.approx(2.5e-5)),
            "expected a sample period between 0.1 ms and 1 s, got 2.5e-05 s (is t in seconds?)",
        ),
        (
            (T, U, W * 0 + 2.5, None),
            SpeedStill(2.5),
            "expected the speed to change after the voltage changes; omega stays at 2.5 rad/s",
        ),
        ((T, U, W, None), None, None),
    ],
)
def test_a_log_no_analysis_takes_is_a_record_worded_above_the_model(log, record, words):
    """Each refusal of runlog.problem as a record with its figures, and its sentence (the
    words the model wrote itself before s35, byte for byte)."""
    got = problem(*log)
    assert got == record
    assert (None if got is None else refusal_words(got)) == words


def test_a_clock_that_does_not_keep_time_is_a_record_worded_above_the_model():
    assert clock_problem(T, np.round(T * 1e6)) is None
    apart = clock_problem(T, np.round(T * 1e5))
    assert apart == ClockApart(pytest.approx(0.0475), pytest.approx(0.475))
    assert refusal_words(apart) == (
        "expected t_us (us) to keep time with t (s) within 2 % (or two sample periods on a short "
        "log): over the log t_us advances 0.0475 s and t 0.475 s (0.1 times as far); is one of "
        "them in other units? Fix it or leave t_us out"
    )


def test_where_the_angle_came_from_is_a_record_worded_above_the_model():
    counts = np.cumsum(np.where(T > 0.2, 3, 0))
    euler = np.concatenate(([0.0], np.diff(counts) * (2 * np.pi / 720) / 0.025))
    said = {}
    for name, extra in (("theta", {"theta": counts * 0.01}), ("count", {"count": counts})):
        source = RunLog(t=T, u=U, omega=euler, extra=extra).angle()[1]
        assert source == AngleFrom(name)
        said[name] = angle_words(source)
    source = RunLog(t=T, u=U, omega=euler).angle()[1]
    assert source == AngleFrom("omega", pytest.approx(0.025))
    said["euler"] = angle_words(source)
    rng = np.random.default_rng(3)
    noisy = RunLog(t=T + rng.uniform(0, 0.004, T.size), u=U, omega=W + rng.normal(0, 0.3, T.size))
    assert noisy.angle()[1] == MEAN_SPEED
    said["mean"] = angle_words(MEAN_SPEED)
    assert said == {
        "theta": "the theta column",
        "count": "the encoder count",
        "euler": "the omega column read as the Euler speed (theta_k - theta_k-1) / 25 ms",
        "mean": "the omega column read as the mean speed over each sample interval",
    }
    assert refusal_words(StillAngle(AngleFrom("count"))) == (
        "expected the wheel to turn; its angle (the encoder count) never changes in the log, so "
        "T, K and J cannot be found from it"
    )


def test_the_model_check_of_a_still_run_says_the_refusal_in_words(tmp_path):
    """The check refuses a recorded run whose count never changes (the encoder not read)
    with a record (LogRefused); the session's model check says it in the one line it shows."""
    with Session.create(tmp_path / "sessions", ["Ada"], date="2026-11-28") as s:
        rec = s.start_run("steps", ts=0.025)
        for k in range(400):
            rec.append(k, 25_000 * k, 0, 4500 if (k // 80) % 2 == 0 and k >= 4 else 0)
        info = s.finish_run(rec)
        assert info is not None
        mc = s.model_check(info.name)
    assert mc.result is None
    assert mc.problem == (
        f"run {info.name}: expected the speed to change after the voltage changes; omega "
        "stays at 0 rad/s"
    )
