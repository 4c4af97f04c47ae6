"""Every place where the UI tests reach into Textual's internals (names with a leading
underscore, or a module function Textual does not document), kept here and nowhere else.
Each reach is here because Textual 8.2 offers no public way to do it; when an upgrade of
Textual breaks one, this file is the one to read. Checked against Textual's source in the
venv and its documentation (Pilot, App.run_test, Input, Screen, textual.keys):

Thirteen names of Textual's internals, in six reaches (each reach's last line says why no
public way does it; the public names looked at are there too):

1. :func:`wait_for_screen`: ``Pilot._wait_for_screen``, done again here, and put in its
   place. The exact wait Pilot itself uses after a key (every node handles what was queued
   on it, a handler under way included); it also returns at once when the app has failed
   (``App._exception_event``). Pilot's own queues a new closure on every node each time,
   and Textual works out each closure's signature (``inspect.signature``) before it calls
   it; the callback here states its own. Pilot's own also queues it on the nodes that are
   idle (reach 4), where it waits for nothing: each such callback cost a message, an Idle
   event and the MRO walk for its handlers, and the tests' waits were about half the
   messages the app processed.
   Why no public way: Pilot's public ``pause()`` adds a forced layout and, with no delay,
   the CPU-idle guess of reach 2, and ``wait_for_animation``/``wait_for_scheduled_animations``
   wait for animations only; a failed app shows in the public ``App.return_code`` (1), a
   value to poll, not an event to wait for.
2. :func:`make_waits_exact`: replaces ``wait_for_idle`` (``textual._wait``) as imported by
   ``textual.app`` and ``textual.pilot``, and ``Pilot._wait_for_screen`` with
   :func:`wait_for_screen`.
   Why no public way: ``Pilot.press`` and ``Pilot.pause()`` call them after every key, and
   neither they nor ``App.run_test`` take an option to wait otherwise.
3. :func:`leave_headless_frames_unpainted`: ``Screen._compositor_refresh`` replaced, and in
   the replacement the screen's ``_compositor._dirty_regions``, ``_dirty_widgets`` and
   ``App._update_mouse_over``.
   Why no public way: no option or ``TEXTUAL_*`` setting turns painting off in a headless
   app (``TEXTUAL_FPS`` only spaces the frames, ``App.batch_update`` holds them for a block).
4. :func:`mark_idle_nodes`: ``MessagePump._get_message`` wrapped so that a node says while
   its message loop waits for the next message: with nothing queued (the public
   ``message_queue_size``) the node then has no handler under way (its loop takes the next
   message only once the one before, its Idle event and its ``call_next`` callbacks are
   done). :func:`idle` reads it. (Until stop 36: ``Queue.get`` of ``textual._queue`` and
   the node's ``MessagePump._message_queue``, two names for what this one does.)
   Why no public way: ``message_queue_size`` says what is queued, not whether a handler is
   under way, and ``MessagePump.is_running`` is true for the node's whole life.
5. :func:`callbacks_before_layouts`: ``Screen._on_idle`` replaced, calling
   ``Screen._invoke_and_clear_callbacks`` at once. What waits for the screen's refresh
   (``call_after_refresh``) runs when the screen is next idle, on the layout it has; a
   widget asks for the next layout only when it is itself next idle, so on a busy machine
   the screen may run them between two layouts. This makes the screen run them before
   every layout still to come, the worst order.
   Why no public way: ``call_after_refresh`` and ``refresh(layout=True)`` say what to do,
   not in which order the screen does the two.
6. :func:`parse_stylesheets_once`: ``Stylesheet._parse_rules`` wrapped with a cache for the
   process, keyed by its arguments and the Stylesheet's ``_variables``. Textual caches the
   parse per Stylesheet only, and a test process starts hundreds of apps, each parsing the
   same CSS again.
   Why no public way: nothing shares parsed CSS between apps; the variables a Stylesheet
   parses with have a setter (``set_variables``) and no getter, and the public
   ``App.get_css_variables()`` is the app's theme now, not what a given Stylesheet holds.

Done with public API here: the running app is ``MessagePump.app`` of a node attached to no
app (not ``textual._context.active_app``); the still cursor is each Input's
``cursor_blink`` set off as it is made (not ``Input._toggle_cursor``); a character's key
name is made from its Unicode name and Textual's ``KEY_NAME_REPLACEMENTS`` (not
``textual.keys._character_to_key``), checked against ``key_to_character``.

Done with public API elsewhere: keys handed over in a burst go in with ``App.post_message``
(not the driver, ``App._driver``), the notifications shown are the ``Notify`` messages heard
through ``run_test(message_hook=...)`` and the ``Toast`` widgets queried by type name (not
``App._notifications`` or ``textual.widgets._toast``), the colour filters are
``App.get_line_filters()`` (not ``App._filters``)."""

