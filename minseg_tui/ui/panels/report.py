"""The summary step: F8 writes the report; the files written."""

from __future__ import annotations

from pathlib import Path

from textual.content import Content
from textual.reactive import reactive
from textual.widgets import Static

from minseg_tui.lab.content.keys import in_palette, key_name
from minseg_tui.ui.panels.view_panel import ViewPanel


def written_in(paths: tuple[str, ...], root: Path | None) -> tuple[str, tuple[str, ...]]:
    """The files a report was written to, said so that no name breaks at 80x24: the session
    folder's whole path, as two lines (the sessions folder ``root`` with a trailing '/', then
    the session's own name, '2026-11-27-ada-bo': a group sees where to look, walk 9's D2, and
    a deep sessions folder never breaks the session's name, walk 6's D7), and the files
    relative to it ('report.md', 'runs/steps-1.csv'); ('', the paths as they are) when the
    files are not all in one session folder under ``root``."""
    if not paths or root is None:
        return "", paths
    folder = Path(paths[0]).parent
    base = Path(root).resolve()
    try:
        where = folder.resolve().relative_to(base)
        names = tuple(Path(p).resolve().relative_to(folder.resolve()).as_posix() for p in paths)
    except ValueError:
        return "", paths
    return f"{base.as_posix()}/\n{where.as_posix()}", names


class ReportPanel(Static):
    """Says how to write the report and lists the files it was last ``written`` to (the
    session folder's words and the files' names, from :func:`written_in`)."""

    written: reactive[tuple[str, tuple[str, ...]]] = reactive(("", ()), layout=True)

    def __init__(self, readonly: bool = False) -> None:
        super().__init__("", classes="panel")
        self.readonly = readonly
        """A read-only session: F8 refuses there, so the panel does not offer it."""

    def watch_written(self) -> None:
        """The files listed above the summary's entries: the step keeps the entry the group
        types in in view (the list pushed it under the footer at 80x24)."""
        self.call_after_refresh(self.post_message, ViewPanel.Drawn())

    def render(self) -> Content:
        """Plain text: a file's or a port's name with brackets in it is shown as it is."""
        return Content(self._text())

    def _text(self) -> str:
        folder, names = self.written
        where = f" in {folder}" if folder else ""
        said = (
            "No report is written from a read-only session."
            if self.readonly
            else f"{key_name('export')} (or {in_palette('export')}) writes report.md, "
            "report.html and the runs' CSV."
        )
        return said + (f"\nwritten{where}:\n" + "\n".join(f"  {p}" for p in names) if names else "")
