"""The Task 10 procedure without a screen (lab.task10), on the virtual MinSeg behind the real
link: stopped mid-run, and a cable pulled mid-run. Every wait is on what the board sends."""

from __future__ import annotations

import itertools
import time
from collections.abc import Iterator
from contextlib import contextmanager, nullcontext

import numpy as np

from minseg_tui.device.factory import open_device
from minseg_tui.device.link import Link, LinkEvent
from minseg_tui.device.standstill import PRE_ROLL
from minseg_tui.device.virtual import forget_board, named_board
from minseg_tui.lab.state.session import Session
from minseg_tui.lab.state.task10 import Task10

_names = itertools.count()
GUARD = 120.0
"""Host seconds against a hang (never a measure: the waits are on board samples)."""


@contextmanager
def _board(seed: int) -> Iterator[tuple[str, Link]]:
    """A named virtual MinSeg on board time behind the real link; closed and forgotten after."""
    name = f"task10-{next(_names)}"
    link = open_device(f"minseg://{name}?clock=virtual&seed={seed}")
    try:
        yield name, link
    finally:
        link.close()
        forget_board(name)


def _feed_until(task: Task10, link, done) -> None:
    end = time.monotonic() + GUARD
    while not done():
        assert time.monotonic() < end, "the board sent nothing more"
        task.feed(link.samples(), link.events())
        time.sleep(0.002)


def test_stopped_mid_run_keeps_what_was_recorded_with_the_motor_off(tmp_path):
    with _board(2) as (name, link):
        with Session.create(tmp_path, ["A"]) as s:
            task = Task10.of(nullcontext(s), link, "fast")
            assert task.plan.ts == 0.005 and task.kind == "fast"
            task.begin()
            assert task.phase == "waiting" and task.run is None and link.u_req == 0
            _feed_until(task, link, lambda: task.run is not None and task.run.samples >= 200)
            assert task.phase == "square_wave" and link.u_req is None  # the board's sequence
            outcome = task.stop("stopped")
            assert outcome is not None and task.outcome is outcome and not task.active
            assert link.u_req == 0  # the motor is off
            assert outcome.why == "stopped" and outcome.problem == "" and outcome.started
            info = outcome.info
            assert info is not None and info.kind == "fast" and info.ts == 0.005
            assert info.interrupted and info.interruption == "stopped"
            assert info.samples == outcome.samples >= 200
            log = s.load_run(info.name)
            assert np.all(np.asarray(log.u)[:PRE_ROLL] == 0.0)  # the standing wheel first
            assert np.all(np.asarray(log.omega)[:PRE_ROLL] == 0.0)
            assert s.runs == [info] and task.stop() is outcome  # ended once


def test_a_cable_pulled_mid_run_keeps_the_samples(tmp_path):
    with _board(3) as (name, link):
        with Session.create(tmp_path, ["A"]) as s:
            task = Task10.of(nullcontext(s), link, "manual")
            task.begin()
            _feed_until(task, link, lambda: task.run is not None and task.run.samples >= 80)
            named_board(name).unplug()
            _feed_until(task, link, lambda: task.outcome is not None)
            outcome = task.outcome
            assert outcome is not None and outcome.why == "cable"
            assert outcome.event is not None and outcome.event.kind == "disconnected"
            assert outcome.info is not None and outcome.info.interruption.startswith("board lost")
            assert [r.name for r in s.runs] == [outcome.run]
            assert outcome.info.samples >= 80


def test_a_silence_on_the_link_does_not_end_the_wait_for_the_wheel(tmp_path):
    """The link says "silent" when no line came for a while on the host's clock: a busy PC
    does that too (a whole-lab test hung at Task 10 on a loaded machine: the wait ended on
    it, no run started). The wait goes on, on board time, and the run starts."""
    with _board(2) as (name, link):
        with Session.create(tmp_path, ["A"]) as s:
            task = Task10.of(nullcontext(s), link, "manual")
            task.begin()
            silent = LinkEvent("silent", f"minseg://{name}: the board has not answered", 0.0)
            task.feed(link.samples(), [silent, *link.events()])
            assert task.outcome is None and task.phase != "ended"
            _feed_until(task, link, lambda: task.run is not None and task.run.samples >= 20)
            assert task.outcome is None and task.phase in ("recording", "square_wave")


def test_the_progress_counts_the_plan_from_the_boards_first_step(tmp_path):
    """Walk 16, D6: a pre-roll that came in one long batch (a busy PC: 1.2 s of standing
    wheel) was counted against the plan: "recording steps-2: 516 samples, 12.9 of 12.0 s"."""
    from minseg_tui.device.samples import SampleBatch

    with _board(5) as (_name, link):
        with Session.create(tmp_path, ["A"]) as s:
            task = Task10.of(nullcontext(s), link, "fast")
            task.begin()
            _feed_until(task, link, lambda: task.phase == "recording")
            run = task.run
            assert run is not None and run.samples == 0
            held: list[SampleBatch] = []  # the stream worker late: 1 s of samples in one batch
            end = time.monotonic() + GUARD
            while not held or held[-1].t_us[-1] - held[0].t_us[0] < 1_000_000:
                assert time.monotonic() < end, "the board sent nothing more"
                b = link.samples()
                if len(b):
                    held.append(b)
                time.sleep(0.002)
            task.feed(SampleBatch.concat(held), link.events())
            assert task.phase == "square_wave" and run.samples > 150
            said = task.progress().text
            assert "of 1.0 s" not in said and "sequence starts next" in said, said
            assert task.progress().fraction == 0.0
            seen: list[float] = []
            while task.outcome is None:
                assert time.monotonic() < end, "the board sent nothing more"
                task.feed(link.samples(), link.events())
                seen.append(run.elapsed)
                time.sleep(0.002)
            assert task.outcome.why == "done"
            duration = task.plan.duration
            assert seen and max(seen) <= duration, (max(seen), duration)
            assert max(seen) >= duration - 0.2  # it counted the plan through
            log = s.load_run(task.outcome.run)
            first_step = float(np.asarray(log.t)[np.flatnonzero(np.asarray(log.u) != 0)[0]])
            assert first_step - float(np.asarray(log.t)[0]) >= 1.0  # the long pre-roll is kept
