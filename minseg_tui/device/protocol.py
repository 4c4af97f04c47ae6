"""Protocol 3 of the MinSeg serial link (firmware/PROTOCOL.md): pure parse and format.

Every line, in both directions, is a small frozen dataclass. The lines are data: the
table ``LINES`` names each kind (its NAME, for ``$EV`` its event tag, its direction and
its typed fields); one generic parser and one generic formatter serve them all.

Units as on the wire: voltages in mV, times in us or ms as the field names say,
currents in uA, resistances in milliohm.
"""

from __future__ import annotations

import binascii
import re
from collections.abc import Callable
from dataclasses import dataclass, fields
from typing import Literal

PROTOCOL_VERSION = 3
"""The protocol version this host speaks (the `proto` field of $BOOT and $ID).

Version 2 replaced version 1's one-byte XOR with a CRC-16 (four hex digits); version 3
added DIR (the counting direction and motor polarity at run time, reported by $ID) and
DIAG (the encoder pins and edges per connector)."""

CHECKSUM_DIGITS = 4
"""Hex digits of the checksum field (`*HHHH`)."""

IDENTIFY_ANY_VERSION = b"ID\n"
"""The ID command as every protocol version reads it (a command may omit its checksum, and
version 1 refused a four-digit one): the handshake sends it so that a board with older
firmware answers with its version instead of a checksum error."""

BAUD = 500000
"""Line rate of the link, baud (8N1)."""

MAX_LINE = 80
"""Longest line in bytes (without the newline); longer lines are discarded whole."""

ERR_CODES = ("CHECKSUM", "UNKNOWN", "ARGS", "RANGE", "BUSY")
ZERO_MODES = ("BRAKE", "COAST")
DIRECTIONS = ("FWD", "REV")
"""The two settings of DIR and of the direction fields of $ID."""

Direction = Literal["board", "host"]


class ProtocolError(ValueError):
    """A line that is not a valid line of this protocol version.

    ``code`` is the $ERR code a board answers with (CHECKSUM, UNKNOWN, ARGS, RANGE);
    ``detail`` names the command when known.
    """

    def __init__(self, code: str, detail: str = "", why: str = "") -> None:
        super().__init__(f"{code}{',' + detail if detail else ''}{': ' + why if why else ''}")
        self.code = code
        self.detail = detail
        self.why = why


# -- field types: (parse, format) -------------------------------------------------------
_INT = re.compile(r"-?[0-9]+\Z")
_NAME = re.compile(r"[A-Z]{1,16}\Z")
_TEXT = re.compile(r"[ -~]*\Z")
_HEX_DIGITS = frozenset(b"0123456789ABCDEFabcdef")

MAX_COMMAND_NAME = 11
"""Longest command name the board reads; a longer one is not a name (UNKNOWN, no detail)."""


def _int_in(lo: int, hi: int) -> Callable[[str], int]:
    def parse(s: str) -> int:
        if not _INT.match(s):
            raise ProtocolError("ARGS", why=f"not an integer: {s!r}")
        if len(s.lstrip("-").lstrip("0")) > 10:  # beyond 32 bits, however many digits
            raise ProtocolError("RANGE", why=f"{s} outside {lo}..{hi}")
        v = int(s)
        if not lo <= v <= hi:
            raise ProtocolError("RANGE", why=f"{v} outside {lo}..{hi}")
        return v

    return parse


def _choice(options: tuple[str, ...]) -> Callable[[str], str]:
    def parse(s: str) -> str:
        if s not in options:
            raise ProtocolError("ARGS", why=f"expected one of {'/'.join(options)}, got {s!r}")
        return s

    return parse


def _text(s: str) -> str:
    if not _TEXT.match(s):
        raise ProtocolError("ARGS", why=f"not printable text: {s!r}")
    return s


def _bit(s: str) -> bool:
    if s not in ("0", "1"):
        raise ProtocolError("ARGS", why=f"expected 0 or 1, got {s!r}")
    return s == "1"


def _name(s: str) -> str:
    if not _NAME.match(s):
        raise ProtocolError("ARGS", why=f"not a command name: {s!r}")
    return s


