"""`minseg-tui class` on real session folders: the rows, what stands out, the report files,
bad input, and that the sessions are left exactly as they were."""

from __future__ import annotations

import csv
import io
import json
import os
import re
import shutil
from pathlib import Path

import pytest

from minseg_tui.cli import main
from minseg_tui.lab.saving.store import lock_owner
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views.check_says import in_words
from minseg_tui.quantities import format_number

from .build import group

NORMAL = 5


@pytest.fixture(scope="module")
def klass(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A class: five ordinary groups, one with slips, one with a current in amperes, one
    unfinished (no run, at Tasks 6-9), and one whose file is not JSON."""
    root = tmp_path_factory.mktemp("class") / "sessions"
    for k in range(NORMAL):
        group(root, [f"Ada {k}", f"Bo {k}"], seed=k, own_T="0.05 s" if k == 0 else None)
    group(
        root,
        ["Rpm", "Man"],
        seed=11,
        R="12 Ω",
        rows={4.5: ("4.6", "74.3", "37 mA"), 3.5: ("3.05", "5.8", "350 mA")},
    )
    group(root, ["Amp", "Ere"], seed=12, rows={2.5: ("2.05", "3.8", "0.0298 mA")})
    group(root, ["Late", "Comer"], seed=13, run=False, at="table")
    (root / "zz-broken").mkdir()
    (root / "zz-broken" / "session.json").write_text("{not json", encoding="utf-8")
    return root


GROUP = pytest.mark.xdist_group("class-klass")
"""The tests reading :func:`klass` run on one worker under make test's -n 2 (--dist
loadgroup), so the module fixture's class of eight groups is built once, not once per worker."""


def _run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["class", *args])
    out, err = capsys.readouterr()
    return code, out, err


def _by_members(doc: dict[str, object]) -> dict[str, dict[str, object]]:
    groups = doc["groups"]
    assert isinstance(groups, list)
    return {" ".join(g["members"]) or g["id"]: g for g in groups}


@GROUP
def test_json_one_row_per_group_numbers_are_the_sessions_own(klass, capsys):
    code, out, err = _run(capsys, "--sessions", str(klass), "--json")
    doc = json.loads(out)
    g = _by_members(doc)
    assert len(g) == NORMAL + 4
    assert code == 2 and err.count("\n") == 1 and "zz-broken" in err  # the unreadable one
    ada = g["Ada 0 Bo 0"]
    s = Session.open(Path(str(ada["folder"])), readonly=True)
    ident = s.results().identification
    assert ident is not None and ident.step is not None
    # one source of numbers: exactly what the session (and so `report`) computes
    assert ada["k_v"] == ident.k_v and ada["f"] == ident.f and ada["k_a"] == ident.k_a
    assert ada["K"] == ident.step.K and ada["T"] == ident.step.T and ada["J"] == ident.step.J
    assert ada["T_63"] == ident.step.T_63 and ada["R"] == s.value("R")
    mc = s.model_check().result
    assert mc is not None and ada["cause"] == in_words(mc.finding.cause)
    assert ada["cause"] == "dry friction"  # the simulated motor has Coulomb friction
    assert ada["step"] == "Task 12" and ada["date"] == "2026-11-22"
    own = ada["own"]
    assert isinstance(own, list) and own[0]["key"] == "own.T"
    assert own[0]["rel_diff"] == pytest.approx(0.05 / ident.step.T_63 - 1.0)
    for k in range(NORMAL):
        assert g[f"Ada {k} Bo {k}"]["flags"] == [], g[f"Ada {k} Bo {k}"]["flags"]
        assert g[f"Ada {k} Bo {k}"]["lacks"] == []


