"""The lab's computations, Tasks 6-15, and what the numbers show.

Units: R ohm, u V, omega rad/s, i_ss mA as entered (A inside the formulas), k_v V s/rad,
k_a N m/A, f N m s/rad, J kg m^2, T s, K rad/s per V.

The package, one module per room:

- :mod:`.steady`: Tasks 6-9 from the table (k_v, k_a, f per row and their medians) and the
  table's u_ss and omega_ss at a requested voltage;
- :mod:`.steps`: the rising steps of a step log and the manual's 63 % reading;
- :mod:`.stepfit`: T and the steady speeds by least squares (Tasks 11-12), from one of
  :mod:`.wholelog` (the model of Task 14 over the whole log) and :mod:`.windowfit` (each
  rising step on its own), searched by :func:`minseg_tui.model.optimize.least_squares`, with
  the intervals of :mod:`.lsq` (they hold with correlated residuals; Student's t);
- :mod:`.observations`: what the numbers show, in sentences a student understands;
- :mod:`.identification`: Tasks 6-15 put together (K, T, J, the model of Task 14, omega at
  5 V) and the ``--json`` object.

Other layers import from here (``from minseg_tui.model.identify import identify``).
"""

from minseg_tui.model.identify.identification import (
    U_TASK15,
    Identification,
    StepResult,
    identify,
    step_alone,
)
from minseg_tui.model.identify.observations import (
    Observation,
    step_observations,
    table_observations,
)
from minseg_tui.model.identify.steady import (
    U_SS_HOW,
    Reading,
    Row,
    omega_ss_at,
    steady_state,
    u_ss_at,
    u_ss_words,
)
from minseg_tui.model.identify.stepfit import (
    RISING_STEPS,
    WHOLE_LOG,
    RisingStep,
    TimeConstantFit,
    fit_time_constant,
    model_reading_63,
    rising_steps,
)
from minseg_tui.model.identify.steps import E63, StepWindow, reading_63, step_windows

__all__ = [
    "E63",
    "RISING_STEPS",
    "WHOLE_LOG",
    "StepWindow",
    "model_reading_63",
    "reading_63",
    "U_TASK15",
    "Observation",
    "Identification",
    "Reading",
    "RisingStep",
    "Row",
    "StepResult",
    "TimeConstantFit",
    "fit_time_constant",
    "identify",
    "omega_ss_at",
    "rising_steps",
    "steady_state",
    "step_alone",
    "step_observations",
    "step_windows",
    "table_observations",
    "u_ss_at",
    "u_ss_words",
    "U_SS_HOW",
]
