"""The status line's words about the link stay true (issue 20, second walk).

After F10 the top line said "board answers again" for the rest of the session, though it had
never said that the board stopped answering. The link says "alive" only after it said
"silent"; the status line now says "again" only after it said the board was silent, and
goes back to the link's counters a few seconds of board time later. The device double hands
the app the link's events and the board's samples, so nothing here depends on the clock."""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from textual.pilot import Pilot

from minseg_tui.device.link import LinkEvent
from minseg_tui.ui.app import TRANSIENT_SHOWN
from minseg_tui.ui.widgets.status import DeviceStatus
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import Heard, settle, standing, start, taken


def _status(app) -> str:
    return str(app.screen.query_one(DeviceStatus).render())


async def _stream(pilot, dev: QuietDevice, seq: int, seconds: float) -> int:
    """``seconds`` of a standing wheel from sample ``seq`` on (25 ms apart), handed to the
    app and taken; the next sequence number."""
    n = round(seconds / 0.025)
    dev.feed(standing(n, seq))
    await taken(pilot, seq + n)
    return seq + n


async def _event(pilot, dev: QuietDevice, heard: Heard, seq: int, kind: str, text: str) -> int:
    """The link's event ``kind`` handed to the app with the next sample, and handled; the next
    sequence number."""
    dev.feed_event(LinkEvent(kind, f"minseg://: {text}", float(seq)))
    seq = await _stream(pilot, dev, seq, 0.025)
    await heard.until(pilot, lambda: kind in heard.kinds)
    await settle(pilot)
    return seq


@asynccontextmanager
async def _on_a_standing_wheel(quiet) -> AsyncIterator[tuple[Pilot[None], QuietDevice, Heard, int]]:
    """The app on the device double, a session started and a second of a standing wheel
    taken: its pilot, the double, what the app heard, and the next sequence number."""
    dev = QuietDevice(seed=1)
    app = quiet(dev)
    heard = Heard()
    async with app.run_test(size=(80, 24), message_hook=heard.hook) as pilot:
        await start(pilot)
        seq = await _stream(pilot, dev, 0, 1.0)
        yield pilot, dev, heard, seq


async def test_answers_again_follows_a_silence_and_gives_way_to_the_link_counters(quiet):
    async with _on_a_standing_wheel(quiet) as (pilot, dev, heard, seq):
        app = pilot.app
        assert "link ok" in _status(app)
        seq = await _event(pilot, dev, heard, seq, "silent", "the board has not answered")
        assert "silent" in _status(app)
        seq = await _event(pilot, dev, heard, seq, "alive", "the board answers again")
        assert "answers again" in _status(app)
        seq = await _stream(pilot, dev, seq, 1.0)
        assert "answers again" in _status(app)  # for a few seconds
        seq = await _stream(pilot, dev, seq, TRANSIENT_SHOWN)
        assert "answers again" not in _status(app)
        assert "link ok" in _status(app)


async def test_no_answers_again_without_a_silence_said_first(quiet):
    async with _on_a_standing_wheel(quiet) as (pilot, dev, heard, seq):
        app = pilot.app
        await _event(pilot, dev, heard, seq, "alive", "the board answers again")
        assert "again" not in _status(app)
        assert "link ok" in _status(app)


async def test_board_reconnected_gives_way_to_the_link_counters(quiet):
    async with _on_a_standing_wheel(quiet) as (pilot, dev, heard, seq):
        app = pilot.app
        seq = await _event(pilot, dev, heard, seq, "disconnected", "the board is gone")
        assert "disconnected" in _status(app)
        seq = await _event(pilot, dev, heard, seq, "connected", "reconnected")
        assert "reconnected" in _status(app)
        await _stream(pilot, dev, seq, TRANSIENT_SHOWN + 0.1)
        assert "link ok" in _status(app)


async def _silence_in_one_pass(pilot, dev: QuietDevice, heard: Heard, seq: int) -> int:
    """Walk 8, D5: a silence of 0.6 s and the answer that ends it, handed to the app in one
    read (as on a busy PC, where the stream found both at once) and handled."""
    dev.feed_event(LinkEvent("silent", "minseg://: the board has not answered", float(seq)))
    dev.feed_event(
        LinkEvent("alive", "minseg://: the board answers again", float(seq), silent_s=0.6)
    )
    seq = await _stream(pilot, dev, seq, 0.025)
    await heard.until(pilot, lambda: "alive" in heard.kinds)
    await settle(pilot)
    return seq


async def test_a_silence_seen_only_by_its_end_is_said_with_it(quiet):
    """The virtual MinSeg runs on the PC: its pause is the PC's, and the line says so."""
    async with _on_a_standing_wheel(quiet) as (pilot, dev, heard, seq):
        app = pilot.app
        seq = await _silence_in_one_pass(pilot, dev, heard, seq)
        line = _status(app)
        assert "paused 0.6 s (PC busy)" in line, line
        await _stream(pilot, dev, seq, TRANSIENT_SHOWN + 0.1)
        assert "paused" not in _status(app) and "link ok" in _status(app)


async def test_a_real_boards_silence_is_said_with_its_length(quiet):
    async with _on_a_standing_wheel(quiet) as (pilot, dev, heard, seq):
        app = pilot.app
        dev.board = None  # a board on a cable: its silence may be its own
        await _silence_in_one_pass(pilot, dev, heard, seq)
        line = _status(app)
        assert "silent 0.6 s, answers again" in line, line
