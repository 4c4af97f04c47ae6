"""The virtual MinSeg's firmware behaviour, on a virtual clock (deterministic)."""

import math
import time

import pytest

from minseg_tui.device import protocol as P
from minseg_tui.device.virtual import RealTime, VirtualBoard, VirtualSettings, settings_from

from .conftest import read_lines, vport


def parsed(lines, cls):
    return [m for m in (P.parse(x) for x in lines) if isinstance(m, cls)]


def test_boot_on_open_then_samples_every_25_ms():
    port = vport("jitter=0")
    lines = read_lines(port, 0.1)
    assert P.parse(lines[0]) == P.Boot("minseg-virtual 3.0.0", 3)
    samples = parsed(lines, P.SampleLine)
    # as the firmware: the first sample one period after $BOOT
    assert [s.seq for s in samples] == [0, 1, 2, 3]
    assert [s.t_us for s in samples] == [25000, 50000, 75000, 100000]
    port.write(b"ID\n")
    (ident,) = parsed(read_lines(port, 0.001), P.Ident)
    assert ident == P.Ident(
        "minseg-virtual 3.0.0", 3, "Virtual", 720, 25000, 5000, "BRAKE", "FWD", "FWD"
    )


def test_clamping_reports_applied_values():
    port = vport()
    read_lines(port, 0.01)
    cases = {
        "V,9000": ("V", ("5000",)),
        "V,-9000": ("V", ("-5000",)),
        "P,500": ("P", ("1000",)),  # the virtual board's floor (the real board: 2000)
        "P,2500": ("P", ("3000",)),  # rounded to 1000 us, half up
        "P,200000": ("P", ("100000",)),
        "SUP,20000": ("SUP", ("12000",)),
        "SUP,1000": ("SUP", ("3000",)),
        # half 20 ms (the floor) at P = 100 ms is one sample: the half period used is 100 ms
        "STEP,-9000,9000,5,0": ("STEP", ("-3000", "3000", "100", "1")),
    }
    for cmd, (name, values) in cases.items():
        port.write(cmd.encode() + b"\n")
        oks = parsed(read_lines(port, 0.0005), P.Ok)
        assert oks[0] == P.Ok(name, values), cmd
        port.write(b"STOP\n")
        read_lines(port, 0.0005)


