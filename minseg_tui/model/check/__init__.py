"""The model check: what the first-order model gets wrong in a step log, and why.

Fit T w' = -w + K u, simulate it on the measured input, show where it deviates, name the
cause among the candidates, fit the extended model and measure the gain. numpy only (no
scipy.optimize, which takes longer to import than the check takes to run), no I/O.

Modules: simulate (exact closed-form pieces per constant-input stretch), candidates (the
causes as data, and which simulator each uses), search (golden section, Nelder-Mead), fit
(whitened least squares, K solved linearly), decide (information criterion with a margin),
evidence (the finding in words), deviations (where the baseline is wrong), anomalies (wild
samples, creep, late steps, gaps), report (the result and its JSON), run (:func:`check`).
"""

from minseg_tui.model.check.report import CheckResult
from minseg_tui.model.check.run import check

__all__ = ["CheckResult", "check"]
