"""Every place where the UI tests reach into Textual's internals (names with a leading
underscore, or a module function Textual does not document), kept here and nowhere else.
Each reach is here because Textual 8.2 offers no public way to do it; when an upgrade of
Textual breaks one, this file is the one to read. Checked against Textual's source in the
venv and its documentation (Pilot, App.run_test, Input, Screen, textual.keys):

1. :func:`running_app`: ``textual._context.active_app``. Textual's own waits take no app,
   and Textual exposes the running app only to its own nodes (``self.app``).
2. :func:`wait_for_screen`: ``Pilot._wait_for_screen``. The exact wait Pilot itself uses
   after a key (every node handles what was queued on it); Pilot's public ``pause()`` adds
   a forced layout and, with no delay, the CPU-idle guess below.
3. :func:`make_waits_exact`: replaces ``wait_for_idle`` (``textual._wait``) as imported by
   ``textual.app`` and ``textual.pilot``: ``Pilot.press`` and ``Pilot.pause()`` call it
   after every key, and App.run_test has no option to wait otherwise.
4. :func:`leave_headless_frames_unpainted`: ``Screen._compositor_refresh`` replaced, and in
   the replacement the screen's ``_compositor._dirty_regions``, ``_dirty_widgets`` and
   ``App._update_mouse_over``. No public switch turns painting off in a headless app.
5. :func:`keep_cursors_still`: ``Input._toggle_cursor``. ``Input.cursor_blink`` is public but
   is set per Input, and the app makes its Inputs itself.
6. :func:`key_name`: ``textual.keys._character_to_key``. Textual turns a typed character
   into its key name (',' -> 'comma') only with this private function (the public
   ``key_to_character`` goes the other way); Pilot.press uses it too.

Done with public API elsewhere: keys handed over in a burst go in with ``App.post_message``
(not the driver, ``App._driver``), the notifications shown are the ``Notify`` messages heard
through ``run_test(message_hook=...)`` and the ``Toast`` widgets queried by type name (not
``App._notifications`` or ``textual.widgets._toast``), the colour filters are
``App.get_line_filters()`` (not ``App._filters``)."""

from __future__ import annotations

from collections.abc import Awaitable, Callable

import pytest
import textual.app
import textual.pilot
from textual._context import active_app
from textual.app import App
from textual.keys import _character_to_key
from textual.pilot import Pilot
from textual.screen import Screen
from textual.widgets import Input


def running_app() -> App[object] | None:
    """The app running in this task (``run_test``), None outside one."""
    try:
        return active_app.get()
    except LookupError:
        return None


async def wait_for_screen(pilot: Pilot[object]) -> None:
    """Wait until the app and every node of its screen have handled what was queued on them
    when this began (a handler under way included)."""
    await pilot._wait_for_screen()


def make_waits_exact(
    monkeypatch: pytest.MonkeyPatch, wait: Callable[[float, float], Awaitable[None]]
) -> None:
    """Pilot's waits after a key and in ``pause()`` become ``wait`` (which takes the arguments
    of Textual's ``wait_for_idle``: min and max sleep, s)."""
    monkeypatch.setattr(textual.app, "wait_for_idle", wait)
    monkeypatch.setattr(textual.pilot, "wait_for_idle", wait)


_compositor_refresh = Screen._compositor_refresh


def unpainted_refresh(self: Screen[object]) -> None:
    """Textual's compositor refresh, except that a headless app's screen is not painted: its
    driver throws every frame away (App._display), and painting them was about 40 % of a UI
    test's CPU. Layout still runs (regions, scrolling, what is under a click), and what a test
    reads off the screen is rendered when it asks: a widget's render(), the snapshots' full
    render (App.export_screenshot), a plot's columns (Canvas.columns)."""
    app = self.app
    if not (app.is_headless and not app.is_inline and self is app.screen):
        _compositor_refresh(self)
        return
    self._compositor._dirty_regions.clear()
    self._dirty_widgets.clear()
    app._update_mouse_over(self)


def leave_headless_frames_unpainted(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every screen refreshes with :func:`unpainted_refresh`."""
    monkeypatch.setattr(Screen, "_compositor_refresh", unpainted_refresh)


def keep_cursors_still(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every Input's cursor stays shown: a blinking cursor would make a screen depend on when
    it was taken (harlequin's tests do the same)."""
    monkeypatch.setattr(Input, "_toggle_cursor", lambda _self: None)


def key_name(key: str) -> str:
    """The name Textual gives the key that types ``key`` when it is one character that is not
    a letter or digit (',' -> 'comma', ' ' -> 'space'), as a terminal's key arrives; any other
    ``key`` (a letter, a digit, a key name such as 'enter') as it is."""
    return _character_to_key(key) if len(key) == 1 and not key.isalnum() else key
