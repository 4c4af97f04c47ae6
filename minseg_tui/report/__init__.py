"""Reports of a session: Markdown, self-contained HTML and CSV."""
