"""`minseg-tui flash` end to end without a board: a stand-in `avrdude` on the PATH (a small
program that checks its arguments as the Mega's bootloader needs them, opens the port, reads
the Intel HEX it is given and records what it wrote) and a virtual MinSeg on a real pty
whose firmware is whatever that avrdude last wrote: before, it runs "Simulink's program"
(bytes that are no line of the protocol); after, the lab firmware of the profile found in
the written image. So the whole path runs: discovery and checks, avrdude, the handshake.
"""

from __future__ import annotations

import dataclasses
import json
import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from serial.tools.list_ports_common import ListPortInfo

from minseg_tui.cli import main
from minseg_tui.device import discovery, flashing, hexfile
from minseg_tui.device import protocol as P
from minseg_tui.device.factory import open_device
from minseg_tui.device.link import Link
from minseg_tui.device.port import close, open_exclusive
from minseg_tui.device.ptyserver import PtyServer
from minseg_tui.device.virtual import VirtualBoard
from minseg_tui.errors import DeviceError

FAKE_AVRDUDE = textwrap.dedent(
    """\
    #!{python}
    # Stand-in for avrdude: the arguments the Mega 2560's bootloader needs, the port
    # opened, the Intel HEX read (data records, checksums checked), what was written kept.
    import json, os, signal, sys, time

    args = sys.argv[1:]
    state = os.environ["FAKE_AVRDUDE_STATE"]
    mode = os.environ.get("FAKE_AVRDUDE_MODE", "ok")

    def opt(flag):
        return args[args.index(flag) + 1] if flag in args else None

    wrong = []
    if opt("-p") not in ("atmega2560", "m2560"):
        wrong.append("part")
    if opt("-c") != "wiring":
        wrong.append("programmer")
    if opt("-b") != "115200":
        wrong.append("baud")
    if "-D" not in args:
        wrong.append("-D (no chip erase: it would need the bootloader's help)")
    spec = opt("-U") or ""
    if not (spec.startswith("flash:w:") and spec.endswith(":i")):
        wrong.append("-U flash:w:FILE:i")
    if wrong:
        print("avrdude error: bad arguments: " + ", ".join(wrong), file=sys.stderr)
        sys.exit(1)
    port = opt("-P")
    try:
        fd = os.open(port, os.O_RDWR | os.O_NOCTTY)
    except OSError as exc:
        print(f"avrdude OS error: cannot open port {{port}}: {{exc.strerror}}", file=sys.stderr)
        sys.exit(1)
    os.close(fd)
    if mode == "hang":  # as avrdude 7.1 can on a port that goes away
        time.sleep(60)
    if mode == "nosync":
        print("avrdude error: timeout communicating with programmer", file=sys.stderr)
        print(f"avrdude error: unable to open programmer wiring on port {{port}}", file=sys.stderr)
        sys.exit(1)
    path = spec[len("flash:w:"):-len(":i")]
    image = {{}}
    base = 0
    for line in open(path, encoding="ascii").read().split():
        rec = bytes.fromhex(line[1:])
        assert sum(rec) & 0xFF == 0, "checksum"
        if rec[3] == 0:
            for i, b in enumerate(rec[4:-1]):
                image[base + (rec[1] << 8 | rec[2]) + i] = b
        elif rec[3] == 4:
            base = (rec[4] << 8 | rec[5]) << 16
    flat = bytes(image.get(a, 0xFF) for a in range(max(image) + 1))
    found = [p for p in ("MinSegMega", "M2V3", "M1V4") if (p + "\\0").encode() in flat]
    print(f"avrdude: writing flash ({{len(image)}} bytes):", file=sys.stderr)
    if mode == "ctrl-c":  # the group presses Ctrl-C halfway
        sys.stderr.flush()
        os.kill(os.getppid(), signal.SIGINT)
        time.sleep(60)
    if mode == "cut":
        print("Writing | #########", file=sys.stderr)
        print("avrdude error: programmer is not responding", file=sys.stderr)
        written = {{"profile": None, "bytes": len(image) // 3}}
        code = 1
    else:
        print("Writing | ################################################## | 100%", file=sys.stderr)
        print(f"avrdude: {{len(image)}} bytes of flash written", file=sys.stderr)
        written = {{"profile": found[0] if len(found) == 1 else None, "bytes": len(image)}}
        code = 0
    with open(state, "w") as f:
        json.dump(dict(written, args=args, runs=1), f)
    sys.exit(code)
    """
)


