"""The .hex files the package ships for `minseg-tui flash`: one per profile, readable where
the installed package finds them, and the maintainers' check that they equal a rebuild
(`make test`'s firmware step runs it on the fresh build)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from minseg_tui.device import flashing, hexfile


def test_shipped_hex_are_intel_hex_of_their_profile():
    """Each shipped .hex reads whole and carries its own profile's name (the one $ID
    reports), and no other's."""
    for profile in flashing.PROFILES:
        image = hexfile.parse(flashing.shipped_hex_text(profile), profile)
        assert 4000 < image.size < 64 * 1024, (profile, image.size)
        named = [p for p in flashing.PROFILES if image.contains(p.encode() + b"\0")]
        assert named == [profile]


def intel_hex(image: hexfile.HexImage, per_record: int) -> str:
    """``image`` written as Intel HEX with ``per_record`` bytes per data record."""
    lines = []
    addresses = sorted(image.data)
    run: list[int] = []
    for a in addresses + [-1]:
        if run and (a != run[-1] + 1 or len(run) == per_record):
            rec = bytes([len(run), run[0] >> 8 & 0xFF, run[0] & 0xFF, 0])
            rec += bytes(image.data[x] for x in run)
            lines.append(":" + (rec + bytes([-sum(rec) & 0xFF])).hex().upper())
            run = []
        run.append(a)
    return "\n".join([*lines, ":00000001FF", ""])


def test_check_compares_the_image_not_the_text(tmp_path, capsys):
    build = tmp_path / "build"
    for profile in flashing.PROFILES:
        (build / profile).mkdir(parents=True)
        (build / profile / "minseg-fw.hex").write_text(flashing.shipped_hex_text(profile))
    assert flashing.main(["check", str(build)]) == 0
    assert "equal to the build" in capsys.readouterr().out
    # the same bytes in records cut another way: the same firmware
    m2v3 = hexfile.parse(flashing.shipped_hex_text("M2V3"))
    built = build / "M2V3" / "minseg-fw.hex"
    built.write_text(intel_hex(m2v3, 32))
    assert built.read_text() != flashing.shipped_hex_text("M2V3")
    assert flashing.main(["check", str(build)]) == 0
    capsys.readouterr()
    # one byte changed: named, with its address, and the command that fixes it
    changed = dict(m2v3.data)
    changed[0x0123] ^= 0x01
    built.write_text(intel_hex(hexfile.HexImage(changed), 16))
    assert flashing.main(["check", str(build)]) == 1
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith("error: M2V3: the shipped minseg_tui/device/hex/M2V3.hex (")
    assert err[0].endswith("first difference at 0x0123)")
    assert err[1] == (
        "error: the shipped .hex files are stale: run `make firmware-hex` and commit "
        "minseg_tui/device/hex/"
    )
    (build / "M1V4" / "minseg-fw.hex").unlink()
    assert flashing.main(["check", str(build)]) == 1
    assert "M1V4: cannot read the build" in capsys.readouterr().err


def test_intel_hex_that_is_not():
    good = flashing.shipped_hex_text("M1V4").splitlines()
    for lines, why in [
        (good[:-1], "no end record"),
        ([good[0][:-2] + "00", *good[1:]], ":1: wrong checksum"),
        (["0C949B00", *good[1:]], ":1: expected an Intel HEX record"),
        ([good[0], good[0], *good[1:]], "written twice"),
        ([*good, good[0]], "a record after the end record"),
    ]:
        with pytest.raises(ValueError, match=why):
            hexfile.parse("\n".join(lines), "x.hex")


def test_the_memory_table_says_what_is_shipped():
    """firmware/README.md's flash column is the size of each shipped image (avr-size's
    Program is the bytes the .hex writes): `make firmware-hex` rewrites the rows, so a
    table left behind by a hand-made refresh fails here."""
    readme = (Path(__file__).resolve().parents[2] / "firmware" / "README.md").read_text()
    for profile in flashing.PROFILES:
        size = hexfile.parse(flashing.shipped_hex_text(profile)).size
        (row,) = re.findall(rf"^\| {profile} \| (\d+) B \(", readme, flags=re.M)
        assert int(row) == size, profile
