"""Sessions: autosave, atomic writes, exact resume, damaged files, the lock, a kill -9 mid-run."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import time
from datetime import UTC, datetime, timedelta
from pathlib import Path

import numpy as np
import pytest

from minseg_tui.cli import main
from minseg_tui.lab.content.steps import step
from minseg_tui.lab.saving import store
from minseg_tui.lab.saving.files import read_run_log
from minseg_tui.lab.saving.runs import applied_voltage, read_partial
from minseg_tui.lab.saving.store import SessionDamaged, SessionLocked, SessionMissing, list_sessions
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.model.plant import PlantParams, record
from tests.seeded import Clock

HERE = Path(__file__).parent


def FakeClock() -> Clock:
    """A clock that advances one second per reading from 2026-11-22 09:00 UTC."""
    return Clock(datetime(2026, 11, 22, 9, 0, 0, tzinfo=UTC))


def _on_disk(s: Session) -> dict:
    return json.loads((s.folder / "session.json").read_text(encoding="utf-8"))


def _fill_table(s: Session) -> None:
    for lv, u, w, i in (
        (2.5, "2.05", "3.8", "29.8 mA"),
        (3.5, "3.05", "5.8", "33.5"),
        (4.5, "4.05", "7.8", "37.2"),
    ):
        s.enter(f"u_ss@{lv:g}", u)
        s.enter(f"omega_ss@{lv:g}", w)
        s.enter(f"i_ss@{lv:g}", i)


def _record_stopped_run(s: Session):
    """A Task 10 run stopped with F2 after one rising step: 80 of the plan's 480 samples."""
    plan = dict(step("task10").plans)["manual"]
    data = record(PlantParams(), np.r_[np.zeros(20), np.full(60, plan.high)], ts=plan.ts)
    rec = s.start_run("steps", plan)
    for j in range(80):
        rec.append(int(data.seq[j]), int(data.t_us[j]), int(data.count[j]), 4500 * (j >= 20))
    return s.finish_run(rec, stopped_early=True, ended_by="stopped")