class FlashableBoard(VirtualBoard):
    """A virtual MinSeg whose firmware is what the stand-in avrdude last wrote (read at
    every reset, as a real board starts what its flash holds): nothing written yet or a
    write cut short, and it runs "Simulink's program", which sends binary data and answers
    nothing; else the lab firmware, reporting the profile found in the image."""

    def __init__(self, state: Path) -> None:
        self.state = state
        self.profile: str | None = None
        super().__init__()

    def reset(self) -> None:
        written = json.loads(self.state.read_text()) if self.state.exists() else {}
        self.profile = written.get("profile")
        super().reset()

    def _emit(self, msg: P.Message) -> None:
        if self.profile is None:  # Simulink's program: raw bytes, no protocol line
            self._out += b"\x00\x10\xa5\x7f\x02\x81\xff\x13"
            return
        if isinstance(msg, P.Ident):  # the profile the image was built for
            msg = dataclasses.replace(msg, board=self.profile)
        super()._emit(msg)

    def feed(self, data: bytes) -> None:
        if self.profile is not None:
            super().feed(data)


@pytest.fixture
def avrdude(tmp_path, monkeypatch):
    """The stand-in avrdude first on the PATH; returns the file where it records a write."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    exe = bin_dir / "avrdude"
    exe.write_text(FAKE_AVRDUDE.format(python=sys.executable))
    exe.chmod(0o755)
    state = tmp_path / "written.json"
    monkeypatch.setenv("PATH", f"{bin_dir}{os.pathsep}{os.environ['PATH']}")
    monkeypatch.setenv("FAKE_AVRDUDE_STATE", str(state))
    monkeypatch.setenv("XDG_RUNTIME_DIR", str(tmp_path))  # the port's lock file
    return state


@pytest.fixture
def board(avrdude, tmp_path):
    server = PtyServer(FlashableBoard(avrdude), link_path=str(tmp_path / "ttyUSB0")).start()
    yield server
    server.stop()


def flash(*argv):
    return main(["flash", *argv])


def test_flash_writes_the_shipped_hex_and_the_board_then_answers(board, avrdude, capsys):
    assert board.board.profile is None  # Simulink's program, to begin with
    assert flash("--port", board.path, "--profile", "m2v3") == 0
    out, err = capsys.readouterr()
    written = json.loads(avrdude.read_text())
    # avrdude got the Mega's bootloader arguments, this port, and the shipped M2V3 image
    args = written["args"]
    assert args[args.index("-P") + 1] == board.path
    with flashing.shipped_hex("M2V3") as path:
        assert args[-1] == f"flash:w:{path}:i"
        shipped = hexfile.parse(path.read_text())
    assert written["profile"] == "M2V3" and written["bytes"] == shipped.size
    # and the board, reset by the handshake, runs it and says so
    assert board.board.profile == "M2V3"
    assert f"writing M2V3 ({shipped.size} B of flash) to {board.path}" in out
    last = out.strip().splitlines()[-1]
    assert last.startswith(f"{board.path}: minseg-virtual ")
    assert f"protocol {P.PROTOCOL_VERSION}, profile M2V3: the lab firmware runs" in last
    assert err == ""


def test_the_port_is_found_by_discovery_when_not_given(board, avrdude, capsys, monkeypatch):
    clone = ListPortInfo(board.path, skip_link_detection=True)
    clone.vid, clone.pid = 0x1A86, 0x7523  # a CH340 board
    monkeypatch.setattr(discovery, "list_ports", lambda: [clone])
    assert flash() == 0
    assert json.loads(avrdude.read_text())["profile"] == "MinSegMega"  # the default profile
    out = capsys.readouterr().out
    assert out.startswith(
        "profile MinSegMega, the default (--profile M2V3 or M1V4 for those boards)\n"
        "writing MinSegMega ("
    )
    assert out.endswith(
        f"profile MinSegMega: the lab firmware runs (next: minseg-tui board-check --port "
        f"{board.path})\n"
    )


def test_dry_run_writes_nothing(board, avrdude, capsys):
    assert flash("--port", board.path, "--profile", "M1V4", "--dry-run") == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("would write M1V4 (") and out[0].endswith(f"to {board.path} with:")
    assert " -c wiring " in out[1] and " -b 115200 -D -U flash:w:" in out[1]
    assert out[1].endswith("M1V4.hex:i")
    assert not avrdude.exists()


def test_unknown_profile(board, avrdude, capsys):
    assert flash("--port", board.path, "--profile", "MinSegMega2") == 2
    err = capsys.readouterr().err
    assert err == (
        "minseg-tui flash: --profile: expected a board profile: MinSegMega, M2V3, M1V4; "
        "got 'MinSegMega2'\n"
    )
    assert not avrdude.exists()


def test_avrdude_missing(board, tmp_path, monkeypatch, capsys):
    empty = tmp_path / "empty"
    empty.mkdir()
    monkeypatch.setenv("PATH", str(empty))
    assert flash("--port", board.path) == 2
    err = capsys.readouterr().err
    assert err.startswith("minseg-tui flash: avrdude not found on the PATH: install avrdude:")
    assert "sudo apt-get install avrdude" in err and "brew install avrdude" in err
    assert "Windows" in err and err.count("\n") == 1


def test_a_port_that_is_not_a_minseg(board, avrdude, capsys, monkeypatch):
    builtin = ListPortInfo(board.path, skip_link_detection=True)  # as a ttyS: no USB ids
    monkeypatch.setattr(discovery, "list_ports", lambda: [builtin])
    assert flash("--port", board.path) == 1
    err = capsys.readouterr().err
    assert err.startswith(f"minseg-tui flash: {board.path} is not a MinSeg (no USB vendor")
    assert "nothing was written" in err and err.count("\n") == 1
    assert not avrdude.exists()
    modem = ListPortInfo(board.path, skip_link_detection=True)
    modem.vid, modem.pid, modem.manufacturer = 0x1BC7, 0x1201, "Telit"
    monkeypatch.setattr(discovery, "list_ports", lambda: [modem])
    assert flash("--port", board.path) == 1
    assert "1BC7:1201 by Telit is not a known" in capsys.readouterr().err
    # --force: a Mega 2560 behind a USB chip discovery does not know
    assert flash("--port", board.path, "--force") == 0
    assert json.loads(avrdude.read_text())["profile"] == "MinSegMega"


def test_no_such_port_and_no_board(avrdude, tmp_path, capsys, monkeypatch):
    assert flash("--port", str(tmp_path / "ttyACM7")) == 1
    assert "ttyACM7: no such port" in capsys.readouterr().err
    monkeypatch.setattr(discovery, "list_ports", lambda: [])
    assert flash() == 1
    assert "no MinSeg found among the serial ports" in capsys.readouterr().err
    assert flash("--port", "minseg://?clock=virtual") == 2
    assert "avrdude writes to real boards only" in capsys.readouterr().err
    assert not avrdude.exists()


@pytest.mark.parametrize("dry_run", [True, False])
def test_a_file_that_is_not_a_device_is_no_port(avrdude, tmp_path, capsys, dry_run):
    regular = tmp_path / "ttyACM0"
    regular.write_text("", encoding="utf-8")
    for port, kind in ((regular, "a regular file"), (tmp_path, "a folder")):
        argv = ["--port", str(port), *(["--dry-run"] if dry_run else [])]
        assert flash(*argv) == 2
        out, err = capsys.readouterr()
        assert out == "" and err.count("\n") == 1
        assert err.startswith("minseg-tui flash: --port: expected the board's serial port")
        assert f"got {port}, {kind}" in err and "nothing was written" in err
    assert not avrdude.exists() and regular.read_text(encoding="utf-8") == ""


def test_no_bootloader_answers(board, avrdude, capsys, monkeypatch):
    monkeypatch.setenv("FAKE_AVRDUDE_MODE", "nosync")
    assert flash("--port", board.path) == 1
    err = capsys.readouterr().err
    assert err.startswith(
        f"minseg-tui flash: avrdude could not reach a Mega 2560 bootloader on {board.path} "
        "(avrdude error: timeout communicating with programmer); nothing was written"
    )
    assert err.count("\n") == 1


def test_an_avrdude_that_hangs_is_stopped(board, avrdude, capsys, monkeypatch):
    monkeypatch.setenv("FAKE_AVRDUDE_MODE", "hang")
    monkeypatch.setattr(flashing, "AVRDUDE_TIMEOUT_S", 1.0)
    assert flash("--port", board.path) == 1
    err = capsys.readouterr().err
    assert err.startswith(
        f"minseg-tui flash: avrdude could not reach a Mega 2560 bootloader on {board.path} "
        "(avrdude did not finish within 1 s: timeout); nothing was written"
    )


def test_a_write_cut_short_says_so_and_flashing_again_mends_it(board, avrdude, capsys, monkeypatch):
    monkeypatch.setenv("FAKE_AVRDUDE_MODE", "cut")
    assert flash("--port", board.path, "--profile", "M1V4") == 1
    err = capsys.readouterr().err
    assert "avrdude failed while writing" in err and "(avrdude error: programmer is not" in err
    assert "the board may be half-written" in err and "flash again with the same command" in err
    assert "the bootloader is not touched" in err and err.count("\n") == 1
    monkeypatch.setenv("FAKE_AVRDUDE_MODE", "ok")
    assert flash("--port", board.path, "--profile", "M1V4") == 0
    assert board.board.profile == "M1V4"


def test_a_second_program_on_the_port_is_refused(board, avrdude, capsys):
    held = open_exclusive(board.path, P.BAUD)  # the lab assistant has the board
    try:
        assert flash("--port", board.path) == 1
        err = capsys.readouterr().err
        assert f"{board.path} is in use by minseg-tui (pid {os.getpid()})" in err
        assert "nothing was written" in err
        assert not avrdude.exists()
    finally:
        close(held)


def test_a_board_running_other_code_is_told_to_flash(board):
    """The connect path (the TUI's and every command's): a board that sends bytes but no
    line of the protocol does not run the lab firmware, and the line says how to fix it."""
    with pytest.raises(DeviceError) as info:
        open_device(board.path, reconnect=False, boot_wait_s=0.2, reply_timeout_s=0.2)
    text = str(info.value)
    assert text.startswith(f"{board.path}: this board does not run the lab firmware")
    assert f"minseg-tui flash --port {board.path}" in text


def test_a_silent_port_gets_the_flash_command_too(scripted_silence):
    link = Link(scripted_silence, reconnect=False, boot_wait_s=0.2, reply_timeout_s=0.2)
    with pytest.raises(DeviceError) as info:
        link.open()
    text = str(info.value)
    assert text.startswith(f"no MinSeg answered on {scripted_silence} (nothing came back")
    assert f"minseg-tui flash --port {scripted_silence}" in text


@pytest.fixture
def scripted_silence():
    """A pty where nothing ever answers."""
    master, slave = os.openpty()
    name = os.ttyname(slave)
    os.close(slave)
    yield name
    os.close(master)


def _as_at_a_terminal() -> None:
    """Ctrl-C as a terminal delivers it, even where the suite was started with SIGINT
    ignored (a background job of a shell without job control): the default, which Python
    turns into KeyboardInterrupt."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_ctrl_c_while_writing_says_the_board_may_be_half_written(board, avrdude, monkeypatch):
    """The command runs as a group runs it, in its own process: the stand-in avrdude sends
    SIGINT to its parent halfway. Run inside pytest's own process, that signal landed in
    whatever the process ran at that instant (once in a garbage collector's callback, which
    swallowed it)."""
    monkeypatch.setenv("FAKE_AVRDUDE_MODE", "ctrl-c")
    proc = subprocess.run(
        [sys.executable, "-m", "minseg_tui", "flash", "--port", board.path],
        capture_output=True,
        text=True,
        timeout=120,
        preexec_fn=_as_at_a_terminal,
    )
    err = proc.stderr
    assert proc.returncode == 1, err
    assert err.startswith(f"minseg-tui flash: interrupted while avrdude wrote {board.path}: ")
    assert "may be half-written" in err and "flash again" in err and err.count("\n") == 1


def test_bad_input_from_the_installed_command_is_one_line():
    """The console script itself, as a group runs it: one line, exit 2, no traceback."""
    exe = Path(sys.executable).with_name("minseg-tui")
    proc = subprocess.run(
        [str(exe), "flash", "--profile", "Mega"], capture_output=True, text=True, timeout=60
    )
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr == (
        "minseg-tui flash: --profile: expected a board profile: MinSegMega, M2V3, M1V4; "
        "got 'Mega'\n"
    )
