"""Issue 20, what walk 15 and stop 36 left (item 2 of /work/coord/B37-fix.md): walk 15's D2
fix asks again when the run ends while Ctrl+Q's question is up ("The run ended while this
was asked: …"), and the run's two notices (Task 10's end, Tasks 11-15's run) covered the
right half of that question for about 10 s at 80x24. A question is never covered now: the
notices wait while a question is up, and show once it is answered (those with time left)."""

from __future__ import annotations

from minseg_tui.device.link import LinkEvent
from minseg_tui.ui.screens.lab import LabScreen
from minseg_tui.ui.screens.quit import RUN_ENDED_CHOICES
from tests.ui.fakes import QuietDevice, square_wave_stream
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    quit_asked_mid_run,
    record_response_run,
    settle,
    start,
    taken,
)


def _toasts(screen) -> list:
    """The regions of the notices drawn on ``screen`` now (none while its rack is hidden)."""
    return [t.region for t in screen.query("Toast") if t.region]


async def test_the_runs_notices_do_not_cover_the_question_asked_when_it_ends(quiet):
    """D2's question at 80x24: F5 on Task 10, Ctrl+Q while it records, the run ends while the
    question is up: the question says so, and neither of the run's notices lies over it.
    Answered "Keep working", the lab screen shows the notices held meanwhile."""
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:  # a run before, T read on it: the new run takes its place
            record_response_run(s)
            s.enter("own.T", "57 ms")
        await goto(pilot, "task10")
        seq = await quit_asked_mid_run(pilot, dev)
        asking = app.screen
        dev.feed(square_wave_stream(seq + 80, (seq + 81) * 25_000, 10.0))
        dev.feed_event(LinkEvent("square_wave_done", "square wave done", 0.0))
        await taken(pilot, seq + 480)
        await settle(pilot, lambda: app.recording is None)
        assert app.screen is asking and asking.choices is RUN_ENDED_CHOICES
        held = [n.title for n in app._notices]  # the app's own list of them (ui/app.py)
        assert "Task 10" in held and "Tasks 11-15" in held, held
        question = asking.query_one("#ask").region

        covering = [t for t in _toasts(asking) if t.overlaps(question)]
        assert not covering, (question, covering)
        await pilot.press("escape")  # Keep working
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
        lab = app.screen
        # the notices held while the question was up, drawn on the lab screen (those whose
        # time is not up: on a loaded machine the Task 10 one may have gone meanwhile)
        left = [n for n in app._notices if not n.has_expired]
        await settle(pilot)
        assert len(_toasts(lab)) >= len([n for n in left if not n.has_expired])