from __future__ import annotations

import asyncio
import inspect
import unicodedata
from asyncio import FIRST_COMPLETED
from collections.abc import Awaitable, Callable
from typing import Any

import pytest
import textual.app
import textual.pilot
from textual.app import App
from textual.css.model import RuleSet
from textual.css.stylesheet import Stylesheet
from textual.keys import KEY_NAME_REPLACEMENTS, key_to_character
from textual.message_pump import MessagePump
from textual.pilot import Pilot, WaitForScreenTimeout
from textual.screen import Screen
from textual.widgets import Input


def running_app() -> App[object] | None:
    """The app running in this task (``run_test``), None outside one: what Textual's
    documented ``MessagePump.app`` gives a node not attached to any app (the current
    asyncio context's app)."""
    try:
        return MessagePump().app
    except RuntimeError:  # Textual's NoActiveAppError: no app runs in this task
        return None


class _Countdown:
    """The nodes yet to reach a :func:`wait_for_screen` callback (the countdown itself, called
    on each node); ``zero`` is set when none is left. Its ``__signature__`` (Python's own
    protocol, read first by ``inspect.signature``) says at once that it takes no argument:
    Textual reads the signature of every callback before it calls it, and works out that of
    a function or a bound method each time (``call_later`` wraps it in a new partial)."""

    __signature__ = inspect.Signature()

    def __init__(self) -> None:
        self.count = 0
        self.zero = asyncio.Event()

    def __call__(self) -> None:
        self.count -= 1
        if self.count == 0:
            self.zero.set()


_WAITING = "_minseg_tests_waiting"
"""The attribute :func:`mark_idle_nodes` sets on a node while its loop waits for a message."""

_get_message = MessagePump._get_message


async def _marked_get_message(self: MessagePump) -> Any:
    """``MessagePump._get_message``, with the node marked as waiting until it returns. Its
    loop waits there, in its queue, for the next message; it returns at once, with nothing
    awaited, a message it had already taken off the queue to look at."""
    setattr(self, _WAITING, True)
    try:
        return await _get_message(self)
    finally:
        setattr(self, _WAITING, False)


