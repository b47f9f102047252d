"""Safe file writing for every layer: atomic writes and JSON-ready values.

:func:`atomic_write_bytes` writes a temporary file in the target's folder and renames it into
place, so a reader never sees half a file and an interrupted write leaves the old file (or
none).  Result folders (:class:`sealsim.output.ResultFolder`) are built on it, and so are the
files written below the output layer: the FE map cache (:mod:`sealsim.pneumatic.contact_maps`)
and a study's work folder (:mod:`sealsim.studies.store`).
"""

from __future__ import annotations

import math
import os
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["JSON_DIGITS", "USER_UMASK", "atomic_write_bytes", "atomic_write_text", "json_ready"]

#: The process's umask: mkstemp/mkdtemp create private (0600/0700) entries, written files get
#: the user's normal modes (0o666 & ~USER_UMASK).
USER_UMASK = os.umask(0)
os.umask(USER_UMASK)

#: significant digits of floats in result JSON files: enough for any model result, and
#: ``67.99999999999949`` is written as ``68.0``
JSON_DIGITS = 12


def json_ready(value: Any, digits: int | None = None) -> Any:
    """Make results JSON-safe: numpy scalars become Python numbers, NaN/inf become None.

    JSON has no NaN; a missing value (e.g. no break-away in a run) is written as null.  With
    ``digits``, floats are rounded to that many significant digits (no ``0.30000000000000004``).

    Examples
    --------
    >>> import numpy as np
    >>> json_ready({"a": np.float64(1.5), "b": [float("nan"), np.int64(2)]})
    {'a': 1.5, 'b': [None, 2]}
    >>> json_ready([67.99999999999949, 1.0e-20 / 3], digits=12)
    [68.0, 3.33333333333e-21]
    """
    if isinstance(value, dict):
        return {k: json_ready(v, digits) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(v, digits) for v in value]
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, float | np.floating):
        if not math.isfinite(value):
            return None
        return float(f"{value:.{digits}g}") if digits else float(value)
    return value


def atomic_write_bytes(path: str | Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` via a temporary file in the same folder and a rename."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, 0o666 & ~USER_UMASK)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def atomic_write_text(path: str | Path, text: str) -> Path:
    """Text variant of :func:`atomic_write_bytes` (UTF-8)."""
    return atomic_write_bytes(path, text.encode("utf-8"))
