"""Protocol 3 on the virtual board: DIR (kept over a reset), DIAG, and the wiring faults
(encoder-off, encoder-reversed, motor-off) a board at the bench can have."""

import pytest

from minseg_tui.device import protocol as P
from minseg_tui.device.virtual import (
    VirtualBoard,
    VirtualSettings,
    settings_from,
    wiring_faults,
)

from .conftest import read_lines, vport


def parsed(lines, cls):
    return [m for m in (P.parse(x) for x in lines) if isinstance(m, cls)]


def ask(port, cmd: str, cls):
    port.write(cmd.encode() + b"\n")
    (reply,) = parsed(read_lines(port, 0.001), cls)
    return reply


def drive(port, mV: int, seconds: float) -> list[P.SampleLine]:
    """Samples while the motor is at mV for ``seconds`` (board time)."""
    port.write(f"V,{mV}\n".encode())
    samples = parsed(read_lines(port, seconds), P.SampleLine)
    port.write(b"STOP\n")
    read_lines(port, 0.05)
    return samples


def test_diag_reply_parses_and_formats_back():
    line = "$DIAG,M1+M2,M2,M1:11:0,M2:01:1440*D13C"
    msg = P.parse(line)
    assert msg == P.Diag(
        "M1+M2", "M2", (P.ConnectorState("M1", "11", 0), P.ConnectorState("M2", "01", 1440))
    )
    assert isinstance(msg, P.Diag) and msg.connector("M2") == P.ConnectorState("M2", "01", 1440)
    assert msg.connector("M3") is None
    assert P.format_line(msg) == line
    for bad in ("M1:2:0", "M1:111:0", "m1:11:0", "M1:11:-1", "M1:11"):
        with pytest.raises(P.ProtocolError):
            P.parse(P.frame("DIAG", "M1", "NONE", bad))


def test_protocol_two_ident_is_refused_by_the_parser():
    with pytest.raises(P.ProtocolError):
        P.parse(
            P.frame("ID", "minseg-fw 2.0.0", "2", "MinSegMega", "720", "25000", "5000", "BRAKE")
        )


def test_positive_voltage_counts_up_and_diag_names_the_connector():
    port = vport("jitter=0")
    read_lines(port, 0.01)
    diag = ask(port, "DIAG", P.Diag)
    assert diag.drive == "M1" and diag.active == "NONE"
    assert diag.connectors[0].edges == 0
    samples = drive(port, 2000, 0.5)
    assert samples[-1].count > 100
    diag = ask(port, "DIAG", P.Diag)
    assert diag.active == "M1"
    (m1,) = diag.connectors
    # every edge counted, and the pins are the quadrature state of the count
    assert m1.edges >= samples[-1].count
    assert m1.pins in ("00", "10", "11", "01")
    port.close()


def test_dir_flips_counting_keeps_the_count_and_survives_a_reset(board_name):
    port = vport("jitter=0", name=board_name)
    read_lines(port, 0.01)
    assert drive(port, 2000, 0.4)[-1].count > 0
    up = parsed(read_lines(port, 0.3), P.SampleLine)[-1].count  # the wheel stands
    assert ask(port, "DIR,REV,FWD", P.Ok) == P.Ok("DIR", ("REV", "FWD"))
    after = parsed(read_lines(port, 0.05), P.SampleLine)
    assert after[-1].count == up  # the switch does not change the count
    down = drive(port, 2000, 0.4)[-1].count
    assert down < up - 50  # counts the other way now
    ident = ask(port, "ID", P.Ident)
    assert (ident.enc_dir, ident.motor_dir) == ("REV", "FWD")
    port.close()
    port = vport("jitter=0", name=board_name)  # opening resets the board
    read_lines(port, 0.01)
    ident = ask(port, "ID", P.Ident)
    assert (ident.enc_dir, ident.motor_dir) == ("REV", "FWD")
    # both reversed: a positive voltage turns the wheel the other way, counted the other way
    ask(port, "DIR,REV,REV", P.Ok)
    assert drive(port, 2000, 0.4)[-1].count > 50
    port.close()


def test_encoder_off_counts_nothing_and_reads_pins_high():
    port = vport("jitter=0&fault=encoder-off")
    read_lines(port, 0.01)
    samples = drive(port, 2000, 0.5)
    assert {s.count for s in samples} == {0}
    diag = ask(port, "DIAG", P.Diag)
    assert diag.active == "NONE" and diag.connectors == (P.ConnectorState("M1", "11", 0),)
    # the wheel did turn: the motor drew current
    assert port.board.plant.theta > 1.0
    port.close()


def test_encoder_reversed_counts_down_for_a_positive_voltage():
    port = vport("jitter=0&fault=encoder-reversed")
    read_lines(port, 0.01)
    assert drive(port, 2000, 0.5)[-1].count < -100
    ask(port, "DIR,REV,FWD", P.Ok)
    ask(port, "Z", P.Ok)
    assert drive(port, 2000, 0.5)[-1].count > 100
    port.close()


def test_motor_off_does_not_turn_and_draws_no_current():
    port = vport("jitter=0&fault=motor-off")
    read_lines(port, 0.01)
    port.write(b"V,3000\n")
    samples = parsed(read_lines(port, 0.5), P.SampleLine)
    assert samples[-1].u_mV == 3000 and {s.count for s in samples} == {0}
    meter = ask(port, "METER", P.Meter)
    assert meter.i_uA == pytest.approx(0, abs=200) and port.board.plant.theta == 0.0
    port.close()


def test_faults_by_name_one_or_several():
    s = settings_from({"fault": "encoder-off,motor-off"})
    assert s.faults.encoder_off and s.faults.motor_off and not s.faults.encoder_reversed
    assert wiring_faults(" Encoder-Reversed ") == ["encoder_reversed"]
    with pytest.raises(ValueError, match="encoder-off, encoder-reversed, motor-off"):
        settings_from({"fault": "wheel-off"})


def test_mending_a_fault_and_turning_by_hand():
    board = VirtualBoard(VirtualSettings(jitter_us=0.0, seed=0))
    board.set_wiring_fault("encoder_off")
    board.turn_by_hand(1.0)
    assert board.edges == 0 and board.pins() == "11"
    board.set_wiring_fault("encoder_off", False)
    board.turn_by_hand(1.0)
    assert board.edges == 720 and board.active
    board.turn_by_hand(-0.5)
    assert board.edges == 1080
    with pytest.raises(ValueError):
        board.set_wiring_fault("silent")
