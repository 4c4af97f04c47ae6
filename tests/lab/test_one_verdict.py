"""One verdict per session file (issue 18, item 8): whatever a file holds, the listing, opening
it and report's read-only look agree on whether it is sound, and none of them, nor what the
TUI and report then compute from it, raises anything but a one-line error.

Seeded mutations of a sound file: one field (anywhere in it) set to one of a set of values
of every JSON type and of hostile sizes, or removed."""

from __future__ import annotations

import json
import random

import pytest

from minseg_tui.errors import MinsegError
from minseg_tui.lab.content.steps import FIELDS, STEPS
from minseg_tui.lab.saving.store import list_sessions
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.views import session as views
from minseg_tui.report.content import build
from tests.lab.test_damaged import _good_session

TRIALS = 120

VALUES = [
    None, True, 0, -1, 1.5, -1e308, 10**30, 2**53 + 1, 10**400, 1e-320, "", "x", "task99",
    "../x", "runs/x.csv", [], [1], [1, 2], [-1], [40], ["a"], {}, {"a": 1}, [[1, 2]],
    ["a", "b", "c"],
]  # fmt: skip


def _sound(root):
    """The damaged-session tests' good session, with a choice, a note and a refusal more."""
    folder = _good_session(root)
    with Session.open(folder) as s:
        s.enter("R", "5.2 kg")
        s.enter("summary.1", "b")
        s.enter("prep1.notes", "wheel [b]")
    return folder


def _places(node, where=()):
    if where:
        yield where
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _places(v, (*where, k))
    elif isinstance(node, list):
        for k, v in enumerate(node):
            yield from _places(v, (*where, k))


def _use(s: Session) -> None:
    """What the TUI computes from an open session."""
    s.results()
    s.table()
    s.warnings()
    s.comparisons()
    s.model_check()
    views.table(s)
    views.runs(s)
    views.check(s)
    views.results(s, "task11")
    for key in FIELDS:
        views.entry(s, key)
        views.typed(s, key)
    for st in STEPS:
        views.comparisons(s, st.id)
        s.step_status(st.id)


@pytest.mark.parametrize("seed", [1, 2])
def test_the_listing_opening_and_report_agree(tmp_path, seed):
    folder = _sound(tmp_path / "sessions")
    path = folder / "session.json"
    sound = json.loads(path.read_text(encoding="utf-8"))
    places = list(_places(sound))
    rng = random.Random(seed)
    verdicts = set()
    for _ in range(TRIALS):
        data = json.loads(json.dumps(sound))
        where, value = rng.choice(places), rng.choice(VALUES)
        node = data
        for part in where[:-1]:
            node = node[part]
        if isinstance(node, dict) and rng.random() < 0.1:
            del node[where[-1]]
        else:
            node[where[-1]] = value
        path.write_text(json.dumps(data), encoding="utf-8")
        case = f"{where} = {value!r:.40}"

        (info,) = list_sessions(folder.parent)
        try:
            with Session.open(folder) as s:
                _use(s)
            opened = True
        except MinsegError as exc:
            assert "\n" not in str(exc), case
            opened = False
        try:  # report's look: what is sound, or nothing at all (not a session file)
            with Session.open(folder, readonly=True) as ro:
                _use(ro)
                build(ro)
                looked_sound = ro.damaged is None
        except MinsegError as exc:
            assert "\n" not in str(exc), case
            looked_sound = False
        assert (info.damaged is None) == opened == looked_sound, case
        verdicts.add(opened)
    assert verdicts == {True, False}  # both kinds were met
