"""The link to a MinSeg (real or virtual) over pyserial: handshake, reader, commands, reconnect.

One :class:`Link` per board. A reader thread owns the port; the caller never blocks on
it except in :meth:`Link.command`, which waits (with a timeout) for the board's reply.

- Samples reach the caller in batches: :meth:`Link.samples` takes everything pending at
  once as a :class:`~minseg_tui.device.samples.SampleBatch` (numpy arrays). The buffer is
  bounded (``capacity``); if nobody takes samples for that long the oldest go and
  ``stats.overflow`` counts them.
- A corrupt line (bad checksum or format, or a sample whose seq, time or count no real
  gap explains: :mod:`minseg_tui.device.timebase`) is counted in ``stats.corrupt`` and
  dropped; so is an old sample line sent again (a USB hub or bridge replaying a block:
  seq goes back with no restart), counted in ``stats.replayed`` too; a gap in ``seq`` is
  counted in ``stats.dropped``. None of them ever becomes a sample.
- ``seq`` and ``t_us`` are unwrapped (uint32 on the wire, int64 here). Each connection
  (the board resets when the port opens) is an *epoch*: across epochs seq continues at
  +1 and t_us continues by the host's estimate of the gap (the one place the host clock
  enters the time base); the encoder count restarts at 0 with the board.
- Events (:class:`LinkEvent`) say what happened: connected, disconnected, silent, alive,
  watchdog, edge, square_wave_done, boot, error. Take them with :meth:`Link.events`, or pass
  ``on_event`` to hear them at once (called from the reader thread: keep it short).
- A pulled cable (OSError/SerialException) gives a ``disconnected`` event at once; the
  samples already received stay; the link reopens the same path (or the same USB
  VID:PID elsewhere) by itself, re-handshakes, sends STOP, restores the sample period,
  supply and zero mode and says ``connected``. The motor voltage is never restored (the
  safe default is motor off): :attr:`Link.u_req` becomes 0 and, if the motor was on, a
  ``motor`` event says so in one line, for the status line. A ``$BOOT`` mid-stream (the
  board restarted by itself) does the same once the samples after it start a new time
  base (an old ``$BOOT`` sent again is counted as replayed, and changes nothing); so does a
  restart whose ``$BOOT`` was lost.
- One program per board (:mod:`minseg_tui.device.port`): a second minseg-tui gets
  "in use by minseg-tui (pid N)", a plain serial monitor cannot open the port.
- Keep-alive: a PING every ``keepalive_s`` (0.25 s), so the board's 1 s watchdog stays
  quiet while the host lives.
"""

from __future__ import annotations

import contextlib
import dataclasses
import re
import threading
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from serial.serialutil import SerialException

from minseg_tui.device import discovery
from minseg_tui.device import port as port_io
from minseg_tui.device import protocol as P
from minseg_tui.device.samples import SampleBatch
from minseg_tui.device.timebase import Timeline
from minseg_tui.errors import DeviceError, InputError
from minseg_tui.model.plant import MeterReading

EVENT_KINDS = (
    "connected",
    "disconnected",
    "silent",
    "alive",
    "watchdog",
    "edge",
    "square_wave_done",
    "boot",
    "error",
    "motor",
)
FLASH_HINT = (
    "flash the firmware shipped with this minseg-tui: minseg-tui flash "
    "(from the sources: make -C firmware upload)"
)


def flash_hint(port: str) -> str:
    """FLASH_HINT with the port filled in (a device path; a URL has nothing to flash)."""
    if "://" in port:
        return FLASH_HINT
    return (
        f"flash the firmware shipped with this minseg-tui: minseg-tui flash --port {port} "
        f"(from the sources: make -C firmware upload PORT={port})"
    )


@dataclass(frozen=True)
class LinkEvent:
    """Something the session should hear about. kind: one of EVENT_KINDS; t_host: s
    (monotonic); silent_s: for ``alive``, how long the board had not answered (s, host
    clock), so that the answer can say the silence it ends (None for the other kinds)."""

    kind: str
    message: str
    t_host: float
    silent_s: float | None = None


@dataclass
class LinkStats:
    """Counters since open: samples kept, dropped (seq gaps), corrupt lines (every line
    refused: bad checksum or format, impossible samples, old lines sent again), replayed
    (of those, the old sample lines sent again), overflow (samples pushed out of a full
    buffer), reconnects, lines received."""

    samples: int = 0
    dropped: int = 0
    corrupt: int = 0
    replayed: int = 0
    overflow: int = 0
    reconnects: int = 0
    lines: int = 0


