"""Walk 16's D7 (issue 20): at 80x24 notices were drawn over the step's title, "Task 4:
u_ss and omega_▌ set a voltage first (F3)", "Task 11: the static gai▌ runs ...". s37-fix
kept them off a question; a notice never hides the step's title either: on top of the
screen they start under it (the heading's title while the step is scrolled down)."""

from __future__ import annotations

from tests.ui.helpers import burst, goto, lab_screen, settle, start, start_with_a_run


def _title(screen):
    pane = screen.pane
    heading = screen.query_one(".heading")
    return heading.title if heading.display else pane.query_one(".title")


def _over_title(screen) -> list:
    title = _title(screen).region
    assert title, "the step's title is on screen"
    return [t.region for t in screen.query("Toast") if t.region.overlaps(title)]


async def test_a_refusal_on_task_4_leaves_the_title_seen(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        screen = lab_screen(app)
        await burst(pilot, "f4")  # at 0 V: "set a voltage first (F3)"
        await settle(pilot, lambda: bool(screen.query("Toast")))
        await settle(pilot)
        assert screen.has_class("-notices-top")  # the entry is in the lower half
        assert not _over_title(screen), (_title(screen).region, _over_title(screen))


async def test_the_run_choice_on_task_11_leaves_the_title_seen(quiet):
    app = quiet()
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start_with_a_run(pilot, "task11")
        screen = lab_screen(app)
        screen.use_run(None)  # Ctrl+P "Use run ...": "runs / Tasks 11-15 ... use run steps-1"
        await settle(pilot, lambda: bool(screen.query("Toast")))
        await settle(pilot)
        assert not _over_title(screen), (_title(screen).region, _over_title(screen))
