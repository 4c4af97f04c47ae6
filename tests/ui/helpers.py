"""Shared steps of the UI tests: start a session, move, type, and a recorded step run."""

from __future__ import annotations

from minseg_tui.lab.steps import step
from minseg_tui.model.plant import Plant, PlantParams
from minseg_tui.ui.widgets.fields import FieldRow, field_id

TABLE = {
    "R": "5.3",
    "u_ss@2.5": "2.05",
    "omega_ss@2.5": "3.1",
    "i_ss@2.5": "28 mA",
    "u_ss@3.5": "3.04",
    "omega_ss@3.5": "4.9",
    "i_ss@3.5": "32 mA",
    "u_ss@4.5": "4.02",
    "omega_ss@4.5": "6.7",
    "i_ss@4.5": "36 mA",
}
"""A filled Task 4-9 table as a group would type it (R in ohm, the rest per row)."""


def enter_all(app, entries: dict[str, str]) -> None:
    """Store every (field key, typed text) through the app's lab session, as typed."""
    for key, text in entries.items():
        app.lab.enter(key, text)


async def start(pilot, names: str = "Ada, Bo") -> None:
    await pilot.pause(0.1)
    await pilot.press(*names)
    await pilot.press("enter")
    await pilot.pause(0.1)


async def goto(pilot, step_id: str) -> None:
    pilot.app.go_to_step(step_id)
    await pilot.pause(0.05)
    await pilot.pause(0.05)


async def type_in(pilot, key: str, text: str) -> FieldRow:
    row = pilot.app.screen.query_one(f"#{field_id(key)}", FieldRow)
    row.input.focus()
    row.input.value = ""
    if text:
        await pilot.press(*text)
    await pilot.press("enter")
    await pilot.pause(0.05)
    return row


def record_step_run(session, seed: int = 5) -> str:
    """Task 10's 25 ms plan on the seeded plant, appended to the session's Recorder as a board
    would send it; the run's name."""
    plan = dict(step("task10").plans)["manual"]
    plant = Plant(PlantParams(), seed=seed)
    rec = session.start_run("steps", plan)
    n = round(plan.duration / plan.ts)
    per_half = round(plan.half_period / plan.ts)
    for k in range(n):
        u = plan.high if (k // per_half) % 2 == 0 and k >= 4 else plan.low
        plant.set_command(u)
        rec.append(k, round(k * plan.ts * 1e6), plant.count, round(u * 1000))
        plant.advance(plan.ts)
    info = session.finish_run(rec)
    return info.name
