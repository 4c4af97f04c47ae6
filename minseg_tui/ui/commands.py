"""Command palette: "Go to step ..." for every step of the lab."""

from __future__ import annotations

from functools import partial

from textual.command import DiscoveryHit, Hit, Hits, Provider


class StepCommands(Provider):
    """One palette entry per step: "Go to: Task 10 step run"."""

    def _steps(self) -> list[tuple[str, str]]:
        lab = getattr(self.app, "lab", None)
        if lab is None:
            return []
        return [(s.id, f"Go to: {s.title}") for s in lab.steps]

    async def discover(self) -> Hits:
        for step_id, text in self._steps():
            yield DiscoveryHit(text, partial(self.app.go_to_step, step_id), help="move to this step")  # type: ignore[attr-defined]

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for step_id, text in self._steps():
            score = matcher.match(text)
            if score > 0:
                yield Hit(score, matcher.highlight(text), partial(self.app.go_to_step, step_id),  # type: ignore[attr-defined]
                          text=text, help="move to this step")
