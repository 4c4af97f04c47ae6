"""Reports from a hand-made session: real files, the session's values in md and html, no external references."""

from __future__ import annotations

import base64
import math
import re
from html import unescape
from html.parser import HTMLParser
from pathlib import Path

import numpy as np

from minseg_tui.cli import main
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.quantities import format_constant, format_interval, format_number, format_value
from minseg_tui.report import content, markdown, svg
from minseg_tui.report.write import write_report
from tests.seeded import Clock, record_square_wave

ROWS = (
    (2.5, "2,05 V", "3.82", "29.8 mA"),
    (3.5, "3.05", "5.81", "33.5"),
    (4.5, "4.05 V", "7.78", "0.0372 A"),
)


def _session(root: Path) -> Session:
    s = Session.create(root, ["Ada Lovelace", "Bo Ek"], date="2026-11-22", clock=Clock())
    s.enter("R", "5.26 Ω")
    for lv, u, w, i in ROWS:
        s.enter(f"u_ss@{lv:g}", u)
        s.enter(f"omega_ss@{lv:g}", w)
        s.enter(f"i_ss@{lv:g}", i)
    s.enter("prep8.T", "a/b")
    s.enter("prep8.K", "b/c")
    s.enter("prep10.gain", "2pi/720")
    s.enter("summary.1", "b")
    s.enter("summary.5", "b, c")
    s.enter("summary.unclear", "why the 20-tap filter lags")
    s.enter("own.T", "0.09 s")
    s.enter("prep3.notes", "y' = 0 gives y = K c")
    record_square_wave(s, seed=21)
    return s


