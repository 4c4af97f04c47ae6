"""Writing the lab firmware to a MinSeg with avrdude, from the .hex files this package ships.

The package carries one Intel HEX per board profile (``minseg_tui/device/hex/<profile>.hex``,
built by ``make -C firmware all-profiles``), so a lab PC needs avrdude but no compiler.
The Mega 2560's bootloader speaks STK500v2 ("wiring" in avrdude) at 115200 baud; ``-D``
keeps avrdude from erasing the chip first (the bootloader erases page by page), and
``-U flash:w:...`` writes the application only: the bootloader is never touched, so a
board whose write was cut short can always be flashed again.

Maintainers: ``python -m minseg_tui.device.flashing check firmware/build`` compares each
profile's build with the shipped .hex (the memory image, :mod:`hexfile`), ``refresh``
copies the build over the shipped files and writes the build's flash and RAM use (avr-size)
into firmware/README.md's memory table (``make firmware-hex`` builds, then refreshes).
"""

from __future__ import annotations

import contextlib
import re
import shutil
import subprocess
import sys
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from minseg_tui.device import hexfile
from minseg_tui.device.board_profiles import DEFAULT_PROFILE as DEFAULT_PROFILE
from minseg_tui.device.board_profiles import PROFILES as PROFILES

MCU = "atmega2560"
PROGRAMMER = "wiring"
"""avrdude's name for the Mega 2560 bootloader (STK500 version 2 with the Wiring reset)."""
BOOTLOADER_BAUD = 115200

INSTALL_AVRDUDE = (
    "install avrdude: Debian/Ubuntu `sudo apt-get install avrdude`, Fedora `sudo dnf install "
    "avrdude`, macOS `brew install avrdude`, Windows: avrdude.exe from "
    "https://github.com/avrdudes/avrdude/releases on the PATH"
)

RECOVER = (
    "flash again with the same command (the bootloader is not touched by a flash write, "
    "so the board can always be written again; unplug and plug it first if it hangs)"
)

AVRDUDE_TIMEOUT_S = 120.0
"""Longest an avrdude run may take, s: a write of 9 kB takes a few seconds, and avrdude 7.1
gives up on a port where no bootloader answers after about 40 s (measured on a pty); on a
port that cannot be opened it can loop for good (seen with avrdude 7.1 and -c wiring), which
is why the command checks the port first."""


def profile_named(name: str) -> str:
    """The profile spelled as the firmware spells it (any case accepted); ValueError with
    the known names otherwise."""
    for profile in PROFILES:
        if profile.lower() == name.strip().lower():
            return profile
    raise ValueError(f"expected a board profile: {', '.join(PROFILES)}; got {name!r}")


def _hex_dir() -> resources.abc.Traversable:
    return resources.files("minseg_tui.device").joinpath("hex")


def shipped_hex_text(profile: str) -> str:
    """The shipped Intel HEX of a profile, as text (FileNotFoundError if it is missing)."""
    return _hex_dir().joinpath(f"{profile}.hex").read_text(encoding="ascii")


@contextlib.contextmanager
def shipped_hex(profile: str) -> Iterator[Path]:
    """A file system path of the shipped .hex of ``profile`` for as long as the context
    lasts (a temporary copy when the package is not unpacked on disk)."""
    with resources.as_file(_hex_dir().joinpath(f"{profile}.hex")) as path:
        yield Path(path)


def find_avrdude() -> str | None:
    """The avrdude on the PATH, or None."""
    return shutil.which("avrdude")


def avrdude_command(avrdude: str, port: str, hex_path: str) -> list[str]:
    """The avrdude command line that writes ``hex_path`` to the Mega 2560 on ``port``.

    The format letter ``i`` (Intel HEX) ends the -U argument, so a Windows path with its
    drive letter (``C:\\...``) is read whole.
    """
    return [
        avrdude,
        "-p",
        MCU,
        "-c",
        PROGRAMMER,
        "-P",
        port,
        "-b",
        str(BOOTLOADER_BAUD),
        "-D",
        "-U",
        f"flash:w:{hex_path}:i",
    ]


@dataclass(frozen=True)
class AvrdudeRun:
    """What an avrdude run did: its exit code and everything it printed."""

    returncode: int
    output: str

    @property
    def ok(self) -> bool:
        """True when avrdude wrote and verified the flash."""
        return self.returncode == 0

    @property
    def began_writing(self) -> bool:
        """True when avrdude got as far as writing the flash (a failure from there on may
        leave the board half-written)."""
        text = self.output.lower()
        return "writing" in text or "bytes of flash written" in text

    def reason(self) -> str:
        """avrdude's own words for what went wrong: its most telling line, shortened."""
        lines = [ln.strip() for ln in self.output.splitlines() if ln.strip()]
        for key in _TELLING:
            found = next((ln for ln in lines if key in ln.lower()), None)
            if found is not None:
                return found if len(found) <= 160 else found[:157] + "..."
        return lines[-1] if lines else f"exit code {self.returncode}"


_TELLING = (
    "timeout communicating",
    "not in sync",
    "verification error",
    "mismatch",
    "not responding",
    "permission denied",
    "cannot open port",
    "can't open",
    "unable to open",
    "did not finish",
    "error",
    "timeout",
)
"""Words of avrdude's lines, the most telling first (a pty's ioctl complaints come before
the timeout that matters, and say less)."""


