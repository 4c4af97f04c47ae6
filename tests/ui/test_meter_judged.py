"""Walk 17's D6: on the virtual MinSeg the multimeter panel read "5.3 Ω", the group typed
"3,5 ohms" and Task 2 got a ✓ (3.5 Ω is inside the manual's 3-6 Ω). On the virtual board the
program knows what its meter showed: the session records it with the reading typed, and the
reading is judged against it (R, and u_ss and i_ss at the voltage they belong to). On a real
board nothing changes. At 80x24 with Pilot on the device double, whose meter always shows
2.05 V, 29.9 mA and 5.3 Ω (tests/ui/fakes.py's METER)."""

from __future__ import annotations

from textual.message import Message

from minseg_tui.lab.content.meter import SETTLE_S
from minseg_tui.lab.state.session import Session
from minseg_tui.ui.messages import MeterRead
from tests.ui.fakes import QuietDevice
from tests.ui.helpers import GUARD, Heard, goto, nav_mark, settle, start, type_in


class Meter(Heard):
    """:class:`Heard`, keeping the multimeter readings the app heard, newest last."""

    def __init__(self) -> None:
        super().__init__()
        self.reads: list[MeterRead] = []

    def hook(self, message: Message) -> None:
        if isinstance(message, MeterRead):
            self.reads.append(message)
        super().hook(message)

    async def read(self, pilot, requested: float | None = None) -> None:
        """Wait for a reading heard from now on (one taken at ``requested`` V once it has stood
        :data:`SETTLE_S`, when given) and for the app to have handled it."""
        first = len(self.reads)

        def came() -> bool:
            return any(
                m.reading is not None
                and (requested is None or (m.requested == requested and m.held >= SETTLE_S))
                for m in self.reads[first:]
            )

        await self.until(pilot, came)
        await settle(pilot)


async def test_r_typed_against_the_virtual_meter(quiet):
    """Task 2 with the panel showing 5.3 Ω: '3,5 ohms' is marked wrong under the entry and ✗
    in the list of steps, saying what the meter showed; the session file keeps the fact (it
    is judged so when opened again); '5,3 ohm' is right again, '53' wrong."""
    app = quiet()
    meter = Meter()
    async with app.run_test(size=(80, 24), message_hook=meter.hook) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        await meter.read(pilot)
        row = await type_in(pilot, "R", "3,5 ohms")
        said = str(row.query_one(".field-msg").render())
        assert "✗ wrong: the virtual multimeter showed 5.3 Ω, not 3.5 Ω: read it again" in said, (
            said
        )
        assert nav_mark(app, "task2") == "✗"
        with app.session as s:
            folder = s.folder
        with Session.open(folder, readonly=True) as saved:  # the fact was saved with the entry
            assert saved.entry("R").meter == (5.3,)
            assert saved.step_status("task2") == "wrong"
        await type_in(pilot, "R", "5,3 ohm")
        assert nav_mark(app, "task2") == "✓"
        row = await type_in(pilot, "R", "53")  # a decimal comma lost: warned, and wrong
        said = str(row.query_one(".field-msg").render())
        assert "showed 5.3 Ω, not 53 Ω" in said, said
        assert nav_mark(app, "task2") == "✗"


async def test_u_ss_and_i_ss_against_the_meter_at_their_voltage(quiet):
    """Task 4: the meter's reading counts for u_ss at 2.5 V only once 2.5 V has stood half a
    second; '3.05' typed there (the 3.5 V row's reading, say) is wrong, '2,05 V' right. Task
    5 likewise for i_ss: '0,0335 A' against 29.9 mA is wrong, '30 mA' right."""
    app = quiet()
    meter = Meter()
    async with app.run_test(size=(80, 24), message_hook=meter.hook) as pilot:
        await start(pilot)
        await goto(pilot, "task4")
        await pilot.press("f3")  # 2.5 V
        await meter.read(pilot, 2.5)
        row = await type_in(pilot, "u_ss@2.5", "3.05")
        said = str(row.query_one(".field-msg").render())
        assert (
            "✗ wrong: at 2.5 V the virtual multimeter showed 2.05 V, not 3.05 V: read it again"
        ) in said, said
        assert nav_mark(app, "task4") == "✗"
        row = await type_in(pilot, "u_ss@2.5", "2,05 V")
        assert "virtual multimeter" not in str(row.query_one(".field-msg").render())
        await goto(pilot, "task5")
        await meter.read(pilot, 2.5)
        row = await type_in(pilot, "i_ss@2.5", "0,0335 A")
        said = str(row.query_one(".field-msg").render())
        assert "at 2.5 V the virtual multimeter showed 29.9 mA, not 33.5 mA" in said, said
        assert nav_mark(app, "task5") == "✗"
        row = await type_in(pilot, "i_ss@2.5", "30 mA")
        assert "virtual multimeter" not in str(row.query_one(".field-msg").render())
        # no reading at 3.5 V was ever shown: its row is not judged by the meter
        row = await type_in(pilot, "i_ss@3.5", "3 mA")
        assert "virtual multimeter" not in str(row.query_one(".field-msg").render())


async def test_on_a_real_board_nothing_changes(quiet):
    """A board without the virtual multimeter: the program cannot know R; '3,5 ohms' is
    stored as before (✓), after as many turns of the stream as read the virtual meter."""
    device = QuietDevice(seed=1)
    device.port = "/dev/ttyACM0"
    device.board = None  # a real board: no multimeter to read
    app = quiet(device)
    async with app.run_test(size=(80, 24)) as pilot:
        await start(pilot)
        await goto(pilot, "task2")
        turns = device.reads
        for _ in range(GUARD):  # the stream worker turns on its own clock: wait for 3 turns
            if device.reads >= turns + 3:  # a virtual meter would have been read by now
                break
            await pilot.pause(0.01)
        else:
            raise AssertionError("the stream worker never turned 3 times")
        await settle(pilot)
        row = await type_in(pilot, "R", "3,5 ohms")
        assert "virtual multimeter" not in str(row.query_one(".field-msg").render())
        assert nav_mark(app, "task2") == "✓"
        with app.session as s:
            assert s.entry("R").meter == ()
