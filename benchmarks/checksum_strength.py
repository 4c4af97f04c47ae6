"""How many corrupted lines each checksum lets through: protocol 1's XOR against
protocol 2's CRC-16.

Corpus: the golden board lines and the lines a virtual MinSeg sends during a step run
(seeded). Corruptions: every swap of two adjacent, different bytes after the `$`, and
every loss of a pair of adjacent, equal bytes (both typical of a serial link that
loses or reorders bytes). A corrupted line is "let through" when its checksum matches
under the scheme and its fields still make a valid line that differs from the original,
that is when it would reach the host as a false message. Prints the fractions.
"""

from __future__ import annotations

from pathlib import Path

from minseg_tui.device import protocol as P
from minseg_tui.device.virtual import VirtualBoard, VirtualSettings

GOLDEN = Path(__file__).resolve().parents[1] / "firmware" / "golden" / "lines.txt"


def xor8(body: str) -> int:
    """Protocol 1's checksum: the XOR of the body's bytes, two hex digits."""
    cs = 0
    for b in body.encode("ascii"):
        cs ^= b
    return cs


def crc8(body: str) -> int:
    """CRC-8 (polynomial 0x07, the alternative considered): two hex digits."""
    crc = 0
    for b in body.encode("ascii"):
        crc ^= b
        for _ in range(8):
            crc = ((crc << 1) ^ 0x07) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc


SCHEMES = {
    "XOR-8 (protocol 1)": (xor8, 2),
    "CRC-8/0x07 (considered)": (crc8, 2),
    "CRC-16/CCITT-FALSE (protocol 2)": (P.checksum, 4),
}


def bodies() -> list[str]:
    """The text between `$` and `*` of every line in the corpus."""
    out = [
        line.split(" ", 1)[1][1:].rsplit("*", 1)[0]
        for line in GOLDEN.read_text().splitlines()
        if line.startswith("board ")
    ]
    board = VirtualBoard(VirtualSettings(seed=7))
    board.run_until(0.01)
    board.feed(b"STEP,0,4500,250,40\n")
    for k in range(200):  # 20 s of a step run, kept alive
        board.run_until(0.01 + 0.1 * (k + 1))
        board.feed(b"PING\n")
    for raw in board.take_output().decode("ascii").splitlines():
        out.append(raw[1:].rsplit("*", 1)[0])
    return out


def accepted(line: str, cs_fn, width: int, original: P.Message) -> bool:
    """True if ``line`` passes the scheme's frame check and parses to another message."""
    if not line.startswith("$") or line.count("*") != 1:
        return False
    body, cs = line[1:].split("*")
    if len(cs) != width or any(c not in "0123456789ABCDEF" for c in cs):
        return False
    if int(cs, 16) != cs_fn(body):
        return False
    try:  # the fields: reframed with protocol 2's checksum and parsed as the host does
        msg = P.parse(P.frame(*body.split(",")))
    except P.ProtocolError:
        return False
    return msg != original


def measure(cs_fn, width: int, corpus: list[str]) -> dict[str, tuple[int, int]]:
    counts = {"swap": [0, 0], "pair": [0, 0]}
    for body in corpus:
        original = P.parse(P.frame(*body.split(",")))
        line = f"${body}*{cs_fn(body):0{width}X}"
        for i in range(1, len(line) - 1):
            a, b = line[i], line[i + 1]
            kind = "swap" if a != b else "pair"
            bad = line[:i] + b + a + line[i + 2 :] if a != b else line[:i] + line[i + 2 :]
            counts[kind][0] += 1
            counts[kind][1] += accepted(bad, cs_fn, width, original)
    return {k: (v[0], v[1]) for k, v in counts.items()}


def main() -> None:
    corpus = bodies()
    print(f"corpus: {len(corpus)} lines (golden board lines and a virtual step run)")
    for name, (fn, width) in SCHEMES.items():
        r = measure(fn, width, corpus)
        for kind, label in (("swap", "swapped adjacent bytes"), ("pair", "lost equal pairs")):
            n, through = r[kind]
            print(f"{name}: {label}: {through}/{n} let through ({100 * through / n:.2f} %)")


if __name__ == "__main__":
    main()
