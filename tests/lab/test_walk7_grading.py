"""Walk 7's grading and lab-logic defects (D6, D7, D13-D16, T's plausible range, Task 14's
model beside a wrong T): on real session folders with a run of the seeded plant."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.lab.content.steps import FIELDS
from minseg_tui.lab.state.entries import read_entry
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import own_first
from minseg_tui.lab.views import session as views
from minseg_tui.report.write import write_report
from tests.seeded import record_square_wave


def _lab(root: Path, skip: tuple[str, ...] = ()) -> Session:
    """A session with R, the table (without the keys in ``skip``) and a Task 10 run of the
    seeded plant (u_ss at 4.5 V: 4.05 V, omega_ss in the steps about 7.8 rad/s)."""
    s = Session.create(root, ["A"])
    s.enter("R", "5.26")
    for lv, u, w, i in (
        (2.5, "2.05", "3.8", "29.8 mA"),
        (3.5, "3.05", "5.8", "33.5"),
        (4.5, "4.05", "7.8", "37.2"),
    ):
        for key, text in ((f"u_ss@{lv:g}", u), (f"omega_ss@{lv:g}", w), (f"i_ss@{lv:g}", i)):
            if key not in skip:
                s.enter(key, text)
    record_square_wave(s, seed=3, jitter_us=1000)
    return s


def _feedback(s: Session, key: str) -> str:
    view = views.entry(s, key)
    assert view is not None
    return view.feedback


def _said(s: Session, step_id: str) -> str:
    return "\n".join(comp for _, _, comp in views.comparisons(s, step_id))


def test_K_divided_by_the_requested_voltage_is_named_and_wrong(tmp_path):
    """D6: 7.9 / 4.5 = 1.76 is 10 % below 7.9 / 4.05 = 1.951, inside the 10 % tolerance; the
    slip the task teaches is marked wrong, by name, on the screen and in the report."""
    with _lab(tmp_path) as s:
        s.enter("own.omega_step", "7,9")
        s.enter("own.K", "1,76")
        said = _feedback(s, "own.K")
        assert said.startswith("✗ wrong: -10 % from 1.951 rad/s/V"), said
        assert (
            "this is omega_ss / 4.5 V, the requested voltage; the task asks for the measured "
            "u_ss = 4.05 V" in said
        )
        assert s.step_status("task11") == "wrong"
        assert "this is omega_ss / 4.5 V" in _said(s, "task11")
        (row,) = [r for r in own_first.step_rows(s) if r.key == "own.K"]
        assert "✗ wrong: this is omega_ss / 4.5 V" in row.cells[3]
        # the honest K, to the digits a group types, stays right
        s.enter("own.K", "1,95")
        assert _feedback(s, "own.K").startswith("✓ right")
        assert s.step_status("task11") == "done"


def test_omega_at_5V_scaled_by_the_requested_voltage_is_named(tmp_path):
    """The same slip on Task 15: omega_ss x 5 V / 4.5 V instead of 5 V x K (K right)."""
    with _lab(tmp_path) as s:
        s.enter("own.omega_step", "7.9")
        s.enter("own.K", "1.95")
        s.enter("own.omega_5", "8.78")  # 7.9 x 5 / 4.5
        said = _feedback(s, "own.omega_5")
        assert said.startswith("✗ wrong") and "scaled by the requested voltage" in said, said
        s.enter("own.omega_5", "9.75")
        assert _feedback(s, "own.omega_5").startswith("✓ right")
        # a K that is itself the slip: omega at 5 V follows it, judged consistent with it
        s.enter("own.K", "1.76")
        s.enter("own.omega_5", "8.8")
        assert _feedback(s, "own.omega_5").startswith("✓ right")


def test_k_v_with_the_requested_voltages_is_named(tmp_path):
    """Task 7: (u_req - R i_ss) / omega_ss per row, median 0.5733, names the slip."""
    with _lab(tmp_path) as s:
        s.enter("own.k_v", "0.573")
        said = _feedback(s, "own.k_v")
        assert said.startswith("✗ wrong") and "requested voltages u_req in place of the" in said
        s.enter("own.k_v", "0.495")
        assert _feedback(s, "own.k_v").startswith("✓ right")


def test_k_a_your_way_is_from_your_k_v(tmp_path):
    """D7: k_a "computed your way" is 0.65 x the group's typed k_v, not the program's."""
    with _lab(tmp_path) as s:
        s.enter("own.k_v", "0.52")
        s.enter("own.k_a", "0.338")  # 0.65 x 0.52
        said = _feedback(s, "own.k_a")
        assert said.startswith("✓ right: 0 % from 0.3380 N m/A"), said
        assert "0.65 × your k_v = 0.52 V s/rad" in _said(s, "table")
        (row,) = [r for r in own_first.table_rows(s) if r.key == "own.k_a"]
        assert "0.65 × the group's k_v = 0.52 V s/rad" in row.cells[2]


def test_exponent_notation_is_echoed_and_T_out_of_range_is_warned():
    """D13: "1e3" and "3.8e0" are not the lab's way of writing a number: echoed. T typed as
    57 s or 1e3 ms is stored with a warning, as other fields warn."""
    r = read_entry(FIELDS["R"], "1e3")
    assert r.ok and r.message == "read as 1000 Ω"
    w = read_entry(FIELDS["omega_ss@2.5"], "3.8e0")
    assert w.ok and w.message == "read as 3.8 rad/s"
    assert read_entry(FIELDS["R"], "5.3").message == ""
    for text in ("57 s", "1e3 ms"):
        t = read_entry(FIELDS["own.T"], text)
        assert t.ok and t.warnings and "tens of ms" in t.warnings[0], text
    assert read_entry(FIELDS["own.T"], "57 ms").warnings == ()
    assert read_entry(FIELDS["own.T"], "43").warnings == ()


def test_a_negative_k_v_keeps_the_run_and_only_J_waits(tmp_path):
    """D14: i_ss typed in A makes the table's k_v negative; the run, omega_ss in the steps,
    K and the 63 % reading need none of it and stay; J says why it waits."""
    with _lab(tmp_path) as s:
        s.enter("i_ss@3.5", "4.7 A")
        s.enter("i_ss@2.5", "4.7 A")
        view = views.results(s, "task12")
        assert view.run == "steps-1" and view.t.size > 0 and view.rises
        assert any("positive k_v" in p for p in view.problems)
        assert not any("gives no step result" in p for p in view.problems)
        s.enter("own.omega_step", "7.8")
        s.enter("own.T", "56 ms")
        assert _feedback(s, "own.omega_step").startswith("✓ right")
        assert _feedback(s, "own.T").startswith("✓ right")
        text = "\n".join(views.results(s, "task12").lines)
        assert "T (63 %) = " in text
        assert "J: waits for R, k_v and f from the table" in text
        s.enter("own.J", "0.0027")
        said = _feedback(s, "own.J")
        assert said.startswith("○ not judged: J needs R, k_v and f"), said
        assert s.step_status("task13") == "unjudged"


def test_K_waits_for_u_ss_at_the_steps_level(tmp_path):
    """D15: u_ss at 4.5 V not entered: K is not judged against an extrapolated u_ss, the
    screen and the report name the missing entry, and no sentence says the row is missing."""
    with _lab(tmp_path, skip=("u_ss@4.5",)) as s:
        s.enter("own.omega_step", "7.8")
        s.enter("own.K", "2")
        said = _feedback(s, "own.K")
        assert said.startswith("○ not judged: u_ss at 4.5 V is not entered (Task 4)"), said
        assert "computed your way" not in _said(s, "task11")
        assert "○ not judged: u_ss at 4.5 V is not entered" in _said(s, "task11")
        assert s.step_status("task11") == "unjudged"
        warned = [n.message for n in s.warnings()]
        assert not any("No table row has" in m for m in warned)
        assert any(m.startswith("u_ss at 4.5 V is not entered (Task 4)") for m in warned)
        md = write_report(s).markdown.read_text(encoding="utf-8")
        assert "No table row has" not in md and "u_ss at 4.5 V is not entered (Task 4)" in md
        (row,) = [r for r in own_first.step_rows(s) if r.key == "own.K"]
        assert row.cells[3].startswith("○ not judged: u_ss at 4.5 V is not entered")


def test_u_ss_above_u_req_names_each_row(tmp_path):
    """D15: "on every row (by 9 %)" with rows above by 52 % and 9 %: each row is named."""
    with _lab(tmp_path) as s:
        s.enter("u_ss@2.5", "3.8")
        s.enter("u_ss@3.5", "3.8")
        s.enter("u_ss@4.5", "4.9")
        warned = [n.message for n in s.warnings() if n.source == "u_ss_above_u_req"]
        assert len(warned) == 1
        assert (
            "all 3 rows the results use (by 52 % at 2.5 V, 9 % at 3.5 V and 9 % at 4.5 V)"
            in (warned[0])
        )


def test_the_falling_current_warning_says_what_should_happen(tmp_path):
    """D16: i_ss should rise a little with the speed (not "yet it rises")."""
    with _lab(tmp_path) as s:
        s.enter("i_ss@4.5", "28 mA")
        (said,) = [n.message for n in s.falling_currents()]
        assert "while i_ss should rise a little with the speed" in said
        assert "yet it rises" not in said


def test_a_model_right_with_a_wrong_T_says_so(tmp_path):
    """Walk 7's observation: the model is judged against the group's own T and K (by design),
    and with their T marked wrong the verdict and the list of steps say it rests on it."""
    with _lab(tmp_path) as s:
        s.enter("own.omega_step", "7.9")
        s.enter("own.K", "1.95")
        s.enter("own.T", "85 ms")
        assert _feedback(s, "own.T").startswith("✗ wrong")
        s.enter("own.model", "0,085 omega' = -omega + 1,95 u_A")
        said = _feedback(s, "own.model")
        assert said.startswith("✓ right: T = 85 ms and K = 1.95 rad/s/V"), said
        assert "consistent with your T and K, and your T was marked wrong (Task 12)" in said
        assert s.step_status("task14") == "warned"  # "!", not "✓"
        (row,) = [r for r in own_first.step_rows(s) if r.key == "own.model"]
        assert "the group's T was marked wrong (Task 12)" in row.cells[3]
        # J from that T: the same
        s.enter("own.J", "0.00271")
        assert "your T was marked wrong (Task 12)" in _feedback(s, "own.J")
        s.enter("own.T", "56 ms")
        s.enter("own.model", "0,056 omega' = -omega + 1,95 u_A")
        assert "marked wrong" not in _feedback(s, "own.model")
        assert s.step_status("task14") == "done"
