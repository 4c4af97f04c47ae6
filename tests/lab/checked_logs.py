"""Seeded logs and their model check, made once per test process for the tests of the
student's words that read the same log (tests/lab/test_check_plain.py and test_check_words.py:
synth's logs of every cause at seed 3 were checked in both, the independent generator's seed 11
twice in test_check_plain). The generators are seeded and the check deterministic, so the
second test would compute the same log and the same result. Those tests share one xdist group
(:data:`GROUP`), so one worker checks each log once."""

from functools import cache

import pytest

from minseg_tui.model.check import CheckResult, check
from minseg_tui.model.synth import SynthLog, make_log
from tests.model import physics_gen

GROUP = pytest.mark.xdist_group("lab-check-words")
"""The xdist group of the tests that read a log of :func:`synth` or :func:`generated`."""


def synth(cause: str, seed: int = 3, touch: bool = False) -> tuple[SynthLog, CheckResult]:
    """synth's log of ``cause`` and its check at the nominal period of 25 ms."""
    return _synth(cause, seed, touch)


@cache
def _synth(cause: str, seed: int, touch: bool) -> tuple[SynthLog, CheckResult]:
    # cached on the arguments in one order: synth("x") and synth("x", seed=3) are one entry
    log = make_log(cause, seed=seed, touch=touch)
    return log, check(log.t, log.u, log.omega, ts=0.025)


def generated(
    seed: int, causes: tuple[str, ...], measured_pole: bool | None = None
) -> tuple[physics_gen.PhysLog, CheckResult]:
    """The independent generator's log and its check."""
    return _generated(seed, causes, measured_pole)


@cache
def _generated(
    seed: int, causes: tuple[str, ...], measured_pole: bool | None
) -> tuple[physics_gen.PhysLog, CheckResult]:
    log = physics_gen.make(seed, causes, measured_pole=measured_pole)
    return log, check(log.t, log.u, log.omega)
