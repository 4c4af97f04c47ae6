"""The footer of keys, never showing part of a key.

Textual's footer lays its keys out in one line and cuts the line where the screen ends: at
80 columns Tasks 11-15 showed 'alt+→ Step  ^' and the palette key after it, a stray '^'
where Ctrl+R Reveal had been cut. :class:`KeyFooter` closes its spacing up when the keys do
not fit (the compact spacing), and when they still do not, leaves out whole keys from the
end of the line (the F1 help lists every key).

It is also built again only when the keys it shows change, once for the changes that come
together: Textual's own footer rebuilds itself (every key unmounted and mounted again, its
style applied) after each change of the screen's bindings, each focus change and each
reactive with bindings; a step change in the lab did that about five times over, the same
keys each time (a quarter of the step change's CPU time).

It is our own widget, made of Textual's public pieces (the screen's ``active_bindings`` and
``bindings_updated_signal``, ``App.get_key_display``, ``App.simulate_key``, the theme's
``$footer-*`` colours), not a subclass of Textual's ``Footer``: measuring that footer's keys
took its private key class (``textual.widgets._footer.FooterKey``), and building it only when
the keys change took overriding its signal handler and setting its private ``_bindings_ready``.
Its keys are :class:`KeyLabel` widgets, spaced and coloured as Textual's footer spaces and
colours its keys, so the screens look the same; their widths are ours to know.
"""

from __future__ import annotations

from typing import NamedTuple

from rich.cells import cell_len
from rich.text import Text
from textual.app import App, ComposeResult
from textual.containers import ScrollableContainer
from textual.reactive import reactive
from textual.screen import Screen
from textual.widget import Widget


class ShownKey(NamedTuple):
    """One key as the footer shows it."""

    key: str
    """The key pressed when the label is clicked ('f9')."""
    display: str
    """The key as written ('f9', '^r')."""
    description: str
    """What it does ('Zoom'; '': the key alone)."""
    enabled: bool
    """False: shown dimmed, a click rings the bell."""
    tooltip: str
    palette: bool = False
    """The command palette's key, docked at the right of the line."""


Shown = tuple[ShownKey, ...]
"""What the footer shows, in order, the palette's key (if any) last."""


class KeyLabel(Widget):
    """One key of :class:`KeyFooter`, 'f9 Zoom': the key on the key colours, then what it
    does. Spaced ' f9 Zoom ' or, compact, 'f9 Zoom' (the footer puts a space after it); the
    palette's key is always compact. A click presses the key (a disabled one rings the
    bell)."""

    ALLOW_SELECT = False
    COMPONENT_CLASSES = {"key-label--key", "key-label--description"}
    DEFAULT_CSS = """
    KeyLabel {
        width: auto;
        height: 1;
        text-wrap: nowrap;
        background: $footer-item-background;
        .key-label--key {
            color: $footer-key-foreground;
            background: $footer-key-background;
            text-style: bold;
        }
        .key-label--description {
            color: $footer-description-foreground;
            background: $footer-description-background;
        }
        &:hover {
            pointer: pointer;
            color: $footer-key-foreground;
            background: $block-hover-background;
        }
        &.-disabled {
            text-style: dim;
        }
    }
    """

    compact: reactive[bool] = reactive(True, layout=True)
    """The compact spacing (the footer's, bound to it; the palette's key always)."""

    def __init__(self, shown: ShownKey) -> None:
        classes = ("-disabled " if not shown.enabled else "") + (
            "-palette" if shown.palette else ""
        )
        super().__init__(classes=classes.strip())
        self.shown = shown
        self.key = shown.key
        self.key_display = shown.display
        self.description = shown.description
        self.enabled = shown.enabled
        self.set_reactive(Widget.shrink, False)  # a key keeps its width; whole keys go
        if shown.tooltip:
            self.tooltip = shown.tooltip

    def show(self, shown: ShownKey) -> None:
        """Show ``shown`` (a key of the same kind: the palette's or not) in place of the key
        shown now, as a new label made for it would (restyled only when it is enabled or
        disabled, laid out again only when its text changed)."""
        if shown == self.shown:
            return
        text = (shown.display, shown.description) != (self.key_display, self.description)
        self.shown = shown
        self.key = shown.key
        self.key_display = shown.display
        self.description = shown.description
        self.enabled = shown.enabled
        self.set_class(not shown.enabled, "-disabled")
        self.tooltip = shown.tooltip or None
        self.refresh(layout=text)

    def render(self) -> Text:
        key_style = self.get_component_rich_style("key-label--key")
        if not self.description:
            text = Text(self.key_display, key_style)
        elif self.compact:
            text = Text.assemble(
                (self.key_display, key_style),
                (" " + self.description, self.get_component_rich_style("key-label--description")),
            )
        else:
            text = Text.assemble(
                (f" {self.key_display} ", key_style),
                (self.description + " ", self.get_component_rich_style("key-label--description")),
            )
        text.stylize_before(self.rich_style)
        return text

    def on_mouse_down(self) -> None:
        if self.enabled:
            self.app.simulate_key(self.key)
        else:
            self.app.bell()

    def width(self, compact: bool) -> int:
        """The columns this key takes in :class:`KeyFooter`, its margin included (see
        :func:`key_width`)."""
        return key_width(self.key_display, self.description, compact, self.has_class("-palette"))


