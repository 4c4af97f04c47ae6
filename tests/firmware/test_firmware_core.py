"""The firmware's board-independent core, tested on the host.

Runs the C++ unit tests (firmware/test/test_core.cpp) through
`make -C firmware host-test`, so `pytest` reports them too. The binary checks
the core against firmware/golden/lines.txt, the same file the Python side
reads; a corrupted copy of that file must make it fail.
"""

import re
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
FIRMWARE = REPO / "firmware"
GOLDEN = FIRMWARE / "golden" / "lines.txt"
CLOSING = re.compile(r"^(\d+) passed, (\d+) failed$")

# one pytest-xdist worker runs this module (make test's --dist loadgroup): its fixture builds
# the sanitized test binary, and two workers each running a test of it built it twice at once
pytestmark = pytest.mark.xdist_group("firmware-host-test")


@pytest.fixture(scope="module")
def host_test() -> tuple[Path, subprocess.CompletedProcess[str]]:
    """`make -C firmware host-test` once, in firmware/build as a developer runs it: make
    compiles the test binary only when it is missing or older than a source (the build under
    the sanitizers takes half a minute), so after `make test`'s firmware-host-test step this
    runs the binary that step built."""
    proc = subprocess.run(
        ["make", "-s", "-C", str(FIRMWARE), "host-test"],
        capture_output=True,
        text=True,
        timeout=1800,  # a hang guard: at a load average of 20 the build passed 300 s
    )
    return FIRMWARE / "build" / "host" / "test_core", proc


@pytest.fixture(scope="module")
def test_binary(host_test: tuple[Path, subprocess.CompletedProcess[str]]) -> Path:
    assert host_test[0].is_file(), host_test[1].stdout + host_test[1].stderr
    return host_test[0]


def run(binary: Path, golden: Path) -> tuple[int, list[str]]:
    proc = subprocess.run([str(binary), str(golden)], capture_output=True, text=True, timeout=60)
    return proc.returncode, proc.stdout.splitlines()


def test_make_host_test_passes_standalone(
    host_test: tuple[Path, subprocess.CompletedProcess[str]],
) -> None:
    proc = host_test[1]
    assert proc.returncode == 0, proc.stdout + proc.stderr
    closing = CLOSING.match(proc.stdout.splitlines()[-1])
    assert closing is not None
    assert int(closing.group(2)) == 0
    assert int(closing.group(1)) > 300


def test_core_against_golden_lines(test_binary: Path) -> None:
    code, lines = run(test_binary, GOLDEN)
    assert code == 0, "\n".join(lines)
    assert [line for line in lines if line.startswith("FAIL")] == []
    closing = CLOSING.match(lines[-1])
    assert closing is not None and closing.group(2) == "0"


def test_corrupted_board_line_is_caught(test_binary: Path, tmp_path: Path) -> None:
    text = GOLDEN.read_text()
    assert "board $OK,PING*6C01\n" in text
    bad = tmp_path / "lines.txt"
    bad.write_text(text.replace("board $OK,PING*6C01\n", "board $OK,PING*6C02\n"))
    code, lines = run(test_binary, bad)
    assert code == 1
    closing = CLOSING.match(lines[-1])
    assert closing is not None and int(closing.group(2)) >= 1
    assert any("$OK,PING*6C02" in line for line in lines if line.startswith("FAIL"))


def test_wrong_error_code_is_caught(test_binary: Path, tmp_path: Path) -> None:
    text = GOLDEN.read_text()
    assert "error UNKNOWN FOO\n" in text
    bad = tmp_path / "lines.txt"
    bad.write_text(text.replace("error UNKNOWN FOO\n", "error ARGS FOO\n"))
    code, lines = run(test_binary, bad)
    assert code == 1
    assert any("FOO" in line for line in lines if line.startswith("FAIL"))


def test_unlisted_host_command_is_caught(test_binary: Path, tmp_path: Path) -> None:
    # a host line the tests have no hand-written expectation for must fail, not pass silently
    bad = tmp_path / "lines.txt"
    bad.write_text(GOLDEN.read_text().replace("host $Z*1A4F\n", "host $Z*1A4F\nhost $V,1*450B\n"))
    code, lines = run(test_binary, bad)
    assert code == 1
    assert any("$V,1*450B" in line for line in lines if line.startswith("FAIL"))