@GROUP
def test_slips_and_far_values_are_said_in_words(klass, capsys):
    _, out, _ = _run(capsys, "--sessions", str(klass), "--json")
    doc = json.loads(out)
    g = _by_members(doc)
    flags = " / ".join(g["Rpm Man"]["flags"])
    assert "R = 12 Ω is outside the 3-6 Ω" in flags
    assert "omega_ss at 4.5 V = 74.30 rad/s looks like rpm" in flags and "7.781 rad/s" in flags
    assert "u_ss at 4.5 V = 4.6 V is above the requested 4.5 V" in flags  # as typed (walk 9, D9)
    assert "i_ss at 3.5 V = 350 mA is above 100 mA" in flags
    assert re.search(
        r"R = 12 Ω is far above the class: \d+ robust standard deviations from its "
        r"median of 5\.\d+ Ω\.",
        flags,
    )
    # each flag a sentence about the value: it names no group and ends as a sentence
    for f in [*g["Rpm Man"]["flags"], *g["Amp Ere"]["flags"]]:
        assert f.endswith(".") and "rpm-man" not in f and "Rpm" not in f, f
    amp = " / ".join(g["Amp Ere"]["flags"])
    assert "i_ss at 2.5 V = 0.0298 mA looks like amperes" in amp
    assert "f = " in amp and "far below the class" in amp  # f rests on that current
    # what rests on a slip is judged, never part of the class's median and MAD
    assert g["Rpm Man"]["left_out_of_class"] == ["R", "k_v", "k_a", "f", "K", "J"]
    assert g["Amp Ere"]["left_out_of_class"] == ["k_v", "k_a", "f", "J"]
    assert g["Ada 0 Bo 0"]["left_out_of_class"] == []
    spreads = doc["class"]
    assert spreads["R"]["n"] == NORMAL + 2  # Amp Ere's and Late Comer's R count
    assert spreads["k_v"]["n"] == NORMAL + 1 and spreads["K"]["n"] == NORMAL + 1
    assert spreads["T"]["n"] == NORMAL + 2  # T rests on none of these readings


def test_a_dropped_decimal_point_in_R_is_named(tmp_path, capsys):
    root = tmp_path / "s"
    for k in range(4):
        group(root, [f"G{k}"], seed=k, run=False)
    group(root, ["Dot"], seed=9, R="53", run=False)
    group(root, ["Kilo"], seed=10, R="0.0052", run=False)
    code, out, _ = _run(capsys, "--sessions", str(root), "--json")
    doc = json.loads(out)
    g = _by_members(doc)
    assert code == 0
    assert g["Dot"]["flags"][0] == (
        "R = 53 Ω is outside the 3-6 Ω this motor reads (Task 2): it looks like 5.3 Ω "
        "with its decimal point dropped."
    )
    assert "looks like 5.2 Ω with the meter on its kΩ range" in g["Kilo"]["flags"][0]
    assert doc["class"]["R"]["n"] == 4 and doc["class"]["k_v"]["n"] == 4


@GROUP
def test_unfinished_and_damaged_are_listed_with_what_they_lack(klass, capsys):
    _, out, _ = _run(capsys, "--sessions", str(klass), "--json")
    g = _by_members(json.loads(out))
    late = g["Late Comer"]
    assert late["step"] == "Tasks 6-9" and late["K"] is None and late["k_v"] is not None
    assert late["lacks"] == ["no run recorded yet (Task 10)"] and late["cause"] == ""
    broken = g["zz-broken"]
    assert broken["members"] == [] and broken["k_v"] is None
    assert (
        broken["lacks"][0].startswith("cannot be read:") and "not valid JSON" in broken["damaged"]
    )


@GROUP
def test_text_table_names_steps_and_units(klass, capsys):
    code, out, err = _run(capsys, "--sessions", str(klass))
    assert code == 2 and "zz-broken" in err
    head = out.splitlines()[0].split()
    assert head[:4] == ["#", "group", "members", "step"]
    assert "Task 12" in out and "Tasks 6-9" in out and "task12" not in out
    assert "units: R Ω, k_v V s/rad" in out
    ada = next(line for line in out.splitlines() if "Ada 0, Bo 0" in line)
    assert re.search(r"dry friction\s+T [+-]\d+ %$", ada)  # the group's own T against T_63
    assert "! R = 12 Ω is outside" in out and "- lacks: no run recorded yet" in out


@GROUP
def test_out_writes_markdown_html_and_csv(klass, tmp_path, capsys):
    out_dir = tmp_path / "out"
    _run(capsys, "--sessions", str(klass), "--out", str(out_dir))
    _, js, _ = _run(capsys, "--sessions", str(klass), "--json")
    groups = json.loads(js)["groups"]
    page = (out_dir / "class.html").read_text(encoding="utf-8")
    assert page.count("<figure") == 7  # R, k_v, f, K, T_63, T, J
    assert not re.search(r"""(src|href)=["']?(https?:|//)""", page) and "<script" not in page
    assert "@media print" in page and "Nothing stands out" not in page
    # seventeen columns: printed on landscape pages (on portrait ones the flags column was
    # cut at the page's edge and each group id took five lines), two figures to a row
    assert "@page { size: A4 landscape;" in page and "max-width: 48% !important" in page
    md = (out_dir / "class.md").read_text(encoding="utf-8")
    assert md.count("data:image/svg+xml;base64,") == 7 and "## What stands out" in md
    # what stands out: one row per group, the group named once, its flags one per line
    stands = md.split("## What stands out")[1].split("##")[0]
    rpm = next(g for g in groups if g["members"] == ["Rpm", "Man"])
    rows = [line for line in stands.splitlines() if line.startswith("| ")]
    assert rows[0] == "| \\# | group | what stands out |"
    assert sum(rpm["id"] in line for line in rows) == 1
    assert len([g for g in groups if g["flags"]]) == len(rows) - 1
    cell = next(line for line in page.split("<tr>") if rpm["id"] in line and "<br>" in line)
    assert cell.count("<br>") == len(rpm["flags"])  # the id's line, then one per flag
    rows = list(csv.DictReader(io.StringIO((out_dir / "class.csv").read_text(encoding="utf-8"))))
    assert [r["id"] for r in rows] == [g["id"] for g in groups]
    for r, g in zip(rows, groups, strict=True):
        for key, col in (("k_v", "k_v (V s/rad)"), ("T", "T (s)"), ("J", "J (kg m^2)")):
            assert (float(r[col]) if r[col] else None) == g[key]
        assert r["flags"] == " | ".join(g["flags"])


