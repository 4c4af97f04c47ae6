"""Walk 9's findings fixed by s30-lab20, each on the screen at 80x24 (Pilot, a real session
folder with the seeded step run)."""

from __future__ import annotations

from tests.ui.helpers import box_text, nav_mark, settle, start_with_a_run, type_in


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
