"""Issue 20, what walk 15 and stop 36 left (items 1 and 5 of /work/coord/B37-fix.md): a
session opened read-only from the class view, at 80x24 with Pilot on real session folders.

Item 1: Task 4's readout still offered "f3 Set V · f4 Capture", which refuse there; so did
the footer (F3, F4, F5, F6, F8), Task 10's line ("F5: 4 steps …"), the summary's ("F8 (or
Ctrl+P → Export report) writes report.md …"), the model check's box to load a log, the
palette (export, save elsewhere, correct the names, load a log, use a run), and each empty
entry's hint ("in rad/s, e.g. 4.6"), where nothing can be typed. None is offered now on any
step (an empty entry says "not entered"); the keys pressed still say why they refuse.

Item 5: the footer never showed "esc Class view": the entries' own Escape (not shown) was
the first binding of the key from the focus up, which is the one a footer shows, though
the screen's runs first. It shows on every step now, the palette's key whole beside it."""

from __future__ import annotations

from pathlib import Path

from minseg_tui.lab.content.keys import PALETTE, USE_RUN
from minseg_tui.lab.content.steps import STEPS
from minseg_tui.ui.panels.report import ReportPanel
from minseg_tui.ui.screens.lab import LabScreen, StepCommands, StepPane
from minseg_tui.ui.widgets.fields import NOT_ENTERED, FieldRow
from minseg_tui.ui.widgets.footer import KeyFooter, KeyLabel
from minseg_tui.ui.widgets.prose import Prose
from tests.classview.build import group
from tests.ui.conftest import quiet_app
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import burst, class_view, goto, heard_notifications, settle, shown

REFUSED_LABELS = {"Set V", "Capture", "Run", "Run 5 ms", "Export"}
"""The footer labels of the keys a read-only session refuses (F3, F4, F5, F6, F8)."""

REFUSED_WORDS = ("f3 Set V", "f4 Capture", "F5:", "F6:", "F8 (")
"""How a step's own lines offered those keys."""


def _files(root: Path) -> dict[str, bytes]:
    return {str(p): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def _step_text(app) -> str:
    """Every line of the step on screen, scrolled into view or not: its prose (the readout,
    a panel's hints) and its panels' own text (the summary's), as drawn."""
    pane = app.screen.query_one(StepPane)
    texts = [p.text for p in pane.query(Prose)]
    texts += [str(w.render()) for w in pane.query(ReportPanel)]
    return "\n".join(texts)


def _footer(app) -> list[str]:
    """The footer's keys shown whole on the screen now: 'esc Class view'."""
    footer = app.screen.query_one(KeyFooter)
    return [
        f"{k.key_display} {k.description}"
        for k in footer.query_children(KeyLabel)
        if k.display and k.region.right <= app.size.width
    ]


async def _open_read_only(pilot) -> None:
    app = pilot.app
    await class_view(pilot)
    await burst(pilot, "enter")
    await settle(pilot, lambda: isinstance(app.screen, LabScreen) and shown(app))
    with app.session as s:
        assert s.readonly


async def test_no_step_of_a_read_only_session_offers_what_it_refuses(tmp_path):
    """Item 1 and item 5: on every step of a session opened from the class view, no key it
    refuses is in the footer or in the step's own lines, the palette offers nothing that
    changes the session, and "esc Class view" is in the footer, whole."""
    root = tmp_path / "sessions"
    group(root, ["Lea P", "Tom R"], seed=1)
    before = _files(root)
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await _open_read_only(pilot)
        lab = app.screen
        assert isinstance(lab, LabScreen)
        for st in STEPS:
            await goto(pilot, st.id)
            footer = _footer(app)
            assert "esc Class view" in footer, (st.id, footer)
            assert footer[-1] == "^p palette", (st.id, footer)
            assert not {f.split(" ", 1)[1] for f in footer} & REFUSED_LABELS, (st.id, footer)
            text = _step_text(app)
            offered = [w for w in REFUSED_WORDS if w in text]
            assert not offered, (st.id, offered, text)
            assert not lab.query("#import-path"), st.id  # no box to load a log into it
            for row in lab.query(FieldRow):  # an empty box asks for nothing there
                if not row.field.options and not row.input.value:
                    assert row.input.placeholder in (NOT_ENTERED, ""), (st.id, row.field.key)
                    hint = row.query_one(".field-hint", Prose)
                    assert hint.text == NOT_ENTERED, (st.id, row.field.key, hint.text)
            titles = {c.title for c in app.get_system_commands(lab)}
            for action in (
                "set_voltage",
                "capture",
                "run_square_wave",
                "run_fast",
                "export",
                "save_elsewhere",
                "correct_names",
                "import_log",
            ):
                assert PALETTE[action] not in titles, (st.id, action)
            provider = StepCommands(lab)
            assert not [t for t, _, _ in provider.entries() if t.startswith(USE_RUN)]
    assert _files(root) == before


async def test_the_keys_not_offered_in_a_read_only_session_still_say_why(tmp_path):
    """The keys left out of a read-only session's footer still answer when pressed: F3, F4,
    F5, F6 and F8 say it is read-only (not "… is not part of this step"), and nothing is
    driven, recorded or written."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, at="task12")
    before = _files(root)
    app = quiet_app(root, QuietDevice(seed=2))
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await _open_read_only(pilot)
        for step_id, key, words in (
            ("task4", "f3", "not driven"),
            ("task4", "f4", "not captured"),
            ("task10", "f5", "nothing can be recorded"),
            ("task10", "f6", "nothing can be recorded"),
            ("summary", "f8", "no report is written"),
        ):
            await goto(pilot, step_id)
            del said[:]
            await burst(pilot, key)
            await settle(pilot, lambda w=words: any(w in m for m in said))
            told = next(m for m in said if words in m)
            assert "read-only" in told and "to look" in told, (key, told)
            assert not any("not part of this step" in m for m in said), (key, said)
        assert app.requested is None and app.motor == "off" and app.recording is None
    assert _files(root) == before


async def test_a_session_of_the_groups_own_still_offers_them(tmp_path):
    """The same steps in a group's own session (from the start screen) keep their keys and
    lines, and no "esc Class view" where there is no class view to go back to."""
    root = tmp_path / "sessions"
    group(root, ["Ada", "Bo"], seed=1, at="task4")
    app = quiet_app(root)
    async with app.run_test(size=(80, 24)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#sessions")))
        app.screen.query_one("#sessions").focus()
        await burst(pilot, "enter")
        await settle(pilot, lambda: shown(app, "task4"))
        with app.session as s:
            assert not s.readonly
        footer = _footer(app)
        assert {"f3 Set V", "f4 Capture", "f8 Export"} <= set(footer), footer
        assert "esc Class view" not in footer
        assert "f3 Set V · f2 STOP · f4 Capture" in _step_text(app)
        await goto(pilot, "task10", focus=None)
        assert "F5: 4 steps" in _step_text(app)
        assert {"f5 Run", "f6 Run 5 ms"} <= set(_footer(app))
        await goto(pilot, "summary")
        assert "F8 (" in _step_text(app)
        await goto(pilot, "model_check", focus=None)
        assert app.screen.query("#import-path")