def _state(root: Path) -> dict[str, tuple[int, bytes]]:
    return {
        str(p): (p.stat().st_mtime_ns, p.read_bytes())
        for p in sorted(root.rglob("*"))
        if p.is_file()
    }


@GROUP
def test_sessions_are_never_written_nor_locked(klass, tmp_path, capsys):
    before = _state(klass)
    names = {p.name for p in klass.rglob("*")}
    _run(capsys, "--sessions", str(klass), "--json")
    _run(capsys, "--sessions", str(klass), "--out", str(tmp_path / "o"))
    assert _state(klass) == before
    assert {p.name for p in klass.rglob("*")} == names


def test_a_group_at_work_is_not_blocked(tmp_path, capsys):
    root = tmp_path / "s"
    for k in range(2):
        group(root, [f"G{k}"], seed=k, run=False)
    folder = sorted(root.iterdir())[0]
    with Session.open(folder) as working:  # the group has its session open
        assert lock_owner(folder) == os.getpid()
        code, out, _ = _run(capsys, "--sessions", str(root), "--json")
        assert code == 0 and len(json.loads(out)["groups"]) == 2
        working.enter("R", "5.3 Ω")  # and goes on working, saved
        assert working.save_problem is None
        assert lock_owner(folder) == os.getpid()
    assert Session.open(folder, readonly=True).value("R") == pytest.approx(5.3)


def test_a_schema_1_session_written_by_hand_is_listed(tmp_path, capsys):
    folder = tmp_path / "s" / "old-group"
    (folder / "runs").mkdir(parents=True)
    entry = {
        "text": "4.9",
        "ok": True,
        "value": 4.9,
        "unit": "Ω",
        "message": "",
        "warnings": [],
        "source": "typed",
        "at": "2025-11-20T10:00:00+00:00",
        "history": [],
    }
    doc = {
        "kind": "minseg-tui session",
        "schema": 1,
        "id": "old-group",
        "members": ["Old", "Timer"],
        "date": "2025-11-20",
        "created": "2025-11-20T10:00:00+00:00",
        "modified": "2025-11-20T10:00:00+00:00",
        "current_step": "task2",
        "selected_run": None,
        "entries": {"R": entry},
        "captures": {},
        "runs": [],
    }
    (folder / "session.json").write_text(json.dumps(doc), encoding="utf-8")
    code, out, err = _run(capsys, "--sessions", str(tmp_path / "s"), "--json")
    assert code == 0, err
    (g,) = json.loads(out)["groups"]
    assert g["members"] == ["Old", "Timer"] and g["R"] == 4.9 and g["step"] == "Task 2"
    assert g["damaged"] is None and "R is not entered" not in " ".join(g["lacks"])


@pytest.mark.parametrize(
    ("make", "expected"),
    [
        (lambda p: p / "nowhere", "does not exist"),
        (lambda p: p, "holds no session"),
    ],
)
def test_bad_sessions_folder_one_line_exit_2(tmp_path, capsys, make, expected):
    code, out, err = _run(capsys, "--sessions", str(make(tmp_path)))
    assert code == 2 and out == "" and err.count("\n") == 1 and expected in err
    assert err.startswith("minseg-tui class: ")


def test_out_that_cannot_be_written_one_line_exit_2(tmp_path, capsys):
    root = tmp_path / "s"
    group(root, ["A"], seed=1, run=False)
    blocker = tmp_path / "file"
    blocker.write_text("x", encoding="utf-8")
    code, out, err = _run(capsys, "--sessions", str(root), "--out", str(blocker / "sub"))
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "cannot write the class report here" in err


