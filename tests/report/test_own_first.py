"""The report as an instructor grading a group reads it: the group's own value leads every
section, the program's follows and is named as the program's, each row says when the group
was shown the computed value, no cell is left blank, and the report names the run it used
(and what interrupted it)."""

from __future__ import annotations

import re
import shutil
from html import unescape
from pathlib import Path

import pytest

from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.quantities import format_constant, format_number
from minseg_tui.report.write import write_report
from tests.report.test_report import _session
from tests.seeded import record_square_wave


def _section(md: str, title: str) -> str:
    return md.split(f"## {title}", 1)[1].split("\n## ", 1)[0]


def _tables(text: str) -> list[list[list[str]]]:
    """Every Markdown table in ``text``: rows of cells (header first, the rule left out),
    backslash escapes undone."""
    out: list[list[list[str]]] = []
    rows: list[list[str]] = []
    for line in [*text.splitlines(), ""]:
        if line.startswith("|"):
            if not line.startswith("|---"):
                cells = re.split(r"(?<!\\)\|", line.strip()[1:-1])
                rows.append([re.sub(r"\\(.)", r"\1", c).strip() for c in cells])
        elif rows:
            out.append(rows)
            rows = []
    return out


def _row(table: list[list[str]], first: str) -> dict[str, str]:
    (row,) = [r for r in table[1:] if r[0].startswith(first)]
    return dict(zip(table[0], row, strict=True))


def _report(s: Session) -> str:
    return write_report(s).markdown.read_text(encoding="utf-8")


def test_every_value_leads_with_the_groups_own(tmp_path: Path) -> None:
    """The step section's first table held the program's T, J, model and omega at 5 V under
    "value", the group's only further down; the steady state listed the program's k_v, k_a
    and f alone. Now each row reads: the group's value, theirs computed their way, the
    program's."""
    s = _session(tmp_path)  # own.T = 0.09 s
    s.enter("own.K", "2.2")
    s.enter("own.k_v", "0.5 V s/rad")
    st = s.results().identification
    assert st is not None and st.step is not None
    md = _report(s)
    s.close()
    steady = _section(md, "Steady state")
    assert "- k_v = " not in steady  # no program value stands alone
    readings, constants = _tables(steady)
    assert readings[0][-2:] == ["k_v, computed (Task 6)", "f, computed (Task 9)"]
    assert constants[0][:3] == ["quantity", "the group's value", "computed from the group's table"]
    k_v = _row(constants, "k_v (Task 7)")
    assert k_v["the group's value"] == "0.5 V s/rad"
    assert k_v["computed from the group's table"].startswith(format_number(st.k_v))
    assert _row(constants, "k_a (Task 8)")["the group's value"] == "not answered"
    results = _section(md, "Step response and model")
    (table,) = _tables(results)  # one table: no second one of the program's values
    assert table[0][:2] == ["quantity", "the group's value"]
    assert table[0][4] == "the program's value (least squares)"
    K = _row(table, "K (Task 11)")
    assert K["the group's value"] == "2.2 rad/s/V"
    assert K["the program's value (least squares)"].startswith(format_number(st.step.K))
    T = _row(table, "T (Task 12)")
    assert T["the group's value"] == "90 ms"  # typed '0.09 s': T in ms, as everywhere (walk 6)
    assert T["computed or read the group's way"].startswith(
        format_constant(st.step.T_63 or 0.0, "s")
    )
    assert "the program's reading by the group's method" in T["computed or read the group's way"]
    assert T["the program's value (least squares)"].startswith(format_constant(st.step.T, "s"))
    J = _row(table, "J (Task 13)")
    assert J["the group's value"] == "not answered"
    assert (
        "from the group's T = 90 ms" in J["computed or read the group's way"]
    )  # its digits, in ms
    assert J["the program's value (least squares)"].startswith(format_number(st.step.J))
    model = _row(table, "the model (Task 14)")
    assert model["computed or read the group's way"].endswith("(with the group's T and K)")
    # the close-up of one rise is the program's reading, and says so
    (caption,) = re.findall(r"^\*(.*)\*$", results, re.M)
    assert caption.startswith("The program's reading of one rise of run steps-1")
    # why the group's way and the program's differ, one sentence each, after the table
    assert "J (Task 13): The least-squares J uses T = " in results
    assert "T (Task 12): Both are fair readings of T: the 63 % reading" in results