class KeyFooter(ScrollableContainer, can_focus=False, can_focus_children=False):
    """The screen's keys in one line at its bottom, each shown whole or not at all, the
    palette's key kept at the right: the roomy spacing where every key fits, else the
    compact spacing, else the compact spacing without the keys from the last one on that do
    not fit. Decided from the keys' text and spacing (:func:`key_width`) before the keys
    are laid out. Built again once for the changes that come together, and only when the keys
    it shows changed (:meth:`shown`). One key per action (the first binding of it), as Textual's
    footer shows them; binding groups are not drawn as groups (the lab has none)."""

    ALLOW_SELECT = False
    DEFAULT_CSS = """
    KeyFooter {
        layout: horizontal;
        color: $footer-foreground;
        background: $footer-background;
        dock: bottom;
        height: 1;
        scrollbar-size: 0 0;
        KeyLabel.-palette {
            dock: right;
            padding-right: 1;
            border-left: vkey $foreground 20%;
        }
        &.-compact {
            KeyLabel {
                margin-right: 1;
            }
            KeyLabel.-palette {
                padding-right: 0;
                margin: 0;
            }
        }
    }
    """

    compact: reactive[bool] = reactive(False, toggle_class="-compact")
    """The compact spacing (chosen by :meth:`_fit`)."""

    def __init__(self) -> None:
        super().__init__()
        self._ready = False
        """The screen said its bindings are in place (nothing is shown before)."""
        self._pending = False
        self._drawn: Shown | None = None
        """What the footer last showed (None: never built with bindings)."""

    def on_mount(self) -> None:
        self.screen.bindings_updated_signal.subscribe(self, self.bindings_changed)
        self.app.screen_change_signal.subscribe(self, self._screen_changed)

    def on_unmount(self) -> None:
        self.screen.bindings_updated_signal.unsubscribe(self)
        self.app.screen_change_signal.unsubscribe(self)

    def _screen_changed(self, screen: Screen[object]) -> None:
        """The app shows another screen: the footer's own again, its keys as they are now
        (they changed while a dialog was over it, and the rebuild asked for then waited)."""
        if screen is self.screen:
            self.bindings_changed(screen)

    def shown(self) -> Shown:
        """What the footer would show now: the screen's active keys meant to be shown, one
        per action, then the command palette's key."""
        active = self.screen.active_bindings
        line: dict[str, ShownKey] = {}
        # the keys of the screen and the app (the same on every step) first, in their order,
        # then those of the widgets under them (a step's panel keys): each key keeps its place
        ordered = sorted(active.values(), key=lambda a: not isinstance(a.node, (Screen, App)))
        for _, binding, enabled, tooltip in ordered:
            if binding.show and binding.action not in line:
                line[binding.action] = ShownKey(
                    binding.key,
                    self.app.get_key_display(binding),
                    binding.description,
                    enabled,
                    tooltip,
                )
        keys = list(line.values())
        palette = active.get(self.app.COMMAND_PALETTE_BINDING)
        if palette is not None and self.app.ENABLE_COMMAND_PALETTE:
            _, binding, enabled, _ = palette
            keys.append(
                ShownKey(
                    binding.key,
                    self.app.get_key_display(binding),
                    binding.description,
                    enabled,
                    binding.tooltip or binding.description,
                    palette=True,
                )
            )
        return tuple(keys)

    def bindings_changed(self, screen: Screen[object]) -> None:
        """The screen's bindings changed: build the footer again once the messages it has
        now are handled, if its keys did. Its own call (``call_later``), not one after the
        next refresh: that call is handed to the app's screen of the moment, and when a
        dialog came or went just then (walk 12's D2) it was lost with the dialog (the
        footer waited for it for ever: the keys of Task 1 shown on Tasks 2-10) or ran in the
        dialog's place (where building the keys raised ReactiveError)."""
        self._ready = True
        if not screen.app.app_focus:
            return
        if self.is_attached and screen is self.screen and not self._pending:
            self._pending = True
            self.call_later(self._rebuild)

    async def _rebuild(self) -> None:
        self._pending = False
        if not self.is_attached or self.screen is not self.app.screen:
            return  # under a dialog: built when its screen is shown again (_screen_changed)
        shown = self.shown()
        if shown == self._drawn:
            return
        drawn, self._drawn = self._drawn, shown
        if not drawn or not await self._relabel(shown):
            await self.recompose()

    async def _relabel(self, shown: Shown) -> bool:
        """Show ``shown`` with the key labels there are: each label given the key at its
        place (:meth:`KeyLabel.show`), labels added for more keys, those left over removed.
        A step change made the footer show new keys two or three times, and a new label for
        every key each time cost about a fifth of the step change's CPU time. False
        (nothing changed): the palette's key came or went (the footer is built anew)."""
        labels = list(self.query_children(KeyLabel))
        line = [k for k in labels if not k.has_class("-palette")]
        palette = [k for k in labels if k.has_class("-palette")]
        keys = [k for k in shown if not k.palette]
        palette_keys = [k for k in shown if k.palette]
        if len(palette_keys) != len(palette):
            return False
        for label, key in zip(line, keys, strict=False):
            label.show(key)
        for label, key in zip(palette, palette_keys, strict=True):
            label.show(key)
        added = [KeyLabel(k) for k in keys[len(line) :]]
        for k in added:
            k.data_bind(compact=KeyFooter.compact)
        kept = [*line[: len(keys)], *added]
        self._fit([*kept, *palette], self.size.width)
        if line[len(keys) :]:
            await self.remove_children(line[len(keys) :])
        if added:
            await self.mount_all(added, before=palette[0] if palette else None)
        return True

    def compose(self) -> ComposeResult:
        if not self._ready:
            return
        keys = [KeyLabel(k) for k in self.shown()]
        for k in keys:
            if not k.has_class("-palette"):
                k.data_bind(compact=KeyFooter.compact)
        self._fit(keys, self.size.width)
        yield from keys

    def on_resize(self) -> None:
        self._fit(list(self.query_children(KeyLabel)), self.size.width)

    def _fit(self, keys: list[KeyLabel], width: int) -> None:
        """Choose the spacing and the keys shown for ``width`` columns (0: not laid out yet,
        everything shown)."""
        palette = [k for k in keys if k.has_class("-palette")]
        line = [k for k in keys if not k.has_class("-palette")]
        for compact in (False, True):
            gap = 1 if compact else 0  # the margin after a key, needed only before another
            room = width - sum(k.width(compact) for k in palette) + gap
            used = sum(k.width(compact) for k in line)
            if used <= room or not width:
                break
        self.compact = compact
        for k in line:
            w = k.width(compact)
            k.display = w <= room
            room = room - w if k.display else -1  # the keys after one left out go too


def key_width(display: str, description: str, compact: bool, palette: bool = False) -> int:
    """The columns a key takes in :class:`KeyFooter`, its margin included: ' f9 Zoom ' or,
    compact, 'f9 Zoom' and a space. The palette's key, docked at the right, is always
    written compact, with a border on its left and, when the footer is not compact, a space
    on its right."""
    if not description:  # the key alone, unpadded (KeyLabel.render)
        text = cell_len(display)
    elif compact or palette:
        text = cell_len(display) + 1 + cell_len(description)
    else:
        text = cell_len(display) + 2 + cell_len(description) + 1
    if palette:
        return 1 + text + (0 if compact else 1)  # its border, its padding on the right
    return text + (1 if compact else 0)  # its margin on the right
