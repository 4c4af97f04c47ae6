"""Port discovery with fake ListPortInfo objects, and the `ports` and `sim` commands."""

import argparse
import json
import os
import signal
import subprocess
import sys

import pytest
import serial
from serial.tools.list_ports_common import ListPortInfo

from minseg_tui.cli import ports as ports_cli
from minseg_tui.device import discovery
from minseg_tui.device import protocol as P


def fake(device, vid=None, pid=None, manufacturer=None):
    info = ListPortInfo(device, skip_link_detection=True)
    info.vid, info.pid, info.manufacturer = vid, pid, manufacturer
    return info


PORTS = [
    fake("/dev/ttyS0"),
    fake("/dev/ttyACM3", 0x1BC7, 0x1201, "Telit"),  # an LTE modem
    fake("/dev/ttyUSB0", 0x0403, 0x6001, "FTDI"),
    fake("/dev/ttyUSB1", 0x1A86, 0x7523),
    fake("/dev/ttyACM0", 0x2341, 0x0042, "Arduino"),
    fake("/dev/ttyACM1", 0x2A03, 0x0010),
]


def test_verdicts_and_order():
    got = {c.device: c.verdict for c in discovery.candidates(PORTS)}
    assert got == {
        "/dev/ttyS0": "ignored",
        "/dev/ttyACM3": "ignored",
        "/dev/ttyUSB0": "possible",
        "/dev/ttyUSB1": "clone",
        "/dev/ttyACM0": "board",
        "/dev/ttyACM1": "board",
    }
    order = [c.device for c in discovery.candidates(PORTS)]
    assert order[:3] == ["/dev/ttyACM0", "/dev/ttyACM1", "/dev/ttyUSB1"]
    modem = next(c for c in discovery.candidates(PORTS) if c.device == "/dev/ttyACM3")
    assert "1BC7:1201" in modem.reason and "Telit" in modem.reason


def test_never_picks_an_unrelated_port():
    assert discovery.find_board(PORTS[:2]) is None  # a ttyS and a modem only
    assert discovery.find_board(PORTS[:3]) is None  # an FTDI adapter is only "possible"
    assert discovery.find_board(PORTS[:4]).device == "/dev/ttyUSB1"
    assert discovery.find_board(PORTS).device == "/dev/ttyACM0"
    assert discovery.find_board(PORTS, vid_pid=(0x2A03, 0x0010)).device == "/dev/ttyACM1"
    assert discovery.find_board(PORTS, vid_pid=(0x1BC7, 0x1201)) is None


def test_ports_command_lists_every_port(capsys, monkeypatch):
    monkeypatch.setattr(discovery, "list_ports", lambda: PORTS)
    assert ports_cli.run(argparse.Namespace(json=False)) == 0
    out = capsys.readouterr().out
    assert all(p.device in out for p in PORTS)
    assert "* = what `auto` opens: /dev/ttyACM0" in out

    def row(device):
        return next(r for r in out.splitlines() if f" {device} " in r)

    # every port says why it was or was not picked
    assert "no USB vendor/product id" in row("/dev/ttyS0")
    assert "1BC7:1201 by Telit is not a known" in row("/dev/ttyACM3")
    assert "not opened automatically" in row("/dev/ttyUSB0")
    assert row("/dev/ttyACM0").startswith("* ") and not row("/dev/ttyACM1").startswith("*")

    assert ports_cli.run(argparse.Namespace(json=True)) == 0
    data = json.loads(capsys.readouterr().out)
    assert {d["device"]: d["picked"] for d in data}["/dev/ttyUSB1"] is True
    assert {d["device"]: d["vid"] for d in data}["/dev/ttyACM0"] == "2341"


def test_ports_command_on_this_machine(capsys):
    assert ports_cli.run(argparse.Namespace(json=True)) == 0
    assert isinstance(json.loads(capsys.readouterr().out), list)


def _as_at_a_terminal() -> None:
    """Ctrl-C as a terminal delivers it to the program in the foreground: whatever runs the
    suite may be a background job of a shell without job control, which starts its children
    with SIGINT ignored (the sim then, rightly, ignores it too)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_sim_command_serves_a_pty_until_ctrl_c():
    """The board's lines are waited for line by line (no read that must finish within a
    fraction of a second: a busy machine makes the sim slower, not wrong); the generous
    timeouts only guard against a hang."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "minseg_tui", "sim", "--seed", "1", "--coulomb", "0"],
        stdout=subprocess.PIPE,
        text=True,
        preexec_fn=_as_at_a_terminal,
    )
    try:
        path = proc.stdout.readline().strip()
        assert os.path.exists(path)
        with serial.Serial(path, P.BAUD, timeout=30) as port:
            assert port.readline().startswith(b"$")  # booted (bytes sent during boot are lost)
            port.write(b"ID\n")
            for _ in range(1000):  # the stream goes on; the reply comes among its lines
                line = port.readline().decode().strip()
                assert line, "the virtual board went silent"
                if line.startswith("$ID"):
                    break
        assert P.parse(line).board == "Virtual"
    finally:
        proc.send_signal(signal.SIGINT)
        code = proc.wait(60)
    assert code == 0


def test_sim_command_stops_on_sigterm_and_removes_its_link(tmp_path):
    """`kill PID` (SIGTERM) stops the sim as Ctrl-C does: exit 0, its symlink gone, not left
    pointing at a closed pty."""
    link = tmp_path / "minseg0"
    proc = subprocess.Popen(
        [sys.executable, "-m", "minseg_tui", "sim", "--seed", "1", "--link", str(link)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert proc.stdout.readline().strip() == str(link)
        assert os.path.islink(link)
    finally:
        proc.send_signal(signal.SIGTERM)
        code = proc.wait(60)
    assert code == 0
    assert not os.path.lexists(link)
    assert "Traceback" not in proc.stderr.read()


def test_sim_command_bad_option_is_one_line():
    r = subprocess.run(
        [sys.executable, "-m", "minseg_tui", "sim", "--seed", "x"],
        capture_output=True,
        text=True,
        timeout=30,
    )
    assert r.returncode == 2
    assert r.stderr.strip().splitlines() == [
        "minseg-tui sim: option seed: expected an integer, got 'x'"
    ]


@pytest.mark.parametrize(
    ("args", "says"),
    [
        (["--R", "nan"], "option R: expected a number, got 'nan'"),
        (["--jitter", "-5"], "option jitter: expected a finite number, not negative, got '-5'"),
        (
            ["--link", "/nonexistent-dir/minseg0"],
            "/nonexistent-dir/minseg0: cannot make the device",
        ),
    ],
)
def test_sim_command_bad_setting_is_one_line(args, says):
    r = subprocess.run(
        [sys.executable, "-m", "minseg_tui", "sim", *args],
        capture_output=True,
        text=True,
        timeout=30,
    )
    assert r.returncode == 2 and r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("minseg-tui sim: ") and says in lines[0], (
        r.stderr
    )


@pytest.mark.parametrize("spec", ["virtual", "minseg://?clock=virtual"])
def test_factory_specs_resolve_without_opening(spec):
    from minseg_tui.device.factory import resolve

    port, vid_pid = resolve(spec)
    assert port.startswith("minseg://") and vid_pid is None
