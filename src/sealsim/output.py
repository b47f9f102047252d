"""Result folders that never lose data.

Every command that writes results does so through :class:`ResultFolder`:

* an existing folder that already holds files is refused up front (before any computing)
  unless ``force=True`` -- :class:`~sealsim.errors.ResultExistsError`;
* results are written into a hidden staging folder next to the target, each file atomically
  (temporary name, then :func:`os.replace`);
* only when the whole run succeeded is the staging folder moved into place (the old results,
  if ``force``, are moved aside first and deleted afterwards).  A run that fails or is
  interrupted leaves the target untouched and no half-written file behind.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from sealsim.errors import InputError, ResultExistsError

__all__ = ["ResultFolder", "atomic_write_bytes", "atomic_write_text", "json_ready"]

# mkstemp/mkdtemp create private (0600/0700) entries; results get the user's normal modes
_UMASK = os.umask(0)
os.umask(_UMASK)


def json_ready(value: Any) -> Any:
    """Make results JSON-safe: numpy scalars become Python numbers, NaN/inf become None.

    JSON has no NaN; a missing value (e.g. no break-away in a run) is written as null.

    Examples
    --------
    >>> import numpy as np
    >>> json_ready({"a": np.float64(1.5), "b": [float("nan"), np.int64(2)]})
    {'a': 1.5, 'b': [None, 2]}
    """
    if isinstance(value, dict):
        return {k: json_ready(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(v) for v in value]
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, float | np.floating):
        return float(value) if math.isfinite(value) else None
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
        os.chmod(tmp, 0o666 & ~_UMASK)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def atomic_write_text(path: str | Path, text: str) -> Path:
    """Text variant of :func:`atomic_write_bytes` (UTF-8)."""
    return atomic_write_bytes(path, text.encode("utf-8"))


class ResultFolder:
    """A result folder written all-or-nothing.

    Parameters
    ----------
    path : str or Path
        Target folder.
    force : bool
        Replace a folder that already holds files.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "run"
    >>> with ResultFolder(out) as folder:
    ...     _ = folder.write_text("note.txt", "hello")
    >>> (out / "note.txt").read_text()
    'hello'
    >>> try:
    ...     ResultFolder(out)
    ... except ResultExistsError as err:
    ...     print("refused:", "--force" in str(err))
    refused: True
    """

    def __init__(self, path: str | Path, force: bool = False):
        self.path = Path(path)
        self.force = force
        if self.path.exists() and not self.path.is_dir():
            raise InputError(f"output path {str(self.path)!r} is a file, expected a folder")
        if self.path.is_dir() and any(self.path.iterdir()) and not force:
            raise ResultExistsError(
                f"output folder {str(self.path)!r} already holds results; "
                "choose another folder or pass --force to replace them")
        self._staging: Path | None = None

    @property
    def staging(self) -> Path:
        if self._staging is None:
            raise RuntimeError("ResultFolder is used outside its 'with' block")
        return self._staging

    def __enter__(self) -> ResultFolder:
        parent = self.path.resolve().parent
        try:
            parent.mkdir(parents=True, exist_ok=True)
            self._staging = Path(tempfile.mkdtemp(dir=parent, prefix=f".{self.path.name}.",
                                                  suffix=".partial"))
            os.chmod(self._staging, 0o777 & ~_UMASK)
        except OSError as exc:
            raise InputError(f"cannot create output folder {str(self.path)!r}: {exc}") from exc
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        staging, self._staging = self._staging, None
        if exc_type is not None:
            shutil.rmtree(staging, ignore_errors=True)
            return
        backup = None
        if self.path.exists():
            backup = self.path.with_name(f".{self.path.name}.{os.getpid()}.old")
            os.replace(self.path, backup)
        os.replace(staging, self.path)
        if backup is not None:
            shutil.rmtree(backup, ignore_errors=True)

    # -- writers -------------------------------------------------------------------------
    def file(self, name: str) -> Path:
        """Final-to-be path of a result file inside the staging folder."""
        target = self.staging / name
        target.parent.mkdir(parents=True, exist_ok=True)
        return target

    def write_text(self, name: str, text: str) -> Path:
        return atomic_write_text(self.file(name), text)

    def write_json(self, name: str, data: Any) -> Path:
        """Write JSON (numpy values and NaN made JSON-safe by :func:`json_ready`)."""
        return self.write_text(name, json.dumps(json_ready(data), indent=2, allow_nan=False)
                               + "\n")

    def write_csv(self, name: str, frame, **kwargs) -> Path:
        """Write a pandas DataFrame as CSV (no index unless asked)."""
        kwargs.setdefault("index", False)
        return self.write_text(name, frame.to_csv(**kwargs))

    def write_netcdf(self, name: str, dataset) -> Path:
        """Write an xarray Dataset to netCDF atomically."""
        target = self.file(name)
        tmp = target.with_name(f".{target.name}.tmp")
        try:
            dataset.to_netcdf(tmp)
            os.replace(tmp, target)
        finally:
            tmp.unlink(missing_ok=True)
        return target

    def savefig(self, name: str, figure, dpi: int = 130) -> Path:
        """Save a matplotlib figure as PNG atomically.

        sealsim builds figures as :class:`matplotlib.figure.Figure` objects without pyplot, so
        no GUI backend is needed and nothing has to be closed.
        """
        target = self.file(name)
        tmp = target.with_name(f".{target.name}.tmp")
        try:
            figure.savefig(tmp, dpi=dpi, format="png", bbox_inches="tight")
            os.replace(tmp, target)
        finally:
            tmp.unlink(missing_ok=True)
        return target

    def final_path(self, name: str = "") -> Path:
        """Where a file will be once the folder is committed."""
        return self.path / name
