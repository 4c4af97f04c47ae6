"""A device double for the pinned screens: no stream at all, so nothing on screen depends on
timing. Behaviour tests use the real virtual MinSeg through the real factory and link."""

from __future__ import annotations

from minseg_tui.device.link import LinkEvent, LinkStats
from minseg_tui.device.protocol import Ident
from minseg_tui.device.samples import SampleBatch
from minseg_tui.model.plant import MeterReading, Plant, PlantParams

METER = MeterReading(2.05, 0.0299, 5.3)
"""What the double's multimeter always shows (pinned screens)."""


class QuietDevice:
    """The :class:`~minseg_tui.ui.device.Device` protocol: answers commands, sends no
    samples; looks like the virtual MinSeg, whose multimeter always reads :data:`METER`."""

    def __init__(self, seed: int = 0) -> None:
        self.port = "minseg://"
        self.ident: Ident | None = Ident(
            "minseg-virtual 1.0.0", 1, "Virtual", 720, 25000, 9000, "BRAKE"
        )
        self.stats = LinkStats()
        self.plant = Plant(PlantParams(), seed=seed)
        self.board: object = self.plant  # not None: the virtual board, with its multimeter
        self.commands: list[str] = []
        self.u_req: float | None = 0.0
        self._fed: list[SampleBatch] = []
        self._events: list[LinkEvent] = []
        self.reads = 0
        """How many times the app's stream worker has read the double (it reads once a turn,
        samples first, and posts what it read before it reads again)."""

    def feed(self, batch: SampleBatch) -> None:
        """Hand the app ``batch`` at its next read (the double sends nothing of its own)."""
        self._fed.append(batch)

    def feed_event(self, event: LinkEvent) -> None:
        """Hand the app ``event`` at its next read."""
        self._events.append(event)

    def samples(self) -> SampleBatch:
        self.reads += 1
        fed, self._fed = self._fed, []
        return SampleBatch.concat(fed)

    def events(self) -> list[LinkEvent]:
        out, self._events = self._events, []
        return out

    def set_voltage(self, u: float) -> float:
        self.commands.append(f"V {u:g}")
        self.plant.set_command(u)
        self.u_req = u
        return u

    def stop(self) -> None:
        self.commands.append("STOP")
        self.u_req = 0.0

    def set_period(self, ts: float) -> float:
        self.commands.append(f"P {ts:g}")
        return ts

    def square_wave(self, low: float, high: float, half_period: float, periods: int) -> None:
        self.commands.append(f"STEP {low:g} {high:g} {half_period:g} {periods}")
        self.u_req = None

    def meter(self) -> MeterReading | None:
        return METER

    def close(self) -> None:
        self.commands.append("CLOSE")


def frozen_stream(seed: int = 3, u: float = 2.5, seconds: float = 4.0) -> SampleBatch:
    """A recorded stream for pinned screens: the seeded plant at ``u`` V for ``seconds`` s,
    sampled every 25 ms, as the link hands it over."""
    plant = Plant(PlantParams(), seed=seed)
    plant.set_command(u)
    rows = []
    for k in range(int(seconds / 0.025)):
        plant.advance(0.025)
        rows.append((k, (k + 1) * 25_000, plant.count, round(u * 1000), 0, 0.0))
    return SampleBatch.from_rows(rows)


def square_wave_stream(first_seq: int, first_us: int, seconds: float, seed: int = 5) -> SampleBatch:
    """Task 10's 25 ms plan as the board sends it, from a standing wheel: the seeded plant
    driven 0 -> 4.5 V every 1.5 s, ``seconds`` s of it, sequence numbers from ``first_seq``
    and board times from ``first_us`` (us)."""
    plant = Plant(PlantParams(), seed=seed)
    rows = []
    for k in range(int(round(seconds / 0.025))):
        u = 4.5 if (k // 60) % 2 == 0 else 0.0
        plant.set_command(u)
        rows.append((first_seq + k, first_us + k * 25_000, plant.count, round(u * 1000), 0, 0.0))
        plant.advance(0.025)
    return SampleBatch.from_rows(rows)