def _fmt_bit(v: object) -> str:
    return "1" if v else "0"


@dataclass(frozen=True)
class ConnectorState:
    """One connector in a $DIAG reply: its name (``M1``), the levels of its encoder pins A
    and B now (``"11"``: both high, as an unplugged encoder reads with the pull-ups) and the
    edges its encoder counted since reset (every edge, whatever its direction)."""

    name: str
    pins: str
    edges: int


_CONNECTOR = re.compile(r"([A-Z][A-Z0-9]{0,7}):([01]{2}):([0-9]{1,10})\Z")


def _connector(s: str) -> ConnectorState:
    m = _CONNECTOR.match(s)
    if not m:
        raise ProtocolError("ARGS", why=f"expected <connector>:<AB>:<edges>, got {s!r}")
    edges = int(m.group(3))
    if edges > 2**32 - 1:
        raise ProtocolError("RANGE", why=f"{edges} edges outside uint32")
    return ConnectorState(m.group(1), m.group(2), edges)


def _fmt_connector(v: object) -> str:
    assert isinstance(v, ConnectorState)
    return f"{v.name}:{v.pins}:{v.edges}"


_I32 = (-(2**31), 2**31 - 1)
FIELD_TYPES: dict[str, tuple[Callable[[str], object], Callable[[object], str]]] = {
    "int": (_int_in(*_I32), str),
    "u32": (_int_in(0, 2**32 - 1), str),
    "i32": (_int_in(*_I32), str),
    "text": (_text, str),
    "name": (_name, str),
    "zero": (_choice(ZERO_MODES), str),
    "err": (_choice(ERR_CODES), str),
    "bit": (_bit, _fmt_bit),
    "dir": (_choice(DIRECTIONS), str),
    "conn": (_connector, _fmt_connector),
}


# -- the lines --------------------------------------------------------------------------
@dataclass(frozen=True)
class Boot:
    """$BOOT: printed once after reset."""

    fw: str
    proto: int


@dataclass(frozen=True)
class Ident:
    """$ID: reply to ID. period_us in us, vsupply_mV in mV, zero BRAKE or COAST; enc_dir
    and motor_dir FWD or REV (the encoder's counting direction and the motor's polarity,
    as DIR set them)."""

    fw: str
    proto: int
    board: str
    cpr: int
    period_us: int
    vsupply_mV: int
    zero: str
    enc_dir: str = "FWD"
    motor_dir: str = "FWD"


@dataclass(frozen=True)
class Diag:
    """$DIAG: reply to DIAG. drive: the connectors the motor command drives (``M1+M2``);
    active: the connector whose encoder the count follows (``NONE`` until one counted 4
    edges since reset); connectors: each connector's encoder pins and edges."""

    drive: str
    active: str
    connectors: tuple[ConnectorState, ...] = ()

    def connector(self, name: str) -> ConnectorState | None:
        """The state of the connector called ``name``, or None."""
        return next((c for c in self.connectors if c.name == name), None)


@dataclass(frozen=True)
class SampleLine:
    """$S: one sample. seq and t_us wrap as uint32; count int32; u_mV in force from now on."""

    seq: int
    t_us: int
    count: int
    u_mV: int


@dataclass(frozen=True)
class Ok:
    """$OK: a command was accepted; values are the applied ones, as text."""

    command: str
    values: tuple[str, ...] = ()


@dataclass(frozen=True)
class Err:
    """$ERR: a command was refused; nothing changed."""

    code: str
    detail: str = ""


@dataclass(frozen=True)
class EvWatchdog:
    """$EV,WDOG: the host was silent for more than 1000 ms; the motor was stopped."""


@dataclass(frozen=True)
class EvSquareWaveEdge:
    """$EV,STEP: a square wave reached edge k of n."""

    k: int
    n: int


@dataclass(frozen=True)
class EvSquareWaveDone:
    """$EV,STEPDONE: the square wave finished; the motor is at the low level."""


@dataclass(frozen=True)
class Meter:
    """$METER (virtual board only): u_A in mV, i in uA, R in milliohm, as a multimeter reads."""

    u_mV: int
    i_uA: int
    R_mohm: int


