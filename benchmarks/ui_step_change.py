"""How long a step change (PgDn/PgUp) takes in the TUI, on the steps that show a view.

Runs the app as the CLI makes it (the virtual MinSeg in real time, plots redrawn every
0.25 s), headless at --size (80x24, a group in tmux), on a new session in a temporary folder
with the table of Tasks 4-9 filled and a seeded Task 10 run recorded. It then moves
--changes times between two neighbouring steps (PgDn, PgUp, ...), each time pressing the key
and waiting until the new step is mounted, focused and its view drawn (no worker left but
the device stream), and prints for each pair of steps the CPU time of the process (all its
threads: time.process_time) and the wall time per change, median and worst.

The stream and the plots' redraws go on while the app waits: their CPU is counted in too, as
a group's machine spends it. ``--profile FILE`` writes a cProfile of the timed changes of the
first pair (main thread only: the event loop, where Textual lays out and draws).

``net`` is the CPU time of a change less what the app spends idle (measured first, per
second) over the change's wall time: on a loaded machine a change takes seconds of wall
time, and the virtual board's stream alone then adds a good part of the CPU time.

``--starts N`` first times N start-ups of the app, each on a new sessions folder: from the
app's start until its start screen takes names, and from the names and Enter until the
lab's first step is shown and focused (CPU of the process and wall time, median and best).

``--no-paint`` leaves out the painting of the frames, as the UI tests do
(tests.ui.textual_internals.unpainted_refresh): the difference from a run without it is
what painting costs (a terminal needs it; the headless driver throws the frames away).
"""

from __future__ import annotations

import argparse
import asyncio
import cProfile
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from textual.pilot import Pilot
from textual.screen import Screen
from textual.widgets import Input

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.state.session import Session
from minseg_tui.model.plant import PlantParams, record
from minseg_tui.ui.app import LabApp, make_app
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.screens.lab import LabScreen, StepPane

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.ui.helpers import TABLE  # the filled Task 4-9 table the UI tests type
from tests.ui.textual_internals import unpainted_refresh  # the UI tests' frames left unpainted

PAIRS = (
    ("task11", "task12"),
    ("task13", "task14"),
    ("task15", "model_check"),
    ("task5", "table"),
)
"""The neighbouring steps moved between: Tasks 11-15 and the model check (views built from
the run), and, for comparison, a live step and the table."""


