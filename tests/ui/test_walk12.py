"""Walk 12's defects (issue 20), each as the walk met it, at 80x24 with Pilot on a real
session folder (/work/coord/WALK12.md)."""

from __future__ import annotations

import pytest

from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.keys import help_lines
from minseg_tui.ui.screens.boardcheck import BoardCheckScreen
from minseg_tui.ui.screens.help import HelpScreen
from minseg_tui.ui.screens.lab import STEP_IDS, LabScreen
from minseg_tui.ui.widgets.footer import KeyFooter, KeyLabel
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import box_text, burst, goto, lab_screen, settle, start, stored_text


async def _task5_at_3_5_v_on_the_4_5_v_row(pilot) -> None:
    """Task 5 with the motor at 3.5 V and i_ss at 4.5 V = '37,1' stored, the keys on that
    row."""
    await start(pilot)
    await goto(pilot, "task5")
    await burst(pilot, "f3", "f3")  # 2.5 V, 3.5 V: the keys on the 3.5 V row
    await burst(pilot, "tab", *"37,1", "enter")
    assert pilot.app.requested == 3.5
    assert stored_text(pilot.app, "i_ss@4.5") == "37,1"


@pytest.mark.parametrize(
    "before", ["end", "escape", "ctrl+z"], ids=["after-end", "after-esc", "after-ctrl-z"]
)
async def test_f3_onto_the_row_with_the_keys_makes_it_ready_for_the_new_reading(quiet, before):
    """D1: on Task 5, the keys on the 4.5 V row ('37,1' stored, the cursor at its end after
    End, Esc, ...), the motor at 3.5 V; 'F3 37 Enter' in one burst stored '37,137' (read as
    37.14 mA, no warning): F3 made the other rows ready for their reading (their text
    selected), but left this one as it stood, and the reading was appended. Now F3 selects
    the text of the row of its voltage that has the keys too: the reading replaces it."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _task5_at_3_5_v_on_the_4_5_v_row(pilot)
        await burst(pilot, before)
        await burst(pilot, "f3", *"37", "enter")
        assert app.requested == 4.5
        assert stored_text(app, "i_ss@4.5") == "37"


async def test_f3_onto_a_refused_text_replaces_it_with_the_new_reading(quiet):
    """D1, walk 11's D2: the 4.5 V row held a refused text; 'F3 0.0372 Enter' kept the
    refused text and lost the reading ('0.03710.0372' refused with it)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _task5_at_3_5_v_on_the_4_5_v_row(pilot)
        await burst(pilot, "ctrl+u", *"37 x", "enter")  # refused: 'x' is not a unit
        assert box_text(app, "i_ss@4.5") == "37 x"
        await burst(pilot, "f3", *"37.2", "enter")
        assert stored_text(app, "i_ss@4.5") == "37.2"


async def test_a_reading_typed_in_its_row_before_f3_is_stored_and_the_next_replaces_it(quiet):
    """The other side of D1: a reading typed (not entered) in the row of F3's voltage is
    stored by F3, as leaving an entry stores it; the keys after F3 are the reading at the new
    voltage and replace it, the row being made ready as F3 makes the other rows (Ctrl+Z
    brings the stored one back)."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await _task5_at_3_5_v_on_the_4_5_v_row(pilot)
        await burst(pilot, "ctrl+u", *"36")
        await burst(pilot, "f3")
        assert stored_text(app, "i_ss@4.5") == "36"
        await burst(pilot, *"37.2", "enter")
        assert stored_text(app, "i_ss@4.5") == "37.2"
        await burst(pilot, "ctrl+z")
        assert box_text(app, "i_ss@4.5") == "36"


def _footer_keys(app) -> list[str]:
    """The keys the lab screen's footer shows ('f7', ...), in order."""
    footer = lab_screen(app).query_one(KeyFooter)
    return [k.key_display for k in footer.query(KeyLabel) if k.display]


