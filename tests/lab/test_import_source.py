"""The import's copy names where this import came from (stop 38's last read: a log's own
``# imported_from:`` line, a copy of a run imported before, came after the copy's and won in
its metadata). The older source is kept, renamed ``earlier_imported_from``; the run's SHA-256
is of the bytes written, so the checksum rule holds for the copy."""

from __future__ import annotations

import hashlib

from minseg_tui.lab.saving import runs
from minseg_tui.lab.state.session import Session

ROWS = "t,u,omega\n0,0,0\n0.025,4,1\n0.05,4,2\n0.075,4,2.5\n"


def test_a_run_imported_again_names_this_import_and_keeps_the_older_source(tmp_path):
    first = tmp_path / "bench" / "step log.csv"
    first.parent.mkdir()
    first.write_text("# written elsewhere\n" + ROWS, encoding="utf-8")
    with Session.create(tmp_path / "a", ["A"]) as a:
        copy = a.folder / a.import_run(first).file
    # the copy in session a's runs/ is imported into session b, CRLF and all
    again = tmp_path / "again.csv"
    again.write_bytes(copy.read_bytes().replace(b"\n", b"\r\n"))
    with Session.create(tmp_path / "b", ["B"]) as b:
        info = b.import_run(again)
        log = b.load_run(info.name)
        data = (b.folder / info.file).read_bytes()
        assert runs.changed_file(b.folder, info) is None
    assert log.metadata["imported_from"] == str(again)
    assert log.metadata["earlier_imported_from"] == str(first)
    assert info.sha256 == hashlib.sha256(data).hexdigest()
    assert data == (
        f"# imported_from: {again}\n".encode()
        + f"# earlier_imported_from: {first}\r\n# written elsewhere\r\n".encode()
        + ROWS.replace("\n", "\r\n").encode()
    )
    assert len(log) == 4


def test_only_the_lines_before_the_header_are_looked_at(tmp_path):
    """A comment among the rows is the log's own (the reader takes no metadata there): the
    bytes are copied as they are, a chunk's worth of lines before the header too."""
    src = tmp_path / "log.csv"
    head = "".join(f"# note {k}: {'x' * 60}\n" for k in range(20_000))  # > 1 MB, many chunks
    src.write_text(
        head + "# imported_from: /old/a.csv\n" + ROWS + "# imported_from: /not/metadata\n",
        encoding="utf-8",
    )
    with Session.create(tmp_path / "s", ["A"]) as s:
        info = s.import_run(src)
        data = (s.folder / info.file).read_bytes()
        log = s.load_run(info.name)
    assert (
        data
        == (
            f"# imported_from: {src}\n{head}# earlier_imported_from: /old/a.csv\n{ROWS}"
            "# imported_from: /not/metadata\n"
        ).encode()
    )
    assert log.metadata["imported_from"] == str(src)
    assert log.metadata["earlier_imported_from"] == "/old/a.csv"
