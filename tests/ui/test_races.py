"""Messages a worker thread read before a key and the app handles after it: what the screen
shows is the link as it is when the message is handled, not as the worker read it.

The stream worker reads the board every 50 ms and posts what it read; a key typed meanwhile
(F2, F3) is handled first when it reaches the app's queue first, and the stream's message,
read before the key, after it. These tests post that message themselves right after the key
was handled, as the stream would have read it before: the order is fixed, nothing depends on
the machine's load. (CI failed once on the same defect with the board check: 1b5b61c.)"""

from __future__ import annotations

import threading

from textual.message import Message
from textual.worker import Worker, WorkerState

from minseg_tui.device.link import LinkEvent
from minseg_tui.errors import DeviceError
from minseg_tui.report.write import write_report
from minseg_tui.ui.app import LabApp
from minseg_tui.ui.config import UiConfig
from minseg_tui.ui.messages import LinkEventArrived, MotorKnown, NoCounts
from tests.ui.conftest import DATE
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import burst, enter_all, goto, heard_notifications, settle, start
from tests.ui.test_walk7_keys import SlowBoard, post_keys, pump


async def test_a_watchdog_read_before_f3_and_handled_after_it_leaves_f3s_voltage(quiet):
    """The board's watchdog stopped the motor, the stream read the event, and F3 (set before
    the event reached the app) put 2.5 V on the motor again: the event said "off" and the
    status line kept it, with F4 capturing at no level, while the wheel turned at 2.5 V."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await burst(pilot, "f3")
        assert app._device.u_req == 2.5 and app.motor == "2.5 V"
        app.post_message(LinkEventArrived(LinkEvent("watchdog", "watchdog", 0.0)))
        await settle(pilot)
        assert app.motor == "2.5 V" and app.requested == 2.5
        assert "watchdog" in str(app.link.event)


async def test_a_restart_read_before_f3_says_off_only_while_the_link_does(quiet):
    """The same event handled with the link still off (nothing set since): off."""
    app = quiet()
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await burst(pilot, "f3")
        app._device.u_req = 0.0  # the board restarted: the link has the motor off
        app.post_message(LinkEventArrived(LinkEvent("boot", "restarted", 0.0)))
        await settle(pilot)
        assert app.motor == "off" and app.requested is None


async def test_no_counts_read_before_f2_is_not_said_after_it(quiet):
    """The stream saw the motor driven at 2.5 V with the count standing still and said so,
    and F2 was handled first: "the motor is driven at 2.5 V and the encoder counts nothing"
    came with the motor off."""
    app = quiet()
    said = heard_notifications(app)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await burst(pilot, "f3")
        app.post_message(NoCounts(2.5))  # the motor is at 2.5 V: said
        await settle(pilot)
        assert sum("counts nothing" in s for s in said) == 1
        await burst(pilot, "f2")
        assert app._device.u_req == 0.0
        app.post_message(NoCounts(2.5))  # read before F2: not said
        await burst(pilot, "f3", "f3")  # 3.5 V now
        app.post_message(NoCounts(2.5))  # read at 2.5 V, handled at 3.5 V: not said
        await settle(pilot)
        assert sum("counts nothing" in s for s in said) == 1


class RefusingBoard(SlowBoard):
    """A slow board that refuses V (DeviceError) while ``refuse`` is set."""

    def __init__(self) -> None:
        super().__init__()
        self.refuse = False

    def set_voltage(self, u: float) -> float:
        self._wait()
        if self.refuse:
            raise DeviceError("minseg://: the board refused V")
        return super().set_voltage(u)


async def test_what_the_link_said_while_a_command_was_on_its_way_is_read_once_it_is_sent(quiet):
    """While F3's command waits for the board, the board restarts (the link: off) and then
    refuses the command: the restart, passed over while the command was on its way (the
    screen shows what F3 asks), is read once the command is done: off."""
    dev = RefusingBoard()
    app = quiet(dev)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await burst(pilot, "f3")
        assert app.motor == "2.5 V"
        dev.answer.clear()
        dev.refuse = True
        post_keys(app, "f3")
        await pump(pilot, lambda: app.requested == 3.5 or dev.stalled)
        dev.u_req = 0.0  # the board restarted: the link has the motor off
        app.post_message(MotorKnown(0.0))
        app.post_message(LinkEventArrived(LinkEvent("boot", "restarted", 0.0)))
        await pump(pilot, lambda: app.link.event != "")
        assert app.motor == "3.5 V"  # the command is on its way: what it asks is shown
        dev.answer.set()
        await settle(pilot)
        assert not dev.stalled
        assert app.motor == "off" and app.requested is None


async def test_two_exports_leave_the_newer_report_on_disk(tmp_path):
    """F8, a change, F8 again while the first report is still being written: both writers
    ran at once on the same files, and the first (the older snapshot) finishing last stood
    on disk after the second was said written. The second now writes after the first, the
    newest snapshot last."""
    gate = threading.Event()
    calls: list[int] = []
    finished: list[str] = []

    def writer(session):
        calls.append(len(calls))
        if len(calls) == 1:  # the first export waits until the second is asked for
            assert gate.wait(SlowBoard.GUARD), "the first export was never let go on"
        paths = write_report(session).paths
        entry = session.entry("summary.unclear")
        finished.append(entry.typed if entry is not None else "")
        return paths

    cfg = UiConfig(device="auto", sessions=tmp_path, today=DATE, animations=False, refresh=0)
    dev = QuietDevice(seed=1)
    app = LabApp(cfg, lambda spec: dev, writer)
    started: list[Worker[object]] = []

    def hook(message: Message) -> None:
        """Keep every report worker that starts (the second cancels the first)."""
        if isinstance(message, Worker.StateChanged) and message.worker.group == "export":
            if message.state == WorkerState.RUNNING:
                started.append(message.worker)

    async with app.run_test(size=(80, 24), message_hook=hook) as pilot:
        await start(pilot)
        enter_all(app, {"summary.unclear": "the first export"})
        post_keys(app, "f8")
        await pump(pilot, lambda: len(calls) == 1)
        enter_all(app, {"summary.unclear": "the second export"})
        post_keys(app, "f8")
        await pump(pilot, lambda: len(started) == 2)
        gate.set()
        await settle(pilot, lambda: bool(app.exported))
        assert finished[-1] == "the second export", finished
        md = next(p for p in app.exported if p.endswith("report.md"))
    text = " ".join(open(md, encoding="utf-8").read().split())
    assert "the second export" in text and "the first export" not in text
