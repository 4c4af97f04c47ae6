"""`python -m minseg_tui` is the same as the `minseg-tui` command."""

import sys

from minseg_tui.cli import main

sys.exit(main())
