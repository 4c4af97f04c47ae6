"""Command palette: "Go to step ..." for every step of the lab, and "Use run ..." for every
recorded run (the run Tasks 11-15 and the model check use)."""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from textual.command import DiscoveryHit, Hit, Hits, Provider


class StepCommands(Provider):
    """One palette entry per step ("Go to: Task 10: the step experiment") and per run ("Use run
    steps-1 for Tasks 11-15")."""

    def _entries(self) -> list[tuple[str, Callable[[], object], str]]:
        """(text, what it does, help) of every entry."""
        lab = getattr(self.app, "lab", None)
        if lab is None:
            return []
        go, use = self.app.go_to_step, self.app.use_run  # type: ignore[attr-defined]
        return (
            [(f"Go to: {s.title}", partial(go, s.id), "move to this step") for s in lab.steps]
            + [
                (
                    f"Use run {name} for Tasks 11-15",
                    partial(use, name),
                    "the run the results and the model check use",
                )
                for name in lab.runs()
            ]
            + [("Use the latest run for Tasks 11-15", partial(use, None), "the default")]
        )

    async def discover(self) -> Hits:
        for text, action, help_text in self._entries():
            yield DiscoveryHit(text, action, help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for text, action, help_text in self._entries():
            score = matcher.match(text)
            if score > 0:
                yield Hit(score, matcher.highlight(text), action, text=text, help=help_text)
