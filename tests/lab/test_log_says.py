"""A run log's header refusals: the model gives a record (model/runlog.BadHeader), the words
are made in lab/content/log_says.py, and the reader of a log file shows them in one line."""

from __future__ import annotations

import pytest

from minseg_tui.errors import InputError
from minseg_tui.lab.content.log_says import header_words
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.model.runlog import MAX_CPR, BadHeader, RunLog, header_problem


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