def test_step_edges_fall_on_sample_instants():
    port = vport("jitter=0")
    read_lines(port, 0.01)  # booted at t=0, sample 0 comes at 25 ms
    port.write(b"STEP,0,3000,100,2\n")  # half = 4 samples of 25 ms
    lines = read_lines(port, 0.5)
    samples = parsed(lines, P.SampleLine)
    u = {s.t_us: s.u_mV for s in samples}
    # first edge at the next sample (25 ms), then 100 ms high / 100 ms low, twice
    expect = {25000 + 25000 * k: (3000 if (k // 4) % 2 == 0 else 0) for k in range(16)}
    expect[25000 + 25000 * 16] = 0
    assert {t: u[t] for t in expect} == expect
    events = [P.parse(x) for x in lines if x.startswith("$EV")]
    assert events == [P.EvSquareWaveEdge(1, 2), P.EvSquareWaveEdge(2, 2), P.EvSquareWaveDone()]
    # each event right after the $S line of its edge
    i = lines.index(P.format_line(P.EvSquareWaveEdge(2, 2)))
    assert P.parse(lines[i - 1]).t_us == 225000
    # a second STEP while one runs is refused
    port.write(b"STEP,0,3000,100,2\nSTEP,0,1000,100,2\n")
    replies = [P.parse(x) for x in read_lines(port, 0.001) if x.startswith(("$OK", "$ERR"))]
    assert replies == [P.Ok("STEP", ("0", "3000", "100", "2")), P.Err("BUSY")]


def test_voltage_applies_from_the_next_sample():
    port = vport("jitter=0")
    read_lines(port, 0.03)  # samples at 0 and 25 ms
    port.write(b"V,2500\n")
    samples = parsed(read_lines(port, 0.1), P.SampleLine)
    assert samples[0].t_us == 50000 and samples[0].u_mV == 2500


def test_watchdog_stops_the_motor_after_one_second_of_silence():
    port = vport("jitter=0")
    read_lines(port, 0.001)
    port.write(b"V,4000\n")
    quiet = read_lines(port, 0.99)
    assert not any(x.startswith("$EV,WDOG") for x in quiet)
    port.write(b"PING\n")  # any command resets the watchdog
    read_lines(port, 0.9)
    assert port.board.u_mV == 4000
    lines = read_lines(port, 0.2)
    assert P.format_line(P.EvWatchdog()) in lines
    i = lines.index(P.format_line(P.EvWatchdog()))
    after = parsed(lines[i:], P.SampleLine)
    assert after and all(s.u_mV == 0 for s in after)
    assert port.board.plant.u_req == 0.0
    # once per silence
    assert sum(x.startswith("$EV,WDOG") for x in read_lines(port, 2.0)) == 0


def test_multimeter_reads_what_the_manual_predicts():
    # published motor, no dry friction: u_A = 2.5 - 0.45 V; at steady state
    # i_ss = u_A - k_v omega_ss over R with omega_ss = K u_A (hand formulas of eq. 3.7)
    port = vport("coulomb=0&seed=4")
    read_lines(port, 0.001)
    port.write(b"V,2500\n")
    for _ in range(3):  # 1.5 s, kept alive
        read_lines(port, 0.5)
        port.write(b"PING\n")
    R, kv, ka, f = 5.26, 0.495, 0.65 * 0.495, 6.0e-4
    u_a = 2.05
    omega = ka / (R * f + kv * ka) * u_a
    i_ss = (u_a - kv * omega) / R
    port.write(b"METER\n")
    (m,) = parsed(read_lines(port, 0.001), P.Meter)
    assert m.u_mV == pytest.approx(2050, abs=15)
    assert m.i_uA == pytest.approx(i_ss * 1e6, abs=300)
    assert m.R_mohm in (5300, 5400)
    direct = port.board.multimeter()
    assert direct.u_A == pytest.approx(2.05, abs=0.015)


def test_supply_setting_scales_the_duty_and_coast_opens_the_bridge():
    port = vport("coulomb=0")
    read_lines(port, 0.001)
    port.write(b"SUP,10000\nV,5000\n")  # duty 0.5 of the true 5 V supply: 2.5 V requested
    read_lines(port, 0.9)
    assert port.board.multimeter().u_A == pytest.approx(2.5 - 0.45, abs=0.015)
    port.write(b"ZM,COAST\nV,0\n")
    read_lines(port, 0.03)
    assert port.board.plant.coasting
    assert port.board.multimeter().i == 0.0


def test_zero_and_overlong_command():
    port = vport()
    read_lines(port, 0.001)
    port.write(b"V,4000\n")
    read_lines(port, 0.5)
    port.write(b"Z\n")
    samples = parsed(read_lines(port, 0.03), P.SampleLine)
    assert abs(samples[-1].count) < 20
    port.write(b"V," + b"1" * 90 + b"\nPING\n")
    replies = [x for x in read_lines(port, 0.001) if not x.startswith("$S")]
    assert replies == ["$ERR,ARGS*AB24", "$OK,PING*6C01"]


def test_settings_by_name():
    s = settings_from({"seed": "3", "kv": "0.5", "coulomb": "0.004", "coast": "1", "pole": "0.01"})
    assert s.seed == 3 and s.params.motor.k_v == 0.5
    assert s.params.motor.k_a == pytest.approx(0.325)
    assert s.params.tau_c == 0.004 and s.params.zero_mode == "coast" and s.params.T2 == 0.01
    with pytest.raises(ValueError, match="unknown"):
        settings_from({"bogus": "1"})


def test_same_seed_same_stream():
    def run(seed):
        b = VirtualBoard(VirtualSettings(seed=seed))
        b.run_until(0.01)
        b.feed(b"V,3000\n")
        b.run_until(1.0)
        return b.take_output()

    assert run(5) == run(5)
    assert run(5) != run(6)  # the loop jitter differs


def test_micros_and_seq_wrap():
    port = vport("jitter=0&micros0=4294917296&seq0=4294967294")
    samples = parsed(read_lines(port, 0.1), P.SampleLine)
    assert [s.seq for s in samples] == [4294967294, 4294967295, 0, 1]
    # micros() at boot is 2**32 - 50000; samples 25 ms apart from one period after boot
    assert [s.t_us for s in samples] == [4294942296, 0, 25000, 50000]
    assert math.isfinite(port.board.now)


def test_stop_and_p_during_a_step_stop_the_motor_at_once():
    port = vport("jitter=0")
    read_lines(port, 0.03)
    port.write(b"V,4000\n")
    read_lines(port, 0.05)
    assert port.board.plant.u_req != 0.0
    port.write(b"STOP\n")
    read_lines(port, 0.001)  # before the next sample: the bridge is already off
    assert port.board.plant.u_req == 0.0 and port.board.u_mV == 0
    port.write(b"STEP,0,4000,1000,5\n")
    read_lines(port, 0.05)
    assert port.board.u_mV == 4000
    port.write(b"P,20000\n")
    read_lines(port, 0.001)
    assert port.board.plant.u_req == 0.0 and port.board.u_mV == 0
    samples = parsed(read_lines(port, 0.1), P.SampleLine)
    assert samples and all(s.u_mV == 0 for s in samples)


def test_a_refused_step_does_not_feed_the_watchdog():
    port = vport("jitter=0")
    read_lines(port, 0.001)
    port.write(b"STEP,0,2000,5000,1\n")
    read_lines(port, 0.6)
    port.write(b"STEP,0,2000,5000,1\n")  # $ERR,BUSY: not a command the board accepted
    lines = read_lines(port, 0.45)
    assert P.format_line(P.EvWatchdog()) in lines


class _Monotonic:
    """A host clock the test moves by hand (s)."""

    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


def test_a_stalled_host_pauses_the_real_time_board_instead_of_tripping_its_watchdog(
    monkeypatch,
):
    """The virtual board runs in the host's process: when the process is not scheduled for
    3 s (a busy machine), board time moves on by at most RealTime.MAX_STEP, so the board does
    not see a host silent for 3 s and its watchdog leaves the motor on. A host that is
    scheduled but sends nothing still trips it after 1 s."""
    host = _Monotonic()
    monkeypatch.setattr("minseg_tui.device.virtual.time.monotonic", host)
    clock = RealTime(5.0)
    assert clock() == 5.0
    host.now += 0.01
    assert clock() == pytest.approx(5.01)  # ordinary steps: host time
    board = VirtualBoard(VirtualSettings(seed=1))
    board.run_until(clock())
    board.take_output()
    board.feed(b"V,4000\n")
    for _ in range(10):  # kept alive for a second
        host.now += 0.1
        board.run_until(clock())
        board.feed(b"PING\n")
    host.now += 3.0  # the process stalls
    board.run_until(clock())
    assert clock() == pytest.approx(6.01 + RealTime.MAX_STEP)
    board.feed(b"PING\n")  # the first thing the host does when it runs again
    assert b"WDOG" not in board.take_output() and board.u_mV == 4000
    for _ in range(12):  # scheduled, but silent: 1.2 s of board time
        host.now += 0.1
        board.run_until(clock())
    assert b"$EV,WDOG" in board.take_output() and board.u_mV == 0


def test_the_simulated_hand_turns_once_give_or_take_and_is_seeded():
    """The hand check on the virtual MinSeg (nobody can turn its wheel): its hand turns it
    once, a little over or under, the same way for the same seed."""
    turns = []
    for seed in (1, 1, 2):
        board = VirtualBoard(VirtualSettings(seed=seed))
        turned = [board.hand_turn() for _ in range(20)]
        turns.append(turned)
        assert all(0.95 < abs(r) < 1.05 for r in turned)
        assert len({round(abs(r), 6) for r in turned}) == 20  # over or under, never the same
    assert turns[0] == turns[1] and turns[0] != turns[2]


def _samples(board):
    out = board.take_output().decode("ascii", "replace").splitlines()
    got = []
    for line in out:
        try:
            msg = P.parse(line)
        except P.ProtocolError:
            continue
        if isinstance(msg, P.SampleLine):
            got.append(msg)
    return got


def test_a_hand_turns_the_wheel_now_even_when_nobody_has_read_the_board_for_a_while():
    """A board run in real time and not read for a while (a busy host's reader): a hand's
    turn is at the present moment, so the samples of the time before it keep the count
    from before. They were made after the turn, all turned already: the TUI's hand check
    read them as its first samples and counted 0 (test_board_check's palette test, once
    under load)."""
    board = VirtualBoard()
    board.clock = RealTime(board.now)
    board.run_until(board.clock())
    time.sleep(0.5)
    board.run_until(board.clock())
    before = _samples(board)
    assert before, "the board streams"
    count0 = before[-1].count
    time.sleep(0.15)  # nobody reads: the board's time stands where the last read left it
    now = board.clock()
    board.hand_turn()
    time.sleep(0.06)  # a sample or two after the turn
    board.run_until(board.clock())
    after = _samples(board)
    pre = [s for s in after if s.t_us < (now - 0.03) * 1e6]
    assert pre and all(s.count == count0 for s in pre)
    assert abs(after[-1].count - count0) > 600
