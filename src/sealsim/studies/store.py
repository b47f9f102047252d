"""Where a study keeps its finished runs until it is complete: the work folder.

A study's results are committed all at once through :class:`sealsim.output.ResultFolder`
(staging folder, lock, ``--force``), like every sealsim run.  Its runs, however, must survive
an interrupted study, and the staging folder does not (it is removed on failure, Ctrl-C or the
next start).  So each finished run is written, as soon as it is finished, into a *work folder*
beside the result folder::

    results/.tolerance.study/
        study.json              fingerprint of the study (decides what --resume may reuse)
        runs/00000017.json      one record per finished run (written atomically)
        runs/00000017.npz       its series, if any (written before the record)

Each file is written atomically (a temporary name, then a rename), so a killed study never
leaves half a record; records are not forced to disk one by one (an ``fsync`` costs about as
much as a short run), so after a power failure a record may be unreadable: ``--resume`` then
treats it as missing and computes the run again.  The work folder is written only while the
result folder's lock is held, so two studies never share it.
``--resume`` reuses the records of a work folder whose fingerprint matches the study and runs
only the missing ones; the work folder is removed once the results are committed.  Run records
are stored with full float precision (``repr``), so a resumed study gives exactly the dataset of
an uninterrupted one.
"""

from __future__ import annotations

import io
import json
import os
import shutil
import time
from pathlib import Path
from typing import Any

import numpy as np

from sealsim import __version__
from sealsim.files import atomic_write_bytes, interrupted_work_left, resume_refused

__all__ = ["WorkFolder", "work_folder_for"]


def work_folder_for(result: str | Path) -> Path:
    """The work folder of result folder ``result``: ``.NAME.study`` next to it."""
    result = Path(result).resolve()
    return result.with_name(f".{result.name}.study")


class WorkFolder:
    """Finished runs of one study (see the module docstring)."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self.runs = self.path / "runs"

    def start(self, fingerprint: str, source: str, n_runs: int, *, resume: bool,
              discard: bool, files: dict[str, str] | None = None) -> set[int]:
        """Open the work folder for a study; returns the indices of runs already finished.

        Parameters
        ----------
        fingerprint : str
            :meth:`sealsim.studies.spec.Study.fingerprint` of the study.
        resume : bool
            Reuse the runs of an interrupted run of the same study.
        discard : bool
            (without ``resume``) drop the runs of an interrupted study (``--force``).
        files : dict, optional
            ``{path: content hash}`` of the files the study's case references (part of the
            fingerprint); a resume refused because one changed names it.

        Raises
        ------
        ResultExistsError
            Finished runs of an interrupted study are here and neither ``resume`` nor
            ``discard`` is set.
        InputError
            ``resume`` but the runs here belong to a different (or changed) study.
        """
        meta = self.path / "study.json"
        if self.path.exists():
            finished = len(self.indices())
            try:
                old = json.loads(meta.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                old = {}
            if resume:
                self._drop_unreadable()
                if old.get("fingerprint") != fingerprint:
                    raise resume_refused("study", "runs", finished, self.path, old,
                                         files or {})
                return self.indices()
            if not discard and finished:
                raise interrupted_work_left("study", "runs", finished, self.path)
            shutil.rmtree(self.path)
        self.runs.mkdir(parents=True)
        atomic_write_bytes(meta, json.dumps({
            "fingerprint": fingerprint, "source": source, "runs": n_runs, "files": files or {},
            "sealsim_version": __version__, "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
        }, indent=2).encode("utf-8"))
        return set()

    def _drop_unreadable(self) -> None:
        for path in self.runs.glob("*.json"):
            try:
                json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                path.unlink(missing_ok=True)

    def indices(self) -> set[int]:
        """Indices of the runs stored here."""
        if not self.runs.is_dir():
            return set()
        return {int(p.stem) for p in self.runs.glob("*.json") if p.stem.isdigit()}

    def save(self, record: dict[str, Any]) -> None:
        """Store one finished run (series first, then the record that marks it finished)."""
        stem = self.runs / f"{record['index']:08d}"
        series = record.get("series") or {}
        if series:
            buffer = io.BytesIO()
            np.savez(buffer, **{name: array for name, (_, array) in series.items()})
            _write(stem.with_suffix(".npz"), buffer.getvalue())
        meta = {k: v for k, v in record.items() if k != "series"}
        meta["series_dims"] = {name: list(dims) for name, (dims, _) in series.items()}
        _write(stem.with_suffix(".json"), json.dumps(meta, allow_nan=True).encode("utf-8"))

    def load(self, index: int) -> dict[str, Any]:
        """A stored run record, with its series."""
        stem = self.runs / f"{index:08d}"
        record = json.loads(stem.with_suffix(".json").read_text(encoding="utf-8"))
        dims = record.pop("series_dims", {})
        record["series"] = {}
        if dims:
            with np.load(stem.with_suffix(".npz")) as arrays:
                record["series"] = {name: (tuple(d), arrays[name]) for name, d in dims.items()}
        return record

    def remove(self) -> None:
        shutil.rmtree(self.path, ignore_errors=True)


def _write(path: Path, data: bytes) -> None:
    """Atomic replace without fsync (see the module docstring)."""
    tmp = path.with_name(f".{path.name}.tmp")
    tmp.write_bytes(data)
    os.replace(tmp, path)