# host commands
@dataclass(frozen=True)
class Identify:
    """ID: ask for $ID."""


@dataclass(frozen=True)
class Ping:
    """PING: keep-alive."""


@dataclass(frozen=True)
class SetVoltage:
    """V: requested voltage in mV (aborts a square wave)."""

    mV: int


@dataclass(frozen=True)
class SquareWave:
    """STEP (the host command): board-timed square wave, levels in mV, half period in ms, n periods."""

    low_mV: int
    high_mV: int
    half_ms: int
    n: int


@dataclass(frozen=True)
class Stop:
    """STOP: zero command, abort the square wave."""


@dataclass(frozen=True)
class SetPeriod:
    """P: sample period in us."""

    period_us: int


@dataclass(frozen=True)
class Zero:
    """Z: zero the encoder count."""


@dataclass(frozen=True)
class SetSupply:
    """SUP: supply voltage in mV used for duty = u / V_supply."""

    mV: int


@dataclass(frozen=True)
class SetZeroMode:
    """ZM: what a zero command does, BRAKE or COAST."""

    mode: str


@dataclass(frozen=True)
class SetStream:
    """STREAM: sample stream on or off."""

    on: bool


@dataclass(frozen=True)
class SetDirection:
    """DIR: the encoder's counting direction and the motor's polarity, FWD or REV each
    (kept in EEPROM on the board)."""

    enc: str
    motor: str


@dataclass(frozen=True)
class ReadDiag:
    """DIAG: ask for a $DIAG reply (encoder pins, edges per connector, the connector in use)."""


@dataclass(frozen=True)
class ReadMeter:
    """METER (virtual board only): ask for a $METER reading."""


Message = (
    Boot
    | Ident
    | SampleLine
    | Ok
    | Err
    | EvWatchdog
    | EvSquareWaveEdge
    | EvSquareWaveDone
    | Meter
    | Diag
    | Identify
    | Ping
    | SetVoltage
    | SquareWave
    | Stop
    | SetPeriod
    | Zero
    | SetSupply
    | SetZeroMode
    | SetStream
    | SetDirection
    | ReadDiag
    | ReadMeter
)


@dataclass(frozen=True)
class LineKind:
    """One kind of line: NAME, event tag (for $EV), direction, class and field types.

    A field type ending in ``?`` is an optional last field; ``*`` collects the rest.
    """

    name: str
    tag: str | None
    direction: Direction
    cls: type
    types: tuple[str, ...]


LINES: tuple[LineKind, ...] = (
    LineKind("BOOT", None, "board", Boot, ("text", "int")),
    LineKind(
        "ID",
        None,
        "board",
        Ident,
        ("text", "int", "text", "int", "int", "int", "zero", "dir", "dir"),
    ),
    LineKind("S", None, "board", SampleLine, ("u32", "u32", "i32", "int")),
    LineKind("OK", None, "board", Ok, ("name", "text*")),
    LineKind("ERR", None, "board", Err, ("err", "text?")),
    LineKind("EV", "WDOG", "board", EvWatchdog, ()),
    LineKind("EV", "STEP", "board", EvSquareWaveEdge, ("int", "int")),
    LineKind("EV", "STEPDONE", "board", EvSquareWaveDone, ()),
    LineKind("METER", None, "board", Meter, ("int", "int", "int")),
    LineKind("DIAG", None, "board", Diag, ("text", "text", "conn*")),
    LineKind("ID", None, "host", Identify, ()),
    LineKind("PING", None, "host", Ping, ()),
    LineKind("V", None, "host", SetVoltage, ("int",)),
    LineKind("STEP", None, "host", SquareWave, ("int", "int", "int", "int")),
    LineKind("STOP", None, "host", Stop, ()),
    LineKind("P", None, "host", SetPeriod, ("int",)),
    LineKind("Z", None, "host", Zero, ()),
    LineKind("SUP", None, "host", SetSupply, ("int",)),
    LineKind("ZM", None, "host", SetZeroMode, ("zero",)),
    LineKind("STREAM", None, "host", SetStream, ("bit",)),
    LineKind("DIR", None, "host", SetDirection, ("dir", "dir")),
    LineKind("DIAG", None, "host", ReadDiag, ()),
    LineKind("METER", None, "host", ReadMeter, ()),
)

