"""Intel HEX, as avr-objcopy writes it and avrdude reads it: the memory image in a file.

Only the image counts (address -> byte): two files with the same bytes at the same
addresses are the same firmware, however their records are cut. Record types 00 (data),
01 (end), 02 (extended segment address) and 04 (extended linear address) are read; 03
and 05 (start address) say where to jump, not what is in flash, and are skipped.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class HexImage:
    """The bytes an Intel HEX file puts into memory: ``data[address]`` (bytes, addresses)."""

    data: dict[int, int]

    @property
    def size(self) -> int:
        """Bytes written, B (the figure avr-size calls Program)."""
        return len(self.data)

    def first_difference(self, other: HexImage) -> int | None:
        """The lowest address (B) where the two images differ (a byte present in one only
        counts), or None when they are the same."""
        for address in sorted(self.data.keys() | other.data.keys()):
            if self.data.get(address) != other.data.get(address):
                return address
        return None

    def contains(self, text: bytes) -> bool:
        """True when ``text`` stands in the image at consecutive addresses."""
        if not self.data:
            return False
        lo, hi = min(self.data), max(self.data)
        flat = bytes(self.data.get(a, 0xFF) for a in range(lo, hi + 1))
        return text in flat


def parse(text: str, source: str = "hex") -> HexImage:
    """The image of an Intel HEX text; ValueError naming ``source`` and the line otherwise
    (a bad record, a wrong checksum, no end record, a byte written twice)."""
    data: dict[int, int] = {}
    base = 0
    ended = False
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line:
            continue
        where = f"{source}:{number}"
        if ended:
            raise ValueError(f"{where}: a record after the end record")
        if not line.startswith(":") or len(line) < 11 or len(line) % 2 == 0:
            raise ValueError(f"{where}: expected an Intel HEX record (':' and hex digits)")
        try:
            record = bytes.fromhex(line[1:])
        except ValueError:
            raise ValueError(f"{where}: expected hex digits after ':'") from None
        count, kind = record[0], record[3]
        if len(record) != count + 5:
            raise ValueError(f"{where}: the record says {count} bytes, holds {len(record) - 5}")
        if sum(record) & 0xFF:
            raise ValueError(f"{where}: wrong checksum")
        payload = record[4:-1]
        address = base + (record[1] << 8 | record[2])
        if kind == 0:
            for i, byte in enumerate(payload):
                if address + i in data:
                    raise ValueError(f"{where}: address 0x{address + i:X} written twice")
                data[address + i] = byte
        elif kind == 1:
            ended = True
        elif kind == 2 and count == 2:
            base = (payload[0] << 8 | payload[1]) << 4
        elif kind == 4 and count == 2:
            base = (payload[0] << 8 | payload[1]) << 16
        elif kind in (3, 5):
            continue
        else:
            raise ValueError(f"{where}: record type {kind:02X} with {count} bytes is not Intel HEX")
    if not ended:
        raise ValueError(f"{source}: no end record (the file is cut short)")
    return HexImage(data)