def test_second_reading_comes_from_the_cache_and_a_change_is_read_again(
    tmp_path, capsys, own_cache
):
    root = tmp_path / "s"
    folders = [group(root, [f"G{k}"], seed=k) for k in range(4)]
    code, cold, _ = _run(capsys, "--sessions", str(root), "--json", "--workers", "2")
    assert code == 0 and len(list(own_cache.glob("*.json"))) == 4
    assert not any("cache" in p.name for p in root.rglob("*"))
    code, warm, _ = _run(capsys, "--sessions", str(root), "--json", "--workers", "1")
    assert code == 0 and warm == cold
    with Session.open(folders[2]) as s:  # the group changes its R: that row is read again
        s.enter("R", "7.5 Ω")
    _, again, _ = _run(capsys, "--sessions", str(root), "--json")
    g = _by_members(json.loads(again))
    assert g["G2"]["R"] == pytest.approx(7.5) and "outside the 3-6 Ω" in g["G2"]["flags"][0]
    assert g["G1"] == _by_members(json.loads(cold))["G1"]
    assert len(list(own_cache.glob("*.json"))) == 5


def test_a_cache_that_cannot_be_written_changes_nothing(tmp_path, capsys, monkeypatch):
    root = tmp_path / "s"
    group(root, ["A"], seed=1, run=False)
    blocker = tmp_path / "blocker"
    blocker.write_text("x", encoding="utf-8")
    monkeypatch.setenv("MINSEG_TUI_CACHE", str(blocker / "cache"))
    code, out, err = _run(capsys, "--sessions", str(root), "--json")
    assert code == 0 and err == "" and json.loads(out)["groups"][0]["members"] == ["A"]


def test_a_copied_session_is_named_by_its_own_folder(tmp_path, capsys):
    root = tmp_path / "s"
    folder = group(root, ["Ada"], seed=1, run=False)
    shutil.copytree(folder, root / "ada-copy")  # its file still says the first id
    _, out, _ = _run(capsys, "--sessions", str(root), "--json")
    ids = [g["id"] for g in json.loads(out)["groups"]]
    assert sorted(ids) == sorted([folder.name, "ada-copy"])


@GROUP
def test_f_is_shown_in_mN_m_s_per_rad_and_kept_si_in_csv_and_json(klass, tmp_path, capsys):
    """The class's text, report and figures showed f in N m s/rad while the lab's table and
    Task 9's entry use mN m s/rad: one unit for f wherever people read it; the CSV and the
    JSON keep SI."""
    _, js, _ = _run(capsys, "--sessions", str(klass), "--json")
    f = [g["f"] for g in json.loads(js)["groups"] if g["f"] is not None]
    _, out, _ = _run(capsys, "--sessions", str(klass))
    assert "f mN m s/rad" in out and " N m s/rad" not in out.replace("mN m s/rad", "")
    _run(capsys, "--sessions", str(klass), "--out", str(tmp_path / "out"))
    md = (tmp_path / "out" / "class.md").read_text(encoding="utf-8")
    assert "| f (mN m s/rad) |" in md and "f (N m s/rad)" not in md
    assert format_number(f[0] * 1e3) in md.split("## What stands out")[0]
    rows = list(csv.DictReader(io.StringIO((tmp_path / "out" / "class.csv").read_text("utf-8"))))
    assert [float(r["f (N m s/rad)"]) for r in rows if r["f (N m s/rad)"]] == f


def test_a_K_divided_by_the_requested_step_height_is_named(tmp_path, capsys):
    """Walk 7, D6's slip in the class view: a group that divided its omega_ss by the
    requested 4.5 V (7.9 / 4.5 = 1.756) instead of by its measured u_ss (4.05 V) is flagged
    by name; a group that divided by u_ss (7.9 / 4.05 = 1.951) is not. Real session folders,
    `minseg-tui class --json`."""
    root = tmp_path / "s"
    rows = {4.5: ("4.05", "7.79", "37.2 mA")}
    for name, K in (("Slip", "1,756"), ("Right", "1,951")):
        folder = group(root, [name], seed=3, rows=rows, run=False)
        with Session.open(folder) as s:
            assert s.enter("own.omega_step", "7,9").ok and s.enter("own.K", K).ok
    code, out, _ = _run(capsys, "--sessions", str(root), "--json")
    g = _by_members(json.loads(out))
    assert code == 0
    (flag,) = [f for f in g["Slip"]["flags"] if f.startswith("K = ")]
    assert flag == (
        "K = 1.756 rad/s/V is omega_ss ÷ 4.5 V (the requested step height), not ÷ the "
        "measured u_ss = 4.050 V (Task 11): 7.900 / 4.05 = 1.951 rad/s/V."
    )
    assert not [f for f in g["Right"]["flags"] if f.startswith("K = ")]