def test_the_shown_column_says_when_the_group_saw_each_value(tmp_path: Path) -> None:
    """Tasks 7-9's "shown" cells were blank though the table shows k_v, k_a and f from the
    start; rows of Tasks 11-15 not yet answered were left out. Every row now says it."""
    s = _session(tmp_path)  # own.T answered
    s.enter("own.f", "1.9")
    views.note_drawn(s, views.results(s.snapshot(), "task12"))  # as the lab screen does
    assert s.reveal("task13") == ["own.J"]
    md = _report(s)
    s.close()
    (constants,) = _tables(_section(md, "Steady state"))[1:]
    for name in ("k_v (Task 7)", "k_a (Task 8)", "f (Task 9)"):
        shown = _row(constants, name)["shown to the group"]
        assert shown.startswith("shown in the program's Task 4-9 table from the start"), shown
    (table,) = _tables(_section(md, "Step response and model"))
    shown = {r[0]: r[-1] for r in table[1:]}
    assert re.fullmatch(
        r"after the group answered \('0.09 s'\): shown on Tasks 11-15, 2026-11-22 10:00:\d\d UTC",
        shown["T (Task 12)"],
    ), shown["T (Task 12)"]
    assert re.fullmatch(
        r"revealed before answering: shown with Ctrl\+R, the lab assistant's key, "
        r"2026-11-22 10:00:\d\d UTC; not answered",
        shown["J (Task 13)"],
    ), shown["J (Task 13)"]
    assert shown["K (Task 11)"] == "not shown on the group's screen in this session (not answered)"
    assert len(shown) == 6  # every value of Tasks 11-15, answered or not
    results = _section(md, "Step response and model")
    assert re.search(
        r"The lab's policy while the group worked, as the session recorded it: answers first "
        r"\(no lab.toml: the default\), from 2026-11-22 10:00:\d\d UTC\.",
        results,
    )
    # lab.toml written after the group worked: the report keeps to what was in force (the
    # rows said "shown from the start by the lab's policy", read from the file at export)
    (tmp_path / "lab.toml").write_text("answers_first = false\n", encoding="utf-8")
    with Session.open(s.folder, readonly=True) as again:
        md2 = write_report(again).markdown.read_text(encoding="utf-8")
    (table2,) = _tables(_section(md2, "Step response and model"))
    assert {r[0]: r[-1] for r in table2[1:]} == shown
    assert (
        "lab.toml now says: computed values at once (lab.toml: answers_first = false); while "
        "the group worked it was: answers first (no lab.toml: the default)"
    ) in _section(md2, "Warnings")


def test_no_cell_of_the_report_is_blank(tmp_path: Path) -> None:
    s = _session(tmp_path)
    md = _report(s)
    s.close()
    for table in _tables(md):
        for row in table:
            assert all(cell for cell in row), (table[0], row)


def _append_run(s: Session, periods: int, stopped_early: bool, ended_by: str = "") -> str:
    info = record_square_wave(
        s, seed=22, periods=periods, stopped_early=stopped_early, ended_by=ended_by
    )
    assert info is not None
    return info.name


def test_the_report_names_the_run_it_used_and_what_interrupted_it(tmp_path: Path) -> None:
    s = _session(tmp_path)  # steps-1, complete
    quit_run = _append_run(s, 2, stopped_early=True, ended_by="quit")
    md = _report(s)
    results = _section(md, "Step response and model")
    assert (
        "Tasks 11-15 and the model check use run steps-1, the newest complete 25 ms run "
        "(the group chose none)." in results
    )
    runs = _tables(_section(md, "Recorded runs"))[0]
    assert _row(runs, quit_run)["interrupted by"] == "quit"
    assert _row(runs, "steps-1")["interrupted by"] == "not interrupted"
    s.select_run(quit_run)
    md = _report(s)
    s.close()
    samples = _row(runs, quit_run)["samples"]
    assert (
        f"Tasks 11-15 and the model check use run {quit_run}, chosen by the group; it ended "
        f"before its plan did ({samples} samples), interrupted by: quit."
        in _section(md, "Step response and model")
    )


