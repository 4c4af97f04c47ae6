"""Helpers for the lab tests: a child process that meets permissions as a plain user does."""

from __future__ import annotations

import ctypes
import os

PR_CAPBSET_DROP = 24
CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH = 1, 2


def as_plain_user() -> None:
    """preexec_fn: the child obeys file permissions (chmod 555 is read-only to it) even when
    the tests run as root: it drops the two capabilities that let root past them. A no-op
    for a plain user, who obeys them anyway."""
    if os.geteuid() != 0:
        return
    libc = ctypes.CDLL(None, use_errno=True)
    for cap in (CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH):
        if libc.prctl(PR_CAPBSET_DROP, cap, 0, 0, 0) != 0:
            raise OSError(ctypes.get_errno(), "prctl(PR_CAPBSET_DROP) failed")
