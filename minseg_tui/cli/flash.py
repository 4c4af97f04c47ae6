"""`minseg-tui flash`: write the lab firmware shipped with this package to a MinSeg, then
shake hands with it to confirm it runs.

The board is found as the lab assistant finds it (by USB id: a Mega 2560 with a 16U2 is
/dev/ttyACM*, a CH340 clone /dev/ttyUSB*), or given with --port. avrdude writes the
profile's .hex through the board's bootloader (-U flash only: the bootloader stays, so a
cut-short write is mended by flashing again). Exit 0: written and the board answers with
this minseg-tui's protocol and the profile written; 2: bad input (an unknown profile, no
avrdude, a URL or a file that is not a device for a port); 1: a device problem (no board, not a MinSeg, avrdude failed,
no answer after the write), each in one line that says what state the board is in.
"""

from __future__ import annotations

import argparse
import os
import shlex
from pathlib import Path

from minseg_tui.device import discovery, flashing, hexfile
from minseg_tui.device import protocol as P
from minseg_tui.device.link import Link
from minseg_tui.device.port import lock_path, not_a_device
from minseg_tui.errors import DeviceError, InputError
from minseg_tui.lock import FileLock, LockHeld

PROGRAM = "minseg-tui flash"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """--port, --profile, --dry-run, --force."""
    parser.add_argument(
        "--port",
        metavar="PORT",
        help="the board's serial port (Linux /dev/ttyACM0 or, CH340 boards, /dev/ttyUSB0; "
        "Windows COM3); default: the board discovery finds (`minseg-tui ports`)",
    )
    parser.add_argument(
        "--profile",
        metavar="NAME",
        help=f"board profile: {', '.join(flashing.PROFILES)} (default {flashing.DEFAULT_PROFILE})",
    )
    parser.add_argument(
        "--dry-run",
        action="store_true",
        help="check everything and print the avrdude command, write nothing",
    )
    parser.add_argument(
        "--force",
        action="store_true",
        help="write even to a port that discovery does not take for a MinSeg "
        "(a Mega 2560 behind a USB chip it does not know)",
    )


def _profile(name: str | None) -> str:
    if name is None:
        return flashing.DEFAULT_PROFILE
    try:
        return flashing.profile_named(name)
    except ValueError as exc:
        raise InputError("--profile", None, str(exc)) from None


def _avrdude() -> str:
    found = flashing.find_avrdude()
    if found is None:
        raise InputError("", None, f"avrdude not found on the PATH: {flashing.INSTALL_AVRDUDE}")
    return found


def _port(requested: str | None, force: bool) -> str:
    """The port to write to: the one given (checked against discovery) or the one found."""
    if requested is None:
        found = discovery.find_board()
        if found is None:
            raise DeviceError(
                "no MinSeg found among the serial ports (`minseg-tui ports` says why each was "
                "left out): plug the board in, or give --port (Linux /dev/ttyACM0 or "
                "/dev/ttyUSB0 for a CH340 board, Windows COM3); nothing was written"
            )
        return found.device
    if "://" in requested:
        raise InputError(
            "--port",
            None,
            f"expected the board's serial device (/dev/ttyACM0, /dev/ttyUSB0, COM3), got the "
            f"URL {requested!r}: avrdude writes to real boards only",
        )
    why = not_a_device(requested)
    if why:
        raise InputError("--port", None, f"{why}; nothing was written")
    real = os.path.realpath(requested)
    listed = {os.path.realpath(c.device): c for c in discovery.candidates()}
    cand = listed.get(real)
    if cand is None and os.name == "posix" and not os.path.exists(requested):
        raise DeviceError(
            f"{requested}: no such port (is the board plugged in? `minseg-tui ports` lists "
            "the serial ports); nothing was written"
        )
    if cand is not None and cand.verdict == "ignored" and not force:
        raise DeviceError(
            f"{requested} is not a MinSeg ({cand.reason}); nothing was written: give the "
            "board's port (`minseg-tui ports`), or --force for a Mega 2560 behind another "
            "USB chip"
        )
    return requested


