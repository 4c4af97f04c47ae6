"""Write a session's report into its folder: report.md, report.html (runs/*.csv are already there)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from minseg_tui.lab.saving.store import atomic_write_text
from minseg_tui.lab.state.session import Session
from minseg_tui.report import content, html, markdown


@dataclass(frozen=True)
class Written:
    """Paths written: the Markdown and HTML reports and the CSV of every recorded run."""

    markdown: Path
    html: Path
    runs: tuple[Path, ...]

    @property
    def paths(self) -> tuple[Path, ...]:
        """Every file: the Markdown report, the HTML report, then the runs' CSV."""
        return (self.markdown, self.html, *self.runs)


def write_report(session: Session) -> Written:
    """Build the report of ``session`` and write report.md and report.html atomically into
    its folder; returns the paths (the run CSVs listed are the session's own files)."""
    rep = content.build(session)
    md_path = session.folder / "report.md"
    html_path = session.folder / "report.html"
    atomic_write_text(md_path, markdown.render(rep))
    atomic_write_text(html_path, html.render(rep))
    runs = tuple(session.folder / r.file for r in session.runs)
    return Written(md_path, html_path, runs)
