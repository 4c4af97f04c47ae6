"""Seeded sessions shared by the report and class-view tests and benchmarks/class_view.py: a
clock that ticks one second per reading, and Task 10's square wave recorded from the
simulated motor (seeded) as a board would send it."""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

import numpy as np

from minseg_tui.lab.content.steps import step
from minseg_tui.lab.saving.runs import RunInfo
from minseg_tui.lab.state.session import Session
from minseg_tui.model.plant import PlantParams, record

LEAD = 20
"""Samples of the motor off recorded before the square wave starts."""

HIGH = 4.5
"""The square wave's high level, V (its low level is 0 V)."""


class Clock:
    """A clock that ticks one second per call, from ``start`` (2026-11-22 10:00 UTC)."""

    def __init__(self, start: datetime = datetime(2026, 11, 22, 10, 0, 0, tzinfo=UTC)) -> None:
        self.t = start

    def __call__(self) -> datetime:
        self.t += timedelta(seconds=1)
        return self.t


def record_square_wave(
    s: Session,
    seed: int,
    jitter_us: float = 800,
    periods: int | None = None,
    stopped_early: bool = False,
    ended_by: str = "",
) -> RunInfo | None:
    """Task 10's manual plan on the seeded plant: :data:`LEAD` samples at 0 V, then the
    square wave between :data:`HIGH` and 0 V for the plan's periods (or the first
    ``periods`` of them), the board's loop late by up to ``jitter_us`` µs; appended to a
    recorder of ``s`` sample by sample (the requested voltage in mV) and finished with
    ``stopped_early`` and ``ended_by``. What ``Session.finish_run`` returns."""
    plan = dict(step("task10").plans)["manual"]
    n = int(round(plan.duration / plan.ts))
    if periods is not None:
        n = n * periods // plan.periods
    u_req = np.concatenate(
        (
            np.zeros(LEAD),
            np.where((np.arange(n) * plan.ts // plan.half_period) % 2 == 0, HIGH, 0.0),
        )
    )
    data = record(PlantParams(), u_req, ts=plan.ts, seed=seed, jitter_us=jitter_us)
    rec = s.start_run("steps", plan)
    for k in range(u_req.size):
        rec.append(
            int(data.seq[k]), int(data.t_us[k]), int(data.count[k]), int(round(u_req[k] * 1000))
        )
    return s.finish_run(rec, stopped_early=stopped_early, ended_by=ended_by)
