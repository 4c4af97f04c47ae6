"""The model check: what the first-order model gets wrong in a run log, and why.

Fit T w' = -w + K u, simulate it on the measured input, show where it deviates, name the
causes among the candidates (several may act at once), fit the extended model holding all
of them, and measure the gain with figures that survive the encoder's noise. What the
check cannot tell from a log, it says. numpy only (no scipy.optimize, which takes longer
to import than the check takes to run), no I/O.

Modules, in the order the check uses them:

- sampling: how the log was sampled (speed over the real interval or the nominal period,
  jitter or lost samples, the speed's resolution and noise floor, counts or a smooth signal);
- simulate: the model and its effects in closed form per mode on a piecewise-constant input;
- effects: the causes, each whole in one entry of one list (names, parameter, search range,
  starts, what a log needs to show it, what its evidence reads off a log (a typed record),
  and its own simulation piece when it acts on the input);
- guess: what the starts are read off the log with;
- fit: whitened least squares (K solved linearly), any set of causes jointly (by
  :mod:`minseg_tui.model.optimize`, the search identify uses too), 95 % intervals;
- decide: the criterion with a margin, causes added and dropped one at a time;
- disturbances: a hand on the wheel, found in the settled stretches and fenced off;
- anomalies: wild samples, creep, late steps, gaps, disturbances, as typed records;
- deviations: where the baseline is wrong;
- evidence: what the evidence reads off a log, and what a log needs to show a cause;
- figures: the gain past the noise, held-out steps, the figure that leads, the close-up;
- result: the result and its JSON (typed records: caveats, evidence, the runner-up; the
  JSON's sentences are asked of :class:`~.result.Says`);
- pipeline: :func:`check`, from start to end.

The check's sentences (evidence, caveats, anomalies, why a
figure leads, the runner-up, the close-up, the sampling) are made from its records outside
the model, in :mod:`minseg_tui.lab.views.check_says` (the JSON of ``analyze --json``:
:func:`~minseg_tui.lab.views.check_says.as_json`); the gain figures' names and the full
text for lab assistants in :mod:`minseg_tui.lab.views.check_text`; a model's parameters in
:mod:`minseg_tui.lab.views.check_params`. The selection's reasons a cause was left out are
records too (:class:`.decide.Reason`, a cause's own :class:`.effects.Refusal`), and so is
where the speed's resolution came from (:class:`.sampling.CountFrom`). Each cause's words (its
label, what a student is told, its two or three words) are its row of
:data:`~minseg_tui.lab.views.check_says.CAUSE_WORDS`, which
:func:`~minseg_tui.lab.views.check_says.in_words` reads: the model holds no sentence.
"""

from minseg_tui.model.check.figures import Gain
from minseg_tui.model.check.pipeline import check
from minseg_tui.model.check.result import CheckResult

__all__ = ["CheckResult", "Gain", "check"]