_BY_KEY: dict[tuple[Direction, str, str | None], LineKind] = {
    (k.direction, k.name, k.tag): k for k in LINES
}
_BY_CLASS: dict[type, LineKind] = {k.cls: k for k in LINES}


# -- frames -----------------------------------------------------------------------------
def checksum(body: str | bytes) -> int:
    """CRC-16/CCITT-FALSE of ``body`` (the text between `$` and `*`): polynomial 0x1021,
    initial value 0xFFFF, no reflection, no final XOR (check value 0x29B1 for "123456789").

    It catches every swap of two adjacent bytes and every error burst up to 16 bits,
    which protocol 1's XOR did not (benchmarks/checksum_strength.py measures both).
    """
    data = body.encode("ascii") if isinstance(body, str) else body
    return binascii.crc_hqx(data, 0xFFFF)


def frame(name: str, *values: str) -> str:
    """``$NAME,v1,...*HHHH`` (no newline)."""
    body = ",".join((name, *values))
    return f"${body}*{checksum(body):04X}"


def split_frame(line: str | bytes) -> list[str]:
    """Check a board line's frame and checksum; return [NAME, field, ...].

    Raises ProtocolError: CHECKSUM for a missing or wrong checksum, ARGS for anything else
    malformed. A `\\r` before the end is ignored.
    """
    if isinstance(line, bytes):
        try:
            line = line.decode("ascii")
        except UnicodeDecodeError:
            raise ProtocolError("ARGS", why="not ASCII") from None
    line = line.rstrip("\n")
    if line.endswith("\r"):
        line = line[:-1]
    if len(line) > MAX_LINE:
        raise ProtocolError("ARGS", why="line too long")
    if not line.startswith("$"):
        raise ProtocolError("ARGS", why="no '$'")
    line = line[1:]
    if "$" in line:
        raise ProtocolError("ARGS", why="'$' inside a line")
    star = line.find("*")
    if star < 0:
        raise ProtocolError("CHECKSUM", why="no checksum")
    body, cs = line[:star], line[star + 1 :]
    if len(cs) != CHECKSUM_DIGITS or any(c not in "0123456789ABCDEF" for c in cs):
        raise ProtocolError("CHECKSUM", why=f"bad checksum field {cs!r}")
    if int(cs, 16) != checksum(body):
        raise ProtocolError("CHECKSUM", why=f"checksum {cs} != {checksum(body):04X}")
    if not _TEXT.match(body) or not body:
        raise ProtocolError("ARGS", why="empty or not printable")
    return body.split(",")


def _build(kind: LineKind, values: list[str]) -> Message:
    """The message of ``kind`` from its field texts, checked in the firmware's order: fields
    left to right, a field beyond the last or one of the wrong form is ARGS at once, a
    number outside its range is RANGE once every field has been read, too few is ARGS."""
    types = kind.types
    rest = bool(types) and types[-1].endswith("*")
    optional = bool(types) and types[-1].endswith("?")
    fixed = types[:-1] if (rest or optional) else types
    wrong_count = ProtocolError("ARGS", why=f"expected {len(types)} fields, got {len(values)}")
    out: list[object] = []
    out_of_range: ProtocolError | None = None
    for i, v in enumerate(values):
        if not rest and i >= len(types):
            raise wrong_count
        t = fixed[i] if i < len(fixed) else types[-1][:-1]
        try:
            out.append(FIELD_TYPES[t][0](v))
        except ProtocolError as exc:
            if exc.code != "RANGE":
                raise
            out_of_range = out_of_range or exc
    if len(values) < len(fixed):
        raise wrong_count
    if out_of_range is not None:
        raise out_of_range
    args = out[: len(fixed)]
    if rest:
        args.append(tuple(out[len(fixed) :]))
    elif optional and len(out) > len(fixed):
        args.append(out[len(fixed)])
    msg: Message = kind.cls(*args)
    return msg