def _record_steps(s: Session, seed: int = 3, n_lead: int = 20):
    plan = dict(step("task10").plans)["manual"]
    n = int(round(plan.duration / plan.ts))
    k = np.arange(n)
    u = np.where((k * plan.ts // plan.half_period) % 2 == 0, plan.high, plan.low)
    u = np.concatenate((np.zeros(n_lead), u))
    data = record(PlantParams(), u, ts=plan.ts, seed=seed, jitter_us=1000)
    rec = s.start_run("steps", plan)
    for j in range(u.size):
        rec.append(int(data.seq[j]), int(data.t_us[j]), int(data.count[j]), int(round(u[j] * 1000)))
    return s.finish_run(rec), data, u


# -- autosave ----------------------------------------------------------------------------------


def test_create_writes_a_versioned_file(tmp_path):
    s = Session.create(tmp_path, ["Ada", "Bo Ek"], date="2026-11-22", clock=FakeClock())
    d = _on_disk(s)
    assert d["kind"] == "minseg-tui session" and d["schema"] == 1
    assert d["id"] == "2026-11-22-ada-bo-ek" == s.id
    assert d["members"] == ["Ada", "Bo Ek"]
    assert d["current_step"] == "prep1"
    assert (s.folder / "runs").is_dir()
    s.close()
    s2 = Session.create(tmp_path, ["Ada", "Bo Ek"], date="2026-11-22")
    assert s2.id == "2026-11-22-ada-bo-ek-2"
    s2.close()


def test_every_entry_is_on_disk_when_enter_returns(tmp_path):
    with Session.create(tmp_path, ["A"], clock=FakeClock()) as s:
        e = s.enter("R", "5,2 Ω")
        assert e.ok and e.value == 5.2
        assert _on_disk(s)["entries"]["R"]["text"] == "5,2 Ω"
        assert _on_disk(s)["entries"]["R"]["value"] == 5.2
        bad = s.enter("i_ss@2.5", "4.7 V")
        assert not bad.ok and "is a voltage" in bad.message
        disk = _on_disk(s)["entries"]["i_ss@2.5"]
        assert disk["text"] == "4.7 V" and disk["ok"] is False and "is a voltage" in disk["message"]
        s.enter("i_ss@2.5", "0.03")
        s.enter("i_ss@2.5", "30 mA")
        disk = _on_disk(s)["entries"]["i_ss@2.5"]
        assert disk["text"] == "30 mA" and disk["value"] == 0.03
        assert [h[0] for h in disk["history"]] == ["4.7 V", "0.03"]


def test_warnings_are_data(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        assert "above 20 Ω" in s.enter("R", "47 Ω").warnings[0]
        assert s.enter("R", "5.2").warnings == ()
        assert "above 100 mA" in s.enter("i_ss@4.5", "180 mA").warnings[0]
        assert "above the requested 2.5 V" in s.enter("u_ss@2.5", "2.7 V").warnings[0]
        assert "faster than this motor" in s.enter("omega_ss@4.5", "40").warnings[0]
        assert [w.source for w in s.warnings("task5")] == ["i_ss@4.5"]


def test_unknown_field_is_a_key_error(tmp_path):
    with Session.create(tmp_path, ["A"]) as s, pytest.raises(KeyError):
        s.enter("nope", "1")


def test_choices_and_formulas(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        assert s.enter("summary.5", "b, c").value == (1, 2)
        assert s.choose("summary.1", [1]).value == (1,)
        refused = s.enter("summary.1", "a, b")
        # refused over an accepted answer: the accepted one stays in effect, the attempt is kept
        assert refused.refused is not None and "one answer" in refused.refused[1]
        assert refused.typed == "a, b" and s.entry("summary.1").value == (1,)
        assert not s.enter("summary.3", "z").ok
        s.enter("prep8.T", "a/b")
        s.enter("prep8.K", "Kc")
        fb = {f.key: f.status for f in s.feedback("prep8")}
        assert fb == {"prep8.T": "right", "prep8.K": "missing"}
        assert not s.entry("prep8.K").ok and s.entry("prep8.K").text == "Kc"


def test_a_refused_entry_never_displaces_an_accepted_one(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        s.enter("R", "5,3")
        e = s.enter("R", "5,3 kg")
        assert e.ok and s.value("R") == 5.3
        assert e.refused[0] == "5,3 kg" and "expected a resistance" in e.refused[1]
        folder = s.folder
    with Session.open(folder) as again:  # the attempt and the value both survive on disk
        e = again.entry("R")
        assert again.value("R") == 5.3 and e.typed == "5,3 kg"
        fixed = again.enter("R", "5.2")
        assert fixed.refused is None and again.value("R") == 5.2
        assert [h[0] for h in fixed.history] == ["5,3", "5,3 kg"]


# -- results recompute -------------------------------------------------------------------------


def test_results_follow_the_entries(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        _fill_table(s)
        assert s.results().identification is None
        assert "R is not entered" in s.results().problems[0]
        s.enter("R", "5 Ω")
        rows = s.table()
        # k_v = (u_ss - R i_ss) / omega_ss, by hand
        assert rows[0].k_v == pytest.approx((2.05 - 5 * 0.0298) / 3.8)
        assert rows[2].k_v == pytest.approx((4.05 - 5 * 0.0372) / 7.8)
        k_v = sorted(
            [(2.05 - 5 * 0.0298) / 3.8, (3.05 - 5 * 0.0335) / 5.8, (4.05 - 5 * 0.0372) / 7.8]
        )[1]
        assert s.results().identification.k_v == pytest.approx(k_v)
        first = s.results()
        s.enter("prep8.T", "a/b")  # an unrelated entry keeps the cached results
        assert s.results() is first
        s.enter("R", "6 Ω")  # going back changes everything after
        assert s.results() is not first
        assert s.table()[0].k_v == pytest.approx((2.05 - 6 * 0.0298) / 3.8)
        s.enter("own.k_v", "0.5 V s/rad")
        (c,) = s.comparisons("table")[:1]
        assert c.own == 0.5 and c.computed == pytest.approx(s.results().identification.k_v)


def test_applied_voltage_mapping_by_hand():
    table = [(2.5, 2.1), (3.5, 3.05), (4.5, 4.0)]
    u, how = applied_voltage(np.array([0.0, 2.5, 3.0, 4.5, 5.0, 1.0, 0.3, -4.5]), table)
    assert u == pytest.approx([0.0, 2.1, 2.575, 4.0, 4.5, 0.6, 0.0, -4.0])
    assert "u_ss" in how
    u, how = applied_voltage(np.array([0.0, 4.5]), [])
    assert list(u) == [0.0, 4.5] and "u = u_req" in how


def test_capture_mean_spread_and_window(tmp_path):
    rng = np.random.default_rng(11)
    t = np.arange(0, 6, 0.025)
    w = 6.8 + 0.1 * rng.standard_normal(t.size)
    with Session.create(tmp_path, ["A"]) as s:
        e = s.capture_omega(4.5, t, w, window=2.0)
        sel = t >= t[-1] - 2.0
        assert e.source == "capture" and e.value == pytest.approx(float(f"{np.mean(w[sel]):.4g}"))
        cap = s.capture_of(4.5)
        assert cap.spread == pytest.approx(np.std(w[sel], ddof=1))
        assert (cap.t0, cap.t1, cap.n) == (
            pytest.approx(t[sel][0]),
            pytest.approx(t[-1]),
            int(sel.sum()),
        )
        assert s.table()[2].spread == cap.spread
        s.enter("omega_ss@4.5", "6.9")  # typed over: the capture no longer describes it
        assert s.capture_of(4.5) is None and s.table()[2].window is None


# -- runs --------------------------------------------------------------------------------------


def test_finished_run_is_a_run_log_with_applied_voltage(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        _fill_table(s)
        s.enter("R", "5.26")
        info, data, u = _record_steps(s)
        assert info.name == "steps-1" and info.samples == u.size and info.dropped == 0
        assert not list((s.folder / "runs").glob("*.partial"))
        log = s.load_run(info.name)
        assert list(log.extra["count"]) == list(data.count)
        assert log.t[0] == 0.0 and log.t[-1] == pytest.approx((data.t_us[-1] - data.t_us[0]) / 1e6)
        high = np.asarray(log.extra["u_req"]) == 4.5
        assert set(np.asarray(log.u)[high]) == {4.05}
        assert set(np.asarray(log.u)[~high]) == {0.0}
        assert "u_ss" in log.metadata["u"]
        res = s.results()
        assert res.run == "steps-1" and res.identification.step is not None
        assert 0.03 < res.identification.step.T < 0.06  # the simulated motor's T is 0.043 s
        mc = s.model_check()
        assert mc.run == "steps-1" and mc.result is not None and mc.problem == ""
        assert mc.result.t.size == u.size
        assert s.model_check() is mc  # cached until something changes
        # a changed u_ss: the run read again has the new u column and K follows; the
        # recording itself (what the board sent) is never written again
        recorded = (s.folder / info.file).read_bytes()
        assert set(np.asarray(read_run_log(s.folder / info.file).u)[high]) == {4.5}
        s.enter("u_ss@4.5", "4.2 V")
        log2 = s.load_run(info.name)
        assert set(np.asarray(log2.u)[high]) == {4.2}
        assert (s.folder / info.file).read_bytes() == recorded
        assert s.results().identification.step.u_ss == pytest.approx(4.2)


def test_dropped_samples_are_counted(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        assert s.model_check().run is None and "Task 10" in s.model_check().problem
        rec = s.start_run("free", ts=0.025)
        for k in (0, 1, 2, 5, 6, 6, 7):  # 3 and 4 lost, 6 repeated
            rec.append(k, 1000 + 25000 * k, k, 0)
        info = s.finish_run(rec)
        assert info.dropped == 2 and info.samples == 6


def test_torn_partial_is_recovered_without_the_torn_line(tmp_path):
    s = Session.create(tmp_path, ["A"])
    rec = s.start_run("free", ts=0.025, flush_interval=0.0)
    for k in range(10):
        rec.append(k, 25000 * k, 3 * k, 2500)
    rec.close()
    with rec.path.open("a") as fh:
        fh.write("10,250000,3")  # a crash mid-line
    s.close()
    with Session.open(s.folder) as s2:
        assert s2.recovered == ["free-1"]
        (info,) = s2.runs
        assert info.interrupted and info.samples == 10
        assert list(s2.load_run("free-1").extra["count"]) == [3 * k for k in range(10)]


def test_flush_interval_bounds_what_is_in_memory(tmp_path):
    now = [0.0]
    with Session.create(tmp_path, ["A"]) as s:
        rec = s.start_run("free", ts=0.025)
        rec._clock = lambda: now[0]
        for k in range(30):
            now[0] = k * 0.025
            rec.append(k, 25000 * k, k, 0)
            on_disk = read_partial(rec.path).seq.size
            # every sample older than the flush interval (0.5 s) is on disk
            assert on_disk >= k + 1 - int(0.5 / 0.025) - 1
        s.discard_run(rec)
        assert not rec.path.exists()


def test_import_run(tmp_path):
    src = tmp_path / "elsewhere.csv"
    src.write_text("t,u,omega\n0,0,0\n0.025,4,1\n0.05,4,2\n0.075,4,2.5\n", encoding="utf-8")
    with Session.create(tmp_path / "s", ["A"]) as s:
        info = s.import_run(src)
        assert info.kind == "imported" and s.load_run(info.name).metadata["imported_from"] == str(
            src
        )


def test_an_import_feeds_the_model_check_and_tasks_11_to_15_only_by_choice(tmp_path):
    """Walk 16, D3: an import is the model check's run (saved); Tasks 11-15 keep theirs, or
    have none, until the group picks the import with 'Use run'; picking a run for Tasks
    11-15 gives the model check that run again."""
    src = tmp_path / "elsewhere.csv"
    src.write_text("t,u,omega\n0,0,0\n0.025,4,1\n0.05,4,2\n0.075,4,2.5\n", encoding="utf-8")
    with Session.create(tmp_path / "s", ["A"]) as s:
        info = s.import_run(src)
        assert s.response_run() is None and s.check_run() == info  # the only run: not theirs
        assert s.model_check().run == info.name
        steps = _record_steps(s)[0].name
        assert s.response_run().name == steps and s.check_run() == info  # still the import
        folder = s.folder
    with Session.open(folder) as s:  # saved
        assert s.response_run().name == steps and s.check_run().name == info.name
        assert (
            views.run_in_use(s)
            == f"Tasks 11-15 use run {steps}; the model check uses run {info.name}"
        )
        s.select_run(info.name)  # "Use run imported-1": Tasks 11-15 on the import too
        assert s.response_run().name == info.name == s.check_run().name
        s.select_run(steps)
        assert s.response_run().name == steps == s.check_run().name
        assert views.run_in_use(s) == f"Tasks 11-15 and the model check use run {steps}"


def test_an_older_session_that_chose_an_import_keeps_it_for_both(tmp_path):
    """A session of an older program whose group's answers were judged on an import it
    chose (no ``check_run`` in its file) opens unchanged: Tasks 11-15 and the model check
    both use the import."""
    src = tmp_path / "elsewhere.csv"
    src.write_text("t,u,omega\n0,0,0\n0.025,4,1\n0.05,4,2\n0.075,4,2.5\n", encoding="utf-8")
    with Session.create(tmp_path / "s", ["A"]) as s:
        _record_steps(s)
        name = s.import_run(src).name
        folder = s.folder
    path = folder / "session.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    data.pop("check_run")
    data["selected_run"] = name  # as the older program's import did
    path.write_text(json.dumps(data), encoding="utf-8")
    with Session.open(folder) as s:
        assert s.response_run().name == name == s.check_run().name


# -- resume ------------------------------------------------------------------------------------


def test_resume_is_exact(tmp_path):
    clock = FakeClock()
    s = Session.create(tmp_path, ["Ada", "Bo"], date="2026-11-22", clock=clock)
    _fill_table(s)
    s.enter("R", "5.3 ohm")
    s.enter("i_ss@3.5", "nonsense")
    s.enter("summary.5", "b c")
    rng = np.random.default_rng(5)
    s.capture_omega(2.5, np.arange(100) * 0.025, 3.8 + 0.05 * rng.standard_normal(100))
    _record_steps(s)
    s.go_to("task12")
    entries, table, runs = s.entries, s.table(), s.runs
    res = s.results().to_json()
    s.close()  # which writes the results just computed (kept for the class view)
    before = (s.folder / "session.json").read_bytes()
    s2 = Session.open(s.folder, clock=clock)
    assert (s.folder / "session.json").read_bytes() == before  # opening writes nothing
    assert s2.current_step == "task12" and s2.step.id == "task12"
    assert s2.entries == entries
    assert s2.table() == table
    assert s2.runs == runs
    assert s2.results().to_json() == res
    assert s2.members == ("Ada", "Bo") and s2.date == "2026-11-22"
    s2.close()


def test_navigation_is_saved(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        assert s.next_step().id == "prep2"
        assert s.previous_step().id == "prep1"
        assert s.previous_step().id == "prep1"
        s.go_to("summary")
        assert s.next_step().id == "summary"
        assert _on_disk(s)["current_step"] == "summary"
        with pytest.raises(KeyError):
            s.go_to("task99")


def test_step_status(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        assert s.step_status("task2") == "todo"
        s.enter("R", "x")
        assert s.step_status("task2") == "refused"
        s.enter("R", "5")
        assert s.step_status("task2") == "done"
        s.enter("R", "5 V")  # refused over the answer in effect: no tick while it shows
        assert s.step_status("task2") == "refused" and s.value("R") == 5.0
        assert s.withdraw_refused("R") and s.step_status("task2") == "done"
        assert not s.withdraw_refused("R") and s.entry("R").text == "5"  # type: ignore[union-attr]
        s.enter("prep8.T", "a/")  # never accepted: withdrawn, the field is empty again
        assert s.step_status("prep8") == "refused"
        assert s.withdraw_refused("prep8.T") and s.entry("prep8.T") is None
        assert s.step_status("prep8") == "todo"
        assert s.step_status("task1") == "todo"  # done once the board check passes
        assert s.step_status("task10") == "todo"


# -- atomic writes and damaged files -----------------------------------------------------------


def test_a_failed_save_leaves_the_old_file(tmp_path, monkeypatch):
    with Session.create(tmp_path, ["A"]) as s:
        s.enter("R", "5.2")
        good = (s.folder / "session.json").read_bytes()

        def boom(src, dst):
            raise OSError("disk gone")

        monkeypatch.setattr(os, "replace", boom)
        e = s.enter("R", "6.1")  # no exception: the value is kept in memory
        assert e.value == 6.1 and s.value("R") == 6.1 and s.unsaved
        assert "disk gone" in s.save_problem.line
        monkeypatch.undo()
        assert (s.folder / "session.json").read_bytes() == good
        assert not [p for p in s.folder.iterdir() if p.name.endswith(".tmp")]
        assert s.save() and s.save_problem is None and not s.unsaved
        assert _on_disk(s)["entries"]["R"]["value"] == 6.1


@pytest.mark.parametrize(
    ("content", "fragment"),
    [
        (b'{"kind": "minseg-tui session", "schema": 1, ', "not valid JSON"),
        (b"\xff\xfe garbage", "not UTF-8"),
        (b'{"kind": "minseg-tui session", "schema": 99}', "schema 99"),
        (b'{"kind": "something else"}', "not a minseg-tui session"),
        (b"[1, 2]", "JSON object"),
    ],
)
def test_damaged_file_is_reported_and_never_overwritten(tmp_path, capsys, content, fragment):
    s = Session.create(tmp_path, ["A"])
    s.close()
    path = s.folder / "session.json"
    path.write_bytes(content)
    with pytest.raises(SessionDamaged) as info:
        Session.open(s.folder)
    msg = str(info.value)
    assert fragment in msg and "left untouched" in msg and "\n" not in msg
    assert path.read_bytes() == content
    assert not (s.folder / "lock").exists()  # the lock was given back
    (listed,) = list_sessions(tmp_path)
    assert listed.damaged and fragment in listed.damaged
    # the report command: one line, exit 2, the file untouched
    assert main(["report", str(s.folder)]) == 2
    err = capsys.readouterr().err
    assert fragment in err and err.count("\n") == 1
    assert path.read_bytes() == content


def test_missing_session(tmp_path):
    with pytest.raises(SessionMissing):
        Session.open(tmp_path / "nothing")


def test_list_sessions(tmp_path):
    a = Session.create(tmp_path, ["Ada"], date="2026-11-20", clock=FakeClock())
    a.go_to("task4")
    a.close()
    clock = FakeClock()
    clock.t += timedelta(days=1)
    b = Session.create(tmp_path, ["Bo", "Cy"], date="2026-11-21", clock=clock)
    listed = list_sessions(tmp_path)
    assert [x.id for x in listed] == [b.id, a.id]  # newest change first
    assert listed[0].members == ("Bo", "Cy") and listed[0].locked_by == os.getpid()
    assert (
        listed[1].last_step == "task4"
        and listed[1].locked_by is None
        and listed[1].date == "2026-11-20"
    )
    b.close()


# -- the lock ----------------------------------------------------------------------------------


def test_one_program_per_session(tmp_path):
    s = Session.create(tmp_path, ["A"])
    with pytest.raises(SessionLocked, match=str(os.getpid())):
        Session.open(s.folder)
    s.close()
    Session.open(s.folder).close()


def test_lock_held_by_a_live_process(tmp_path):
    s = Session.create(tmp_path, ["A"])
    s.close()
    code = (
        "import sys, time; from pathlib import Path; from minseg_tui.lab.state.session import Session; "
        "s = Session.open(Path(sys.argv[1])); print('open', flush=True); time.sleep(60)"
    )
    child = subprocess.Popen(
        [sys.executable, "-c", code, str(s.folder)], stdout=subprocess.PIPE, text=True
    )
    try:
        assert child.stdout.readline().strip() == "open"
        with pytest.raises(SessionLocked, match=f"pid {child.pid}"):
            Session.open(s.folder)
    finally:
        child.kill()
        child.wait()
    with Session.open(s.folder) as again:  # its owner is dead: the kernel let its lock go
        assert (again.folder / "lock").read_text().split() == ["minseg-tui", str(os.getpid())]
        assert store.lock_owner(again.folder) == os.getpid()


def test_stale_lock_from_dead_pid(tmp_path):
    s = Session.create(tmp_path, ["A"])
    s.close()
    dead = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True
    )
    (s.folder / "lock").write_text(dead.stdout)
    assert store.lock_owner(s.folder) is None
    Session.open(s.folder).close()
    assert not (s.folder / "lock").exists()


# -- kill -9 mid-recording ---------------------------------------------------------------------


def test_kill_9_mid_recording_loses_nothing_typed_and_at_most_a_second(tmp_path):
    env = {**os.environ, "PYTHONPATH": str(HERE.parents[1])}
    child = subprocess.Popen(
        [sys.executable, str(HERE / "record_child.py"), str(tmp_path)],
        stdout=subprocess.PIPE,
        text=True,
        env=env,
    )
    typed: list[str] = []
    last_sent = None
    sid = ""
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            line = child.stdout.readline()
            if not line:
                break
            word, *rest = line.split()
            if word == "id":
                sid = rest[0]
            elif word == "typed":
                typed.append(rest[0])
            elif word == "sent":
                last_sent = (int(rest[0]), int(rest[1]))
                if last_sent[0] >= 420:  # 2.1 s into the stream
                    break
        os.kill(child.pid, signal.SIGKILL)
    finally:
        child.kill()
        child.wait()
    assert child.returncode == -signal.SIGKILL
    assert last_sent is not None and len(typed) == 6
    folder = tmp_path / sid
    assert (folder / "runs" / "fast-1.partial").exists()
    with Session.open(folder) as s:  # takes over the dead child's lock, rebuilds the run
        assert s.current_step == "task10"
        assert s.entry("R").text == "5,3 Ω" and s.value("R") == 5.3
        assert s.entry("i_ss@2.5").text == "29 mA" and s.entry("i_ss@2.5").history[0][0] == "0.047"
        assert s.entry("summary.unclear").text == "why the filter lags"
        assert s.entry("prep8.T").text == "a/b"
        assert s.recovered == ["fast-1"]
        (info,) = s.runs
        assert info.interrupted and info.kind == "fast"
        log = s.load_run("fast-1")
        t_us = np.asarray(log.extra["t_us"])
        lost = (last_sent[1] - t_us[-1]) / 1e6
        print(f"kill -9: {len(log)} samples kept, {lost:.3f} s of the stream lost")
        assert lost <= 1.0, f"lost {lost:.3f} s of the stream"
        assert list(np.asarray(log.extra["seq"])) == list(range(len(log)))  # a clean prefix
        assert not (folder / "runs" / "fast-1.partial").exists()


# -- leftovers of a kill -9 --------------------------------------------------------------------


def test_a_kill_9_mid_save_leaves_a_temporary_file_that_the_next_open_removes(tmp_path):
    s = Session.create(tmp_path, ["A"])
    s.enter("R", "5.2")
    s.close()
    code = (
        "import os, signal, sys; from pathlib import Path\n"
        "from minseg_tui.lab.state.session import Session\n"
        "s = Session.open(Path(sys.argv[1]))\n"
        "os.replace = lambda a, b: os.kill(os.getpid(), signal.SIGKILL)  # killed mid-save\n"
        "s.enter('R', '6.1')\n"
    )
    env = {**os.environ, "PYTHONPATH": str(HERE.parents[1])}
    child = subprocess.run([sys.executable, "-c", code, str(s.folder)], env=env)
    assert child.returncode == -signal.SIGKILL
    left = [p.name for p in s.folder.iterdir() if p.name.endswith(".tmp")]
    assert len(left) == 1 and re.fullmatch(r"\.session\.json\.\d+\.tmp", left[0])
    (s.folder / "runs" / f".steps-1.csv.{_pid_of(left)}.build").write_text("half a log")
    mine = s.folder / f".report.md.{os.getpid()}.tmp"  # a live program's: not touched
    mine.write_text("being written")
    with Session.open(s.folder) as again:
        assert again.value("R") == 5.2  # the save that was killed never happened
        assert sorted(again.recovery_notes) == sorted(
            f"removed {name}, left by a program that was killed"
            for name in (left[0], f"runs/.steps-1.csv.{_pid_of(left)}.build")
        )
    assert [p.name for p in s.folder.iterdir() if p.name.endswith((".tmp", ".build"))] == [
        mine.name
    ]
    assert not list((s.folder / "runs").iterdir())


def _pid_of(names: list[str]) -> str:
    return names[0].split(".")[-2]


def test_a_run_stopped_before_its_plan_ended_says_so_in_tasks_11_to_15(tmp_path):
    from minseg_tui.lab.views import session as views

    with Session.create(tmp_path, ["A"]) as s:
        _fill_table(s)
        info, _, _ = _record_steps(s)
        assert info is not None and not info.interrupted
        assert not any("ended before its plan" in p for p in views.results(s, "task11").problems)
        short = _record_stopped_run(s)
        assert short is not None and short.interrupted
    with Session.open(s.folder) as again:  # kept in the session file
        assert again.runs[-1].interrupted and again.runs[-1].interruption == "stopped"
        assert again.response_run() == info  # never an interrupted run the group did not choose
        again.select_run(short.name)
        said = views.results(again, "task11").problems
        assert any(
            f"run {short.name} ended before its plan did (stopped; 80 samples" in p for p in said
        )


def test_the_computed_value_stands_in_the_unit_the_group_typed_theirs_in(tmp_path):
    from minseg_tui.lab.views import session as views

    with Session.create(tmp_path, ["A"]) as s:
        _fill_table(s)
        s.enter("R", "5.26")
        _record_steps(s)
        T = s.results().lookup("step.T_63")
        assert isinstance(T, float)
        s.enter("own.T", "57 ms")
        (label, yours, computed), *_ = [c for c in views.comparisons(s, "task12") if c[1] != "—"]
        assert yours == "57 ms" and computed.startswith(f"read your way {T * 1e3:.4g} ms"), computed
        s.enter("own.T", "0.057 s")  # typed in s: shown in ms, as T is everywhere
        (_, yours, computed), *_ = [c for c in views.comparisons(s, "task12") if c[1] != "—"]
        first = computed.splitlines()[0]  # the second line is the least-squares T
        assert yours == "57 ms" and " ms (" in first and " s (" not in first


def test_unticking_every_answer_leaves_the_question_unanswered(tmp_path):
    """Walk 6: every box of summary.5 unticked showed none ticked while 'b' stayed in
    effect, refused in the file's letters ("expected one or more of a/b/c; got '' (still
    using 'b')"). Now no answer ticked is no answer stored, as the list shows it."""
    with Session.create(tmp_path, ["A"]) as s:
        s.choose("summary.5", [1])
        assert s.step_status("summary") == "started"
        assert s.choose("summary.5", []) is None
        assert s.entry("summary.5") is None
        assert views.entry(s, "summary.5") is None
        assert s.choose("summary.5", []) is None  # nothing to untick: nothing changes
        assert s.choose("summary.5", [1, 2]).value == (1, 2)
    with Session.open(s.folder) as again:
        assert again.entry("summary.5").value == (1, 2)
        with pytest.raises(KeyError):
            again.choose("nope", [])


def test_a_refused_choice_is_said_in_the_answers_words(tmp_path):
    """A refusal on a question names its answers as the screen shows them, never by the
    letters the session file keeps them in."""
    with Session.create(tmp_path, ["A"]) as s:
        s.choose("summary.5", [1])
        s.enter("summary.5", "")
        said = views.entry(s, "summary.5").message
        assert said.endswith(": no answer ticked (still using 'the input amplitude')")
        s.choose("summary.1", [1])
        s.enter("summary.1", "a, b")
        said = views.entry(s, "summary.1").message
        assert said.endswith(
            ": pick one answer, not 2: 'a model' and 'a system' (still using 'a system')"
        )
        s.enter("summary.3", "z")
        said = views.entry(s, "summary.3").message
        assert "'z' names none of the answers: 'how fast the system reacts" in said
        for letters in ("a/b", "'b'", "expected one"):
            assert letters not in said


def test_task10_is_started_not_done_while_its_only_run_was_interrupted(tmp_path):
    """Walk 14: Task 10 read ✓ in the list of steps with its only run cut short, a run that
    Tasks 11-15 never use unless the group chooses it."""
    with Session.create(tmp_path, ["A"]) as s:
        _fill_table(s)
        assert s.step_status("task10") == "todo"
        short = _record_stopped_run(s)
        assert short is not None and short.interrupted
        assert s.step_status("task10") == "started"
        info, _, _ = _record_steps(s)
        assert info is not None and not info.interrupted
        assert s.step_status("task10") == "done"
