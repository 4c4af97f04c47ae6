"""The lab's computations, Tasks 6-15, and what the numbers show.

Units: R ohm, u V, omega rad/s, i_ss mA as entered (A inside the formulas), k_v V s/rad,
k_a N m/A, f N m s/rad, J kg m^2, T s, K rad/s per V.

The package, one module per room:

- :mod:`.steady`: Tasks 6-9 from the table (k_v, k_a, f per row and their medians) and the
  table's u_ss and omega_ss at a requested voltage;
- :mod:`.rises`: the rises of a run log and the manual's 63 % reading;
- :mod:`.risefit`: T and the steady speeds by least squares (Tasks 11-12), from one of
  :mod:`.wholelog` (the model of Task 14 over the whole log) and :mod:`.windowfit` (each
  rise on its own), searched by :func:`minseg_tui.model.optimize.least_squares`, with
  the intervals of :mod:`.lsq` (they hold with correlated residuals; Student's t);
- :mod:`.observations`: what the numbers show, as typed records (their sentences are
  :mod:`minseg_tui.lab.content.identify_says`'s);
- :mod:`.refusals`: why identify refuses a table, R or a log, as records (worded there too);
- :mod:`.identification`: Tasks 6-15 put together (K, T, J, the model of Task 14, omega at
  5 V) and the ``--json`` object.

Other layers import from here (``from minseg_tui.model.identify import identify``).
"""

from minseg_tui.model.identify.identification import (
    U_TASK15,
    Identification,
    ResponseResult,
    ZeroVoltRefusal,
    ZeroVoltRise,
    identify,
    response_alone,
    response_observed,
)
from minseg_tui.model.identify.observations import (
    Observation,
    response_observations,
    table_observations,
)
from minseg_tui.model.identify.refusals import IdentifyRefusal, IdentifyRefused
from minseg_tui.model.identify.risefit import (
    RISES,
    WHOLE_LOG,
    Rise,
    TimeConstantFit,
    fit_time_constant,
    model_reading_63,
    rises,
)
from minseg_tui.model.identify.rises import E63, RiseWindow, reading_63, rise_windows
from minseg_tui.model.identify.steady import (
    U_SS_HOW,
    Reading,
    Row,
    UssHow,
    omega_ss_at,
    steady_state,
    u_ss_at,
)

__all__ = [
    "E63",
    "RISES",
    "WHOLE_LOG",
    "RiseWindow",
    "model_reading_63",
    "reading_63",
    "U_TASK15",
    "Observation",
    "Identification",
    "IdentifyRefusal",
    "IdentifyRefused",
    "Reading",
    "Rise",
    "Row",
    "ResponseResult",
    "TimeConstantFit",
    "fit_time_constant",
    "identify",
    "omega_ss_at",
    "rises",
    "steady_state",
    "response_alone",
    "response_observed",
    "response_observations",
    "rise_windows",
    "table_observations",
    "u_ss_at",
    "U_SS_HOW",
    "UssHow",
    "ZeroVoltRefusal",
    "ZeroVoltRise",
]
