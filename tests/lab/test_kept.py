"""The session file keeps what the lab computed of its run (the model check in brief, Tasks
11-13's numbers) under the key of the run and the table, and gives it back only while that
key holds."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from minseg_tui.lab.saving import kept
from minseg_tui.lab.state.session import Session
from tests.classview.build import group

OLD = Path(__file__).parent / "old_sessions" / "schema1"


def _file(folder: Path) -> dict[str, object]:
    return json.loads((folder / "session.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def computed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A group's session as the lab leaves it: its results and model check computed."""
    folder = group(tmp_path_factory.mktemp("kept"), ["Ada", "Bo"], seed=2, own_T="0.05 s")
    with Session.open(folder) as s:
        s.results()
        s.model_check()
    return folder


GROUP = pytest.mark.xdist_group("kept-computed")
"""The tests reading :func:`computed` run on one worker under make test's -n 2 (--dist
loadgroup), so the module fixture's session (its results and model check) is built once, not
once per worker."""


@GROUP
def test_the_lab_keeps_the_results_of_its_run_in_the_session_file(computed, tmp_path):
    folder = tmp_path / "g"
    shutil.copytree(computed, folder)
    data = _file(folder)
    assert data["schema"] == 1  # an optional part: the layout's version stays
    part = data["kept"]
    assert isinstance(part, dict) and part["version"] == kept.VERSION and part["run"] == "steps-1"
    with Session.open(folder, readonly=True) as s:
        ident = s.results().identification
        mc = s.model_check().result
        got = s.kept()
    assert ident is not None and ident.step is not None and mc is not None and got is not None
    assert got.step is not None and got.check is not None
    st = ident.step
    assert (got.step.K, got.step.T, got.step.T_63, got.step.u_ss, got.step.omega_ss) == (
        st.K,
        st.T,
        st.T_63,
        st.u_ss,
        st.omega_ss,
    )
    assert got.check.cause == mc.finding.cause == "coulomb_friction"
    assert got.check.model == mc.extended.model and dict(got.check.params) == mc.extended.params
    assert "J" not in part["step"]  # J follows the table's R, k_v and f: never kept


@GROUP
def test_kept_numbers_give_the_results_and_comparisons_the_fit_gives(computed):
    with Session.open(computed, readonly=True) as s:
        full = s.results()
        got = s.kept()
        assert got is not None and got.step is not None
        short = s.results(got.step)
        assert short.identification is not None and short.identification.step is None
        assert short.step == full.step  # J included, to the last bit
        assert short.problems == full.problems and short.run == full.run
        assert s.comparisons(results=short) == s.comparisons()
        for path in ("step.K", "step.T_63", "step.J", "step.omega_ss", "model", "omega_at_5V"):
            assert short.lookup(path) == full.lookup(path), path


@GROUP
def test_kept_results_hold_only_for_the_run_and_table_they_were_computed_from(computed, tmp_path):
    folder = tmp_path / "g"
    shutil.copytree(computed, folder)
    with Session.open(folder) as s:
        s.enter("R", "5.6 Ω")  # R is neither the run nor the table's u_ss: they still hold
        assert s.kept() is not None
        s.enter("u_ss@4.5", "3.95 V")  # the applied voltage of the run changed
        assert s.kept() is None
        s.go_to("task13")
    assert _file(folder)["kept"]["key"] == _file(computed)["kept"]["key"]  # nothing new
    with Session.open(folder) as s:
        s.model_check()  # computed again: kept again under the new key, for the check only
    with Session.open(folder, readonly=True) as s:
        got = s.kept()
        assert got is not None and got.check is not None and got.step is None
    (folder / "runs" / "steps-1.csv").write_bytes(
        (computed / "runs" / "steps-1.csv").read_bytes() + b"\n"
    )
    with Session.open(folder, readonly=True) as s:  # a log changed by a byte
        assert s.kept() is None


def test_results_a_snapshot_computes_are_kept_with_the_sessions_next_save(tmp_path):
    folder = group(tmp_path, ["Cy"], seed=5)
    assert "kept" not in _file(folder)
    with Session.open(folder) as s:
        snap = s.snapshot()  # as the lab's screens compute, in a worker
        snap.results()
        snap.model_check()
        s.go_to("task14")  # the next save writes them
        data = _file(folder)
        assert data["current_step"] == "task14" and data["kept"]["check"]["cause"]
        assert "K" in data["kept"]["step"]


def test_closing_writes_results_computed_since_the_last_save_and_keeps_its_time(tmp_path):
    folder = group(tmp_path, ["Di"], seed=6)
    before = _file(folder)["modified"]
    with Session.open(folder) as s:
        s.model_check()
    data = _file(folder)
    assert data["kept"]["check"]["cause"] and data["modified"] == before


@GROUP
def test_a_read_only_session_writes_nothing(computed, tmp_path):
    folder = tmp_path / "g"
    shutil.copytree(computed, folder)
    with Session.open(folder) as s:
        s.enter("u_ss@4.5", "3.9 V")  # its kept results no longer hold
    on_disk = (folder / "session.json").read_bytes()
    with Session.open(folder, readonly=True) as s:
        s.results()
        s.model_check()
    assert (folder / "session.json").read_bytes() == on_disk


@pytest.mark.parametrize("part", [5, "x", {"version": 1, "run": 5}, {"version": 99}])
@GROUP
def test_a_kept_part_that_cannot_be_read_is_passed_over(computed, tmp_path, part):
    folder = tmp_path / "g"
    shutil.copytree(computed, folder)
    data = _file(folder)
    data["kept"] = part
    (folder / "session.json").write_text(json.dumps(data), encoding="utf-8")
    with Session.open(folder, readonly=True) as s:
        assert s.damaged is None and s.kept() is None
    with Session.open(folder) as s:  # opens for writing too, and keeps anew
        assert s.kept() is None
        s.model_check()
    with Session.open(folder, readonly=True) as s:
        got = s.kept()
        assert got is not None and got.check is not None


def test_a_schema_1_session_from_before_keeps_nothing_until_computed_then_reads_the_same(
    tmp_path,
):
    folder = tmp_path / "schema1"
    shutil.copytree(OLD, folder)
    with Session.open(folder, readonly=True) as s:
        assert s.kept() is None
    with Session.open(folder) as s:
        K = s.results().identification.step.K
        s.model_check()
    data = _file(folder)
    assert data["schema"] == 1 and data["kept"]["step"]["K"] == K
    with Session.open(folder, readonly=True) as s:
        got = s.kept()
        assert got is not None and got.step is not None and got.step.K == K
        assert got.check is not None and got.check.cause == "coulomb_friction"


@GROUP
def test_a_change_to_the_code_that_computes_them_gives_another_key(computed, monkeypatch):
    # kept results follow the model check's and identify's code as well as the run: the key
    # hashes their source, so a new program never reads an old program's numbers as its own
    names = {p.relative_to(p.parents[2]).as_posix() for p in kept.computing_sources()}
    assert {"model/check/pipeline.py", "model/identify/identification.py"} <= names
    with Session.open(computed, readonly=True) as s:
        run = s.response_run()
    before = kept.run_key(computed, run, [(2.5, 2.4)])
    monkeypatch.setattr(kept, "code_fingerprint", lambda: "another program")
    assert run is not None and before is not None
    assert kept.run_key(computed, run, [(2.5, 2.4)]) != before
