"""Finished evaluations of a fit, kept so that an interrupted fit resumes (``--resume``).

A fit's cost is its objective: the model run at every parameter set the optimiser tries (a
rotary fit simulates every fit run for each, about a second apiece).  So that Ctrl-C, a killed
process or a lost machine does not lose them, each finished evaluation is written, as soon as
it is finished, into a *work folder* beside the result folder::

    results/.oring.fit/
        fit.json                     fingerprint of the fit (decides what --resume may reuse)
        evaluations/<hash>.json      one finished evaluation, named by a hash of its key

Every file is written with :func:`sealsim.files.atomic_write_bytes` (a killed fit never
leaves half a record; a record that cannot be read is computed again).  The key of an
evaluation holds the fit stage and the parameter values; the fingerprint covers everything
else the model's answer depends on: the resolved fit case, the prepared runs (measured
signals, contact maps, duty cycles), the content of the files the case reads and sealsim's
version.  The records keep every float exactly (JSON's shortest repr; arrays as their
bytes), and the optimiser (``scipy.optimize.least_squares`` with fixed finite-difference
steps) is deterministic: a resumed fit asks for the same parameter sets in the same order,
finds the finished ones here and computes only the missing ones, so it ends at the result of
an uninterrupted fit, bit for bit.

The work folder is opened while the result folder's lock is held (two fits never share it) and
removed once the results are committed.
"""

from __future__ import annotations

import base64
import hashlib
import json
import shutil
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from sealsim import __version__
from sealsim.files import atomic_write_bytes, interrupted_work_left, resume_refused

__all__ = ["KeptEvaluations", "fingerprint", "work_folder_for"]


def work_folder_for(result: str | Path) -> Path:
    """The work folder of result folder ``result``: ``.NAME.fit`` next to it."""
    result = Path(result).resolve()
    return result.with_name(f".{result.name}.fit")


def fingerprint(*parts: Any) -> str:
    """sha256 of ``parts``: dicts, lists, numbers, strings, None, numpy arrays (their bytes),
    pydantic models (their JSON dump).

    Examples
    --------
    >>> fingerprint({"a": 1.0, "b": np.arange(3.0)}) == fingerprint({"b": np.arange(3.0),
    ...                                                              "a": 1.0})
    True
    >>> fingerprint([0.1]) == fingerprint([0.1 + 1e-16])     # the next float: another key
    False
    """
    h = hashlib.sha256()
    _update(h, parts)
    return h.hexdigest()


def _update(h, value: Any) -> None:
    if hasattr(value, "model_dump"):
        value = value.model_dump(mode="json")
    if isinstance(value, dict):
        h.update(b"{")
        for key in sorted(value, key=str):
            h.update(repr(str(key)).encode("utf-8") + b":")
            _update(h, value[key])
        h.update(b"}")
    elif isinstance(value, list | tuple):
        h.update(b"[")
        for item in value:
            _update(h, item)
            h.update(b",")
        h.update(b"]")
    elif isinstance(value, np.ndarray):
        array = np.ascontiguousarray(value)
        h.update(f"array{array.dtype.str}{array.shape}".encode() + array.tobytes())
    elif isinstance(value, float | np.floating):
        h.update(repr(float(value)).encode())
    else:
        h.update(repr(value).encode("utf-8"))


