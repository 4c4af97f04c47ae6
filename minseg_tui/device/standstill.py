"""Waiting for the wheel to stand before a square-wave run (Task 10).

A square-wave run that starts with the wheel still turning (the motor was at 4.5 V a moment
before, in Task 4) has a first step that starts from speed, and the model check finds an
early step where there is none. So the motor is stopped first, the run waits until the
encoder count has not moved for :data:`STILL_FOR` s of board time, and the recording takes
:data:`PRE_ROLL` samples of the standing wheel before the board starts the sequence.

:class:`StandStill` judges the samples it is fed (by the Task 10 procedure,
:mod:`minseg_tui.lab.state.task10`, in the TUI's stream worker or headless). It counts board time,
so the answer does not depend on how busy the host is.
"""

from __future__ import annotations

from typing import Literal

from minseg_tui.device.samples import SampleBatch

STILL_FOR: float = 0.15
"""The count must stay the same this long (board time, s): six 25 ms samples; the wheel
then turns slower than one count per 0.15 s, 0.06 rad/s."""

STILL_TIMEOUT: float = 5.0
"""Board time (s) after which a wheel that still turns is given up on (a hand on it, or the
motor coasting without friction)."""

PRE_ROLL: int = 4
"""Samples of the standing wheel a run records before the board starts the sequence (its
first step then has a speed before the edge to start from)."""

State = Literal["waiting", "still", "turning"]


def timeout_message(timeout: float = STILL_TIMEOUT) -> str:
    """The one line for a wheel that did not stand within ``timeout`` s."""
    return (
        f"the wheel still turns {timeout:g} s after the motor was switched off (a hand on "
        "it? the motor coasting?): the run did not start; start it again once it stands"
    )


class StandStill:
    """Fed the stream's samples after STOP, says when the wheel stands: the count unchanged
    for ``still_for`` s of board time (``still``), or not within ``timeout`` s
    (``turning``); until then ``waiting``. Samples with the motor still driven (sent before
    the STOP took effect) and a reconnect start the watch over."""

    def __init__(self, still_for: float = STILL_FOR, timeout: float = STILL_TIMEOUT) -> None:
        self.still_for = still_for
        self.timeout = timeout
        self._start: float | None = None  # board time of the first sample seen, s
        self._since: float | None = None  # board time the count last changed, s
        self._count: int | None = None
        self._epoch: int | None = None
        self.state: State = "waiting"

    def feed(self, batch: SampleBatch) -> State:
        """Look at the next samples (board time, counts); the state after them."""
        if self.state != "waiting":
            return self.state
        for t_us, count, u_req, epoch in zip(
            batch.t_us.tolist(),
            batch.count.tolist(),
            batch.u_req.tolist(),
            batch.epoch.tolist(),
            strict=True,
        ):
            t = t_us / 1e6
            if u_req != 0.0:  # sent before the STOP took effect: the motor still drove it
                self._start = None
                continue
            if self._start is None or epoch != self._epoch:  # a reconnect: start over
                self._start, self._since, self._count, self._epoch = t, t, count, epoch
                continue
            if count != self._count:
                self._count, self._since = count, t
            assert self._since is not None
            if t - self._since >= self.still_for:
                self.state = "still"
                break
            if t - self._start >= self.timeout:
                self.state = "turning"
                break
        return self.state
