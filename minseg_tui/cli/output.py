"""What the headless commands write: JSON that is JSON, and files that never overwrite
their own input.

JSON has no NaN or Infinity (Python's json module writes them by default, and a reader in
another language refuses the whole document): a value that is not a finite number is
written as null, the JSON for "no value".
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Mapping
from pathlib import Path

from minseg_tui.errors import InputError


def finite_or_none(obj: object) -> object:
    """``obj`` with every float that is NaN or infinite replaced by None (recursively through
    dicts, lists and tuples; tuples become lists, as JSON has them)."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: finite_or_none(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [finite_or_none(v) for v in obj]
    if hasattr(obj, "dtype") and hasattr(obj, "tolist"):  # a numpy scalar or array
        return finite_or_none(obj.tolist())
    return obj


def json_text(obj: object, indent: int | None = None) -> str:
    """``obj`` as strict JSON: NaN and infinities become null (see the module docstring)."""
    return json.dumps(finite_or_none(obj), indent=indent, allow_nan=False)


def print_json(obj: object, indent: int | None = None) -> None:
    """Print ``obj`` as strict JSON, one document and a newline."""
    print(json_text(obj, indent))


def output_file(path: str, inputs: Mapping[str, str], what: str) -> Path:
    """``path`` checked as a file to write ``what`` into (InputError otherwise): not a
    directory, in a folder that exists, and none of ``inputs`` (path -> what it is, for the
    message), whatever the name: the same path spelled differently, a symlink or a hard
    link to it."""
    out = Path(path)
    if out.is_dir():
        raise InputError(path, None, f"expected a file name for the {what}, got a directory")
    for name, role in inputs.items():
        same = out.resolve() == Path(name).resolve()
        if not same and out.exists():
            try:
                same = os.path.samefile(out, name)
            except OSError:
                same = False
        if same:
            raise InputError(
                path,
                None,
                f"expected a new file for the {what}; this is {role} ({name}), which "
                "writing would destroy",
            )
    if not out.parent.is_dir():
        raise InputError(
            path, None, f"cannot write the {what}: the folder {out.parent} does not exist"
        )
    return out
