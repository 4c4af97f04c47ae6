"""A device double for the pinned screens: no stream at all, so nothing on screen depends on
timing. Behaviour tests use the real virtual MinSeg through the real factory and link."""

from __future__ import annotations

import time

import numpy as np

from minseg_tui.model.plant import Plant, PlantParams
from minseg_tui.ui.ports import Batch, DeviceInfo, LinkHealth, Meter

METER = Meter(2.05, 0.0299, 5.3)
"""What the double's multimeter always shows (pinned screens)."""


class QuietDevice:
    """Answers commands, sends no samples; its multimeter reads the seeded plant."""

    def __init__(self, seed: int = 0) -> None:
        self.info = DeviceInfo("Virtual", "minseg-virtual 1.0.0", True, "minseg://", fallback=True)
        self.plant = Plant(PlantParams(), seed=seed)
        self.commands: list[str] = []

    def health(self) -> LinkHealth:
        return LinkHealth("ok", 0, 0)

    def read(self, timeout: float) -> Batch:
        time.sleep(timeout)
        empty = np.zeros(0, dtype=np.int64)
        return Batch(empty, empty, empty, empty)

    def set_voltage(self, u: float) -> None:
        self.commands.append(f"V {u:g}")
        self.plant.set_command(u)

    def stop(self) -> None:
        self.commands.append("STOP")

    def set_period(self, period: float) -> None:
        self.commands.append(f"P {period:g}")

    def run_steps(self, low: float, high: float, half: float, n: int) -> None:
        self.commands.append(f"STEP {low:g} {high:g} {half:g} {n}")

    def meter(self) -> Meter | None:
        return METER

    def close(self) -> None:
        self.commands.append("CLOSE")


def frozen_stream(
    seed: int = 3, u: float = 2.5, seconds: float = 4.0
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A recorded stream for pinned screens: the seeded plant at ``u`` V for ``seconds`` s,
    sampled every 25 ms: board time (s), counts, requested V."""
    plant = Plant(PlantParams(), seed=seed)
    plant.set_command(u)
    t, c = [], []
    for k in range(int(seconds / 0.025)):
        plant.advance(0.025)
        t.append((k + 1) * 0.025)
        c.append(plant.count)
    return np.array(t), np.array(c, dtype=np.int64), np.full(len(t), u)