async def test_the_footer_follows_the_steps_after_a_change_as_a_dialog_comes_or_goes(quiet):
    """D2: after the board check's result (F10) and the palette over it, the footer kept
    'f10 Board check' on Tasks 2-10 (no F3, F4, F7, F5/F6) until the program was started
    again; in another session it kept 'f3 Set V' on Tasks 4, 6-9 and Preparation 14. The
    lab screen's keys changed as a dialog came or went (the lab's signal handled while the
    dialog was the app's screen): the footer's rebuild, asked for after the next refresh,
    went to the dialog's screen, where it was lost with the dialog (the footer then waited
    for it for ever) or ran in the dialog's place (ReactiveError: the app stopped). The
    footer now rebuilds itself, and again when its screen is the app's screen again."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task1")
        await settle(pilot, lambda: "f10" in _footer_keys(app))
        lab = lab_screen(app)
        footer = lab.query_one(KeyFooter)
        app.push_screen(BoardCheckScreen(True, "The wheel turns and the count follows."))
        await settle(pilot, lambda: isinstance(app.screen, BoardCheckScreen))
        footer.bindings_changed(lab)  # the lab's keys changed while the dialog is on top
        await burst(pilot, "escape")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
        assert "f10" in _footer_keys(app)
        await goto(pilot, "table")
        await settle(pilot, lambda: "f7" in _footer_keys(app))
        assert "f10" not in _footer_keys(app)
        await goto(pilot, "task10")
        await settle(pilot, lambda: {"f5", "f6"} <= set(_footer_keys(app)))


def _writing_app(root):
    """The app on the device double, with a report writer that writes a real file."""

    def writer(session):
        path = session.folder / "report.md"
        path.write_text("# report\n")
        return [path]

    cfg = UiConfig(device="auto", sessions=root, today=DATE, animations=False, refresh=0)
    return LabApp(cfg, lambda spec: QuietDevice(seed=1), writer)


async def test_f8_keeps_the_focused_question_in_view(tmp_path):
    """D4: on Summary, Tab Tab Tab (Q4 'The static gain K describes', its answers on
    screen), F8: the report was written and the step scrolled back up to Q2 and Q3, Q4's
    label on the last line and its answers off screen."""
    app = _writing_app(tmp_path / "sessions")
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "summary")
        await burst(pilot, "tab", "tab", "tab")
        row = lab_screen(app).pane.current
        assert row is not None and row.field.key == "summary.4"
        answers = row.answers
        assert answers is not None and app.screen.can_view_entire(answers)
        await burst(pilot, "f8")
        await settle(pilot, lambda: app.exported)
        await settle(pilot)
        assert lab_screen(app).pane.current is row
        assert app.screen.can_view_entire(answers)


async def test_f1_names_the_tasks_where_f3_and_f4_act(quiet):
    """D6: F1 said 'F4 Capture: omega_ss over the settled window (Task 4/5)'; on Task 5, F4
    says 'capturing omega_ss is not part of this step'. And F3 ('(Task 4/5)') sets the
    voltage on Task 3 too."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        where: dict[str, list[str]] = {"set_voltage": [], "capture": []}
        for step_id in STEP_IDS:
            await goto(pilot, step_id, focus=None)
            for action, steps in where.items():
                if lab_screen(app).offers(action):
                    steps.append(step_id)
    assert where == {"set_voltage": ["task3", "task4", "task5"], "capture": ["task4"]}
    helps = dict(help_lines())
    assert helps["F3"].endswith("(Tasks 3-5)")
    assert helps["F4"].endswith("(Task 4)")


@pytest.mark.parametrize("dialog", ["board-check", "help"])
async def test_ctrl_p_over_a_result_goes_to_a_step(quiet, dialog):
    """D3: on Task 1, F10, then 'Ctrl+P task 2' over the board check's result: "No matches
    found" (the steps are the lab screen's commands, and the palette was the dialog's), and
    the 'Enter 5,3 ohm Enter' typed after it went into the palette's search. Ctrl+P over a
    result the group reads (the board check's, F1's list) closes it first, as Escape does:
    the palette is the lab's, and the keys after its Enter land in the step."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task1")
        if dialog == "help":
            app.push_screen(HelpScreen(help_lines()))
        else:
            app.push_screen(BoardCheckScreen(True, "The wheel turns and the count follows."))
        await settle(pilot, lambda: not isinstance(app.screen, LabScreen))
        await burst(pilot, "ctrl+p", *"task 2", "enter", *"5.3", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
        with app.session as s:
            assert s.current_step == "task2"
        assert stored_text(app, "R") == "5.3"
