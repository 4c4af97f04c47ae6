"""What the last stop left of issue 20 on Tasks 11-15 and F8, at 80x24 (Pilot, real session
folder, the seeded plant's step run): F8 says what is still unanswered; each comparison
gives the group's value first, then the value had their way (named as read or computed),
then the least-squares one with why; one unit per quantity, whatever unit was typed; the
same T with the same digits wherever it is written."""

from __future__ import annotations

import re

from textual.content import Content
from textual.widgets._toast import Toast

from minseg_tui.quantities import format_constant
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import (
    TABLE,
    enter_all,
    goto,
    nav_mark,
    record_response_run,
    settle,
    start,
    start_with_a_run,
    type_in,
)


def _text(app, selector: str) -> str:
    """What the widget at ``selector`` shows, on one line (no-break spaces as spaces)."""
    return " ".join(str(app.screen.query_one(selector).render()).replace("\u00a0", " ").split())


def _lines(widget) -> list[str]:
    """What ``widget`` shows, line by line, wrapped at its width as it is drawn."""
    drawn = widget.render()
    content = drawn if isinstance(drawn, Content) else Content.from_rich_text(drawn)
    return [line.plain for line in content.wrap(widget.content_size.width)]


async def test_f8_says_what_is_still_unanswered_and_exports_all_the_same(tmp_path):
    """F8 wrote the report without a word while summary questions (and Task 13's J) were
    unanswered; only '… Summary' in the list of steps showed the gap."""
    dev = QuietDevice(seed=1)
    cfg = UiConfig(device="auto", sessions=tmp_path, today=DATE, animations=False, refresh=0)
    app = LabApp(cfg, lambda spec: dev, lambda session: write_report(session).paths)
    async with app.run_test(size=(80, 24), notifications=True) as pilot:
        await start(pilot)
        enter_all(app, TABLE)
        with app.session as s:
            record_response_run(s)
            for key, text in (("own.omega_step", "7.8"), ("own.K", "1.9"), ("own.T", "57 ms")):
                s.enter(key, text)
            for key, text in (("own.model", "0.057 omega' = -omega + 1.9 u_A"),):
                s.enter(key, text)
            s.enter("own.omega_5", "9.5")
            for n in (1, 2, 3, 6):
                s.enter(f"summary.{n}", "a")
        await goto(pilot, "summary", focus=None)
        await pilot.press("f8")
        await settle(pilot, lambda: bool(app.exported))
        await settle(pilot, lambda: len(app.screen.query(Toast)) >= 1)  # one: files, unanswered
        toasts = list(app.screen.query(Toast))
        said = [" ".join(" ".join(_lines(t)).split()) for t in toasts]
        (warning,) = [t for t, s in zip(toasts, said, strict=True) if "unanswered" in s]
        line = " ".join(" ".join(_lines(warning)).split())
        tasks = re.search(r"Task ([\d, ]+)", line)
        assert tasks is not None and "Summary Q4, 5;" in line, line
        numbers = {int(n) for n in tasks.group(1).split(",") if n.strip()}
        assert 13 in numbers and not {11, 12, 14, 15} & numbers and "Q1" not in line, line
        region = warning.region  # all of it on the 80x24 screen
        assert region.y >= 0 and region.bottom <= 24 and region.right <= 80, region
        assert any(p.endswith("report.md") for p in app.exported)
        md = next(p for p in app.exported if p.endswith("report.md"))
    text = " ".join(open(md, encoding="utf-8").read().split())
    warnings = text.split("## Warnings", 1)[1].split("## ", 1)[0]
    assert "not answered when this report was written" in warnings, warnings
    assert "question 4: The static gain K describes" in warnings, warnings
    assert "Task 13: the inertia J: the group's J" in warnings, warnings


