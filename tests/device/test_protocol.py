"""Protocol 3 against the golden lines, both ends: the host parser and the virtual board."""

import random

import pytest

from minseg_tui.device import protocol as P

from .conftest import golden, read_lines, vport


@pytest.mark.parametrize("line", golden("board"))
def test_board_lines_parse_and_format_back(line):
    msg = P.parse(line, "board")
    assert P.format_line(msg) == line


@pytest.mark.parametrize("line", golden("host"))
def test_host_commands_parse_and_format_back(line):
    msg = P.parse_command(line)
    assert P.format_line(msg) == line
    # a student may type it without $ and checksum
    bare = line[1:].split("*")[0]
    assert P.parse_command(bare) == msg


@pytest.mark.parametrize("line", golden("reject"))
def test_malformed_board_lines_are_rejected(line):
    with pytest.raises(P.ProtocolError):
        P.parse(line, "board")


@pytest.mark.parametrize("case", golden("error"))
def test_malformed_commands_get_their_error_code(case):
    code, _, cmd = case.partition(" ")
    with pytest.raises(P.ProtocolError) as info:
        P.parse_command(cmd)
    assert info.value.code == code


def test_golden_values_by_hand():
    s = P.parse("$S,4294967295,4294967292,2147483647,-4500*916B")
    assert s == P.SampleLine(4294967295, 4294967292, 2147483647, -4500)
    assert P.parse("$EV,STEP,3,10*9F38") == P.EvSquareWaveEdge(3, 10)
    assert P.parse("$ERR,ARGS,V*DCDA") == P.Err("ARGS", "V")
    assert P.parse("$OK,STEP,0,4500,1000,5*CD5B") == P.Ok("STEP", ("0", "4500", "1000", "5"))
    assert P.checksum("PING") == 0x6427
    assert P.checksum("123456789") == 0x29B1  # the CRC-16/CCITT-FALSE check value
    assert P.encode(P.Ping()) == b"$PING*6427\n"


def test_crlf_and_overlong_lines():
    assert P.parse("$OK,PING*6C01\r") == P.Ok("PING")
    with pytest.raises(P.ProtocolError):
        P.parse("$OK,PING," + "9" * 80 + "*0000")


def test_meter_extension_round_trip():
    m = P.Meter(2050, 29800, 5300)
    assert P.parse(P.format_line(m)) == m
    assert P.parse_command("METER") == P.ReadMeter()


@pytest.mark.parametrize("case", golden("error"))
def test_virtual_board_answers_malformed_commands_and_changes_nothing(case):
    code, _, cmd = case.partition(" ")
    port = vport("jitter=0")
    read_lines(port, 0.01)
    port.write(b"ID\n")
    before = [x for x in read_lines(port, 0.001) if x.startswith("$ID")]
    port.write(cmd.encode() + b"\n")
    reply = [x for x in read_lines(port, 0.001) if not x.startswith("$S")]
    assert len(reply) == 1
    err = P.parse(reply[0])
    assert isinstance(err, P.Err) and err.code == code
    port.write(b"ID\n")
    after = [x for x in read_lines(port, 0.001) if x.startswith("$ID")]
    assert before == after
    later = [P.parse(x) for x in read_lines(port, 0.2) if x.startswith("$S")]
    assert later and all(s.u_mV == 0 for s in later)
    port.close()


@pytest.mark.parametrize("line", golden("host"))
def test_virtual_board_accepts_every_golden_command(line):
    port = vport()
    read_lines(port, 0.01)
    port.write(line.encode() + b"\n")
    reply = [P.parse(x) for x in read_lines(port, 0.001) if not x.startswith("$S")]
    assert reply and isinstance(reply[0], P.Ok | P.Ident | P.Diag)
    port.close()


def _corruptions(line: str) -> list[str]:
    """Every adjacent-byte swap and every loss of a pair of equal bytes, after the `$`."""
    out = []
    for i in range(1, len(line) - 1):
        a, b = line[i], line[i + 1]
        if a != b:
            out.append(line[:i] + b + a + line[i + 2 :])
        else:
            out.append(line[:i] + line[i + 2 :])
    return out


def _sample_lines() -> list[str]:
    """Sample lines as a step run sends them (seeded), the most frequent lines on the link."""
    rng = random.Random(10)
    out, count = [], 0
    for seq in range(400):
        count += rng.randrange(0, 40)
        u = rng.choice((0, 4500, -4500, 2500, 1100))
        out.append(P.format_line(P.SampleLine(seq * 97, 1024 + seq * 25000, count, u)))
    return out


def test_swapped_adjacent_bytes_are_always_caught():
    # a swap is an error burst of at most 16 bits: CRC-16 catches every one
    lines = golden("board") + _sample_lines()
    let_through = []
    for line in lines:
        for bad in _corruptions(line):
            if len(bad) == len(line):
                try:
                    P.parse(bad)
                    let_through.append((line, bad))
                except P.ProtocolError:
                    pass
    assert let_through == []


def test_lost_pairs_of_equal_bytes_are_caught():
    lines = golden("board") + _sample_lines()
    tried, let_through = 0, []
    for line in lines:
        for bad in _corruptions(line):
            if len(bad) == len(line) - 2:
                tried += 1
                try:
                    P.parse(bad)
                    let_through.append((line, bad))
                except P.ProtocolError:
                    pass
    assert tried > 500
    assert let_through == []
