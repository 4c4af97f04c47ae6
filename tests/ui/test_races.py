"""Messages a worker thread read before a key and the app handles after it: what the screen
shows is the link as it is when the message is handled, not as the worker read it.

The stream worker reads the board every 50 ms and posts what it read; a key typed meanwhile
(F2, F3) is handled first when it reaches the app's queue first, and the stream's message,
read before the key, after it. These tests post that message themselves right after the key
was handled, as the stream would have read it before: the order is fixed, nothing depends on
the machine's load. (CI failed once on the same defect with the board check: 1b5b61c.)"""

from __future__ import annotations

from minseg_tui.device.link import LinkEvent
from minseg_tui.errors import DeviceError
from minseg_tui.ui.messages import LinkEventArrived, MotorKnown, NoCounts
from tests.ui.helpers import burst, goto, heard_notifications, settle, start
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