async def test_task12_gives_yours_then_the_reading_your_way_then_least_squares(quiet):
    """Task 12's comparison began 'computed 56.14 ms (the program's reading by your
    method…)': a reading is not computed. It reads: yours, read your way, least squares
    and one sentence on why they differ."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        await type_in(pilot, "own.T", "57 ms")
        await settle(pilot)
        compare = _text(app, "#compare")
        with app.session as s:
            st = s.results().identification.step
        T_63, T = format_constant(st.T_63, "s"), format_constant(st.T, "s")
        assert "computed" not in compare, compare
        yours, way, lsq = (compare.index(x) for x in ("yours 57 ms", f"read your way {T_63}", T))
        assert yours < way < lsq, compare
        after = compare[lsq:]
        assert after.startswith(f"{T}. ") and "63 % reading" in after, compare
        await goto(pilot, "task13")
        await type_in(pilot, "own.J", "1.8e-3")
        compare = _text(app, "#compare")
        assert re.search(r"yours .* · computed your way .*least squares: .*\. The ", compare), (
            compare
        )


async def test_an_omega_typed_in_rpm_is_shown_back_in_rad_per_s(quiet):
    """'80 rpm' for omega_ss in the steps was compared as 'yours 80 rpm · computed 74.35
    rpm': one unit per quantity, rad/s, wherever it is shown; what was typed is named once,
    under the entry."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        row = await type_in(pilot, "own.omega_step", "80 rpm")
        await settle(pilot)
        echo = " ".join(row.message.replace("\u00a0", " ").split())
        assert echo.startswith("read as 8.378 rad/s (typed 80 rpm)"), echo
        assert "rpm" not in echo.replace("(typed 80 rpm)", ""), echo
        await type_in(pilot, "own.K", "2")
        compare = _text(app, "#compare")
        assert "rpm" not in compare and "yours 8.378 rad/s" in compare, compare
        assert "8.378 rad/s ÷ " in compare, compare  # K computed from it, in rad/s too


async def test_every_quantity_is_echoed_in_its_one_unit(quiet):
    """The same for every quantity: a current typed in A is read back in mA, T in s is read
    back in ms, T typed in ms as the screen writes it needs no echo; every unit the
    program shows is taken."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task5")
        row = await type_in(pilot, "i_ss@4.5", "0.0372 A")
        said = " ".join(row.message.replace("\u00a0", " ").split())
        assert said.startswith("read as 37.2 mA (typed 0.0372 A)"), said
        await goto(pilot, "task12")
        row = await type_in(pilot, "own.T", "0,057 s")
        assert " ".join(row.message.split()).startswith("read as 57 ms"), row.message
        row = await type_in(pilot, "own.T", "57 ms")
        assert not row.message.startswith("read as"), row.message
        await goto(pilot, "table")
        row = await type_in(pilot, "own.f", "1,9 mN m s/rad")
        said = " ".join(row.message.replace("\u00a0", " ").split())
        assert said.startswith("read as 1.9 mN m s/rad") and "typed" not in said, said


async def test_the_same_T_has_the_same_digits_on_task12_and_the_model_check(quiet):
    """The zoom's caption gave the 63 % crossing as '0.05599 s' beside '56.14 ms', and the
    model check's first-order model 'T = 40.5 ms' with three digits: every T four."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task12")
        await type_in(pilot, "own.T", "57 ms")
        await pilot.press("f9")
        await settle(pilot)
        caption = " ".join(
            " ".join(str(w.render()).split()) for w in app.screen.query("Prose")
        ).replace("\u00a0", " ")
        assert re.search(r"crosses it \d+\.\d\d ms after the edge", caption), caption
        assert not re.search(r"crosses it [\d.]+ s\b", caption), caption
        await goto(pilot, "model_check", focus=None)
        await settle(pilot, lambda: bool(app.screen.query("#check-story")))
        story = app.screen.query_one("#check-story").text.replace("\u00a0", " ")
        T = re.search(r"fitted to this run \(T = ([0-9.]+) ms, K = ([0-9.]+) rad/s/V", story)
        assert T is not None, story  # T and K as the details give them: four digits
        assert all(len(T.group(k).replace(".", "").lstrip("0")) == 4 for k in (1, 2)), story


async def test_task11_is_not_ticked_while_k_is_still_to_give(quiet):
    """The walk at 80x24: omega_ss in the steps typed on Task 11, K not yet, and the list of
    steps read '✓ Task 11'; it reads '…' (started) until K is given too."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start_with_a_run(pilot, "task11")
        await type_in(pilot, "own.omega_step", "7.8")
        await settle(pilot)
        assert nav_mark(app, "task11") == "…"
        await type_in(pilot, "own.K", "1.93")
        await settle(pilot)
        assert nav_mark(app, "task11") == "✓"
