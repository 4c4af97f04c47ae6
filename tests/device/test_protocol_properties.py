"""Round trips of protocol 3 over generated lines (hypothesis, derandomised and without a
database, so every run tries the same examples): every line kind of ``protocol.LINES``, built from any valid field
values, formats to a line that parses back to the same message; and one byte changed
anywhere in a board line never becomes another message (CRC-16 catches every burst of up
to 16 bits)."""

from dataclasses import fields

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from minseg_tui.device import protocol as p

_TEXT = st.text(
    alphabet=st.characters(min_codepoint=0x20, max_codepoint=0x7E, exclude_characters=",*$"),
    max_size=12,
)
_FIELD = {
    "int": st.integers(-(2**31), 2**31 - 1),
    "i32": st.integers(-(2**31), 2**31 - 1),
    "u32": st.integers(0, 2**32 - 1),
    "text": _TEXT,
    "name": st.from_regex(r"[A-Z]{1,11}", fullmatch=True),
    "zero": st.sampled_from(p.ZERO_MODES),
    "err": st.sampled_from(p.ERR_CODES),
    "bit": st.booleans(),
    "dir": st.sampled_from(p.DIRECTIONS),
    "conn": st.builds(
        p.ConnectorState,
        st.from_regex(r"[A-Z][A-Z0-9]{0,7}", fullmatch=True),
        st.sampled_from(["00", "01", "10", "11"]),
        st.integers(0, 2**32 - 1),
    ),
}


def _field(t: str) -> st.SearchStrategy[object]:
    base = _FIELD[t.rstrip("*?")]
    if t.endswith("*"):
        return st.lists(base, max_size=3).map(tuple)
    if t.endswith("?"):
        return st.one_of(st.just(""), base)
    return base


def _message(kind: p.LineKind) -> st.SearchStrategy[object]:
    names = [f.name for f in fields(kind.cls)]
    return st.fixed_dictionaries(
        {n: _field(t) for n, t in zip(names, kind.types, strict=True)}
    ).map(lambda kw: kind.cls(**kw))


BOARD = st.one_of(*(_message(k) for k in p.LINES if k.direction == "board"))
HOST = st.one_of(*(_message(k) for k in p.LINES if k.direction == "host"))
FAST = settings(max_examples=200, derandomize=True, database=None, deadline=None)


@FAST
@given(BOARD)
def test_every_board_line_parses_back_to_itself(msg):
    line = p.format_line(msg)  # type: ignore[arg-type]
    if len(line) > p.MAX_LINE:  # no board sends it: a receiver refuses it whole
        with pytest.raises(p.ProtocolError, match="too long"):
            p.parse(line)
        return
    assert p.parse(line) == msg
    assert p.encode(msg).decode("ascii") == line + "\n"  # type: ignore[arg-type]


@FAST
@given(HOST)
def test_every_command_parses_back_to_itself_with_or_without_its_checksum(msg):
    line = p.format_line(msg)  # type: ignore[arg-type]
    assume(len(line) <= p.MAX_LINE)  # the board refuses longer lines before it parses them
    assert p.parse_command(line) == msg
    assert p.parse_command(line.split("*")[0].removeprefix("$")) == msg


@FAST
@given(BOARD, st.data())
def test_one_byte_changed_in_a_board_line_never_becomes_a_message(msg, data):
    line = p.format_line(msg)  # type: ignore[arg-type]
    i = data.draw(st.integers(0, len(line) - 1))
    new = data.draw(st.integers(0x20, 0x7E).filter(lambda c: c != ord(line[i])))
    altered = line[:i] + chr(new) + line[i + 1 :]
    try:
        got = p.parse(altered)
    except p.ProtocolError:
        return
    raise AssertionError(f"{altered!r} became {got!r}")
