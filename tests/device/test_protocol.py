"""Protocol 1 against the golden lines, both ends: the host parser and the virtual board."""

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
    s = P.parse("$S,4294967295,4294967292,2147483647,-4500*72")
    assert s == P.SampleLine(4294967295, 4294967292, 2147483647, -4500)
    assert P.parse("$EV,STEP,3,10*1F") == P.EvStep(3, 10)
    assert P.parse("$ERR,ARGS,V*14") == P.Err("ARGS", "V")
    assert P.parse("$OK,STEP,0,4500,1000,5*3F") == P.Ok("STEP", ("0", "4500", "1000", "5"))
    assert P.checksum("PING") == 0x10
    assert P.encode(P.Ping()) == b"$PING*10\n"


def test_crlf_and_overlong_lines():
    assert P.parse("$OK,PING*38\r") == P.Ok("PING")
    with pytest.raises(P.ProtocolError):
        P.parse("$OK,PING," + "9" * 80 + "*00")


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
    assert reply and isinstance(reply[0], P.Ok | P.Ident)
    port.close()