def test_the_model_check_opens_as_the_screen_does_on_the_edge_its_close_up_shows(
    tmp_path: Path,
) -> None:
    """As on the screen: the run and the close-up's span first, then the sentences a student
    reads, about the edge the close-up shows (and the evidence in the details names the
    same edge), then the figures, the details last."""
    s = _session(tmp_path)
    r = s.model_check().result
    md = _report(s)
    s.close()
    assert r is not None and r.close_up is not None
    check = _section(md, "Model check")
    paragraphs = [p for p in check.split("\n\n") if p.strip()]
    assert paragraphs[0].startswith("The group wrote no notes on the model check")
    head = re.match(r"Run steps-1, close-up ([0-9.]+)-([0-9.]+) s: ", paragraphs[1])
    assert head, paragraphs[1]
    t0, t1 = (float(x) for x in head.groups())
    assert (t0, t1) == pytest.approx((r.close_up.t0, r.close_up.t1), abs=0.006)
    story, details = paragraphs[2], check.split("### Details", 1)[1]
    evidence = details.split("Why dry friction, over the whole run:", 1)[1].split("\n")[0]
    for text in (story, evidence):
        edges = [float(x) for x in re.findall(r"t = ([0-9.]+) s", text)]
        assert edges and all(t0 <= t <= t1 for t in edges), (t0, t1, text)
    assert check.index(story) < check.index("![") < check.index("### Details")
    # the close-up's caption spells its span as the line above the story does
    captions = re.findall(r"^\*(.*)\*$", check, re.M)
    assert any(c.startswith(paragraphs[1].rstrip(".")) for c in captions), captions


def test_a_policy_file_that_cannot_be_read_is_a_warning(tmp_path: Path) -> None:
    """The "shown to the group" cells follow lab.toml: one that cannot be read (answers
    first then holds) is said in the report's warnings, as Tasks 11-15 say it on screen."""
    s = _session(tmp_path)
    views.note_drawn(s, views.results(s.snapshot(), "task12"))
    s.close()
    (tmp_path / "lab.toml").write_text("answers_first = maybe\n", encoding="utf-8")
    with Session.open(s.folder, readonly=True) as again:
        md = write_report(again).markdown.read_text(encoding="utf-8")
    warnings = _section(md, "Warnings")
    assert "lab.toml: cannot be read" in warnings and "answers first" in warnings
    (table,) = _tables(_section(md, "Step response and model"))
    assert _row(table, "T (Task 12)")["shown to the group"].startswith("after the group answered")


def test_an_incomplete_row_says_what_is_missing(tmp_path: Path) -> None:
    """A row the group has not filled read '–' in every cell: the readings now say they were
    not entered, the program's k_v and f which readings they need and where (walk 8, D7)."""
    with Session.create(tmp_path, ["A"], date="2026-11-22") as s:
        s.enter("R", "5.26")
        s.enter("u_ss@4.5", "4.05 V")
        md = _report(s)
    readings = _tables(_section(md, "Steady state"))[0]
    row = _row(readings, "4.5 V")
    assert row["u_ss"] == "4.05 V" and row["omega_ss (± spread)"] == "not entered"
    assert row["capture window (board clock)"] == "no capture" and row["i_ss"] == "not entered"
    assert (
        row["k_v, computed (Task 6)"] == "not computed: needs omega_ss (Task 4) and i_ss (Task 5)"
    )


