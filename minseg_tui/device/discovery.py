"""Which serial port is a MinSeg: by USB vendor and product id, never by guesswork.

A port is picked only when its VID:PID is in ``KNOWN``. There is no catch-all: a
port without USB ids (a built-in ttyS, a modem, a Bluetooth link) or with unknown ids
is never picked, and every port gets a reason saying why.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import asdict, dataclass
from typing import Any, Literal, Protocol

Verdict = Literal["board", "clone", "possible", "ignored"]

RANK: dict[str, int] = {"board": 0, "clone": 1, "possible": 2, "ignored": 3}
"""Lower is better; only ``board`` and ``clone`` are picked automatically."""

KNOWN: dict[tuple[int, int], tuple[Verdict, str]] = {
    (0x2341, 0x0010): ("board", "Arduino Mega 2560"),
    (0x2341, 0x0042): ("board", "Arduino Mega 2560 R3"),
    (0x2341, 0x0242): ("board", "Arduino Mega 2560 R3 (16U2 bootloader id)"),
    (0x2A03, 0x0010): ("board", "Arduino Mega 2560 (arduino.org)"),
    (0x2A03, 0x0042): ("board", "Arduino Mega 2560 R3 (arduino.org)"),
    (0x1A86, 0x7523): ("clone", "CH340 USB-serial (Mega 2560 clones)"),
    (0x0403, 0x6001): ("possible", "FTDI FT232R USB-serial (could be anything: give --port)"),
}


class PortInfo(Protocol):
    """What discovery reads from pyserial's ListPortInfo."""

    device: str
    vid: int | None
    pid: int | None
    description: str
    manufacturer: str | None
    serial_number: str | None


@dataclass(frozen=True)
class PortCandidate:
    """One serial port as a candidate for the board, and what discovery thinks of it."""

    device: str
    vid: int | None
    pid: int | None
    description: str
    verdict: Verdict
    reason: str

    @property
    def picked(self) -> bool:
        """True when ``auto`` may open this port."""
        return self.verdict in ("board", "clone")

    def as_dict(self) -> dict[str, Any]:
        """For JSON: ids as 4-digit hex strings."""
        d = asdict(self)
        d["vid"] = None if self.vid is None else f"{self.vid:04X}"
        d["pid"] = None if self.pid is None else f"{self.pid:04X}"
        d["picked"] = self.picked
        return d


def judge(port: PortInfo) -> PortCandidate:
    """The verdict on one port, with the reason."""
    vid, pid = port.vid, port.pid
    desc = port.description or ""
    if vid is None or pid is None:
        reason = "no USB vendor/product id (built-in or virtual serial port): never opened"
        return PortCandidate(port.device, vid, pid, desc, "ignored", reason)
    known = KNOWN.get((vid, pid))
    if known is None:
        maker = f" by {port.manufacturer}" if port.manufacturer else ""
        reason = f"USB {vid:04X}:{pid:04X}{maker} is not a known Arduino or USB-serial bridge: never opened"
        return PortCandidate(port.device, vid, pid, desc, "ignored", reason)
    verdict, what = known
    why = {
        "board": f"{what} ({vid:04X}:{pid:04X})",
        "clone": f"{what} ({vid:04X}:{pid:04X})",
        "possible": f"{what}; not opened automatically",
    }[verdict]
    return PortCandidate(port.device, vid, pid, desc, verdict, why)


def list_ports() -> list[Any]:
    """The system's serial ports (pyserial ListPortInfo objects)."""
    from serial.tools import list_ports as lp

    return list(lp.comports())


def candidates(ports: Iterable[PortInfo] | None = None) -> list[PortCandidate]:
    """Every port judged, best first (boards, then clones, possibles, ignored)."""
    judged = [judge(p) for p in (list_ports() if ports is None else ports)]
    return sorted(judged, key=lambda c: (RANK[c.verdict], c.device))


def find_board(
    ports: Iterable[PortInfo] | None = None, vid_pid: tuple[int, int] | None = None
) -> PortCandidate | None:
    """The best port ``auto`` may open (or the first with exactly ``vid_pid``); None if none."""
    for c in candidates(ports):
        if vid_pid is not None:
            if (c.vid, c.pid) == vid_pid and c.verdict != "ignored":
                return c
        elif c.picked:
            return c
    return None
