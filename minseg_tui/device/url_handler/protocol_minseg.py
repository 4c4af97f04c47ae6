"""pyserial URL handler ``minseg://``: a virtual MinSeg in-process, behind a pyserial port.

    minseg://[name]?seed=1&coulomb=0.004&clock=virtual

``name`` (optional) names a board shared in this process: reopening the same URL reaches
the same board (and its wheel), as replugging a cable does; without a name every open
makes a new board. The query takes the options of ``virtual.OPTIONS`` and ``clock``:

- ``clock=real`` (default): board time is host time; samples come at the board's rate.
- ``clock=virtual``: board time moves only while the host reads: a read with timeout
  T advances the board by at most T (less when output appears first). Deterministic.
  The port then offers ``board_clock()`` (board time, s), which the link uses for its
  keep-alive so the board's watchdog sees the same time.

Opening a port resets the board (as DTR resets a Mega). Registered with pyserial by
importing :mod:`minseg_tui.device`.
"""

from __future__ import annotations

import time
import urllib.parse
from collections.abc import Callable
from typing import TYPE_CHECKING

from serial.serialutil import PortNotOpenError, SerialBase, SerialException

from minseg_tui.device.virtual import RealTime, VirtualBoard, named_board, settings_from

if TYPE_CHECKING:
    from typing_extensions import Buffer

CLOCKS = ("real", "virtual")


def parse_url(url: str) -> tuple[str, str, dict[str, str]]:
    """(name, clock, options) of a minseg:// URL; raises ValueError on a bad one."""
    parts = urllib.parse.urlsplit(url)
    if parts.scheme.lower() != "minseg":
        raise ValueError(f"not a minseg:// URL: {url!r}")
    opts = dict(urllib.parse.parse_qsl(parts.query, keep_blank_values=True))
    clock = opts.pop("clock", "real")
    if clock not in CLOCKS:
        raise ValueError(f"clock must be real or virtual, got {clock!r}")
    return parts.netloc + parts.path, clock, opts


class Serial(SerialBase):
    """A pyserial port whose other end is a :class:`VirtualBoard`."""

    board: VirtualBoard
    board_clock: Callable[[], float] | None
    _clock: RealTime | None = None  # the board's real-time clock; None: virtual time

    def open(self) -> None:
        """Open (and reset) the board named by the URL."""
        if self.is_open:
            raise SerialException("Port is already open.")
        if self.port is None:
            raise SerialException("Port must be configured before it can be used.")
        try:
            name, clock, opts = parse_url(self.port)
            settings = settings_from(opts)
        except ValueError as exc:
            raise SerialException(f"could not open port {self.port}: {exc}") from None
        board = named_board(name, settings) if name else VirtualBoard(settings)
        with board.lock:
            if not board.plugged:
                raise SerialException(
                    f"could not open port {self.port}: [Errno 2] No such file or directory"
                )
            if board.attached:
                raise SerialException(
                    f"Could not exclusively lock port {self.port}: "
                    "[Errno 11] Resource temporarily unavailable"
                )
            board.attached = True
            self._virtual = clock == "virtual"
            if self._virtual:
                board.clock = None
                self._clock = None
            else:
                if not isinstance(board.clock, RealTime):
                    board.clock = RealTime(board.now)
                self._clock = board.clock
                board.run_until(self._clock())
            board.reset()
        self.board = board
        self.board_clock = (lambda: board.now) if self._virtual else None
        self.is_open = True

    def close(self) -> None:
        """Release the board (it keeps running: the wheel does not stop with the port)."""
        if self.is_open:
            self.is_open = False
            with self.board.lock:
                self.board.attached = False
                self.board.changed.notify_all()

    # settings do not matter to a virtual board
    def _reconfigure_port(self, *args: object, **kwargs: object) -> None:
        return None

    def _update_dtr_state(self) -> None:
        return None

    def _update_rts_state(self) -> None:
        return None

    def _update_break_state(self) -> None:
        return None

    def _check(self) -> None:
        if not self.is_open:
            raise PortNotOpenError()
        if not self.board.plugged:
            raise SerialException("read failed: [Errno 5] Input/output error")

    def _sync(self) -> None:
        if self._clock is not None:
            self.board.run_until(self._clock())

    @property
    def in_waiting(self) -> int:
        """Bytes the board has sent and the host has not read."""
        self._check()
        self._sync()
        return self.board.pending_output

    def read(self, size: int = 1) -> bytes:
        """Read up to ``size`` bytes, waiting at most the timeout (board time when virtual)."""
        self._check()
        board = self.board
        timeout = 1.0 if self.timeout is None else float(self.timeout)
        out = bytearray()
        with board.lock:
            if self._virtual:
                end = board.now + timeout
                while True:
                    out += board.take_output(size - len(out))
                    if len(out) >= size or board.now >= end or not board.plugged:
                        break
                    board.run_until(end, stop_on_output=True)
            else:
                clock = self._clock
                assert clock is not None  # a real-time port has its clock
                end = time.monotonic() + timeout
                while True:
                    board.run_until(clock())
                    out += board.take_output(size - len(out))
                    left = end - time.monotonic()
                    if len(out) >= size or left <= 0 or not board.plugged or not self.is_open:
                        break
                    wait = min(left, board.next_event() - clock())
                    board.changed.wait(max(wait, 0.0))
        if not out:
            self._check()
        return bytes(out)

    def write(self, b: Buffer, /) -> int:
        """Send bytes to the board, received at board time now."""
        data = bytes(b)
        self._check()
        self._sync()
        self.board.feed(data)
        return len(data)

    def reset_input_buffer(self) -> None:
        """Discard what the board has sent."""
        self._check()
        self._sync()
        self.board.take_output()

    def reset_output_buffer(self) -> None:
        """Nothing is buffered towards the board."""
        self._check()

    def cancel_read(self) -> None:
        """Wake a waiting read."""
        with self.board.lock:
            self.board.changed.notify_all()

    @property
    def out_waiting(self) -> int:
        """Nothing waits to be sent."""
        return 0

    @property
    def cts(self) -> bool:
        """Always true."""
        return True

    @property
    def dsr(self) -> bool:
        """Always true."""
        return True

    @property
    def ri(self) -> bool:
        """Always false."""
        return False

    @property
    def cd(self) -> bool:
        """Always true."""
        return True
