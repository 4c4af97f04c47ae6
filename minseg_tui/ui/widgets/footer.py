"""The footer of the keys, built again only when the keys it shows change."""

from __future__ import annotations

from textual.binding import Binding
from textual.screen import Screen
from textual.widgets import Footer

Shown = tuple[tuple[str, str, str, str, bool, str, str | None], ...]
"""What the footer shows of each key: (key, as displayed, description, action, enabled,
tooltip, group)."""


class KeysFooter(Footer):
    """Textual's Footer, built again once per refresh, and only when what it shows changed.

    Textual's own rebuilds itself (all its keys unmounted and mounted again, their styles
    applied) after every change of the screen's bindings, each focus change and each
    reactive with bindings: a step change in the lab did that about five times over, the
    same keys each time (a quarter of the step change's CPU time)."""

    def __init__(self) -> None:
        super().__init__()
        self._pending = False
        self._drawn: Shown | None = None
        """What the footer last showed (None: never built with bindings)."""

    def shown(self) -> Shown:
        """What the footer would show now: the screen's active keys, as its compose reads them."""
        rows: list[tuple[Binding, bool, str]] = [
            (binding, enabled, tooltip)
            for (_, binding, enabled, tooltip) in self.screen.active_bindings.values()
            if binding.show
        ]
        palette = self.screen.active_bindings.get(self.app.COMMAND_PALETTE_BINDING)
        if palette is not None and self.show_command_palette and self.app.ENABLE_COMMAND_PALETTE:
            rows.append((palette[1], palette[2], palette[3]))
        return tuple(
            (
                b.key,
                self.app.get_key_display(b),
                b.description,
                b.action,
                enabled,
                tooltip or b.tooltip,
                b.group.description if b.group else None,
            )
            for b, enabled, tooltip in rows
        )

    def bindings_changed(self, screen: Screen[object]) -> None:
        self._bindings_ready = True
        if not screen.app.app_focus:
            return
        if self.is_attached and screen is self.screen and not self._pending:
            self._pending = True
            self.call_after_refresh(self._rebuild)

    async def _rebuild(self) -> None:
        self._pending = False
        if not self.is_attached:
            return
        shown = self.shown()
        if shown != self._drawn:
            self._drawn = shown
            await self.recompose()
