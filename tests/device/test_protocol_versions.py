"""A board running older firmware is told apart by its protocol version, not lost.

A protocol-1 board (XOR checksums of two hex digits) that is already running (no $BOOT
on open, as with a board whose reset line is not wired) must still answer the host's
ID and get the clear version message, not "no MinSeg answered".
"""

import os
import threading
import tty

import pytest

from minseg_tui.device.link import Link
from minseg_tui.errors import DeviceError


def _xor_line(body: str) -> bytes:
    cs = 0
    for b in body.encode():
        cs ^= b
    return f"${body}*{cs:02X}\n".encode()


class ProtocolOneBoard:
    """A pty that answers as minseg-fw 1.0.0 (protocol 1) does: ID with or without a
    two-digit checksum gets $ID, a four-digit checksum gets $ERR,CHECKSUM."""

    def __init__(self) -> None:
        self.master, slave = os.openpty()
        tty.setraw(slave)
        self.path = os.ttyname(slave)
        self._slave = slave  # kept open so the pty stays up before the link opens it
        self._stop = threading.Event()
        self.heard: list[bytes] = []
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self) -> None:
        buf = b""
        os.set_blocking(self.master, False)
        while not self._stop.is_set():
            try:
                buf += os.read(self.master, 1024)
            except BlockingIOError:
                self._stop.wait(0.005)
                continue
            except OSError:
                return
            *lines, buf = buf.split(b"\n")
            for line in lines:
                self.heard.append(line)
                cmd = line.rstrip(b"\r").lstrip(b"$")
                name, _, cs = cmd.partition(b"*")
                if name == b"ID" and len(cs) in (0, 2):
                    reply = _xor_line("ID,minseg-fw 1.0.0,1,MinSegMega,720,25000,5000,BRAKE")
                else:
                    reply = _xor_line("ERR,CHECKSUM")
                os.write(self.master, reply)

    def close(self) -> None:
        self._stop.set()
        self.thread.join(2)
        os.close(self.master)
        os.close(self._slave)


@pytest.fixture
def old_board():
    board = ProtocolOneBoard()
    yield board
    board.close()


def test_a_running_protocol_one_board_gets_the_version_message(old_board):
    link = Link(old_board.path, boot_wait_s=0.1, reply_timeout_s=1.0, reconnect=False)
    with pytest.raises(DeviceError) as info:
        link.open()
    text = str(info.value)
    assert "minseg-fw 1.0.0" in text and "protocol 1" in text and "protocol 3" in text
    assert "minseg-tui flash" in text