def mark_idle_nodes(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every node says while its message loop waits for the next message (:func:`idle`)."""
    monkeypatch.setattr(MessagePump, "_get_message", _marked_get_message)


def idle(node: MessagePump) -> bool:
    """The node has nothing queued (Textual's public ``message_queue_size``) and no handler
    under way: its message loop waits for the next message (False until it first does so,
    after its Compose and Mount, and when :func:`mark_idle_nodes` is not in force)."""
    return not node.message_queue_size and getattr(node, _WAITING, False)


def marking_idle_nodes() -> bool:
    """:func:`mark_idle_nodes` is in force (a test's fixtures; not in a process a test
    starts, which waits as Pilot does)."""
    return MessagePump._get_message is _marked_get_message


def all_idle(app: App[object]) -> bool:
    """The app and every node of its screen are idle (:func:`idle`; the nodes
    :func:`wait_for_screen` waits for), or the app has ended (its nodes handle nothing
    more). The screens under it are not asked: a node of theirs may stay under way while a
    screen is over them (make test's first run with this had two tests wait in vain under
    a modal screen, Help and Quit)."""
    if not app.is_running:
        return True
    try:
        screen = app.screen
    except Exception:  # no screen yet or any more: nothing to wait for
        return True
    return idle(app) and all(idle(n) for n in screen.walk_children(with_self=True))


async def wait_for_screen(pilot: Pilot[object], timeout: float = 30.0) -> bool:
    """Wait until the app and every node of its screen have handled what was queued on them
    when this began (a handler under way included): a callback queued on each of them that
    is not idle (:func:`idle`: it has nothing to handle), then wait until all have run, or
    the app has failed. As ``Pilot._wait_for_screen`` of Textual 8.2 does, line for line,
    with a bound method for the callback and the idle nodes left out. True: all of them
    ran; raises Textual's ``WaitForScreenTimeout`` after ``timeout`` s (a hang guard)."""
    app = pilot.app
    try:
        screen = app.screen
    except Exception:
        return False
    countdown = _Countdown()
    for node in [app, *screen.walk_children(with_self=True)]:
        if not idle(node) and node.call_later(countdown):
            countdown.count += 1
    if countdown.count:
        waits = [
            asyncio.create_task(countdown.zero.wait()),
            asyncio.create_task(app._exception_event.wait()),
        ]
        _, pending = await asyncio.wait(waits, timeout=timeout, return_when=FIRST_COMPLETED)
        for task in pending:
            task.cancel()
        if len(pending) == len(waits):
            raise WaitForScreenTimeout(
                "Timed out while waiting for widgets to process pending messages."
            )
        if countdown.count > 0:
            return False
    return True


def make_waits_exact(
    monkeypatch: pytest.MonkeyPatch, wait: Callable[[float, float], Awaitable[None]]
) -> None:
    """Pilot's waits after a key and in ``pause()`` become ``wait`` (which takes the arguments
    of Textual's ``wait_for_idle``: min and max sleep, s), and its wait for the screen
    :func:`wait_for_screen`."""
    monkeypatch.setattr(textual.app, "wait_for_idle", wait)
    monkeypatch.setattr(textual.pilot, "wait_for_idle", wait)
    monkeypatch.setattr(Pilot, "_wait_for_screen", wait_for_screen)


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


_parse_rules = Stylesheet._parse_rules
_parsed: dict[tuple[object, ...], list[RuleSet]] = {}


def _parse_rules_once(
    self: Stylesheet,
    css: str,
    read_from: tuple[str, str],
    is_default_rules: bool = False,
    tie_breaker: int = 0,
    scope: str = "",
) -> list[RuleSet]:
    """``Stylesheet._parse_rules``, its result kept for the process: the same CSS source,
    read from the same place, with the same variables (the theme's colours), gives the same
    rules. Textual keeps them per Stylesheet (``_parse_cache``), and shares one source's
    rules between the parses of one app (a Stylesheet's ``reparse`` starts a new one): the
    rules are not changed once made."""
    key = (css, read_from, is_default_rules, tie_breaker, scope, *self._variables.items())
    rules = _parsed.get(key)
    if rules is None:
        rules = _parse_rules(self, css, read_from, is_default_rules, tie_breaker, scope)
        _parsed[key] = rules
    return rules


def parse_stylesheets_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every Stylesheet parses a CSS source once per process (:func:`_parse_rules_once`)."""
    monkeypatch.setattr(Stylesheet, "_parse_rules", _parse_rules_once)


def keep_cursors_still(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every Input's cursor stays shown: a blinking cursor would make a screen depend on when
    it was taken (harlequin's tests do the same). Each Input is made with its public
    ``cursor_blink`` off (the app's and Textual's own, the command palette's)."""
    made = Input.__init__

    def still(self: Input, *args: Any, **kwargs: Any) -> None:
        made(self, *args, **kwargs)
        self.cursor_blink = False

    monkeypatch.setattr(Input, "__init__", still)


def key_name(key: str) -> str:
    """The name Textual gives the key that types ``key`` when it is one character that is not
    a letter or digit (',' -> 'comma', ' ' -> 'space'), as a terminal's key arrives; any other
    ``key`` (a letter, a digit, a key name such as 'enter') as it is. Made as Textual makes
    it (the character's Unicode name, with Textual's public ``KEY_NAME_REPLACEMENTS``), and
    checked against Textual's public inverse, ``key_to_character``, where it knows the name
    (it reads 'minus' as no character): a Textual that names a key otherwise fails here,
    not in a test's burst."""
    if len(key) != 1 or key.isalnum():
        return key
    name = unicodedata.name(key).lower().replace("-", "_").replace(" ", "_")
    name = KEY_NAME_REPLACEMENTS.get(name, name)
    read = key_to_character(name)
    if read not in (key, None):
        raise ValueError(f"Textual reads key {name!r} as {read!r}, not {key!r}")
    return name


async def _callbacks_first(self: Screen[object], event: Any) -> None:
    """An idle screen's handler that runs what waits for its refresh at once, before the
    layout it was asked for (Textual's own first lets its update timer lay the screen out)."""
    event.prevent_default()
    await self._invoke_and_clear_callbacks()


def callbacks_before_layouts(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every screen runs what waits for its refresh before the layouts still to come (reach 5):
    what a widget placed after a refresh reads the layout before the last."""
    monkeypatch.setattr(Screen, "_on_idle", _callbacks_first)
