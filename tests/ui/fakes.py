"""Test doubles of the UI's ports while the real session and link are not in the tree.

FakeLab keeps entries in memory and parses with the real lab/entry.py; FakeDevice samples
the real plant (model/plant.py) on a virtual clock: each read() advances 50 ms.
"""

from __future__ import annotations

from collections.abc import Sequence

from minseg_tui import signals
from minseg_tui.errors import MinsegError
from minseg_tui.lab import capture as cap
from minseg_tui.lab.entry import parse_quantity
from minseg_tui.lab.steps import FIELDS, STEPS
from minseg_tui.model.plant import Plant, PlantParams
from minseg_tui.ui.ports import (
    Batch,
    DeviceInfo,
    EntryResult,
    LinkHealth,
    Meter,
    SessionSummary,
    Steady,
    TableView,
)


class FakeDevice:
    def __init__(self, seed: int = 0) -> None:
        self.info = DeviceInfo("Virtual", "fw 1", True, "auto")
        self.plant = Plant(PlantParams(), seed=seed)
        self.period = 0.025
        self.commands: list[str] = []
        self.t = 0.0

    def health(self) -> LinkHealth:
        return LinkHealth("ok", 0, 0)

    def read(self, timeout: float) -> Batch:
        import time

        time.sleep(min(timeout, 0.05))
        ts, cs, us = [], [], []
        for _ in range(2):
            self.plant.advance(self.period)
            self.t += self.period
            ts.append(self.t)
            cs.append(self.plant.count)
            us.append(self.plant.u_req)
        return Batch(ts, cs, us)

    def set_voltage(self, u: float) -> None:
        self.commands.append(f"V {u}")
        self.plant.set_command(u)

    def stop(self) -> None:
        self.commands.append("STOP")
        self.plant.set_command(0.0)

    def run_steps(self, low: float, high: float, half: float, n: int, period: float) -> None:
        self.commands.append(f"STEP {low} {high} {half} {n} {period}")

    def meter(self) -> Meter | None:
        m = self.plant.multimeter()
        return Meter(m.u_A, m.i, m.R)

    def close(self) -> None:
        self.commands.append("CLOSE")


class FakeLab:
    def __init__(self, members: str = "", date: str = "") -> None:
        self.steps = STEPS
        self.members, self.date = members, date
        self.texts: dict[str, str] = {}
        self.results: dict[str, EntryResult] = {}
        self._current = STEPS[0].id

    def text(self, key: str) -> str:
        return self.texts.get(key, "")

    def result(self, key: str) -> EntryResult | None:
        return self.results.get(key)

    def enter(self, key: str, text: str) -> EntryResult:
        fld = FIELDS[key]
        self.texts[key] = text
        if fld.kind != "quantity":
            r = EntryResult(True)
        else:
            try:
                p = parse_quantity(text, fld.unit, label=fld.label, allow_negative=fld.allow_negative,
                                   allow_zero=fld.allow_zero)
            except MinsegError as exc:
                r = EntryResult(False, str(exc))
            else:
                w = tuple(m for pl in fld.plausible for m in pl.warnings(p.value))
                r = EntryResult(True, p.note, w)
        self.results[key] = r
        return r

    @property
    def current(self) -> str:
        return self._current

    def go(self, step_id: str) -> None:
        self._current = step_id

    def steady(self, t: Sequence[float], count: Sequence[int]) -> Steady:
        w = signals.timestamp_velocity(t, count)
        s = cap.steadiness(t, w)
        return Steady(s.settled, s.mean, s.spread, cap.DEFAULT_WINDOW)

    def capture(self, level: float, steady: Steady) -> EntryResult:
        if not steady.settled:
            return EntryResult(False, "not settled yet")
        return self.enter(f"omega_ss@{level:g}", f"{steady.mean:.3f}")

    def table(self) -> TableView:
        return TableView(("u", "u_ss"), ())

    def store_run(self, *a: object) -> None:
        pass

    def run(self, name: str) -> None:
        return None

    def run_status(self) -> str:
        return "no runs yet"

    def results_text(self) -> str:
        return "no step run yet"

    def model_check_text(self) -> str:
        return "no step run yet"

    def export(self) -> list[str]:
        return []


class FakeStore:
    def __init__(self) -> None:
        self.labs: dict[str, FakeLab] = {}

    def list(self) -> list[SessionSummary]:
        return [SessionSummary(k, v.members, v.date, v.current) for k, v in self.labs.items()]

    def new(self, members: str, date: str) -> FakeLab:
        lab = FakeLab(members, date)
        self.labs[f"s{len(self.labs)}"] = lab
        return lab

    def open(self, path: str) -> FakeLab:
        return self.labs[path]
