"""The footer of keys, never showing part of a key.

Textual's footer lays its keys out in one line and cuts the line where the screen ends: at
80 columns Tasks 11-15 showed 'alt+→ Step  ^' and the palette key after it, a stray '^'
where Ctrl+R Reveal had been cut. :class:`KeyFooter` closes its spacing up when the keys do
not fit (Textual's compact style), and when they still do not, leaves out whole keys from
the end of the line (the F1 help lists every key).

It is also built again only when the keys it shows change, once per refresh: Textual's own
footer rebuilds itself (every key unmounted and mounted again, its style applied) after each
change of the screen's bindings, each focus change and each reactive with bindings; a step
change in the lab did that about five times over, the same keys each time (a quarter of the
step change's CPU time).
"""

from __future__ import annotations

from rich.cells import cell_len
from textual.app import ComposeResult
from textual.binding import Binding
from textual.screen import Screen
from textual.widget import Widget
from textual.widgets import Footer
from textual.widgets._footer import FooterKey

Shown = tuple[tuple[str, str, str, str, bool, str, str | None], ...]
"""What the footer shows of each key: (key, as displayed, description, action, enabled,
tooltip, group)."""


class KeyFooter(Footer):
    """A :class:`Footer` whose keys are shown whole or not at all, the palette's key kept at
    the right: Textual's spacing where every key fits, else the compact spacing, else the
    compact spacing without the keys from the last one on that do not fit. Decided from the
    keys' text and Textual's spacing (the widths :func:`key_width` gives), before the keys
    are laid out; only the compact palette key's margin, which the last key needs to end
    where it begins, is taken away. Built again once per refresh at most, and only when the
    keys it shows changed (:meth:`shown`)."""

    DEFAULT_CSS = """
    KeyFooter.-compact FooterKey.-command-palette { margin: 0; }
    """

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

    def compose(self) -> ComposeResult:
        widgets = list(super().compose())
        self._fit(widgets, self.size.width)
        yield from widgets

    def on_resize(self) -> None:
        self._fit(list(self.children), self.size.width)

    def _fit(self, widgets: list[Widget], width: int) -> None:
        """Choose the spacing and the keys shown for ``width`` columns (0: not laid out yet,
        everything shown)."""
        keys = [w for w in widgets if isinstance(w, FooterKey)]
        palette = [k for k in keys if k.has_class("-command-palette")]
        line = [k for k in keys if not k.has_class("-command-palette")]
        if len(line) != len(widgets) - len(palette):  # a group or a label: Textual's layout
            return
        for compact in (False, True):
            gap = 1 if compact else 0  # the margin after a key, needed only before another
            room = width - sum(key_width(k, compact, palette=True) for k in palette) + gap
            used = sum(key_width(k, compact) for k in line)
            if used <= room or not width:
                break
        self.compact = compact
        for k in line:
            w = key_width(k, compact)
            k.display = w <= room
            room = room - w if k.display else -1  # the keys after one left out go too


def key_width(key: FooterKey, compact: bool, palette: bool = False) -> int:
    """The columns ``key`` takes in :class:`KeyFooter`, its margin included: ' f9 Zoom ' or,
    compact, 'f9 Zoom' and a space. The palette's key, docked at the right, is always
    written compact (Textual binds only the others to the footer's spacing), with a border
    on its left and, when the footer is not compact, a space on its right."""
    if not key.description:  # the key alone, unpadded (FooterKey.render)
        text = cell_len(key.key_display)
    elif compact or palette:
        text = cell_len(key.key_display) + 1 + cell_len(key.description)
    else:
        text = cell_len(key.key_display) + 2 + cell_len(key.description) + 1
    if palette:
        return 1 + text + (0 if compact else 1)  # its border, its padding on the right
    return text + (1 if compact else 0)  # its margin on the right
