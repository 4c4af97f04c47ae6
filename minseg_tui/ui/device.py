"""The device as the UI drives it: one Protocol, met by the device layer's
:class:`~minseg_tui.device.link.Link` (the board or the virtual MinSeg) and by the test
double in tests/ui/fakes.py; and who the status line says we talk to."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Protocol

from minseg_tui.device import factory
from minseg_tui.device.link import LinkEvent, LinkStats
from minseg_tui.device.protocol import Diag, Ident
from minseg_tui.device.samples import SampleBatch
from minseg_tui.model.plant import MeterReading


class Device(Protocol):
    """The board or the virtual MinSeg: what the UI uses of a :class:`Link`. The commands
    raise DeviceError with one line when the board does not answer; volts and seconds."""

    port: str
    ident: Ident | None
    stats: LinkStats
    board: Any
    """The virtual board behind a ``minseg://`` URL (it has the multimeter), else None."""

    @property
    def u_req(self) -> float | None:
        """The voltage (V) the motor is requested at as far as the link knows: 0 after STOP,
        the watchdog, a reconnect or a board restart (nothing is restored); None while a
        board-timed square wave runs."""
        ...

    def samples(self) -> SampleBatch:
        """Every sample received since the last call (worker thread)."""
        ...

    def events(self) -> list[LinkEvent]:
        """Every event since the last call, oldest first (worker thread)."""
        ...

    def set_voltage(self, u: float) -> object:
        """Request ``u`` V on the motor."""
        ...

    def stop(self) -> object:
        """Motor off, any square wave aborted."""
        ...

    def set_period(self, ts: float) -> object:
        """Sample every ``ts`` s (board-timed)."""
        ...

    def square_wave(self, low: float, high: float, half_period: float, periods: int) -> object:
        """Board-timed square wave between ``low`` and ``high`` V, ``half_period`` s at each,
        ``periods`` times."""
        ...

    def meter(self) -> MeterReading | None:
        """The multimeter on M1A/M1B (the virtual board's), else None."""
        ...

    def diag(self) -> Diag:
        """The board's encoder pins and edges per connector, the connector in use."""
        ...

    def set_direction(self, enc: str, motor: str) -> object:
        """The encoder's counting direction and the motor's polarity, FWD or REV each."""
        ...

    def close(self) -> None:
        """Motor off and port closed."""
        ...


@dataclass(frozen=True)
class DeviceInfo:
    """Who the app talks to: ``name`` (the board's profile) and ``firmware`` from its
    handshake, the ``port``; ``virtual`` True for the virtual MinSeg, ``fallback`` True when
    it was chosen because no board was found."""

    name: str
    firmware: str
    virtual: bool
    port: str = ""
    fallback: bool = False

    @classmethod
    def of(cls, device: Device, fallback: bool = False) -> DeviceInfo:
        """The info of an opened ``device``."""
        ident = device.ident
        return cls(
            name=ident.board if ident else "?",
            firmware=ident.fw if ident else "?",
            virtual=device.board is not None,
            port=device.port,
            fallback=fallback,
        )


LINK_STATES: dict[str, str] = {
    "connected": "ok",
    "alive": "ok",
    "disconnected": "lost",
    "silent": "silent",
    "error": "lost",
}
"""The link's state after each kind of link event (the others leave it as it was)."""


@dataclass(frozen=True)
class LinkState:
    """How the link is: ``state`` (ok, lost, silent), the lines ``dropped`` (gaps in seq) and
    ``corrupt`` (refused) so far, and ``event``: what the last link event said, shown in place
    of the counters until the link is fine again (empty then). Good news (the board answers
    again, reconnected) is ``passing``: shown for a few seconds of board time from ``since``
    (s, the newest sample's board time when it came; None: no sample yet), then the counters
    again (:meth:`aged`)."""

    state: str = "ok"
    dropped: int = 0
    corrupt: int = 0
    event: str = ""
    passing: bool = False
    since: float | None = None

    def after(
        self, event: LinkEvent, text: str, passing: bool = False, since: float | None = None
    ) -> LinkState:
        """The state after ``event``, which the status line shows as ``text`` (``passing``:
        for a while from board time ``since``, s)."""
        state = LINK_STATES.get(event.kind, self.state)
        return LinkState(state, self.dropped, self.corrupt, text, passing and bool(text), since)

    def counted(self, stats: LinkStats) -> LinkState:
        """The same state with the link's counters now."""
        return replace(self, dropped=stats.dropped, corrupt=stats.corrupt)

    def news_over(self) -> LinkState:
        """The same state with a passing text given way to the counters at once (a new run
        begins: "square wave done" of the last one is no longer news)."""
        if not self.passing:
            return self
        return replace(self, event="", passing=False, since=None)

    def aged(self, t: float | None, shown: float) -> LinkState:
        """The state at board time ``t`` (s, the newest sample's): a passing text shown for
        ``shown`` s gives way to the counters (so does one from before a board restart, whose
        clock began again)."""
        if not self.passing or t is None:
            return self
        if self.since is None:
            return replace(self, since=t)
        if t - self.since >= shown or t < self.since:
            return self.news_over()
        return self


def open_device(spec: str, seed: int = 0) -> Device:
    """The board or the virtual MinSeg for the UI's ``spec``: ``auto`` (a board if one is
    found, else the virtual MinSeg), ``sim`` (the virtual MinSeg in real time, seeded), a
    port or a pyserial URL. DeviceError with one line when it cannot be opened."""
    virtual = f"{factory.VIRTUAL}&seed={seed}"
    return factory.open_device("virtual" if spec == "sim" else spec, virtual=virtual)