def test_the_groups_notes_lead_the_model_check(tmp_path: Path) -> None:
    """The model check is the program's work; what the group wrote about it came only at the
    end of the report, among the Notes. It now opens the section, and is not repeated."""
    s = _session(tmp_path)
    s.enter("model_check.notes", "the wheel stops early after each drop")
    md = _report(s)
    s.close()
    check = _section(md, "Model check")
    first = check.strip().split("\n\n")[0]
    assert first == "The group's notes on the model check: the wheel stops early after each drop"
    assert md.count("the wheel stops early after each drop") == 1
    assert "y' = 0 gives y = K c" in _section(md, "Notes")  # the other notes stay there


def test_a_value_the_model_check_showed_first_was_revealed_before_answering(
    tmp_path: Path,
) -> None:
    """Issue 20, item 1: the report said "after the group answered" of every value the group
    had typed by the time of the export, though the model check, which writes the fitted T
    and K, may have been on their screen before. What was recorded decides now."""
    s = _session(tmp_path)  # own.T answered; K not yet
    views.note_drawn(s, views.check(s.snapshot()))  # the group opens the model check
    s.enter("own.K", "1.9")
    views.note_drawn(s, views.results(s.snapshot(), "task11"))
    md = _report(s)
    s.close()
    (table,) = _tables(_section(md, "Step response and model"))
    K = _row(table, "K (Task 11)")["shown to the group"]
    assert re.fullmatch(
        r"revealed before answering: shown by the model check \(it writes the fitted T and K\), "
        r"2026-11-22 10:00:\d\d UTC; answered 2026-11-22 10:00:\d\d UTC",
        K,
    ), K
    T = _row(table, "T (Task 12)")["shown to the group"]
    assert T.startswith("after the group answered ('0.09 s'): shown by the model check"), T
    assert _row(table, "J (Task 13)")["shown to the group"].startswith("not shown")


def test_an_answer_changed_after_the_value_was_shown_is_said(tmp_path: Path) -> None:
    s = _session(tmp_path)  # own.T = 0.09 s
    views.note_drawn(s, views.results(s.snapshot(), "task12"))
    s.enter("own.T", "56 ms")  # the group saw the 63 % reading, then changed theirs
    md = _report(s)
    s.close()
    (table,) = _tables(_section(md, "Step response and model"))
    T = _row(table, "T (Task 12)")["shown to the group"]
    assert T.startswith("after the group answered ('0.09 s')"), T
    assert re.search(r"; the answer was changed after that, to '56 ms', 2026-11-22 10:00:\d\d", T)


def test_an_old_session_says_what_it_cannot_know(tmp_path: Path) -> None:
    """A session of a program that did not record showings or the policy: the report does not
    claim "after the group answered", nor a policy read from today's file."""
    folder = tmp_path / "schema1"
    shutil.copytree(Path(__file__).parents[1] / "lab" / "old_sessions" / "schema1", folder)
    with Session.open(folder, readonly=True) as s:
        answered = s.answered()
        md = _report(s)
    (table,) = _tables(_section(md, "Step response and model"))
    for row in table[1:]:
        assert row[-1].startswith("not known: the session was begun with an older program"), row
    assert answered  # the old group did answer some: no "after the group answered" for them
    assert "The lab's policy while the group worked is not known" in md
    assert "the lab's policy is not recorded in this session" in _section(md, "Warnings")


_SECOND_PERSON = re.compile(r"\b(you|your|yours|yourselves)\b", re.I)