def _take_port(port: str) -> FileLock | None:
    """minseg-tui's lock on the port (DeviceError when another minseg-tui has it)."""
    lock = FileLock(Path(lock_path(port)), PROGRAM)
    try:
        lock.acquire()
    except LockHeld as exc:
        raise DeviceError(
            f"{port} is in use by {exc.holder}: close that program first; nothing was written"
        ) from None
    except OSError:
        return None  # no writable runtime folder: avrdude's own open still fails if busy
    return lock


def _write(avrdude: str, port: str, profile: str, dry_run: bool, chosen: bool) -> bool:
    """Run avrdude (or print its command); True when it wrote. ``chosen``: the profile was
    given (else the default is named as such)."""
    with flashing.shipped_hex(profile) as hex_path:
        try:
            size = hexfile.parse(hex_path.read_text(encoding="ascii"), str(hex_path)).size
        except (OSError, ValueError) as exc:
            raise DeviceError(
                f"the {profile} firmware shipped with this minseg-tui cannot be read ({exc}): "
                "reinstall minseg-tui; nothing was written"
            ) from None
        command = flashing.avrdude_command(avrdude, port, str(hex_path))
        what = f"{profile} ({size} B of flash)"
        if not chosen:
            others = " or ".join(p for p in flashing.PROFILES if p != profile)
            print(f"profile {profile}, the default (--profile {others} for those boards)")
        if dry_run:
            print(f"would write {what} to {port} with:")
            print(shlex.join(command))
            return False
        lock = _take_port(port)
        try:
            print(f"writing {what} to {port} with avrdude ...", flush=True)
            result = flashing.run_avrdude(command)
        except KeyboardInterrupt:
            raise DeviceError(
                f"interrupted while avrdude wrote {port}: the board may be half-written and "
                f"will not run until written whole: {flashing.RECOVER}"
            ) from None
        finally:
            if lock is not None:
                lock.release()
    if result.ok:
        return True
    if result.began_writing:
        raise DeviceError(
            f"avrdude failed while writing {port} ({result.reason()}): the board may be "
            f"half-written and will not run until written whole: {flashing.RECOVER}"
        )
    raise DeviceError(
        f"avrdude could not reach a Mega 2560 bootloader on {port} ({result.reason()}); "
        "nothing was written, the board runs what it ran before: check the port "
        "(`minseg-tui ports`), that no other program has it open, and on Linux that you may "
        "use it (group dialout: sudo usermod -aG dialout $USER, then log in again)"
    )


def _confirm(port: str, profile: str) -> P.Ident:
    """Shake hands with the freshly written board; DeviceError when it does not answer
    with this minseg-tui's protocol and ``profile``."""
    link = Link(port, reconnect=False, program=PROGRAM)
    try:
        ident = link.open()
    except DeviceError as exc:
        raise DeviceError(
            f"avrdude wrote and verified {profile} on {port}, but the handshake failed: {exc}"
        ) from None
    finally:
        link.close()
    if ident.board != profile:
        raise DeviceError(
            f"{port} answers as {ident.board} ({ident.fw}) after {profile} was written: "
            f"flash again with --profile {profile}, or check which board this is"
        )
    return ident


def run(args: argparse.Namespace) -> int:
    """Check the profile, avrdude and the port, write, confirm; exit 0 when the board runs
    the firmware written."""
    profile = _profile(args.profile)
    avrdude = _avrdude()
    port = _port(args.port, args.force)
    if not _write(avrdude, port, profile, args.dry_run, args.profile is not None):
        return 0
    ident = _confirm(port, profile)
    print(
        f"{port}: {ident.fw}, protocol {ident.proto}, profile {ident.board}: the lab "
        f"firmware runs (next: minseg-tui board-check --port {port})"
    )
    return 0
