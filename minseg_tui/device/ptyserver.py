"""The virtual MinSeg on a pseudo-terminal, in real time: any serial program can open it.

The server holds the master side of a pty pair and serves a :class:`VirtualBoard` on it;
programs open the slave side (``path``). Opening the slave resets the board, as DTR
resets a Mega; while nobody has it open the board keeps running and its output is lost.
``unplug()`` closes the master (the program's reads fail, as with a pulled cable) and
``replug()`` makes a new pty; give ``link_path`` to get a stable symlink that always
points at the current one.
"""

from __future__ import annotations

import contextlib
import errno
import os
import select
import threading
import time
import tty

from minseg_tui.device.virtual import RealTime, VirtualBoard

_IDLE_S = 0.02  # how often to look for a program opening the slave, s
_MAX_PENDING = 64 * 1024  # bytes kept when the program does not read; the rest is lost


class PtyServer:
    """Serve one virtual board on a pty. Board time is host time (real-time clock)."""

    def __init__(self, board: VirtualBoard | None = None, link_path: str | None = None) -> None:
        self.board = board or VirtualBoard()
        self.link_path = link_path
        self.clock = RealTime(self.board.now)
        self.board.clock = self.clock  # a hand's turn happens now (VirtualBoard.turn_by_hand)
        self.master: int | None = None
        self.slave_name = ""
        self.lost_bytes = 0
        self.opens = 0
        self._attached = False
        self._pending = bytearray()
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._thread: threading.Thread | None = None
        self._make_pty()

    @property
    def path(self) -> str:
        """The device a program opens: the symlink if one was asked for, else the slave."""
        return self.link_path or self.slave_name

    def _make_pty(self) -> None:
        master, slave = os.openpty()
        tty.setraw(slave)
        os.set_blocking(master, False)
        self.slave_name = os.ttyname(slave)
        os.close(slave)  # keep no slave open: a program opening it is then visible (no HUP)
        self.master = master
        self._attached = False
        self._pending.clear()
        if self.link_path:
            tmp = f"{self.link_path}.new"
            try:
                with contextlib.suppress(FileNotFoundError):
                    os.unlink(tmp)
                os.symlink(self.slave_name, tmp)
                os.replace(tmp, self.link_path)
            except OSError:
                with contextlib.suppress(OSError):
                    os.unlink(tmp)
                os.close(master)
                self.master = None
                raise

    # -- the cable -------------------------------------------------------------------------
    def unplug(self) -> None:
        """Pull the cable: the board loses power and the program's port fails.

        The symlink goes first, as udev removes a board's /dev/serial/by-id link when it is
        unplugged: a program that tries the link meanwhile finds no such port. Left in
        place, it would name the pty's number once the kernel hands that number to another
        pty, and a program trying it would open (and lock) someone else's port."""
        with self._lock:
            self._remove_link()
            if self.master is not None:
                os.close(self.master)
                self.master = None
            self._attached = False
            self.board.unplug()

    def replug(self) -> None:
        """Plug it back: a new pty (the symlink follows); opening it boots the board."""
        with self._lock:
            self.board.replug()
            if self.master is None:
                self._make_pty()

    # -- serving ---------------------------------------------------------------------------
    def start(self) -> PtyServer:
        """Serve in a background thread (returns self)."""
        self._thread = threading.Thread(target=self.serve_forever, name="minseg-pty", daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        """Stop serving and close the pty (and remove the symlink)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(2.0)
        with self._lock:
            if self.master is not None:
                os.close(self.master)
                self.master = None
        self._remove_link()

    def _remove_link(self) -> None:
        """Remove the symlink if it still names this server's pty (else it is not ours)."""
        if self.link_path:
            with contextlib.suppress(OSError):
                if os.readlink(self.link_path) == self.slave_name:
                    os.unlink(self.link_path)

    def serve_forever(self) -> None:
        """Run the board until :meth:`stop` (or KeyboardInterrupt in the caller)."""
        while not self._stop.is_set():
            with self._lock:
                wait = self._serve_once()
            if wait <= 0:
                continue
            if self.master is None or not self._attached:
                time.sleep(wait)
            else:
                self._wait(wait)

    def _wait(self, seconds: float) -> None:
        master = self.master
        if master is None:
            return
        poller = select.poll()
        poller.register(master, select.POLLIN)
        poller.poll(max(0.0, seconds) * 1000.0)

    def _serve_once(self) -> float:
        """Do what is due now; return how long to wait, s."""
        board, now = self.board, self.clock()
        board.run_until(now)
        master = self.master
        if master is None:
            return _IDLE_S
        poller = select.poll()
        poller.register(master, select.POLLIN)
        ready = dict(poller.poll(0))
        hup = bool(ready.get(master, 0) & select.POLLHUP)
        if hup:
            if self._attached:
                self._attached = False
            board.take_output()  # nobody listens
            self._pending.clear()
            return _IDLE_S
        if not self._attached:
            self._attached = True  # a program opened the slave: DTR resets the board
            self.opens += 1
            board.reset()
        if ready.get(master, 0) & select.POLLIN:
            try:
                data = os.read(master, 4096)
            except OSError:
                data = b""
            if data:
                board.feed(data)
        self._pending += board.take_output()
        if self._pending:
            try:
                n = os.write(master, self._pending)
                del self._pending[:n]
            except BlockingIOError:
                pass
            except OSError as exc:
                if exc.errno not in (errno.EIO, errno.EAGAIN):
                    raise
            if len(self._pending) > _MAX_PENDING:
                self.lost_bytes += len(self._pending)
                self._pending.clear()
        if self._pending:
            return 0.001
        return max(0.0, min(board.next_event() - self.clock(), 0.05))