@dataclass
class _Waiter:
    name: str
    done: threading.Event = field(default_factory=threading.Event)
    reply: P.Message | None = None


REPLY_GUARD = 30.0
"""The longest a command waits for its reply however busy the host, s (real time)."""


def _proto_of(line: str) -> tuple[str, int] | None:
    """(fw, proto) from a $BOOT or $ID line even if the rest does not parse (other versions)."""
    m = re.match(r"\$(?:BOOT|ID),([^,*]*),(-?\d+)", line)
    return (m.group(1), int(m.group(2))) if m else None


class Link:
    """A MinSeg behind a serial port (a device path or a pyserial URL such as minseg://)."""

    def __init__(
        self,
        port: str,
        *,
        baud: int = P.BAUD,
        on_event: Callable[[LinkEvent], None] | None = None,
        keepalive_s: float = 0.25,
        reply_timeout_s: float = 1.0,
        boot_wait_s: float = 2.5,
        silence_s: float = 0.75,
        reconnect: bool = True,
        retry_s: float = 0.25,
        capacity: int = 2_000_000,
        vid_pid: tuple[int, int] | None = None,
        program: str = "minseg-tui",
        board: Any = None,
    ) -> None:
        self.port = port
        self.baud = baud
        self.on_event = on_event
        self.keepalive_s = keepalive_s
        self.reply_timeout_s = reply_timeout_s
        self.boot_wait_s = boot_wait_s
        self.silence_s = silence_s
        self.reconnect = reconnect
        self.retry_s = retry_s
        self.vid_pid = vid_pid
        self.program = program
        self.board = board  # the VirtualBoard behind a minseg:// URL (for the multimeter), or None
        self.ident: P.Ident | None = None
        self.stats = LinkStats()
        self._ser: Any = None
        self._opened: dict[Any, port_io.OpenPort] = {}  # each open port and its lock file
        self._port_lock = threading.Lock()
        self._lock = threading.Lock()
        self._rows: deque[tuple[int, int, int, int, int, float]] = deque(maxlen=capacity)
        self._events: deque[LinkEvent] = deque(maxlen=10000)
        self._waiters: deque[_Waiter] = deque()
        self._restore: dict[str, str] = {}
        self._u_req: float | None = 0.0  # V as the host knows it; None: a square wave runs
        self._square_wave_low = 0.0  # V, where a square wave ends
        self._closing = threading.Event()
        self._thread: threading.Thread | None = None
        self._clock: Callable[[], float] = time.monotonic
        self._timeline = Timeline()
        self._epoch_said = -1  # the last epoch the link has said (connected, boot)
        self._boot_fw: str | None = None  # the fw of a $BOOT not yet confirmed
        self._bad_lines = 0  # lines that failed the checksum or the format
        self._last_rx = 0.0
        self._last_tx = 0.0
        self._silent = False
        self._gave_up = False
        self._heard = 0  # bytes received during the last handshake
        self._pass_begun = 0.0  # monotonic s: when the reader's last complete pass began

    # -- opening and closing -------------------------------------------------------------
    def open(self) -> P.Ident:
        """Open the port, handshake (raises DeviceError) and start the reader."""
        ser = self._open_port(self.port)
        try:
            self.ident = self._handshake(ser)
        except BaseException:
            self._close_port(ser)
            raise
        self._ser = ser
        self._new_epoch()
        self._emit(
            "connected",
            f"{self.port}: {self.ident.board} {self.ident.fw}, protocol {self.ident.proto}",
        )
        self._thread = threading.Thread(
            target=self._run, name=f"minseg-link {self.port}", daemon=True
        )
        self._thread.start()
        return self.ident

    def close(self) -> None:
        """Stop the motor if possible, stop the reader, release the port and its lock."""
        if self._closing.is_set():
            return
        with contextlib.suppress(Exception):
            if self._ser is not None:
                self._write(P.encode(P.Stop()))
        self._closing.set()
        if self._thread is not None:
            self._thread.join(2.0)
        with self._port_lock:
            ser, self._ser = self._ser, None
        if ser is not None:
            self._close_port(ser)
        self._fail_waiters()

    def __enter__(self) -> Link:
        if self._thread is None:
            self.open()
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def connected(self) -> bool:
        """True while the port is open and the board answered the handshake."""
        return self._ser is not None

    def _open_port(self, port: str) -> Any:
        """Open the port for this program only (:mod:`minseg_tui.device.port`)."""
        opened = port_io.open_exclusive(port, self.baud, self.program)
        ser = opened.ser
        self._opened[ser] = opened
        clock = getattr(ser, "board_clock", None)
        self._clock = clock if callable(clock) else time.monotonic
        if self.board is None and hasattr(ser, "board"):
            self.board = ser.board
        return ser

    def _close_port(self, ser: Any) -> None:
        opened = self._opened.pop(ser, None)
        if opened is not None:
            port_io.close(opened)
        else:
            with contextlib.suppress(Exception):
                ser.close()

    # -- the handshake --------------------------------------------------------------------
    def _read_lines(self, ser: Any, until: float, want: Callable[[str], bool]) -> str | None:
        """Read lines until one satisfies ``want`` (returned) or the clock passes ``until``."""
        buf = b""
        while self._clock() < until:
            data: bytes = ser.read(max(1, ser.in_waiting))
            self._heard += len(data)
            buf += data
            *lines, buf = buf.split(b"\n")
            for raw in lines:
                line: str = raw.decode("ascii", "replace").rstrip("\r")
                if want(line):
                    return line
        return None

    def _check_version(self, line: str) -> None:
        got = _proto_of(line)
        if got is not None and got[1] != P.PROTOCOL_VERSION:
            fw, proto = got
            newer = " or update minseg-tui" if proto > P.PROTOCOL_VERSION else ""
            raise DeviceError(
                f"{self.port}: the board's firmware ({fw}) speaks protocol {proto}, this "
                f"minseg-tui speaks protocol {P.PROTOCOL_VERSION}: {flash_hint(self.port)}{newer}"
            )

    def _handshake(self, ser: Any) -> P.Ident:
        """Wait for $BOOT (or any valid line from a running board), then ID and check it."""
        self._heard = 0  # bytes received during this handshake

        def first(line: str) -> bool:
            if line.startswith(("$BOOT,", "$ID,")):
                self._check_version(line)
            try:
                P.parse(line)
            except P.ProtocolError:
                return False
            return True

        self._read_lines(ser, self._clock() + self.boot_wait_s, first)
        for _attempt in range(5):
            ser.write(P.IDENTIFY_ANY_VERSION)
            self._last_tx = self._clock()
            got = self._read_lines(
                ser, self._clock() + self.reply_timeout_s, lambda s: s.startswith("$ID,")
            )
            if got is None:
                continue
            self._check_version(got)
            try:
                ident = P.parse(got)
            except P.ProtocolError:
                continue
            assert isinstance(ident, P.Ident)
            self._last_rx = self._clock()
            return ident
        if self._heard:  # bytes came, none of them a line of ours: another program runs there
            raise DeviceError(
                f"{self.port}: this board does not run the lab firmware (it sends data, but no "
                f"line minseg-tui can read: still Simulink's program?): {flash_hint(self.port)}"
            )
        raise DeviceError(
            f"no MinSeg answered on {self.port} (nothing came back to ID): is it the right port? "
            f"A board still running Simulink's program may be silent too: {flash_hint(self.port)}"
        )

    # -- commands -------------------------------------------------------------------------
    def command(self, cmd: P.Message | str, timeout: float | None = None) -> P.Message:
        """Send a command and return the board's reply ($OK, $ERR, $ID, $DIAG or $METER).

        ``cmd`` is a protocol message or a line as a student would type it ("V,2500").
        Raises DeviceError when not connected or no reply came within the timeout, and
        InputError for a line that is not a command.
        """
        if isinstance(cmd, str):
            try:
                cmd = P.parse_command(cmd)
            except P.ProtocolError as exc:
                raise InputError(
                    "command", None, f"not a MinSeg command: {cmd!r} ({exc})"
                ) from None
        line = P.encode(cmd)
        name = line[1:].split(b"*")[0].split(b",")[0].decode()
        waiter = _Waiter("ID" if name == "ID" else name)
        with self._lock:
            self._waiters.append(waiter)
        try:
            self._write(line)
        except (SerialException, OSError, DeviceError) as exc:
            self._drop_waiter(waiter)
            raise DeviceError(f"{self.port}: cannot send {name}: {exc}") from None
        if name in ("P", "SUP", "ZM", "STREAM"):
            self._restore[name] = line.decode().strip()
        if not self._await_reply(waiter, self.reply_timeout_s if timeout is None else timeout):
            self._drop_waiter(waiter)
            raise DeviceError(f"{self.port}: no reply to {name} from the board")
        if waiter.reply is None:
            raise DeviceError(f"{self.port}: the board was disconnected before it answered {name}")
        return waiter.reply

    def _await_reply(self, waiter: _Waiter, limit: float) -> bool:
        """Wait for ``waiter``'s reply (true once it came). The reply is missing once the
        reader has read and handled the port in a pass begun ``limit`` s (real time) after
        the command went out: a host too busy to run the reader (a loaded machine) delays
        that pass, so a reply already on its way is never taken for a missing one, while a
        silent board is found out after ``limit`` s as before. :data:`REPLY_GUARD` caps the
        wait (a reader that no longer runs)."""
        sent = time.monotonic()
        if waiter.done.wait(limit):
            return True
        while self._pass_begun <= sent + limit:
            if time.monotonic() - sent > REPLY_GUARD:
                return waiter.done.is_set()
            if waiter.done.wait(0.02):
                return True
        return waiter.done.is_set()

    def _note_motor(self, ok: P.Ok) -> None:
        """Follow the requested voltage through the board's replies (V, STEP, STOP), in the
        reader thread, so a watchdog or restart that comes after a reply wins."""
        if ok.command == "V" and ok.values:
            self._u_req = int(ok.values[0]) / 1000.0
        elif ok.command == "STEP" and ok.values:
            self._u_req, self._square_wave_low = None, int(ok.values[0]) / 1000.0
        elif ok.command == "STOP":
            self._u_req = 0.0
        elif ok.command == "Z":
            self._timeline.count_zeroed()
        elif ok.command == "DIR" and len(ok.values) == 2 and self.ident is not None:
            self.ident = dataclasses.replace(
                self.ident, enc_dir=ok.values[0], motor_dir=ok.values[1]
            )

    @property
    def u_req(self) -> float | None:
        """The voltage (V) the motor is requested at, as far as the link knows: what the last
        V asked for, 0 after STOP, the board's watchdog or a restart (a reconnect restores
        no voltage), None while a board-timed square wave runs."""
        return self._u_req

    def _motor_off(self, why: str) -> None:
        """The board restarted (``why``: what happened, said first): its motor is off. Say so
        if it was not."""
        was, self._u_req = self._u_req, 0.0
        if was == 0.0:
            return
        before = "running a square wave" if was is None else f"at {was:g} V"
        self._emit(
            "motor",
            f"{why}: the motor is off (it was {before}); nothing is restored, "
            "set the voltage again",
        )

    def _drop_waiter(self, waiter: _Waiter) -> None:
        with self._lock, contextlib.suppress(ValueError):
            self._waiters.remove(waiter)

    def _write(self, data: bytes) -> None:
        with self._port_lock:
            ser = self._ser
            if ser is None:
                raise DeviceError(f"{self.port} is disconnected")
            ser.write(data)
            self._last_tx = self._clock()

    def _ok(self, cmd: P.Message) -> P.Ok:
        reply = self.command(cmd)
        if isinstance(reply, P.Err):
            raise DeviceError(
                f"{self.port}: the board refused it: {reply.code} {reply.detail}".rstrip()
            )
        assert isinstance(reply, P.Ok)
        return reply

    def set_voltage(self, u: float) -> float:
        """Request u (V) from the next sample on; returns the voltage applied (clamped), V."""
        return int(self._ok(P.SetVoltage(round(u * 1000))).values[0]) / 1000.0

    def square_wave(self, low: float, high: float, half_period: float, periods: int) -> P.Ok:
        """Board-timed square wave: levels in V, half period in s, number of periods."""
        return self._ok(
            P.SquareWave(round(low * 1000), round(high * 1000), round(half_period * 1000), periods)
        )

    def stop(self) -> P.Ok:
        """Zero command, abort a square wave."""
        return self._ok(P.Stop())

    def set_period(self, ts: float) -> float:
        """Sample period ts (s); returns the period the board applied, s."""
        return int(self._ok(P.SetPeriod(round(ts * 1e6))).values[0]) / 1e6

    def zero(self) -> P.Ok:
        """Zero the encoder count."""
        return self._ok(P.Zero())

    def set_direction(self, enc: str, motor: str) -> P.Ok:
        """The encoder's counting direction and the motor's polarity, "FWD" or "REV" each;
        the board keeps them (EEPROM) and :attr:`ident` follows."""
        return self._ok(P.SetDirection(enc.upper(), motor.upper()))

    def diag(self) -> P.Diag:
        """The board's $DIAG: encoder pin levels and edges per connector, the one in use."""
        reply = self.command(P.ReadDiag())
        if not isinstance(reply, P.Diag):
            what = f"{reply.code} {reply.detail}".rstrip() if isinstance(reply, P.Err) else reply
            raise DeviceError(f"{self.port}: the board did not answer DIAG ({what})")
        return reply

    def meter(self) -> MeterReading | None:
        """The multimeter on M1A/M1B (virtual board only): u_A (V), i (A), R (ohm); else None."""
        reply = self.command(P.ReadMeter())
        if not isinstance(reply, P.Meter):
            return None
        return MeterReading(u_A=reply.u_mV / 1000.0, i=reply.i_uA / 1e6, R=reply.R_mohm / 1000.0)

    # -- what the caller takes -----------------------------------------------------------
    def samples(self) -> SampleBatch:
        """Every sample received since the last call, as one batch (maybe empty)."""
        with self._lock:
            rows, self._rows = list(self._rows), deque(maxlen=self._rows.maxlen)
        return SampleBatch.from_rows(rows)

    def events(self) -> list[LinkEvent]:
        """Every event since the last call, oldest first."""
        with self._lock:
            out = list(self._events)
            self._events.clear()
        return out

    def _emit(self, kind: str, message: str, silent_s: float | None = None) -> None:
        ev = LinkEvent(kind, message, time.monotonic(), silent_s)
        with self._lock:
            self._events.append(ev)
        if self.on_event is not None:
            self.on_event(ev)

    # -- the reader ----------------------------------------------------------------------
    def _run(self) -> None:
        buf = bytearray()
        skipping = False
        while not self._closing.is_set():
            ser = self._ser
            if ser is None:
                if self.reconnect and not self._gave_up:
                    self._try_reconnect()
                else:
                    time.sleep(self.retry_s)
                buf.clear()
                skipping = False
                continue
            begun = time.monotonic()
            try:
                data = ser.read(max(1, ser.in_waiting))
                now = self._clock()
                if now - self._last_tx >= self.keepalive_s:
                    self._write(P.encode(P.Ping()))
            except (SerialException, OSError, DeviceError) as exc:
                self._lost(exc)
                continue
            if data:
                buf += data
                while True:
                    nl = buf.find(b"\n")
                    if nl < 0:
                        break
                    line = bytes(buf[:nl])
                    del buf[: nl + 1]
                    if skipping:  # the tail of an over-long line
                        skipping = False
                        continue
                    self._on_line(line)
                if len(buf) > P.MAX_LINE + 1:
                    self._bad_lines += 1
                    self.stats.corrupt += 1
                    buf.clear()
                    skipping = True
            self._pass_begun = begun  # every reply read in this pass has been handed over
            if now - self._last_rx > self.silence_s and not self._silent:
                self._silent = True
                self._emit(
                    "silent", f"{self.port}: the board has not answered for {self.silence_s:g} s"
                )
        # closed: a port still here (close() gave up waiting for this thread) goes back now
        with self._port_lock:
            ser, self._ser = self._ser, None
        if ser is not None:
            self._close_port(ser)

    def _on_line(self, raw: bytes) -> None:
        self.stats.lines += 1
        try:
            msg = P.parse(raw)
        except P.ProtocolError:
            if raw.strip(b"\r"):
                self._bad_lines += 1
                self.stats.corrupt += 1
            return
        before, self._last_rx = self._last_rx, self._clock()
        if self._silent:
            self._silent = False
            gap = self._last_rx - before
            self._emit(
                "alive", f"{self.port}: the board answers again after {gap:.1f} s", silent_s=gap
            )
        if isinstance(msg, P.SampleLine):
            self._on_sample(msg)
        elif isinstance(msg, P.Ok | P.Err | P.Ident | P.Meter | P.Diag):
            self._on_reply(msg)
        elif isinstance(msg, P.EvWatchdog):
            self._u_req = 0.0
            self._emit("watchdog", "the board's watchdog stopped the motor (host silent > 1 s)")
        elif isinstance(msg, P.EvSquareWaveEdge):
            self._emit("edge", f"square wave edge {msg.k} of {msg.n}")
        elif isinstance(msg, P.EvSquareWaveDone):
            self._u_req = self._square_wave_low
            self._emit("square_wave_done", "square wave done")
        elif isinstance(msg, P.Boot):  # said once the samples show it (timebase.boot)
            self._boot_fw = msg.fw
            self._timeline.boot()
            self._said_restart()

    def _on_reply(self, msg: P.Message) -> None:
        if isinstance(msg, P.Ok):
            self._note_motor(msg)  # here, in order with the board's events
            name = msg.command
        elif isinstance(msg, P.Ident):
            name = "ID"
        elif isinstance(msg, P.Meter):
            name = "METER"
        elif isinstance(msg, P.Diag):
            name = "DIAG"
        else:
            assert isinstance(msg, P.Err)
            name = msg.detail
        with self._lock:
            target = next((w for w in self._waiters if w.name == name), None)
            if target is None and isinstance(msg, P.Err) and self._waiters:
                target = self._waiters[0]
            if target is not None:
                self._waiters.remove(target)
        if target is not None:
            target.reply = msg
            target.done.set()

    def _new_epoch(self) -> None:
        """A new connection: a new epoch, said by the caller (connected)."""
        if self.ident is not None and self.ident.cpr > 0:
            self._timeline.cpr = self.ident.cpr
        self._timeline.new_epoch()
        self._epoch_said = self._timeline.epoch
        self._boot_fw = None

    def _said_restart(self) -> None:
        """Say a restart the timeline has taken (a $BOOT confirmed, or one whose $BOOT was
        lost): the motor is off."""
        tl = self._timeline
        if tl.epoch == self._epoch_said:
            return
        self._epoch_said = tl.epoch
        fw, self._boot_fw = self._boot_fw, None
        what = f"({fw})" if fw is not None else "(its $BOOT line was lost)"
        self._emit("boot", f"{self.port}: the board restarted {what}")
        self._motor_off(f"{self.port}: the board restarted")

    def _on_sample(self, s: P.SampleLine) -> None:
        tl = self._timeline
        rows = tl.place(s, self._clock(), time.monotonic())
        self._said_restart()
        if not tl.boot_pending:
            self._boot_fw = None
        self.stats.dropped = tl.dropped
        replayed = tl.replayed + tl.repeated + tl.false_boots
        self.stats.replayed = replayed
        self.stats.corrupt = self._bad_lines + tl.refused + replayed
        if not rows:
            return
        with self._lock:
            for row in rows:
                if len(self._rows) == self._rows.maxlen:
                    self.stats.overflow += 1
                self._rows.append(row)
        self.stats.samples += len(rows)

    # -- losing and finding the board -----------------------------------------------------
    def _fail_waiters(self) -> None:
        with self._lock:
            waiters, self._waiters = list(self._waiters), deque()
        for w in waiters:
            w.done.set()

    def _lost(self, exc: BaseException) -> None:
        with self._port_lock:
            ser, self._ser = self._ser, None
        if ser is not None:
            self._close_port(ser)
        self._fail_waiters()
        self._emit(
            "disconnected",
            f"{self.port}: connection lost ({exc}); everything recorded so far is kept; "
            "waiting for the board to come back",
        )

    def _try_reconnect(self) -> None:
        time.sleep(self.retry_s)
        paths = [self.port]
        if self.vid_pid is not None:
            found = discovery.find_board(vid_pid=self.vid_pid)
            if found is not None and found.device != self.port:
                paths.append(found.device)
        mismatch: DeviceError | None = None
        for path in paths:
            try:
                ser = self._open_port(path)
            except DeviceError:
                continue
            try:
                ident = self._handshake(ser)
            except DeviceError as exc:  # not our board there (yet): try the next path
                self._close_port(ser)
                if "protocol" in str(exc):
                    mismatch = exc
                continue
            except (SerialException, OSError):
                self._close_port(ser)
                continue
            self.port = path
            self.ident = ident
            self._new_epoch()
            with self._port_lock:  # atomic with close()'s taking of the port
                closed = self._closing.is_set()
                if not closed:
                    self._ser = ser
            if closed:  # the program closed the link meanwhile: give the port back
                self._close_port(ser)
                return
            # motor off whatever the board did meanwhile; then period, supply, zero mode, stream
            for line in (P.encode(P.Stop()).decode().strip(), *self._restore.values()):
                with contextlib.suppress(SerialException, OSError, DeviceError):
                    self._write((line + "\n").encode())
            self.stats.reconnects += 1
            self._silent = False
            self._emit("connected", f"{path}: reconnected to {ident.board} {ident.fw}")
            self._motor_off(f"{path}: reconnected")
            return
        if mismatch is not None:  # only a board with another protocol answered: say so, stop
            self._gave_up = True
            self._emit("error", str(mismatch))
