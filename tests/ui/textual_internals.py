"""Every place where the UI tests reach into Textual's internals (names with a leading
underscore, or a module function Textual does not document), kept here and nowhere else.
Each reach is here because Textual 8.2 offers no public way to do it; when an upgrade of
Textual breaks one, this file is the one to read. Checked against Textual's source in the
venv and its documentation (Pilot, App.run_test, Input, Screen, textual.keys):

Eleven names of Textual's internals, in five reaches (each reach's last line says in one line
why no public way does it; the public names looked at are in the lines above it):

1. :func:`make_waits_exact`: replaces ``wait_for_idle`` (``textual._wait``) as imported by
   ``textual.app`` and ``textual.pilot``, and ``Pilot._wait_for_screen`` with
   :func:`wait_for_screen`, the exact wait Pilot itself uses after a key, done again here with
   public names only. Pilot's public ``pause()`` adds a forced layout and, with no delay, the
   CPU-idle guess, and ``wait_for_animation``/``wait_for_scheduled_animations`` wait for
   animations only.
   Why: Pilot.press and pause() call them after every key; neither they nor run_test take another.
2. :func:`leave_headless_frames_unpainted`: ``Screen._compositor_refresh`` replaced, and in
   the replacement the screen's ``_compositor._dirty_regions``, ``_dirty_widgets`` and
   ``App._update_mouse_over``. ``TEXTUAL_FPS`` only spaces the frames, and
   ``App.batch_update`` holds them for a block.
   Why: no option or ``TEXTUAL_*`` setting turns painting off in a headless app.
3. :func:`mark_idle_nodes`: ``MessagePump._get_message`` wrapped so that a node says while
   its message loop waits for the next message: with nothing queued (the public
   ``message_queue_size``) the node then has no handler under way (its loop takes the next
   message only once the one before, its Idle event and its ``call_next`` callbacks are
   done). :func:`idle` reads it. ``MessagePump.is_running`` is true for the node's whole
   life; the public ``message_signal`` is published before the node's Idle and callbacks.
   Why: ``message_queue_size`` says what is queued, not whether a handler is under way.
4. :func:`callbacks_before_layouts`: ``Screen._on_idle`` replaced, calling
   ``Screen._invoke_and_clear_callbacks`` at once. What waits for the screen's refresh
   (``call_after_refresh``) runs when the screen is next idle, on the layout it has; a
   widget asks for the next layout only when it is itself next idle, so on a busy machine
   the screen may run them between two layouts. This makes the screen run them before
   every layout still to come, the worst order.
   Why: ``call_after_refresh`` and ``refresh(layout=True)`` say what to do, not in which order.
5. :func:`parse_stylesheets_once`: ``Stylesheet._parse_rules`` wrapped with a cache for the
   process, keyed by its arguments and the variables the Stylesheet parses with, which it
   notes as they are handed to it (its public constructor and ``set_variables``; until stop
   37 read off its private ``_variables``). Textual caches the parse per Stylesheet only,
   and a test process starts hundreds of apps, each parsing the same CSS again.
   Why: nothing public shares parsed CSS between apps, or parses a source with a cache.

posting, harlequin and toolong (their newest snapshots, read at stop 37) do none of these:
they wait with ``pause()``, ``workers.wait_for_complete()`` and polls, paint every frame and
parse CSS per app; harlequin stills its Input cursors through ``Input._toggle_cursor`` (done
here with the public ``cursor_blink``) and imports ``textual.widgets._tree``.

Done with public API here: :func:`wait_for_screen` sees that the app has failed in its
documented ``App.return_code`` (1), looked at every :data:`FAILED_LOOK` s (until stop 37:
``App._exception_event``, which Pilot's own waits on); the running app is ``MessagePump.app``
of a node attached to no app (not ``textual._context.active_app``); the still cursor is each
Input's ``cursor_blink`` set off as it is made (not ``Input._toggle_cursor``); a character's
key name is made from its Unicode name and Textual's ``KEY_NAME_REPLACEMENTS`` (not
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


FAILED = 1
"""``App.return_code`` of an app that has failed (Textual's documented value for an app that
exited with a fatal error: an exception in a handler; None while it runs)."""

FAILED_LOOK = 0.05
"""How often (s) :func:`wait_for_screen` looks whether the app has failed while it waits: a
failed app's nodes handle nothing more, and the wait ends within this of the failure."""


async def wait_for_screen(pilot: Pilot[object], timeout: float = 30.0) -> bool:
    """Wait until the app and every node of its screen have handled what was queued on them
    when this began (a handler under way included): a callback queued on each of them that
    is not idle (:func:`idle`: it has nothing to handle), then wait until all have run, or
    the app has failed. As ``Pilot._wait_for_screen`` of Textual 8.2 does, with a callback
    that states its own signature, the idle nodes left out, and the failure seen in the
    public ``App.return_code`` (:data:`FAILED`), not in ``App._exception_event``. Pilot's
    own queues a new closure on every node each time, and Textual works out each closure's
    signature (``inspect.signature``) before it calls it; it also queues one on the idle
    nodes, where it waits for nothing: each cost a message, an Idle event and the MRO walk
    for its handlers, and the tests' waits were about half the messages the app processed.
    True: all of them ran; False: the app failed first; raises Textual's
    ``WaitForScreenTimeout`` after ``timeout`` s (a hang guard)."""
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
        loop = asyncio.get_running_loop()
        end = loop.time() + timeout
        zero = asyncio.create_task(countdown.zero.wait())
        try:
            while not zero.done() and app.return_code != FAILED:
                if loop.time() >= end:
                    raise WaitForScreenTimeout(
                        "Timed out while waiting for widgets to process pending messages."
                    )
                await asyncio.wait((zero,), timeout=FAILED_LOOK)
        finally:
            zero.cancel()
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

_VARIABLES = "_minseg_tests_variables"
"""The attribute that holds the variables (the theme's colours) a Stylesheet was made or last
set with, as ``(name, value)`` pairs: what it parses CSS with (:func:`parse_stylesheets_once`)."""

_made = Stylesheet.__init__
_set_variables = Stylesheet.set_variables


def _made_noting(self: Stylesheet, *, variables: dict[str, str] | None = None) -> None:
    """``Stylesheet(variables=...)``, which notes the variables it is made with."""
    _made(self, variables=variables)
    setattr(self, _VARIABLES, tuple((variables or {}).items()))


def _set_noting(self: Stylesheet, variables: dict[str, str]) -> None:
    """Textual's public ``Stylesheet.set_variables``, which notes the variables set."""
    _set_variables(self, variables)
    setattr(self, _VARIABLES, tuple(variables.items()))


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
    key = (css, read_from, is_default_rules, tie_breaker, scope, getattr(self, _VARIABLES))
    rules = _parsed.get(key)
    if rules is None:
        rules = _parse_rules(self, css, read_from, is_default_rules, tie_breaker, scope)
        _parsed[key] = rules
    return rules


def parse_stylesheets_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every Stylesheet parses a CSS source once per process (:func:`_parse_rules_once`), and
    notes the variables it parses with as they are handed to it (its public constructor and
    ``set_variables``)."""
    monkeypatch.setattr(Stylesheet, "__init__", _made_noting)
    monkeypatch.setattr(Stylesheet, "set_variables", _set_noting)
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
    """Every screen runs what waits for its refresh before the layouts still to come (reach 4):
    what a widget placed after a refresh reads the layout before the last."""
    monkeypatch.setattr(Screen, "_on_idle", _callbacks_first)