def test_the_report_speaks_of_the_group_not_to_it(tmp_path: Path) -> None:
    """Issue 20, item 3: an instructor reads the report; cells said "your T", "yours divides
    ...", the Preparation feedback "check your working", a refused entry "your model". The
    whole report, Markdown and HTML, now names the group; a message the program gave the
    group is quoted as such."""
    s = _session(tmp_path)
    for key, text in (
        ("own.omega_step", "7.0"),
        ("own.K", "1.75"),
        ("own.J", "0.0006"),
        ("own.model", "0.09 omega' = -omega + 1.75 u_A"),
        ("own.omega_5", "8.75"),
        ("own.k_v", "0.49"),
        ("prep14.T", "R J"),  # wrong, no named slip: "not right yet; check your working"
        ("prep7.t_63", "10 min"),
        ("prep7.T", "6 min"),  # "consistent with your readings"
        ("prep7.K", "0.05"),  # "enter final temperature first"
        ("own.f", "0.00186"),  # refused: "... if you mean it"
    ):
        s.enter(key, text)
    views.note_drawn(s, views.results(s.snapshot(), "task15"))
    written = write_report(s)
    s.close()
    md = written.markdown.read_text(encoding="utf-8")
    html = re.sub(r"<[^>]+>", " ", unescape(written.html.read_text(encoding="utf-8")))
    told = "the program told the group:"
    for doc in (md, html):
        said = [line.split(told)[0] for line in doc.splitlines()]
        found = [m.group(0) for line in said for m in _SECOND_PERSON.finditer(line)]
        assert not found, [line for line in said if _SECOND_PERSON.search(line)]
    assert "consistent with the group's readings" in md and "not right" in md
    assert "not checked: final temperature is not entered" in md
    assert f"Tasks 6-9, the group's f: '0.00186' ({told} " in md


def test_why_the_two_T_differ_names_what_the_fit_used(tmp_path: Path) -> None:
    """Issue 20, item 4: the report said the least-squares T "fits the whole rise" while its
    own "How T was fitted" said one model fits the whole log, every edge rising and falling.
    The sentence now holds for either way of fitting (and for the numbers a session keeps)."""
    s = _session(tmp_path)  # own.T = 0.09 s
    st = s.results().identification.step
    md = _report(s)
    s.close()
    assert st is not None and st.fit.method == "whole_log"
    results = _section(md, "Step response and model")
    assert "whole rise" not in results
    assert "the least-squares fit models the sampling, so its T describes the motor." in results
    assert "J uses T = " in results and "fitted over whole stretches of the run;" in results
    assert "How T was fitted: one first-order model fits the whole log" in results


def test_an_old_session_continued_claims_nothing_from_before_its_record(tmp_path: Path) -> None:
    """An older program's session opened again: what the group saw before that opening is
    not known, so a value first recorded with the group's answer in place is not said to be
    "after the group answered"; one shown before any answer still is revealed before."""
    folder = tmp_path / "schema1"
    shutil.copytree(Path(__file__).parents[1] / "lab" / "old_sessions" / "schema1", folder)
    with Session.open(folder) as s:
        assert s.shown_since is not None and s.shown_since > s.created
        s.enter("own.T", "57 ms")
        views.note_drawn(s, views.results(s.snapshot(), "task12"))
        md = _report(s)
    (table,) = _tables(_section(md, "Step response and model"))
    T = _row(table, "T (Task 12)")["shown to the group"]
    assert T.startswith("not known whether before or after answering: first recorded on "), T
    assert "not known before: the session was begun with an older program" in T


def test_the_report_marks_each_value_and_says_what_the_marks_mean(tmp_path: Path) -> None:
    """Issue 20: the marks of the group's screen (✓ right, ✗ wrong, ○ stored, not judged yet)
    are the report's, and the report says what each means under its tables."""
    from tests.lab.test_compare import _lab

    with _lab(tmp_path) as s:
        st = s.results().identification.step  # type: ignore[union-attr]
        s.enter("own.T", format_number(st.T_63 * 1e3) + " ms")  # right: the 63 % reading
        s.enter("own.J", "1")  # wrong by far
        md = _report(s)
    steps = _section(md, "Step response and model (Tasks 10-15)")
    said = " ".join(unescape(steps).split())
    assert "Marks: ✓ right; ✗ wrong" in said and f"○ {views.NOT_JUDGED}" in said
    (table,) = [t for t in _tables(steps) if t[0][0] == "quantity"]
    assert "✓ right" in _row(table, "T (Task 12)")["difference"]
    assert "✗ wrong" in _row(table, "J (Task 13)")["difference"]