def run_avrdude(command: Sequence[str], timeout_s: float | None = None) -> AvrdudeRun:
    """Run avrdude, its output collected (stdout and stderr together). A run that outlives
    ``timeout_s`` (default :data:`AVRDUDE_TIMEOUT_S`) is killed and reported with exit code
    -1 and what it had printed."""
    if timeout_s is None:
        timeout_s = AVRDUDE_TIMEOUT_S
    try:
        proc = subprocess.run(
            list(command),
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            errors="replace",
            timeout=timeout_s,
            check=False,
        )
    except subprocess.TimeoutExpired as exc:
        out = exc.output or ""
        text = out if isinstance(out, str) else out.decode("ascii", "replace")
        return AvrdudeRun(-1, f"{text}\navrdude did not finish within {timeout_s:g} s: timeout")
    return AvrdudeRun(proc.returncode, proc.stdout)


# -- maintainers: the shipped .hex against a build ---------------------------------------
def _built(build: Path, profile: str) -> Path:
    return build / profile / "minseg-fw.hex"


def check(build: Path) -> list[str]:
    """One line per profile whose build differs from the shipped .hex (empty: all same)."""
    problems = []
    for profile in PROFILES:
        built_path = _built(build, profile)
        try:
            built = hexfile.parse(built_path.read_text(encoding="ascii"), str(built_path))
        except (OSError, ValueError) as exc:
            problems.append(f"{profile}: cannot read the build ({exc})")
            continue
        try:
            shipped = hexfile.parse(shipped_hex_text(profile), f"shipped {profile}.hex")
        except (OSError, ValueError) as exc:
            problems.append(f"{profile}: cannot read the shipped .hex ({exc})")
            continue
        at = built.first_difference(shipped)
        if at is not None:
            problems.append(
                f"{profile}: the shipped minseg_tui/device/hex/{profile}.hex ({shipped.size} B) "
                f"is not what the firmware builds to now ({built_path}, {built.size} B; first "
                f"difference at 0x{at:04X})"
            )
    return problems


def refresh(build: Path, into: Path) -> list[str]:
    """Copy each profile's built .hex into ``into`` as <profile>.hex; one line per file."""
    done = []
    for profile in PROFILES:
        src = _built(build, profile)
        image = hexfile.parse(src.read_text(encoding="ascii"), str(src))
        shutil.copyfile(src, into / f"{profile}.hex")
        done.append(f"{profile}: {image.size} B from {src}")
    return done


_SIZE = re.compile(r"^(Program|Data):\s+(\d+) bytes \(([\d.]+)% Full\)", re.M)


def memory_use(elf: Path) -> tuple[str, str]:
    """(flash, RAM) of a built ELF as firmware/README.md's table writes them ("9102 B
    (3.5 %)", "827 B (10.1 %)"), from ``avr-size -C``; OSError/ValueError if it cannot."""
    out = subprocess.run(
        ["avr-size", "-C", f"--mcu={MCU}", str(elf)],
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    ).stdout
    found = {m.group(1): f"{m.group(2)} B ({m.group(3)} %)" for m in _SIZE.finditer(out)}
    if set(found) != {"Program", "Data"}:
        raise ValueError(f"avr-size printed no Program/Data lines for {elf}")
    return found["Program"], found["Data"]


def refresh_table(build: Path, readme: Path) -> list[str]:
    """Rewrite the rows of the profiles in ``readme``'s memory table (``| <profile> | flash
    | RAM |``) with what avr-size says of the build, a new profile's row put after the row of
    the profile before it; one line per row written."""
    text = readme.read_text(encoding="utf-8")
    done: list[str] = []
    for profile in PROFILES:
        flash, ram = memory_use(build / profile / "minseg-fw.elf")
        row = f"| {profile} | {flash} | {ram} |"
        text, n = re.subn(rf"^\| {profile} \| [^|\n]* \| [^|\n]* \|$", row, text, flags=re.M)
        if n == 0 and done and text.count(f"\n{done[-1]}\n") == 1:
            text = text.replace(f"\n{done[-1]}\n", f"\n{done[-1]}\n{row}\n")
        elif n != 1:
            raise ValueError(f"{readme}: expected one memory table row for {profile}, found {n}")
        done.append(row)
    readme.write_text(text, encoding="utf-8")
    return done


def main(argv: Sequence[str] | None = None) -> int:
    """``check BUILD`` (exit 1 with a line per difference) or ``refresh BUILD``."""
    args = list(sys.argv[1:] if argv is None else argv)
    if len(args) != 2 or args[0] not in ("check", "refresh"):
        print("usage: python -m minseg_tui.device.flashing check|refresh BUILD", file=sys.stderr)
        return 2
    build = Path(args[1])
    if args[0] == "refresh":
        into = Path(__file__).resolve().parent / "hex"
        try:
            for line in refresh(build, into):
                print(f"shipped hex refreshed: {line}")
            readme = build.parent / "README.md"
            for line in refresh_table(build, readme):
                print(f"{readme}: {line}")
        except (OSError, ValueError, subprocess.SubprocessError) as exc:
            print(f"error: cannot refresh the shipped hex: {exc}", file=sys.stderr)
            return 1
        return 0
    problems = check(build)
    for line in problems:
        print(f"error: {line}", file=sys.stderr)
    if problems:
        print(
            "error: the shipped .hex files are stale: run `make firmware-hex` and commit "
            "minseg_tui/device/hex/",
            file=sys.stderr,
        )
        return 1
    print(f"shipped hex: {', '.join(PROFILES)} equal to the build in {build}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