class _Refs(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.attrs: list[tuple[str, str | None]] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        self.attrs += attrs


def test_report_files_hold_the_sessions_values(tmp_path):
    s = _session(tmp_path)
    written = write_report(s)
    s.close()
    md = written.markdown.read_text(encoding="utf-8")
    html = written.html.read_text(encoding="utf-8")
    assert written.markdown == s.folder / "report.md" and written.html == s.folder / "report.html"
    assert written.runs == (s.folder / "runs" / "steps-1.csv",) and written.runs[0].exists()
    k_v = sorted(
        [
            (2.05 - 5.26 * 0.0298) / 3.82,
            (3.05 - 5.26 * 0.0335) / 5.81,
            (4.05 - 5.26 * 0.0372) / 7.78,
        ]
    )[1]
    assert "5.26\u00a0Ω" in unescape(html)  # a number and its unit never part at a line end
    for doc in (md, unescape(html).replace("\u00a0", " ")):
        for text in (
            "Ada Lovelace",
            "2026-11-22",
            "5.26 Ω",
            "29.8 mA",
            "33.5 mA",
            "37.2 mA",
            "2.05 V",
            "3.82 rad/s",
            format_number((2.05 - 5.26 * 0.0298) / 3.82),
            f"{format_number(k_v)} V s/rad (median of the rows",
            f"{format_number(0.65 * k_v)} N m/A",
            "a/b",
            "b/c",
            "upside down",
            "a system",
            "the input amplitude; the static gain",
            "why the 20-tap filter lags",
            "y' = 0 gives y = K c",
            "steps-1",
            "runs/steps-1.csv",
            "the program's value (least squares)",
            "90 ms",
            "omega at u_A = 5 V",
            "Why dry friction, over the whole run: ",
            "is the first-order model the check fitted to this run itself and ran on",
            # why the check's T is not Task 12's, saying whose that T is (walk of 11-27:
            # "Tasks 11-12 give T = 0.04284 s" where the group's Tasks 11-12 gave 57 ms)
            "The program's least-squares reading of the run used in Tasks 11-12 (not the "
            "group's own values) gives T = ",
            # the model the check simulated, named with its numbers (read as the group's)
            "the first-order model the check fitted to this run (T = ",
            "the two T differ by",
        ):
            assert text in doc, text
        assert "Tasks 11-12 give" not in doc
    ident = s.results().identification
    assert format_value(ident.step.K, "rad/s/V") in md and format_constant(
        ident.step.T, "s"
    ) in unescape(html).replace("\u00a0", " ")
    # identify's findings land in the warnings, in words (not by their code, T_short)
    assert "is shorter than 3 sample periods" in md and "T_short" not in md


def test_html_is_self_contained(tmp_path):
    s = _session(tmp_path)
    html = write_report(s).html.read_text(encoding="utf-8")
    s.close()
    low = html.lower()
    for needle in (
        "http://",
        "https://",
        "src=",
        "href=",
        "url(",
        "@import",
        "<script",
        "<link",
        "<img",
        "<iframe",
    ):
        assert needle not in low, needle
    p = _Refs()
    p.feed(html)
    # the zoomed step; the model check's whole run and its close-up; the recorded run
    assert p.tags.count("figure") == 4
    # panels: 1 + (2 + 1) + (3 + 1) + (2 + 1): each figure is one <svg> holding its panels
    assert p.tags.count("svg") == 11
    # omega samples; measured and 2 models, 2 residuals; the same in the close-up and 2 angle
    # errors; omega x2 and u x2 of the run
    assert p.tags.count("polyline") == 1 + 5 + 7 + 4
    assert "style" in p.tags and "table" in p.tags


def test_markdown_figures_are_svg_files_beside_it(tmp_path):
    """report.md was 190 KB of base64: its figures are now files beside it, linked by a
    relative name, and the Markdown is text a person reads (the HTML stays whole)."""
    s = _session(tmp_path)
    written = write_report(s)
    md = written.markdown.read_text(encoding="utf-8")
    s.close()
    assert "base64" not in md and len(md.encode("utf-8")) < 20_000
    targets = re.findall(r"!\[[^\]]*\]\(([^)]*)\)", md)
    assert targets == [f"report-figure-{k}.svg" for k in range(1, 5)]  # one per figure
    assert written.figures == tuple(s.folder / t for t in targets)
    for target in targets:
        doc = (s.folder / target).read_text(encoding="utf-8")
        assert doc.startswith("<svg") and doc.endswith("</svg>")
    html = written.html.read_text(encoding="utf-8")
    assert "report-figure-" not in html and html.count("<svg") == 11
    # a later report with fewer figures leaves none of the earlier ones lying beside it
    (s.folder / "report-figure-9.svg").write_text("<svg/>", encoding="utf-8")
    with Session.open(s.folder, readonly=True) as again:
        write_report(again)
    assert not (s.folder / "report-figure-9.svg").exists()
    assert (s.folder / "report-figure-4.svg").exists()


def test_markdown_figures_inline_without_a_prefix(tmp_path):
    s = _session(tmp_path)
    md = markdown.render(content.build(s))
    s.close()
    targets = re.findall(r"!\[[^\]]*\]\(([^)]*)\)", md)
    assert len(targets) == 4
    for target in targets:
        assert target.startswith("data:image/svg+xml;base64,")
        doc = base64.b64decode(target.split(",", 1)[1]).decode("utf-8")
        assert doc.startswith("<svg") and doc.endswith("</svg>")


def test_cli_report_into_a_folder_it_cannot_write_says_so_in_one_line(tmp_path, capsys):
    s = _session(tmp_path)
    s.close()
    (s.folder / "report-figure-1.svg").mkdir()  # in the way of the first figure
    assert main(["report", str(s.folder)]) == 2
    err = capsys.readouterr().err
    assert "cannot write the report" in err and err.count("\n") == 1
    assert not (s.folder / "report.md").exists()


def test_report_does_not_touch_the_session(tmp_path):
    s = _session(tmp_path)
    s.close()
    before = (s.folder / "session.json").read_bytes()
    assert main(["report", s.id, "--sessions", str(tmp_path)]) == 0
    assert (s.folder / "session.json").read_bytes() == before
    assert (s.folder / "report.md").exists() and (s.folder / "report.html").exists()


def test_empty_session_reports_what_is_missing(tmp_path):
    with Session.create(tmp_path, ["A"], date="2026-11-22") as s:
        md = write_report(s).markdown.read_text(encoding="utf-8")
    assert "No step result yet" in md and "R is not entered yet" in md and "No run recorded." in md


def test_cli_report(tmp_path, capsys):
    s = _session(tmp_path)
    s.close()
    assert main(["report", str(s.folder)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out == [
        str(s.folder / "report.md"),
        str(s.folder / "report.html"),
        str(s.folder / "runs" / "steps-1.csv"),
    ]
    assert main(["report", "no-such-session", "--sessions", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "no session found" in err and err.count("\n") == 1


def test_refused_entries_are_listed(tmp_path):
    with Session.create(tmp_path, ["A"]) as s:
        s.enter("i_ss@2.5", "4.7 V")
        md = write_report(s).markdown.read_text(encoding="utf-8")
    assert "refused entry Task 5, i_ss at 2.5 V: '4.7 V'" in md


def test_svg_ticks_and_thinning():
    assert svg.nice_ticks(0.0, 10.0, 5) == [0.0, 2.0, 4.0, 6.0, 8.0, 10.0]
    assert svg.nice_ticks(-0.3, 0.3, 3) == [-0.2, 0.0, 0.2]
    rng = np.random.default_rng(2)
    x = np.arange(10000.0)
    y = rng.standard_normal(10000)
    y[5000] = 50.0
    tx, ty = svg.thin(x, y, 600)
    assert tx.size <= 600 and 50.0 in ty and tx[0] == 0 and tx[-1] == 9999


def test_intervals_say_which_side_the_log_does_not_bound():
    assert format_interval(0.04, 0.05, "s") == "0.04000 – 0.05000 s"
    assert format_interval(0.11, math.inf, "V") == "0.1100 V or more: no upper bound from this log"
    assert format_interval(-math.inf, 3.0, "s") == "up to 3.000 s: no lower bound from this log"
    assert format_interval(-math.inf, math.inf, "s") == "not bounded by this log"


def test_the_report_compares_the_groups_way_and_says_what_was_revealed(tmp_path):
    """J from the group's own T, the least-squares J beside it with why, and a reveal."""
    from minseg_tui.model.motor import inertia_from_time_constant

    s = _session(tmp_path)
    ident = s.results().identification
    assert ident is not None and ident.step is not None
    T_own = 0.0568
    s.enter("own.T", "56.8 ms")
    J_own = inertia_from_time_constant(T_own, ident.R, ident.f, ident.k_v, ident.k_a)
    s.enter("own.J", f"{J_own * 1.003:.5g}")
    views.note_drawn(s, views.results(s.snapshot(), "task13"))  # the group sees its J compared
    assert s.reveal("task15") == ["own.omega_5"]
    md = write_report(s).markdown.read_text(encoding="utf-8")
    s.close()
    (row,) = [line for line in md.splitlines() if line.startswith("| J (Task 13)")]
    assert "from the group's T = 56.8" in row and "+0.3 %" in row and "+0 %" not in row
    assert format_number(ident.step.J) in row and "after the group answered" in row
    (row5,) = [line for line in md.splitlines() if line.startswith("| omega at u_A = 5 V")]
    assert "revealed before answering" in row5
    assert "J grows in proportion to T" in md


def test_the_reports_table_keeps_a_readings_trailing_zero(tmp_path):
    """Walk 13 D6: u_ss typed '4,0' was "4 V" in the report's table, so an instructor could
    not see the group read 4.0 to 0.1 V. The table gives each reading with the digits it
    was typed with ('47,0 mA' "47.0 mA", '0.0470 A' "47.0 mA", R '5,30' "5.30 Ω");
    the computed k_v and f keep their own four digits."""
    s = Session.create(tmp_path, ["Ada Lovelace", "Bo Ek"], date="2026-11-22", clock=Clock())
    s.enter("R", "5,30")
    for lv, u, w, i in (
        (2.5, "2,05", "3.80", "0.0300 A"),
        (3.5, "3.05", "5.81", "33.5"),
        (4.5, "4,0", "7.78", "47,0 mA"),
    ):
        s.enter(f"u_ss@{lv:g}", u)
        s.enter(f"omega_ss@{lv:g}", w)
        s.enter(f"i_ss@{lv:g}", i)
    md = write_report(s).markdown.read_text(encoding="utf-8")
    row = s.table()[2]
    s.close()
    lines = {line.split("|")[1].strip(): line for line in md.splitlines() if line.startswith("| ")}
    cells = [c.strip() for c in lines["4.5 V"].split("|")[1:-1]]
    assert cells[1] == "4.0 V" and cells[2] == "7.78 rad/s" and cells[4] == "47.0 mA", cells
    assert cells[5] == format_value(row.k_v, "V s/rad"), cells
    cells = [c.strip() for c in lines["2.5 V"].split("|")[1:-1]]
    assert cells[1:3] == ["2.05 V", "3.80 rad/s"] and cells[4] == "30.0 mA", cells
    assert "R = 5.30 Ω (Task 2)." in md.replace("\u00a0", " ")
