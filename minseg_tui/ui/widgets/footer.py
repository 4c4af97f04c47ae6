"""The footer of keys, never showing part of a key.

Textual's footer lays its keys out in one line and cuts the line where the screen ends: at
80 columns Tasks 11-15 showed 'alt+→ Step  ^' and the palette key after it, a stray '^'
where Ctrl+R Reveal had been cut. :class:`KeyFooter` closes its spacing up when the keys do
not fit (Textual's compact style), and when they still do not, leaves out whole keys from
the end of the line (the F1 help lists every key).
"""

from __future__ import annotations

from rich.cells import cell_len
from textual.app import ComposeResult
from textual.widget import Widget
from textual.widgets import Footer
from textual.widgets._footer import FooterKey


class KeyFooter(Footer):
    """A :class:`Footer` whose keys are shown whole or not at all, the palette's key kept at
    the right: Textual's spacing where every key fits, else the compact spacing, else the
    compact spacing without the keys from the last one on that do not fit. Decided from the
    keys' text and Textual's spacing (the widths :func:`key_width` gives), before the keys
    are laid out; only the compact palette key's margin, which the last key needs to end
    where it begins, is taken away."""

    DEFAULT_CSS = """
    KeyFooter.-compact FooterKey.-command-palette { margin: 0; }
    """

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
