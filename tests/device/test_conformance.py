"""The virtual MinSeg against the conformance script, firmware/golden/conformance.txt.

The same script runs against the firmware in simavr (firmware/sim/sim_conformance.c, in
`make -C firmware sim-test`), so the two boards answer every command in it byte for byte
alike. The runner here follows the script's rules as written at its top.
"""

from __future__ import annotations

import binascii
import re
from collections import deque
from dataclasses import dataclass, field
from pathlib import Path

from minseg_tui.device.virtual import BOARD, FIRMWARE, VirtualBoard, VirtualSettings

SCRIPT = Path(__file__).resolve().parents[2] / "firmware" / "golden" / "conformance.txt"
SETTLE_S = 0.004  # board time after a send, for the reply (as the simavr harness)
SYNC_MAX_S = 0.2
_ESCAPE = re.compile(rb"\\(x[0-9A-Fa-f]{2}|[rnt0\\])")
_CHARS = {b"r": b"\r", b"n": b"\n", b"t": b"\t", b"0": b"\0", b"\\": b"\\"}


def unescape(text: str) -> bytes:
    """The bytes a `>` line stands for (escapes as the script describes them)."""

    def one(m: re.Match[bytes]) -> bytes:
        e = m.group(1)
        return bytes([int(e[1:], 16)]) if e.startswith(b"x") else _CHARS[e]

    return _ESCAPE.sub(one, text.encode("ascii"))


def expected_line(text: str, fw: str, board: str) -> str:
    """A `<` line with the board's names filled in and, for those, its checksum."""
    line = text.replace("{fw}", fw).replace("{board}", board)
    if line.endswith("*{crc}"):
        body = line[1:-6]
        line = f"${body}*{binascii.crc_hqx(body.encode('ascii'), 0xFFFF):04X}"
    return line


@dataclass
class VirtualDriver:
    """A virtual board on a virtual clock, no loop jitter, seen as the script sees a board."""

    board: VirtualBoard = field(
        default_factory=lambda: VirtualBoard(VirtualSettings(jitter_us=0.0, seed=0))
    )
    partial: bytes = b""

    def send(self, data: bytes) -> None:
        self.board.feed(data)

    def run(self, seconds: float) -> list[str]:
        self.board.run_until(self.board.now + seconds)
        data = self.partial + self.board.take_output()
        *lines, self.partial = data.split(b"\n")
        return [x.decode("latin-1") for x in lines]

    def reset(self) -> None:
        self.board.reset()
        self.partial = b""


def run_script(drv: VirtualDriver, fw: str, board: str) -> tuple[int, list[str]]:
    """(steps run, failures) of the whole script against one board."""
    queue: deque[str] = deque()
    failures: list[str] = []
    last_u: int | None = None
    samples = 0
    steps = 0

    def take(lines: list[str]) -> None:
        nonlocal last_u, samples
        for line in lines:
            if line.startswith("$S,"):
                last_u = int(line.split("*")[0].split(",")[4])
                samples += 1
            elif not line.startswith("$BOOT,"):
                queue.append(line)

    def checkpoint(where: str) -> None:
        if queue:
            failures.append(f"{where}: not expected: {list(queue)}")
            queue.clear()

    def booted() -> None:
        for _ in range(100):
            lines = drv.run(0.001)
            boot = any(x.startswith("$BOOT,") for x in lines)
            take(lines)
            if boot:
                return
        failures.append("no $BOOT after a reset")

    booted()
    for number, raw in enumerate(SCRIPT.read_text(encoding="ascii").splitlines(), start=1):
        where = f"conformance.txt:{number}"
        if not raw.strip() or raw.startswith("#"):
            continue
        steps += 1
        op, _, arg = raw.partition(" ")
        if op in (">", ">>"):
            checkpoint(where)
            drv.send(unescape(arg) + (b"\n" if op == ">" else b""))
            take(drv.run(SETTLE_S))
        elif op == "<":
            want = expected_line(arg, fw, board)
            got = queue.popleft() if queue else None
            if got != want:
                failures.append(f"{where}: expected {want!r}, got {got!r}")
        elif op == "=":
            take(drv.run(float(arg) / 1000.0))
        elif op == "sync":
            before, waited = samples, 0.0
            while samples == before and waited < SYNC_MAX_S:
                take(drv.run(0.0001))
                waited += 0.0001
            if samples == before:
                failures.append(f"{where}: no sample line within {SYNC_MAX_S * 1000:g} ms")
        elif op == "u":
            if last_u != int(arg):
                failures.append(f"{where}: expected the last sample with u = {arg}, got {last_u}")
        elif op == "reset":
            checkpoint(where)
            drv.reset()
            booted()
        else:
            failures.append(f"{where}: unknown directive {raw!r}")
    checkpoint("end of the script")
    return steps, failures


def test_unescape_and_expected_lines():
    assert unescape(r"V,1\0\x80\r\\") == b"V,1\x00\x80\r\\"
    line = expected_line("$ID,{fw},2,{board},720*{crc}", "fw 1", "B")
    body = "ID,fw 1,2,B,720"
    assert line == f"${body}*{binascii.crc_hqx(body.encode(), 0xFFFF):04X}"


def test_virtual_board_follows_the_conformance_script():
    steps, failures = run_script(VirtualDriver(), FIRMWARE, BOARD)
    assert steps > 250
    assert failures == []