class KeptEvaluations:
    """The finished evaluations of one fit in its work folder (see the module docstring).

    Made before the fit computes anything: a work folder left by an interrupted fit is refused
    at once unless ``resume`` (reuse it) or ``discard`` (``--force``: start over).
    :meth:`start` then checks (``resume``) or writes the fit's fingerprint.

    Parameters
    ----------
    path : path
        The work folder (:func:`work_folder_for` of the result folder).
    resume : bool
        Reuse the evaluations of an interrupted run of the same fit.
    discard : bool
        (without ``resume``) drop the evaluations of an interrupted fit.
    source : str
        The fit case file (for the message of a refused resume).
    files : dict, optional
        :func:`sealsim.files.file_digests` of the files the fit reads (part of its
        fingerprint); a resume refused because one changed names it.

    Raises
    ------
    ResultExistsError
        An interrupted fit left evaluations here and neither ``resume`` nor ``discard`` is set.
    """

    def __init__(self, path: str | Path, *, resume: bool = False, discard: bool = False,
                 source: str = "", files: dict[str, str] | None = None):
        self.path = Path(path)
        self.source = source
        self.files = dict(files or {})
        self.records = self.path / "evaluations"
        self.resume = resume
        self.discard = discard
        self.reused = 0           # evaluations read from the work folder
        self.computed = 0         # ... and computed (and kept) by this fit
        self._key = ""
        self._seen: dict[str, Any] = {}
        found = self.count()
        if found and not resume and not discard:
            raise interrupted_work_left("fit", "evaluations", found, self.path)

    def count(self) -> int:
        """Number of evaluations kept in the work folder."""
        return sum(1 for _ in self.records.glob("*.json")) if self.records.is_dir() else 0

    def start(self, *parts: Any) -> None:
        """Open the work folder for a fit whose evaluations depend on ``parts`` (the resolved
        case, the prepared runs: see the module docstring), the files and sealsim's version.

        Raises
        ------
        InputError
            ``resume``, but the evaluations here belong to another fit, or to this one before
            its case, its data or sealsim changed.
        """
        key = fingerprint(__version__, self.files, *parts)
        meta = self.path / "fit.json"
        if self.path.exists():
            try:
                old = json.loads(meta.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                old = {}
            if self.resume and self.count():
                if old.get("fingerprint") != key:
                    raise resume_refused("fit", "evaluations", self.count(), self.path, old,
                                         self.files, " (its case, its contact maps or sealsim "
                                         "changed)")
                self._key = key
                return
            shutil.rmtree(self.path)
        self.records.mkdir(parents=True)
        atomic_write_bytes(meta, json.dumps({
            "fingerprint": key, "source": self.source, "files": self.files,
            "sealsim_version": __version__, "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
        }, indent=2).encode("utf-8"))
        self._key = key

    @property
    def started(self) -> bool:
        """Whether :meth:`start` opened the work folder for this fit."""
        return bool(self._key)

    def counts(self) -> dict[str, int]:
        """``{"computed": ..., "reused": ...}`` evaluations of this fit so far."""
        return {"computed": self.computed, "reused": self.reused}

    def _file(self, key: Any) -> Path:
        if not self._key:
            raise RuntimeError("KeptEvaluations.start() was not called")
        return self.records / f"{fingerprint(self._key, key)[:32]}.json"

    def evaluate(self, key: Any, compute: Callable[[], Any]) -> Any:
        """The kept value of evaluation ``key`` (JSON data: the stage and parameter values),
        or ``compute()``'s, kept (JSON: lists, dicts, floats, strings; numpy float arrays)
        before it is returned.
        """
        path = self._file(key)
        if path.name in self._seen:        # asked again by this fit (the optimiser does)
            return self._seen[path.name]
        try:
            value = json.loads(path.read_text(encoding="utf-8"),
                               object_hook=_from_plain)["value"]
            self.reused += 1
        except (OSError, ValueError, KeyError):   # not computed yet, or a damaged record
            value = compute()
            atomic_write_bytes(path, json.dumps({"key": key, "value": value},
                                                default=_plain).encode("utf-8"))
            self.computed += 1
        self._seen[path.name] = value
        return value

    def remove(self) -> None:
        """Drop the work folder (once the results are committed)."""
        shutil.rmtree(self.path, ignore_errors=True)

    def remove_if_empty(self) -> None:
        """Drop the work folder if it keeps nothing (a fit that failed before it evaluated)."""
        if not self.count():
            self.remove()


def _plain(value: Any) -> Any:
    """JSON data of numpy values: a float array as its bytes (exact, 2.5x smaller than its
    numbers in decimals: a friction fit's residuals are up to max_samples long)."""
    if isinstance(value, np.ndarray):
        data = np.ascontiguousarray(value, dtype="<f8")
        return {"float64": base64.b64encode(data.tobytes()).decode("ascii"),
                "shape": list(data.shape)}
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"{type(value).__name__} is not JSON data")


def _from_plain(item: dict) -> Any:
    if item.keys() == {"float64", "shape"}:
        data = np.frombuffer(base64.b64decode(item["float64"]), dtype="<f8")
        return data.reshape(item["shape"]).astype(float)
    return item
