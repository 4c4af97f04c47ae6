"""The report names the run each of the group's answers of Tasks 11-15 was judged against,
and says when an answer is judged again: given while one run was in use, judged against
another since (issue 20's leftovers, walk 9's D10: a new run took over Tasks 11-15 after T
was answered, and the report graded T against it without a word). A real session folder,
the seeded plant's runs, the Markdown report as written."""

from __future__ import annotations

import json
from pathlib import Path

from minseg_tui.lab.state.session import Session
from tests.report.test_own_first import _report, _row, _section, _tables
from tests.report.test_report import _session
from tests.seeded import record_square_wave

_STEP = "Step response and model (Tasks 10-15)"
_DIFF = "difference"


def _step_rows(s: Session) -> list[list[str]]:
    (table,) = [t for t in _tables(_section(_report(s), _STEP)) if t[0][0] == "quantity"]
    return table


def test_each_answer_names_the_run_it_was_judged_against(tmp_path: Path) -> None:
    """T given on the first run, a second complete run recorded after (it takes over Tasks
    11-15), K given on the second: T's row says it is judged again against the second run,
    given while the first was in use; K's row names the second run alone; a value not
    answered names none."""
    s = _session(tmp_path)  # own.T = 0.09 s, given before any run: not known on which
    first = s.response_run()
    assert first is not None
    s.enter("own.T", "60 ms")  # given on the first run
    second = record_square_wave(s, seed=22)
    assert second is not None and s.response_run() == second
    s.enter("own.K", "2.2")
    table = _step_rows(s)
    T, K = _row(table, "T (Task 12)"), _row(table, "K (Task 11)")
    J = _row(table, "J (Task 13)")
    assert T[_DIFF].endswith(
        f"; judged again, against run {second.name}: the group gave it while run "
        f"{first.name} was in use"
    ), T[_DIFF]
    assert K[_DIFF].endswith(f"; judged against run {second.name}"), K[_DIFF]
    assert "judged against run" not in J[_DIFF] and "judged again," not in J[_DIFF]
    # the group goes back to the run T was given on: judged there, not again
    s.select_run(first.name)
    T = _row(_step_rows(s), "T (Task 12)")
    assert T[_DIFF].endswith(f"; judged against run {first.name}"), T[_DIFF]
    s.close()


def test_the_run_an_answer_was_given_on_is_kept_in_the_session_file(tmp_path: Path) -> None:
    """Closed and opened again, the session still knows on which run each answer was given;
    a refused text over the answer does not change it, an answer given before any run has
    none, and a session file without it (an older program's) opens with none."""
    s = _session(tmp_path)
    folder = s.folder
    first = s.response_run()
    assert first is not None and s.entry("own.T").run == ""  # type: ignore[union-attr]
    s.enter("own.T", "60 ms")
    record_square_wave(s, seed=22)
    s.enter("own.T", "sixty")  # refused: the answer in effect stands, with its run
    s.close()
    with Session.open(folder) as again:
        e = again.entry("own.T")
        assert e is not None and e.text == "60 ms" and e.run == first.name
    data = json.loads((folder / "session.json").read_text(encoding="utf-8"))
    assert data["entries"]["own.T"]["run"] == first.name
    del data["entries"]["own.T"]["run"]
    (folder / "session.json").write_text(json.dumps(data), encoding="utf-8")
    with Session.open(folder) as old:
        e = old.entry("own.T")
        assert e is not None and e.run == ""
        T = _row(_step_rows(old), "T (Task 12)")
        assert "judged again," not in T[_DIFF]
        assert T[_DIFF].endswith(f"; judged against run {old.response_run().name}")  # type: ignore[union-attr]
