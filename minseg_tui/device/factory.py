"""One switch for real and simulated boards: open a device by a spec, get a Link.

Specs: ``auto`` (the discovered board, else a virtual one), ``virtual`` (a virtual
board in real time), a port path (``/dev/ttyACM0``, a ``minseg-tui sim`` pty) or any
pyserial URL (``minseg://?seed=1&coulomb=0.004``). The UI and the tests use only this.
"""

from __future__ import annotations

from typing import Any

from minseg_tui.device import discovery
from minseg_tui.device.link import Link

VIRTUAL = "minseg://?clock=real"
"""The virtual board ``auto`` falls back to (and ``virtual`` means)."""


def resolve(spec: str = "auto", virtual: str = VIRTUAL) -> tuple[str, tuple[int, int] | None]:
    """(port or URL, USB VID:PID to rediscover it by) for a spec, without opening anything."""
    if spec == "auto":
        found = discovery.find_board()
        if found is not None and found.vid is not None and found.pid is not None:
            return found.device, (found.vid, found.pid)
        return virtual, None
    if spec == "virtual":
        return virtual, None
    return spec, None


def open_device(spec: str = "auto", *, virtual: str = VIRTUAL, **link_options: Any) -> Link:
    """Open and handshake a board by spec (see the module); raises DeviceError with the reason.

    ``link_options`` go to :class:`Link` (on_event, keepalive_s, reconnect, ...).
    """
    port, vid_pid = resolve(spec, virtual)
    link = Link(port, vid_pid=vid_pid, **link_options)
    link.open()
    return link
