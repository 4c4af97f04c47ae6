"""Step logs of the project's own plant (minseg_tui.model.plant) for identify's tests: the
published MinSeg with its dry friction, sampled as the firmware's loop samples it."""

import math

import numpy as np

from minseg_tui.model.plant import Plant, PlantParams
from minseg_tui.model.runlog import RunLog
from minseg_tui.model.synth import IDENT_V_DROP

Q = 2 * math.pi / 720
"""rad per encoder count."""


def friction_log(u_req: float = 2.0, with_u_req: bool = True) -> tuple[RunLog, PlantParams]:
    """The published MinSeg with its dry friction, four steps 0 -> u_req V and back (25 ms,
    a loop late by up to 2 ms, seeded); ``with_u_req``: the log has the u_req column (else
    K divides by the log's own u)."""
    params = PlantParams(tau_c=7.3e-3, v_drop=IDENT_V_DROP)
    rng = np.random.default_rng(8)
    half = 60
    cmd = np.concatenate([np.zeros(20)] + [np.full(half, u_req), np.zeros(half)] * 4)
    plant = Plant(params, seed=8)
    t = np.arange(cmd.size) * 0.025 + rng.uniform(0, 0.002, cmd.size)
    count = np.empty(cmd.size, dtype=np.int64)
    for k in range(cmd.size):
        plant.advance(t[k] - plant.t)
        count[k] = plant.count
        plant.set_command(float(cmd[k]))
    log = RunLog(
        t=t,
        u=np.array([params.u_applied(v) for v in cmd]),
        omega=np.concatenate(([0.0], np.diff(count) * Q / np.diff(t))),
        extra={"count": count, "t_us": np.round(t * 1e6).astype(np.int64)}
        | ({"u_req": cmd} if with_u_req else {}),
    )
    return log, params