def fill(session: Session, seed: int = 5) -> None:
    """The table and a seeded 25 ms Task 10 run on the lab's motor."""
    for key, text in TABLE.items():
        session.enter(key, text)
    plan = dict(step("task10").plans)["manual"]
    n = round(plan.duration / plan.ts)
    per_half = round(plan.half_period / plan.ts)
    k = np.arange(n)
    u_req = np.where(((k // per_half) % 2 == 0) & (k >= 4), plan.high, plan.low)
    data = record(PlantParams(), u_req, ts=plan.ts, seed=seed, jitter_us=800)
    rec = session.start_run("steps", plan)
    for j in range(n):
        rec.append(int(data.seq[j]), int(data.t_us[j]), int(data.count[j]), round(u_req[j] * 1000))
    assert session.finish_run(rec) is not None


async def settle(pilot: Pilot[None], until: object = None) -> None:
    """Process the app's messages and wait for its workers (all but the device stream),
    four rounds at least, until ``until()`` holds."""
    app = pilot.app
    for k in range(10_000):
        await pilot.pause(0)
        busy = [w for w in app.workers if w.group != "stream" and not w.is_finished]
        if busy:
            await app.workers.wait_for_complete(busy)
            continue
        if k >= 4 and (until is None or until()):  # type: ignore[operator]
            return
    raise SystemExit("the app never settled")


def shown(app: LabApp, step_id: str) -> bool:
    screen = app.screen
    if not isinstance(screen, LabScreen):
        return False
    panes = screen.query(StepPane)
    return bool(panes) and panes.last().is_mounted and panes.last().step.id == step_id


async def start_up(size: tuple[int, int], root: Path) -> tuple[float, float, float, float]:
    """One start-up of the app on a new sessions folder ``root``: CPU and wall time (s) until
    its start screen takes names, then from the names and Enter until the lab shows its
    first step."""
    app = make_app(UiConfig(device="sim", sessions=root, today="2026-11-27"))
    c0, w0 = time.process_time(), time.perf_counter()
    async with app.run_test(size=size) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        c1, w1 = time.process_time(), time.perf_counter()
        app.screen.query_one("#members", Input).insert_text_at_cursor("Ada, Bo")
        await pilot.press("enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen) and app.screen.shown.is_set())
        c2, w2 = time.process_time(), time.perf_counter()
    return c1 - c0, w1 - w0, c2 - c1, w2 - w1


async def start_ups(args: argparse.Namespace, root: Path) -> None:
    cols, rows = (int(v) for v in args.size.split("x"))
    got = [await start_up((cols, rows), root / f"s{k}") for k in range(args.starts + 1)][1:]
    print(f"{args.starts} start-ups at {cols}x{rows} (the first, untimed, loads the modules)")
    print(f"{'':<22} {'CPU ms':>7} {'best':>6} {'wall ms':>8} {'best':>6}")
    for i, what in ((0, "app to start screen"), (2, "Enter to first step")):
        cpu = [g[i] for g in got]
        wall = [g[i + 1] for g in got]
        print(
            f"{what:<22} {1e3 * statistics.median(cpu):7.0f} {1e3 * min(cpu):6.0f} "
            f"{1e3 * statistics.median(wall):8.0f} {1e3 * min(wall):6.0f}"
        )


async def run(args: argparse.Namespace, root: Path) -> None:
    cols, rows = (int(v) for v in args.size.split("x"))
    app = make_app(UiConfig(device="sim", sessions=root, today="2026-11-27"))
    async with app.run_test(size=(cols, rows)) as pilot:
        await settle(pilot, lambda: bool(app.screen.query("#members")))
        await pilot.press(*"Ada, Bo", "enter")
        await settle(pilot, lambda: isinstance(app.screen, LabScreen))
        assert app.session is not None
        with app.session as s:
            fill(s)
        print(f"app at {cols}x{rows}, {args.changes} changes per pair of steps")
        screen = app.screen
        assert isinstance(screen, LabScreen)
        screen.go_to(PAIRS[0][0])
        await settle(pilot, lambda: shown(app, PAIRS[0][0]))
        c0, w0 = time.process_time(), time.perf_counter()
        await asyncio.sleep(args.idle)
        idle = (time.process_time() - c0) / (time.perf_counter() - w0)
        print(f"idle on {PAIRS[0][0]} (the stream, the status line): {1e3 * idle:.0f} ms CPU/s")
        print(
            f"{'steps':<18} {'CPU ms/change':>14} {'worst':>7} {'net':>7} {'wall ms':>8} "
            f"{'worst':>7}"
        )
        pairs = [pair for pair in PAIRS if not args.only or pair[0] in args.only]
        for first, (a, b) in enumerate(pairs):
            screen = app.screen
            assert isinstance(screen, LabScreen)
            screen.go_to(a)
            await settle(pilot, lambda a=a: shown(app, a))
            for _ in range(2):  # once each way untimed: the first visit builds what it caches
                await pilot.press("pagedown")
                await settle(pilot, lambda b=b: shown(app, b))
                await pilot.press("pageup")
                await settle(pilot, lambda a=a: shown(app, a))
            cpu: list[float] = []
            wall: list[float] = []
            prof = cProfile.Profile() if args.profile and first == 0 else None
            for k in range(args.changes):
                key, to = ("pagedown", b) if k % 2 == 0 else ("pageup", a)
                c0, w0 = time.process_time(), time.perf_counter()
                if prof:
                    prof.enable()
                await pilot.press(key)
                await settle(pilot, lambda to=to: shown(app, to))
                if prof:
                    prof.disable()
                cpu.append(time.process_time() - c0)
                wall.append(time.perf_counter() - w0)
            if prof:
                prof.dump_stats(args.profile)
            net = [c - idle * w for c, w in zip(cpu, wall, strict=True)]
            print(
                f"{a + ' <> ' + b:<18} {1e3 * statistics.median(cpu):14.0f} "
                f"{1e3 * max(cpu):7.0f} {1e3 * statistics.median(net):7.0f} "
                f"{1e3 * statistics.median(wall):8.0f} {1e3 * max(wall):7.0f}"
            )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--changes", type=int, default=20, help="timed changes per pair of steps")
    ap.add_argument("--size", default="80x24", help="terminal size, COLSxROWS")
    ap.add_argument("--idle", type=float, default=5.0, help="s of idle measured first")
    ap.add_argument("--only", nargs="*", help="only the pairs whose first step is one of these")
    ap.add_argument("--profile", help="write a cProfile of the first pair's changes here")
    ap.add_argument("--starts", type=int, default=0, help="time this many start-ups first")
    ap.add_argument("--no-paint", action="store_true", help="no frame painted (as in the tests)")
    args = ap.parse_args()
    if args.no_paint:
        Screen._compositor_refresh = unpainted_refresh  # type: ignore[method-assign]
    with tempfile.TemporaryDirectory() as tmp:
        if args.starts:
            asyncio.run(start_ups(args, Path(tmp) / "starts"))
        if args.changes:
            asyncio.run(run(args, Path(tmp) / "sessions"))


if __name__ == "__main__":
    main()