def parse(line: str | bytes, direction: Direction = "board") -> Message:
    """Parse one line sent in ``direction`` ("board": board to host, "host": a command).

    Board lines must carry a valid checksum; host commands may omit `$` and `*CS` and are
    read by :func:`parse_command`. Raises ProtocolError with the $ERR code a board would
    answer.
    """
    if direction == "host":
        return parse_command(line)
    parts = split_frame(line)
    name, values = parts[0], parts[1:]
    if not _NAME.match(name):
        raise ProtocolError("UNKNOWN", why=f"not a line name: {name!r}")
    kind = _BY_KEY.get((direction, name, None))
    if kind is None and values:
        kind = _BY_KEY.get((direction, name, values[0]))
        values = values[1:]
    if kind is None:
        raise ProtocolError("UNKNOWN", name)
    try:
        return _build(kind, values)
    except ProtocolError as exc:
        raise ProtocolError(exc.code, name, exc.why) from None


def parse_command(line: str | bytes) -> Message:
    """Parse one host command (without its newline) exactly as the firmware does: the same
    checks in the same order, so the same $ERR code and detail (firmware/PROTOCOL.md).

    In order: an optional leading `$`; a `$` anywhere else is ARGS; a `*` must be followed
    by exactly four hex digits, either case, matching the checksum, else CHECKSUM; the name
    (up to the first `,`) must be 1-11 upper-case letters, else UNKNOWN without detail; an
    unknown name is UNKNOWN,<NAME>; a byte outside printable ASCII in the fields is
    ARGS,<NAME>; then the fields as :func:`_build` reads them (ARGS or RANGE, <NAME>).
    The board ignores an empty line; here it is ARGS.
    """
    s = line.encode("utf-8") if isinstance(line, str) else bytes(line)
    if not s:
        raise ProtocolError("ARGS", why="empty command (the board ignores it)")
    if s[:1] == b"$":
        s = s[1:]
    if b"$" in s:
        raise ProtocolError("ARGS", why="'$' inside a command")
    star = s.find(b"*")
    if star >= 0:
        cs = s[star + 1 :]
        if len(cs) != CHECKSUM_DIGITS or not _HEX_DIGITS.issuperset(cs):
            raise ProtocolError("CHECKSUM", why=f"bad checksum field {cs!r}")
        if int(cs, 16) != checksum(s[:star]):
            raise ProtocolError("CHECKSUM", why=f"checksum {cs!r} != {checksum(s[:star]):04X}")
        s = s[:star]
    comma = s.find(b",")
    name_bytes = s if comma < 0 else s[:comma]
    if not (1 <= len(name_bytes) <= MAX_COMMAND_NAME and all(65 <= c <= 90 for c in name_bytes)):
        raise ProtocolError("UNKNOWN", why=f"not a command name: {name_bytes!r}")
    name = name_bytes.decode("ascii")
    kind = _BY_KEY.get(("host", name, None))
    if kind is None:
        raise ProtocolError("UNKNOWN", name)
    fields_text = s[len(name_bytes) :]
    if any(c < 0x20 or c > 0x7E for c in fields_text):
        raise ProtocolError("ARGS", name, "not printable")
    values = fields_text.decode("ascii").split(",")[1:] if fields_text else []
    try:
        return _build(kind, values)
    except ProtocolError as exc:
        raise ProtocolError(exc.code, name, exc.why) from None


def format_line(msg: Message) -> str:
    """The line for a message, with `$` and checksum, without the newline."""
    kind = _BY_CLASS[type(msg)]
    values: list[str] = [kind.tag] if kind.tag else []
    for f, t in zip(fields(msg), kind.types, strict=True):
        v = getattr(msg, f.name)
        fmt = FIELD_TYPES[t.rstrip("*?")][1]
        if t.endswith("*"):
            values.extend(fmt(x) for x in v)
        elif t.endswith("?"):
            if v != "":
                values.append(fmt(v))
        else:
            values.append(fmt(v))
    return frame(kind.name, *values)


def encode(msg: Message) -> bytes:
    """The bytes on the wire for a message: its line and a newline."""
    return (format_line(msg) + "\n").encode("ascii")
