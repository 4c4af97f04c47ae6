"""Walk 9's findings fixed by s30-lab20, each on the screen at 80x24 (Pilot, a real session
folder with the seeded step run)."""

from __future__ import annotations

from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    answer_T_on_a_run,
    box_text,
    goto,
    heard_notifications,
    nav_mark,
    record_a_square_wave,
    settle,
    start_with_a_run,
    type_in,
)


async def test_a_model_that_cannot_be_read_as_an_equation_is_refused_not_graded(quiet):
    """Walk 9, D7: 'T=34ms K=1.93' on Task 14 (two '=', no equation) was stored, and the
    step marked ✗ wrong: the report and the class view graded a group whose T and K may be
    right as wrong. It is now refused, as any entry that cannot be read: '?' in the list,
    the text kept to mend, nothing stored. A read equation that is no first-order model
    ('w = 1,9 u', no omega' term) stays an answer, and a wrong one."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task14")
        row = await type_in(pilot, "own.model", "T=34ms K=1.93")
        await settle(pilot)
        said = " ".join(row.message.split())
        assert "one equation with one '=' is needed" in said, said
        assert nav_mark(app, "task14") == "?"
        assert box_text(app, "own.model") == "T=34ms K=1.93"
        with app.session as s:
            e = s.entry("own.model")
            assert e is None or not e.ok
            assert "own.model" not in s.answered()
        row = await type_in(pilot, "own.model", "w = 1,9 u")
        await settle(pilot)
        assert nav_mark(app, "task14") == "✗"
        with app.session as s:
            assert "own.model" in s.answered()


async def test_a_new_run_that_takes_over_tasks_11_to_15_says_so(quiet):
    """Walk 9, D10: T answered right on the run in use, then F5 on Task 10: once the new run
    was kept it was the run in use, and Task 12 turned ✗ with no word of why. The end of the
    run now says that Tasks 11-15 use the new run, which answers it judges now, and how to
    go back; a new run that does not take over (the group's choice stays) says nothing."""
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        first = await answer_T_on_a_run(pilot)
        said = heard_notifications(app)
        await goto(pilot, "task10")
        now = await record_a_square_wave(pilot, dev)
        assert now != first
        (changed,) = [n for n in said if n.startswith("Tasks 11-15 now use")]
        assert changed == (
            f"Tasks 11-15 now use run {now}, not {first}: your answers (T (Task 12)) are "
            f"judged against {now} now; Ctrl+P 'Use run {first}' goes back to the run in "
            "use when you gave them"
        )
        app.screen.use_run(first)  # the group's choice: a new run does not take over
        said.clear()
        await record_a_square_wave(pilot, dev)
        assert not [n for n in said if n.startswith("Tasks 11-15 now use")]
