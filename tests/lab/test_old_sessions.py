"""Sessions written before recordings kept what the board sent still open and read the same.

``old_sessions/schema1`` was written by the program of main before this change (commit
7cfdf8f): session.json of schema 1 and a run whose u column holds u_A, rewritten by that
program when the group typed u_ss@4.5 = 4.1 V after the run. The figures below are what that
program read from it (K, T, u_ss of Task 11; the model check's cause and extended fit).
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.state.session import Session

OLD = Path(__file__).parent / "old_sessions" / "schema1"


def _copy(tmp_path: Path) -> Path:
    folder = tmp_path / "schema1"
    shutil.copytree(OLD, folder)
    return folder


def test_the_old_form_is_what_it_says():
    assert json.loads((OLD / "session.json").read_text(encoding="utf-8"))["schema"] == 1
    log = read_run_log(OLD / "runs" / "steps-1.csv")
    high = np.asarray(log.extra["u_req"]) == 4.5
    assert set(np.asarray(log.u)[high]) == {4.1}  # u_A, as the old program wrote it
    assert log.metadata["u"].startswith("u = u_A mapped from u_req")


@pytest.mark.parametrize("readonly", [True, False])
def test_a_schema_1_session_reads_the_values_it_read_before(tmp_path, readonly):
    folder = _copy(tmp_path)
    with Session.open(folder, readonly=readonly) as s:
        assert [r.name for r in s.runs] == ["steps-1"]
        on_disk = read_run_log(folder / "runs" / "steps-1.csv")
        log = s.load_run("steps-1")
        for name in ("t", "u", "omega"):
            assert np.array_equal(getattr(log, name), getattr(on_disk, name)), name
        for name, column in on_disk.extra.items():
            assert np.array_equal(log.extra[name], column), name
        st = s.results().identification.step
        assert (st.u_ss, st.u_ss_how) == (4.1, "row")
        # the values the old program read, to the least-squares search's own tolerance (the
        # search itself changed since: s23-lsq's one solver, K moved by 4e-11, T by 2e-9 relative)
        assert st.K == pytest.approx(1.899000136983378, rel=1e-7)
        assert st.T == pytest.approx(0.042619013801033175, rel=1e-7)
        mc = s.model_check()
        assert mc.result is not None and mc.result.finding.cause == "coulomb_friction"
        assert mc.result.extended.params["T"] == pytest.approx(0.04291441362325852, rel=1e-9)
        assert mc.result.extended.params["u_c"] == pytest.approx(0.11897229200445704, rel=1e-9)


def test_typing_u_ss_in_an_old_session_leaves_its_recording_as_it_is(tmp_path):
    folder = _copy(tmp_path)
    recorded = (folder / "runs" / "steps-1.csv").read_bytes()
    with Session.open(folder) as s:
        s.enter("u_ss@4.5", "3.9 V")
        high = np.asarray(s.load_run("steps-1").extra["u_req"]) == 4.5
        assert set(np.asarray(s.load_run("steps-1").u)[high]) == {3.9}
        assert s.results().identification.step.u_ss == pytest.approx(3.9)
    assert (folder / "runs" / "steps-1.csv").read_bytes() == recorded
    with Session.open(folder, readonly=True) as again:  # saved, and read the same way again
        high = np.asarray(again.load_run("steps-1").extra["u_req"]) == 4.5
        assert set(np.asarray(again.load_run("steps-1").u)[high]) == {3.9}
